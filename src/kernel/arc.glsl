// The arc fraction of Podee et al. 2021, Sec. 3.3 ("the ratio of the angle of the light arc
// to that of the whole arc"), computed exactly on the unit sphere.
//
// Between two instants the reflection is assumed to move from r0 to r1 along the
// great-circle arc at constant angular speed (slerp). Along that arc, for any fixed X,
//   r(psi) = cos(psi) r0 + sin(psi) w,   r(psi) . X = A cos(psi) + B sin(psi),
// with w the unit tangent at r0, psi in [0, theta], theta = angle(r0, r1). A spherical cap
// {r : angle(r, X) <= rho} meets the arc's circle in one interval of psi, centred on
// phi = atan2(B, A) with half-width alpha, where (sin(beta) = n . X for the circle's unit
// normal n)
//   cos(alpha) = cos(rho) / cos(beta),   alpha = atan2(sqrt(sin^2 rho - sin^2 beta), cos rho),
// the second form keeping full relative precision for the sun's 0.27 degree disk. The
// light cone is the cap about L of radius rho; "below the horizon" (r.y <= 0) is the cap
// about -y of radius 90 degrees. The in-light fraction counts only time above the horizon,
// so in_light = |cone| - |cone and below| and in_light + below <= 1.
//
// Degenerate arcs (|r0 x r1| at or below the precision's rounding: the endpoints coincide
// or are antipodal to within ~1e-12 rad in double, ~3e-6 rad in float):
//  * r0 . r1 > 0: no motion; each fraction is 0 or 1 by the spec's tests on the midpoint.
//  * r0 . r1 < 0: antipodal, the great circle is undefined; the half circle from r0 through
//    the zenith side is chosen (w = the unit component of +y orthogonal to r0; for a
//    vertical r0 the horizontal component of L, or world x). The choice depends on the
//    pair {r0, r1} only, so reversing the arc gives the same result.
// Zero or non-finite endpoints (which the host checks before the frame) give no light and
// no sea: (0, 0).

struct ArcFractions {
  real in_light;  // fraction of the interval with angle(r, L) <= rho and r.y > 0
  real below;     // fraction of the interval with r.y <= 0
};

struct GreatArc {
  vec3 a;
  vec3 w;
  vec3 n;
  real theta;
};

// At most three disjoint intervals of [0, theta].
struct Intervals {
  real lo[3];
  real hi[3];
  int count;
};

SG_FN Intervals intervals_empty() {
  Intervals v;
  for (int i = 0; i < 3; ++i) {
    v.lo[i] = 0.0;
    v.hi[i] = 0.0;
  }
  v.count = 0;
  return v;
}

SG_FN void intervals_add(INOUT(Intervals) v, real l, real h) {
  if (h > l && v.count < 3) {
    v.lo[v.count] = l;
    v.hi[v.count] = h;
    v.count += 1;
  }
}

SG_FN real intervals_measure(IN(Intervals) v) {
  real m = 0.0;
  for (int i = 0; i < v.count; ++i)
    m += v.hi[i] - v.lo[i];
  return m;
}

SG_FN real intervals_overlap(IN(Intervals) p, IN(Intervals) q) {
  real m = 0.0;
  for (int i = 0; i < p.count; ++i) {
    for (int j = 0; j < q.count; ++j)
      m += max(0.0, min(p.hi[i], q.hi[j]) - max(p.lo[i], q.lo[j]));
  }
  return m;
}

// {psi in [0, theta] : angle(r(psi), X) <= rho} for unit X.
SG_FN Intervals cap_on_arc(IN(GreatArc) arc, vec3 X, real sin_rho, real cos_rho) {
  Intervals res = intervals_empty();
  real A = dot(arc.a, X);
  real B = dot(arc.w, X);
  if (A == 0.0 && B == 0.0) {
    // X is a pole of the circle: every point of it lies at exactly 90 degrees from X.
    if (cos_rho <= 0.0) intervals_add(res, 0.0, arc.theta);
    return res;
  }
  real sin_beta = abs(dot(arc.n, X));
  real s2 = (sin_rho - sin_beta) * (sin_rho + sin_beta);
  if (s2 < 0.0) return res;  // the circle passes outside the cap
  real alpha = atan(sqrt(s2), cos_rho);
  if (alpha >= kPi) {
    intervals_add(res, 0.0, arc.theta);
    return res;
  }
  real phi = atan(B, A);  // in [-pi, pi]
  // theta <= pi and 2 alpha < 2 pi: the copies phi + 2 pi m, m in {-1, 0, 1}, cover every
  // intersection with [0, theta], and they are disjoint.
  for (int m = -1; m <= 1; ++m) {
    real c = phi + kTwoPi * real(m);
    intervals_add(res, max(0.0, c - alpha), min(arc.theta, c + alpha));
  }
  return res;
}

// The fractions for a direction that does not move.
SG_FN ArcFractions arc_still(vec3 r, IN(Light) l) {
  ArcFractions f;
  f.in_light = 0.0;
  f.below = 0.0;
  if (r.y <= 0.0) {
    f.below = 1.0;
  } else if (light_contains(l, r)) {
    f.in_light = 1.0;
  }
  return f;
}

// |r0 x r1| at or below this is a degenerate arc: about 1e4 times the rounding of a unit
// vector's cross product (1e-12 in double, 2e-6 in float), below which the arc's angle
// has lost its digits and the arc is shorter than any feature the midpoint test misses.
SG_FN real arc_degenerate_sin() {
  return kDoublePrecision ? 1e-12 : 2e-6;
}

// r0, r1: reflections at the start and end of the interval (any non-zero length).
SG_FN ArcFractions arc_fractions(vec3 r0_in, vec3 r1_in, IN(Light) l) {
  ArcFractions none;
  none.in_light = 0.0;
  none.below = 0.0;
  real len0 = length(r0_in);
  real len1 = length(r1_in);
  if (!(len0 > 0.0 && len0 < kRealMax && len1 > 0.0 && len1 < kRealMax)) return none;
  vec3 r0 = r0_in / len0;
  vec3 r1 = r1_in / len1;
  // Early outs, exact: every point of the arc lies within theta/2 of an endpoint, so when
  // both endpoints are further than rho + theta/2 from L the arc misses the light's cone,
  // and when both lie above the horizon by more than theta/2 it never dips below it. Half
  // the arc's angle from chord lengths: sin(theta/2) = |r1 - r0| / 2,
  // cos(theta/2) = |r1 + r0| / 2, and cos(rho + theta/2) by angle addition.
  real sh = 0.5 * length(r1 - r0);
  real ch = 0.5 * length(r1 + r0);
  real cos_reach = l.cos_radius * ch - l.sin_radius * sh;
  bool misses_light =
      l.radius < 0.5 * kPi && ch > 0.0 && max(dot(r0, l.L), dot(r1, l.L)) < cos_reach;
  bool stays_above = min(r0.y, r1.y) > sh;
  if (misses_light && stays_above) return none;

  vec3 cr = cross(r0, r1);
  real s = length(cr);
  real c = dot(r0, r1);
  GreatArc arc;
  arc.a = r0;
  if (s > arc_degenerate_sin()) {
    arc.theta = atan(s, c);
    arc.n = cr / s;
    arc.w = normalize(cross(arc.n, r0));
  } else if (c > 0.0) {
    return arc_still(normalize(r0 + r1), l);
  } else {
    // Antipodal: the half circle through the zenith side.
    vec3 w = vec3(0.0, 1.0, 0.0) - r0.y * r0;
    if (length(w) < 1e-6) {
      w = vec3(l.L.x, 0.0, l.L.z);
      if (length(w) < 1e-6) w = vec3(1.0, 0.0, 0.0);
      w -= dot(w, r0) * r0;
    }
    arc.w = normalize(w);
    arc.n = normalize(cross(r0, arc.w));
    arc.theta = kPi;
  }

  Intervals cone = intervals_empty();
  if (!misses_light) cone = cap_on_arc(arc, l.L, l.sin_radius, l.cos_radius);
  Intervals below = intervals_empty();
  if (!stays_above) below = cap_on_arc(arc, vec3(0.0, -1.0, 0.0), 1.0, 0.0);
  ArcFractions f;
  f.below = clamp(intervals_measure(below) / arc.theta, 0.0, 1.0);
  f.in_light = clamp((intervals_measure(cone) - intervals_overlap(cone, below)) / arc.theta, 0.0,
                     1.0 - f.below);
  return f;
}
