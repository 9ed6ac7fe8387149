// Gaussians on the light plane: principal axes, the mass beyond a line, and the mass
// inside the light disk at one instant (Podee et al. 2021, Eq. 17 without the time
// integral; the "convolution of the RDF with the light disk" of Sec. 3.6, the fallback).
//
// gaussian_disk_mass: in the Gaussian's principal frame (major axis s, minor axis w) the
// mass is the 1D integral over s of the major marginal times the minor conditional's
// probability of falling in the disk's chord, an erf difference:
//     mass = int phi(s / s1) / s1 [Phi((c_w + h(s)) / s2) - Phi((c_w - h(s)) / s2)] ds,
//     h(s) = sqrt(R^2 - (s - c_s)^2)
// with (c_s, c_w) the disk centre relative to the mean. The substitution s = c_s + R sin(u)
// removes the chord's square-root ends, the range is clipped to +-9 s1 about the mean, and
// the integral is split where the chord's half-length equals |c_w| (where the minor
// conditional steps); 30-point Gauss-Legendre on each piece then gives 4e-6 or better for
// any elongation (measured against 2D quadrature, gaussian_disk_test), degenerate
// (s2 = 0) distributions included. Beyond 9 standard deviations the tails (below 3e-18)
// are taken as 0 or 1 without quadrature.
//
// gaussian_disk_mass_riemann: the paper's fallback, a Riemann sum of the density over an
// n x n grid of cells covering the disk (cell centres inside the disk).

// The 30-point Gauss-Legendre rule on [-1, 1]: the 15 positive nodes and their weights
// (from Boost.Math's gauss<double, 30>, which tabulates them to full precision).
const real kGauss30Node[15] =
    SG_ARRAY(real, 15,
             (0.051471842555317698, 0.15386991360858354, 0.25463692616788985, 0.35270472553087812,
              0.44703376953808915, 0.53662414814201986, 0.62052618298924289, 0.69785049479331585,
              0.76777743210482619, 0.82956576238276836, 0.88256053579205274, 0.92620004742927431,
              0.96002186496830755, 0.98366812327974718, 0.99689348407464951));
const real kGauss30Weight[15] = SG_ARRAY(
    real, 15,
    (0.10285265289355884, 0.1017623897484055, 0.099593420586795267, 0.096368737174644253,
     0.092122522237786122, 0.086899787201082976, 0.080755895229420213, 0.073755974737705204,
     0.065974229882180491, 0.057493156217619065, 0.048402672830594053, 0.03879919256962705,
     0.028784707883323369, 0.018466468311090958, 0.007968192496166605));

// 8-point Gauss-Legendre on [0, 1]: nodes (1 +- x) / 2, weights w / 2 (the same source,
// Boost.Math's gauss<double, 8>); gaussian_disk_mass_along's sub-intervals and the smooth
// terms' pieces (smooth_terms.glsl) take it.
const real kGl8X[4] = SG_ARRAY(
    real, 4, (0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363));
const real kGl8W[4] = SG_ARRAY(
    real, 4, (0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763));

// Eigen-decomposition of a symmetric 2x2 covariance: major standard deviation s1 >= minor
// s2 >= 0 and the unit major axis u (minor axis (-u.y, u.x)). The minor eigenvalue of an
// elongated covariance cancels (mean - rad): it carries the precision's rounding times the
// major one, 1e-16 in double, 1e-7 in float (docs/porting.md).
struct PrincipalAxes {
  real s1;
  real s2;
  vec2 u;
};

SG_FN PrincipalAxes principal_axes(mat2 c) {
  real a = c[0][0];
  real b = 0.5 * (c[1][0] + c[0][1]);
  real d = c[1][1];
  real mean = 0.5 * (a + d);
  real diff = 0.5 * (a - d);
  real rad = sqrt(diff * diff + b * b);
  real l1 = mean + rad;
  real l2 = mean - rad;
  PrincipalAxes p;
  p.s1 = sqrt(max(0.0, l1));
  p.s2 = sqrt(max(0.0, l2));
  // The eigenvector of l1: (b, l1 - a) or (l1 - d, b), whichever is longer (better
  // conditioned); both vanish for an isotropic covariance, where any axis will do.
  vec2 u1 = vec2(b, l1 - a);
  vec2 u2 = vec2(l1 - d, b);
  vec2 u = dot(u1, u1) > dot(u2, u2) ? u1 : u2;
  real uu = dot(u, u);
  p.u = uu > 0.0 ? u * inversesqrt(uu) : vec2(1.0, 0.0);
  return p;
}

// The mass of N(mean, cov) in the half-plane a . p + c <= 0: a . p + c is normal with mean
// a . mean + c and variance a^T cov a (a step when that variance is 0).
SG_FN real gaussian_half_plane_mass(vec2 mean, mat2 cov, vec2 a, real c) {
  real m = dot(a, mean) + c;
  real var = dot(a, cov * a);
  if (!(var > 0.0)) return m <= 0.0 ? 1.0 : 0.0;
  // Beyond 9 standard deviations the tail is below 1.2e-19: 0 or 1 without the erfc.
  real z = m * inversesqrt(var);
  if (z >= 9.0) return 0.0;
  if (z <= -9.0) return 1.0;
  return 0.5 * erfc(z * kInvSqrtTwo);
}

// The integrand of gaussian_disk_mass at u (see above).
SG_FN real disk_mass_integrand(real u, real cs, real cw, real R, real s1, real s2) {
  real s = cs + R * sin(u);
  real h = R * cos(u);
  real dens = exp(-0.5 * sqr(s / s1)) * kInvSqrtTwoPi / s1;
  return dens * normal_interval(cw - h, cw + h, s2) * h;
}

SG_FN real disk_mass_piece(real lo, real hi, real cs, real cw, real R, real s1, real s2) {
  if (!(hi > lo)) return 0.0;
  real mid = 0.5 * (lo + hi);
  real half_width = 0.5 * (hi - lo);
  real sum = 0.0;
  SG_COUNT(nodes, 30);
  for (int q = 0; q < 15; ++q) {
    real dx = half_width * kGauss30Node[q];
    sum += (disk_mass_integrand(mid + dx, cs, cw, R, s1, s2) +
            disk_mass_integrand(mid - dx, cs, cw, R, s1, s2)) *
           kGauss30Weight[q];
  }
  return half_width * sum;
}

// The mass of N(mean, cov) inside the disk |p| <= R.
SG_FN real gaussian_disk_mass(vec2 mean, mat2 cov, real R) {
  PrincipalAxes p = principal_axes(cov);
  if (p.s1 <= 0.0) return dot(mean, mean) <= R * R ? 1.0 : 0.0;
  vec2 w = vec2(-p.u.y, p.u.x);
  vec2 c = -mean;  // the disk centre relative to the mean
  real cs = dot(c, p.u);
  real cw = dot(c, w);
  // Beyond 9 major standard deviations the mass is below 3e-18 (the chi distribution's
  // tail with 2 degrees of freedom, exp(-81/2)).
  real dm = length(mean);
  if (dm >= R + 9.0 * p.s1) return 0.0;
  if (dm + 9.0 * p.s1 <= R) return 1.0;
  // Likewise along the minor axis (tail ~2e-19).
  if (abs(cw) >= R + 9.0 * p.s2) return 0.0;
  real lo = max(cs - R, -9.0 * p.s1);
  real hi = min(cs + R, 9.0 * p.s1);
  if (hi <= lo) return 0.0;
  real ulo = asin(clamp((lo - cs) / R, -1.0, 1.0));
  real uhi = asin(clamp((hi - cs) / R, -1.0, 1.0));
  // Where the chord's half-length R cos(u) is below |c_w| - 9 s2 the chord lies beyond 9
  // minor standard deviations: trim those ends.
  if (abs(cw) - 9.0 * p.s2 > 0.0) {
    real umax = acos(min(1.0, (abs(cw) - 9.0 * p.s2) / R));
    ulo = max(ulo, -umax);
    uhi = min(uhi, umax);
    if (uhi <= ulo) return 0.0;
  }
  // Split where the chord's half-length equals |c_w|: at most two cuts inside (ulo, uhi).
  real c1 = uhi;
  real c2 = uhi;
  if (abs(cw) < R) {
    real us = acos(abs(cw) / R);
    if (-us > ulo && -us < uhi) c1 = -us;
    if (us > ulo && us < uhi) c2 = us;
    if (c1 == uhi) c1 = c2;
  }
  real mass = disk_mass_piece(ulo, c1, cs, cw, R, p.s1, p.s2);
  mass += disk_mass_piece(c1, c2, cs, cw, R, p.s1, p.s2);
  mass += disk_mass_piece(c2, uhi, cs, cw, R, p.s1, p.s2);
  return mass;
}

// The mass of N(mean, cov) in the disk's segment cut off by a half-plane: |p| <= R and
// a . p + c <= 0 (a != 0). With n = a / |a| and d = c / |a| the segment is n . p <= -d;
// with t = n . p and s = w . p (w across n) the Gaussian splits into the marginal
// N(t; m_t, v_t) and the conditional N(s; m_s + r (t - m_t), v_s - r^2 v_t), r = C_ts / v_t,
// and the mass is the integral over t in [-R, -d] of the marginal times the conditional's
// mass on the chord [-h, h], h = sqrt(R^2 - t^2). It is taken in u (t = R sin u, dt = h du:
// smooth at the rim) over the part of [-R, -d] within 9 deviations of m_t, by 30-point
// Gauss-Legendre (staa: the light's disk where it crosses the horizon; tested against a
// grid in kernel/disk_segment_test.cpp).
SG_FN real gaussian_disk_segment_mass(vec2 mean, mat2 cov, real R, vec2 a, real c) {
  real la = length(a);
  vec2 n = a / la;
  real d = c / la;
  if (-d <= -R) return 0.0;
  if (-d >= R) return gaussian_disk_mass(mean, cov, R);
  vec2 w = vec2(-n.y, n.x);
  real mt = dot(n, mean);
  real ms = dot(w, mean);
  real vt = dot(n, cov * n);
  real vs = dot(w, cov * w);
  real cts = dot(n, cov * w);
  if (!(vt > 0.0)) {
    if (mt > -d || abs(mt) >= R) return 0.0;
    real h = sqrt(R * R - mt * mt);
    return normal_interval(-h - ms, h - ms, sqrt(max(vs, 0.0)));
  }
  real st = sqrt(vt);
  real r = cts / vt;
  real sc = sqrt(max(vs - cts * r, 0.0));
  real lo = max(-R, mt - 9.0 * st);
  real hi = min(-d, mt + 9.0 * st);
  if (!(hi > lo)) return 0.0;
  real ulo = asin(clamp(lo / R, -1.0, 1.0));
  real uhi = asin(clamp(hi / R, -1.0, 1.0));
  real mid = 0.5 * (ulo + uhi);
  real half_width = 0.5 * (uhi - ulo);
  real sum = 0.0;
  SG_COUNT(nodes, 30);
  for (int q = 0; q < 30; ++q) {
    real u = mid + half_width * (q < 15 ? kGauss30Node[q] : -kGauss30Node[q - 15]);
    real t = R * sin(u);
    real h = R * cos(u);
    real m = ms + r * (t - mt);
    real dens = exp(-0.5 * sqr((t - mt) / st)) * kInvSqrtTwoPi / st;
    sum += kGauss30Weight[q < 15 ? q : q - 15] * dens * normal_interval(-h - m, h - m, sc) * h;
  }
  return half_width * sum;
}

// The mass of N(a + t (b - a), cov) in the disk |p| <= R averaged over t in [0, 1]: Eq. 17's
// time integral along one straight sub-segment of the path, in closed form in time (the
// fallback along the path, staa.glsl: a midpoint rule would need a sample per third of the
// bump's width, up to 32 an instant's cost each, and its count would differ between
// neighbouring pixels). With x along the segment's unit
// direction e (length L) and y along its normal n, the Gaussian splits into the marginal
// N(y; c_y, v_y) of its normal coordinate (c_y = n . a, v_y = n^T cov n) and the
// conditional of x, N(x; a_x + t L + r (y - c_y), v_x|y) (r = e^T cov n / v_y,
// v_x|y = e^T cov e - r^2 v_y). The mean moves along x only, so the time average of the
// conditional is (Phi((x - m) / s) - Phi((x - m - L) / s)) / L (m = a_x + r (y - c_y),
// s = sqrt(v_x|y)), and its integral over the disk's chord [-h, h] (h = sqrt(R^2 - y^2)) is,
// with int Phi(z) dz = G(z) = z Phi(z) + phi(z) = max(z, 0) + T(|z|), T(z) = phi(z) - z Phi(-z),
//     (1 / L) [overlap([-h, h], [m, m + L]) + s (T(|z1|) - T(|z2|) - T(|z3|) + T(|z4|))],
// z1,2 = (+-h - m) / s and z3,4 = z1,2 - L / s: the overlap is the exact limit as s -> 0 and
// the T terms, each below phi(z), correct it near the ends. What is left is a 1D integral
// over y of the marginal times that, taken as gaussian_disk_mass takes its own
// (y = R sin(u), the range clipped to +-9 deviations about c_y, pieces between the
// integrand's kinks). A segment of length 0 is the instant's mass (the chord average's
// limit, segment_chord_average); a Gaussian that is a
// line along the segment (v_y = 0) has the one chord y = c_y.
//
// Each piece takes as many nodes as its integrand's features ask, from 8-point
// Gauss-Legendre on sub-intervals (a fixed 30-point rule per piece spent 30 nodes where the
// disk is narrow against the marginal, most pieces in practice, and still erred by up to
// 8e-6 where it was not):
//  - the marginal's Gaussian varies over s_y in y: one sub-interval per 2 s_y of the
//    piece's extent in y;
//  - the chord's average varies only through the T terms, each a step of width s in x
//    centred where z_i = 0, i.e. at the piece's ends (the kinks). In u, z_i moves by at
//    most R sqrt(1 + r^2) / s per radian, so a step is at least delta = s / (R sqrt(1 +
//    r^2)) wide: where 6 delta is under a quarter of the piece, a sub-interval of 6 delta
//    at each end takes the step and the rest is smooth; otherwise the piece is cut in
//    sub-intervals of 2 delta. The steps weigh s / L against the overlap's L: where
//    s < 0.02 L they are left to the ends' nodes;
//  - at most 4 sub-intervals for the steps, 9 for the marginal (its 18 deviations).
// Measured on the arguments the fallback met on the four shared scenes and fresnel-sky
// (38,253 calls at 640x360) against 8 x 64 nodes a piece: 10.1 nodes a call instead of 29.2,
// largest error 9.8e-7 instead of 8.0e-6 (with at most 4 sub-intervals for the marginal
// too; 9 since, for the narrowest lines at L = 0: docs/benchmarks.md).
// T(|z|) = phi(z) - |z| Phi(-|z|) from upper = Phi(-|z|) (special.glsl,
// normal_upper_tail); 0 past 9 deviations.
SG_FN real gaussian_tail_integral(real z, real upper) {
  real t = abs(z);
  if (t >= 9.0) return 0.0;
  return exp(-0.5 * t * t) * kInvSqrtTwoPi - t * upper;
}

// The chord's time average along the segment (above). Where L is below a small fraction
// d of s, the tails' differences would cancel (the precision's rounding times s / L), so
// the average is taken as its value at the segment's middle, the instant's probability
// Phi(z1) - Phi(z2) of the chord there (off by d^2 / 24 at most: d = 1e-5 in double,
// 1e-2 in float, where rounding and that error balance); L = 0 is that instant. A segment
// of length 0 thus takes this code, not the instant's own quadrature (gaussian_disk_mass):
// code that a GL program holds costs it even where no pixel runs it (docs/benchmarks.md).
SG_FN real segment_chord_average(real h, real m, real L, real s) {
  if (!(s > 0.0)) {
    if (!(L > 0.0)) return abs(m) < h ? 1.0 : 0.0;
    return max(0.0, min(h, m + L) - max(-h, m)) / L;
  }
  bool instant = !(L > (kDoublePrecision ? 1e-5 : 1e-2) * s);
  real mc = instant ? m + 0.5 * L : m;
  real z1 = (h - mc) / s;
  real z2 = (-h - mc) / s;
  real q1 = normal_upper_tail(z1);
  real q2 = normal_upper_tail(z2);
  if (instant) return normal_mass_of_tails(z2, z1, q2, q1);
  real z3 = z1 - L / s;
  real z4 = z2 - L / s;
  real overlap = max(0.0, min(h, m + L) - max(-h, m));
  real tails = gaussian_tail_integral(z1, q1) - gaussian_tail_integral(z2, q2) -
               gaussian_tail_integral(z3, normal_upper_tail(z3)) +
               gaussian_tail_integral(z4, normal_upper_tail(z4));
  return (overlap + s * tails) / L;
}

// gaussian_disk_mass_along's integrand over u in [v0, v1], 8-point Gauss-Legendre: the
// marginal N(y; c_y, s_y^2) at y = R sin(u) times the chord's time average, times dy/du.
SG_FN real disk_along_interval(real v0, real v1, real R, real cy, real sy, real ax, real r, real L,
                               real s) {
  real width = v1 - v0;
  real sum = 0.0;
  SG_COUNT(nodes, 8);
  for (int q = 0; q < 8; ++q) {
    real x = q < 4 ? -kGl8X[q] : kGl8X[q - 4];
    real u = v0 + 0.5 * (1.0 + x) * width;
    real y = R * sin(u);
    real h = R * cos(u);
    real dens = exp(-0.5 * sqr((y - cy) / sy)) * kInvSqrtTwoPi / sy;
    real m = ax + r * (y - cy);
    sum += dens * segment_chord_average(h, m, L, s) * h * (q < 4 ? kGl8W[q] : kGl8W[q - 4]);
  }
  return 0.5 * width * sum;
}

SG_FN real gaussian_disk_mass_along(vec2 a, vec2 b, mat2 cov, real R) {
  vec2 d = b - a;
  real L = length(d);
  // A segment of length 0 (the instant) is taken along the Gaussian's minor axis: the
  // conditional's steps then lie across the marginal's major spread, as
  // gaussian_disk_mass takes them.
  vec2 e = vec2(0.0);
  if (L > 0.0) {
    e = d / L;
  } else {
    PrincipalAxes pa = principal_axes(cov);
    e = vec2(-pa.u.y, pa.u.x);
  }
  vec2 n = vec2(-e.y, e.x);
  real vy = dot(n, cov * n);
  real cy = dot(n, a);
  real ax = dot(e, a);
  if (!(vy > 0.0)) {
    // A line along the segment: the one chord y = c_y.
    if (!(abs(cy) < R)) return 0.0;
    return segment_chord_average(sqrt(R * R - cy * cy), ax, L, sqrt(max(0.0, dot(e, cov * e))));
  }
  real sy = sqrt(vy);
  real r = dot(e, cov * n) / vy;
  real s = sqrt(max(0.0, dot(e, cov * e) - r * r * vy));
  // Beyond 9 deviations of the marginal, nothing.
  real lo = max(-R, cy - 9.0 * sy);
  real hi = min(R, cy + 9.0 * sy);
  if (hi <= lo) return 0.0;
  // The pieces: [ulo, uhi] cut where the lines x = m(y) and x = m(y) + L cross the circle
  // (where the chord's ends pass the segment's ends: the integrand's kinks as s -> 0),
  // (alpha + r y)^2 + y^2 = R^2 with alpha = a_x - r c_y (+ L).
  real cut[6];
  cut[0] = asin(clamp(lo / R, -1.0, 1.0));
  int count = 1;
  real uhi = asin(clamp(hi / R, -1.0, 1.0));
  for (int line = 0; line < 2; ++line) {
    real alpha = ax - r * cy + (line == 1 ? L : 0.0);
    real q2 = 1.0 + r * r;
    real disc = R * R * q2 - alpha * alpha;
    if (!(disc > 0.0)) continue;
    for (int sign = 0; sign < 2; ++sign) {
      real y = (-alpha * r + (sign == 0 ? -1.0 : 1.0) * sqrt(disc)) / q2;
      real u = asin(clamp(y / R, -1.0, 1.0));
      if (u > cut[0] && u < uhi) {
        cut[count] = u;
        count += 1;
      }
    }
  }
  // Sorted (insertion), then the upper end.
  for (int i = 2; i < count; ++i) {
    for (int j = i; j > 1 && cut[j] < cut[j - 1]; --j) {
      real t = cut[j];
      cut[j] = cut[j - 1];
      cut[j - 1] = t;
    }
  }
  cut[count] = uhi;
  // The narrowest width in u of the chord average's steps, and whether they weigh enough
  // to be resolved (above).
  real delta = s / (R * sqrt(1.0 + r * r));
  bool steps = s > 0.02 * L;
  real mass = 0.0;
  for (int piece = 0; piece < count; ++piece) {
    real u0 = cut[piece];
    real u1 = cut[piece + 1];
    if (!(u1 > u0)) continue;
    real extent = R * (sin(u1) - sin(u0));
    real edge = steps && 6.0 * delta < 0.25 * (u1 - u0) ? 6.0 * delta : 0.0;
    real parts = min(extent / (2.0 * sy), 9.0);
    if (steps && !(edge > 0.0)) parts = max(parts, min((u1 - u0) / (2.0 * delta), 4.0));
    int m = int(clamp(ceil(parts), 1.0, 9.0));
    if (edge > 0.0) {
      mass += disk_along_interval(u0, u0 + edge, R, cy, sy, ax, r, L, s);
      mass += disk_along_interval(u1 - edge, u1, R, cy, sy, ax, r, L, s);
    }
    real a0 = u0 + edge;
    real step = (u1 - edge - a0) / real(m);
    for (int j = 0; j < m; ++j) {
      mass +=
          disk_along_interval(a0 + real(j) * step, a0 + real(j + 1) * step, R, cy, sy, ax, r, L, s);
    }
  }
  return mass;
}

// The paper's fallback: a Riemann sum over n x n cells covering the disk.
SG_FN real gaussian_disk_mass_riemann(vec2 mean, mat2 cov, real R, int n) {
  real det = determinant(cov);
  if (!(det > 0.0)) return gaussian_disk_mass(mean, cov, R);  // no density to sample
  mat2 inv = inverse(cov);
  real norm = 1.0 / (kTwoPi * sqrt(det));
  real cell = 2.0 * R / real(n);
  real sum = 0.0;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      vec2 q = vec2(-R + (real(i) + 0.5) * cell, -R + (real(j) + 0.5) * cell);
      if (dot(q, q) > R * R) continue;
      SG_COUNT(nodes, 1);
      vec2 d = q - mean;
      sum += exp(-0.5 * dot(d, inv * d));
    }
  }
  return sum * norm * cell * cell;
}
