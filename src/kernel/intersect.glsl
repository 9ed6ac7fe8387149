// Where a camera ray meets the water (scene spec, "Radiance along a camera ray", 1).
//
// flat: the plane y = 0. displaced: the first intersection with the height field
// y = h(x, z, t), marched inside the slab |y| <= sum |A_i| that bounds the surface. Along
// the ray, f(s) = y(s) - h(x(s), z(s), t) changes at most at the rate
//     Lip = |d.y| + (sum_i A_i |k_i|) |d.xz|
// so a step of f(s) / Lip cannot pass a zero of f: the first crossing is never skipped.
// Steps are at least graze_depth / Lip, so the only intersections that can be missed are
// grazes that dip less than graze_depth below the surface before leaving it (1e-6 m in
// double, 1e-4 m in float, where positions of ~100 m carry 1e-5 m of rounding). The
// bracketed root is refined by the Illinois variant of regula falsi (Dowell and Jarratt
// 1971) to |f| <= root_tolerance (1e-9 m in double, 1e-5 m in float) or a bracket at
// rounding width. The march stops after kMaxMarchSteps steps (a graze along the whole
// slab at the smallest step), as a miss.

const int kMaxMarchSteps = 2000000;
const int kMaxRefineSteps = 100;

struct RayHit {
  bool hit;
  real s;  // ray parameter along the direction given (point = origin + s dir)
  vec3 point;
};

SG_FN real graze_depth() {
  return kDoublePrecision ? 1e-6 : 1e-4;
}
SG_FN real root_tolerance() {
  return kDoublePrecision ? 1e-9 : 1e-5;
}

SG_FN RayHit no_hit() {
  RayHit r;
  r.hit = false;
  r.s = 0.0;
  r.point = vec3(0.0);
  return r;
}

// The plane y = 0; `d` need not be unit length.
SG_FN RayHit intersect_flat(vec3 o, vec3 d) {
  RayHit r = no_hit();
  if (o.y > 0.0 ? d.y >= 0.0 : d.y <= 0.0) return r;
  r.s = -o.y / d.y;
  r.point = o + r.s * d;
  r.point.y = 0.0;
  r.hit = true;
  return r;
}

// f(s) = y(s) - h at the point o + s d.
SG_FN real height_above_water(IN(WaveBuffer) waves, IN(Frame) f, vec3 o, vec3 d, real s, real dt) {
  vec3 p = o + s * d;
  return p.y - water_height(waves, f, p.x, p.z, dt);
}

// The first intersection with y = h(x, z, t), dt = t - display time; `d` unit length.
SG_FN RayHit intersect_displaced(IN(WaveBuffer) waves, IN(Frame) f, vec3 o, vec3 d, real dt) {
  RayHit r = no_hit();
  real amax = f.amplitude_bound;
  // The part of the ray inside the slab |y| <= amax.
  real s0 = 0.0;
  real s1 = 0.0;
  if (d.y < 0.0) {
    s0 = max(0.0, (o.y - amax) / -d.y);
    s1 = (o.y + amax) / -d.y;
  } else if (d.y > 0.0) {
    if (o.y > amax) return r;
    s1 = (amax - o.y) / d.y;
  } else {
    if (abs(o.y) > amax) return r;
    s1 = kRealMax;
  }
  if (!(s1 >= s0)) return r;
  real lip = abs(d.y) + f.slope_bound * length(vec2(d.x, d.z));
  real min_step = graze_depth() / max(lip, 1e-30);

  real s = s0;
  real fs = height_above_water(waves, f, o, d, s, dt);
  if (fs <= 0.0) {
    // The ray starts at or below the surface (only when the camera is inside the slab).
    r.hit = true;
    r.s = s;
    r.point = o + s * d;
    return r;
  }
  for (int step = 0; step < kMaxMarchSteps && s < s1; ++step) {
    real next = min(s1, s + max(fs / lip, min_step));
    if (!(next < kRealMax)) break;
    real fn = height_above_water(waves, f, o, d, next, dt);
    if (fn <= 0.0) {
      // Root bracketed in [s, next] (f(s) > 0 >= f(next)): Illinois iterations.
      real a = s;
      real fa = fs;
      real b = next;
      real fb = fn;
      int side = 0;
      for (int it = 0; it < kMaxRefineSteps && -fb > root_tolerance(); ++it) {
        real c = (a * fb - b * fa) / (fb - fa);
        if (!(c > a && c < b)) c = 0.5 * (a + b);
        real fc = height_above_water(waves, f, o, d, c, dt);
        if (fc > 0.0) {
          a = c;
          fa = fc;
          if (side == -1) fb *= 0.5;
          side = -1;
        } else {
          b = c;
          fb = fc;
          if (side == 1) fa *= 0.5;
          side = 1;
        }
        if (b - a <= 4.0 * kRealEpsilon * abs(b)) break;
      }
      // b is on the surface's side f <= 0 within the tolerance; keep its exact height.
      fb = height_above_water(waves, f, o, d, b, dt);
      r.hit = true;
      r.s = b;
      r.point = o + b * d;
      r.point.y = r.point.y - fb;
      return r;
    }
    s = next;
    fs = fn;
  }
  return r;
}
