// Lookups in the path-integral tables of Podee et al. 2021, Sec. 3.5 (Eqs. 17-19) and
// Sec. 4, for the unit disk. The tables are made on the host (shading/path_table.h: what
// they hold, their ranges and how they are generated and cached) and read here with
// texelFetch, interpolated by hand: a GPU's hardware filtering has 8 fractional bits,
// which would put errors of up to ~1% into the difference quotient of S, and each sigma
// slice has its own extent.
//  * F(d, sigma): the mass of N(c, sigma^2 I), |c| = d, inside the unit disk; R32F texture
//    of n_distance samples of d (x) by n_sigma slices (y).
//  * S(u, v, sigma) = integral from -R to u of F(sqrt(u'^2 + v^2), sigma) du' (Eq. 18);
//    R32F texture array of n_u samples of u in [-R, 0] (x) by n_v of v in [0, R] (y) by
//    n_sigma slices (layers). S is even in v, and F is even in u, so S(u) = 2 S(0) - S(-u):
//    the half u > 0 is not stored.
// The radial coordinates (d of F, v of S) are sampled densely about the disk's edge, where a
// narrow Gaussian's F and S change fastest (kernel/path_table_grid.glsl).
// Slice 0 is sigma = 0; slices 1..n-1 are log-spaced from sigma_min to sigma_max; slice
// k's extent is R_k = 1 + extent_k sigma_k. Lookups are bilinear within a slice and linear
// between slices in c(sigma) = sigma / sigma_min below sigma_min and
// 1 + log(sigma / sigma_min) / log(q) above. Above sigma_max the three-term wide-Gaussian
// expansion of F (shading/disk_gaussian.h) and its closed-form integral along u are used.

SG_FN real slice_sigma(IN(PathTableInfo) t, int k) {
  if (k == 0) return 0.0;
  if (k == t.n_sigma - 1) return t.sigma_max;
  return t.sigma_min * exp(real(k - 1) * t.log_q);
}

SG_FN real slice_extent(IN(PathTableInfo) t, int k) {
  return 1.0 + t.extent_k * slice_sigma(t, k);
}

// The slice below sigma and the weight of the one above.
SG_FN void locate_sigma(IN(PathTableInfo) t, real sigma, OUT(int) k, OUT(real) w) {
  real c = 0.0;
  if (sigma <= 0.0) {
    c = 0.0;
  } else if (sigma < t.sigma_min) {
    c = sigma / t.sigma_min;
  } else {
    c = 1.0 + log(sigma / t.sigma_min) / t.log_q;
  }
  k = min(int(c), t.n_sigma - 2);
  w = min(c - real(k), 1.0);
}

SG_FN real f_slice(IN(R32Texture2D) F, IN(PathTableInfo) t, int k, real d) {
  real R = slice_extent(t, k);
  if (d > R) return 0.0;
  real x = table_radial(R, d) * real(t.n_distance - 1);
  int i = min(int(x), t.n_distance - 2);
  real a = x - real(i);
  return (1.0 - a) * texelFetch(F, ivec2(i, k), 0).x + a * texelFetch(F, ivec2(i + 1, k), 0).x;
}

// A row of a slice of S: the v cell (j, j + 1) and the weight b of row j + 1.
struct SRow {
  int j;
  real b;
};

SG_FN SRow s_row(IN(PathTableInfo) t, real R, real v) {
  real y = table_radial(R, v) * real(t.n_v - 1);
  SRow r;
  r.j = min(int(y), t.n_v - 2);
  r.b = y - real(r.j);
  return r;
}

// The stored half: S(-a, v) for 0 <= a (clamped to R), bilinear.
SG_FN real s_half(IN(R32Texture3D) S, IN(PathTableInfo) t, int k, real R, SRow r, real a) {
  real x = (R - min(a, R)) * real(t.n_u - 1) / R;
  int i = min(int(x), t.n_u - 2);
  real w = x - real(i);
  real lo = (1.0 - w) * texelFetch(S, ivec3(i, r.j, k), 0).x +
            w * texelFetch(S, ivec3(i + 1, r.j, k), 0).x;
  real hi = (1.0 - w) * texelFetch(S, ivec3(i, r.j + 1, k), 0).x +
            w * texelFetch(S, ivec3(i + 1, r.j + 1, k), 0).x;
  return (1.0 - r.b) * lo + r.b * hi;
}

// S(0, v): the last column, half the line's whole integral.
SG_FN real s_middle(IN(R32Texture3D) S, IN(PathTableInfo) t, int k, SRow r) {
  return (1.0 - r.b) * texelFetch(S, ivec3(t.n_u - 1, r.j, k), 0).x +
         r.b * texelFetch(S, ivec3(t.n_u - 1, r.j + 1, k), 0).x;
}

SG_FN real s_slice(IN(R32Texture3D) S, IN(PathTableInfo) t, int k, real u, real v) {
  real R = slice_extent(t, k);
  v = abs(v);
  if (v > R) return 0.0;
  SRow r = s_row(t, R, v);
  real h = s_half(S, t, k, R, r, abs(u));
  return u > 0.0 ? 2.0 * s_middle(S, t, k, r) - h : h;
}

// One slice's time average along the segment [u0, u1] at distance v (u1 >= u0). Shorter
// than one u cell h, the difference quotient becomes a first-order estimate while F at
// the midpoint is second order: below h / 2 the slice returns F(midpoint), above h the
// quotient, and in between a linear blend, so the result is continuous in the length.
SG_FN real path_slice(IN(R32Texture2D) F, IN(R32Texture3D) S, IN(PathTableInfo) t, int k, real u0,
                      real u1, real v) {
  real len = u1 - u0;
  real R = slice_extent(t, k);
  real h = R / real(t.n_u - 1);
  real mid = len >= h ? 0.0 : f_slice(F, t, k, length(vec2(0.5 * (u0 + u1), v)));
  if (len <= 0.5 * h) return mid;
  real quotient = 0.0;
  if (v <= R) {
    // S(u1) - S(u0) from the stored half, S(u) = 2 S(0) - S(-u) for u > 0: S(0) cancels
    // unless the segment crosses u = 0.
    SRow r = s_row(t, R, v);
    real h0 = s_half(S, t, k, R, r, abs(u0));
    real h1 = s_half(S, t, k, R, r, abs(u1));
    if (u0 > 0.0) {
      quotient = h0 - h1;
    } else if (u1 > 0.0) {
      quotient = 2.0 * s_middle(S, t, k, r) - h1 - h0;
    } else {
      quotient = h1 - h0;
    }
    quotient /= len;
  }
  if (len >= h) return quotient;
  real w = 2.0 * len / h - 1.0;
  return (1.0 - w) * mid + w * quotient;
}

// The three-term wide-Gaussian expansion of F (sigma > 0; shading/disk_gaussian.h):
// F ~ exp(-rho^2 / 2) / (2 sigma^2) [1 + (rho^2 - 2) / (8 sigma^2) + (rho^4 - 8 rho^2 + 8) /
// (192 sigma^4)], rho = d / sigma, relative error O(sigma^-6).
SG_FN real disk_gaussian_wide(real d, real sigma) {
  real rho2 = (d / sigma) * (d / sigma);
  real is2 = 1.0 / (sigma * sigma);
  return 0.5 * is2 * exp(-0.5 * rho2) *
         (1.0 + (rho2 - 2.0) * is2 / 8.0 + (rho2 * rho2 - 8.0 * rho2 + 8.0) * is2 * is2 / 192.0);
}

// The closed-form integral from -inf to u of the expansion along the line at distance v:
// with x = u' / sigma, a = v / sigma and r = x^2 + a^2 written as c0 + c2 x^2 + c4 x^4, and
// the Gaussian moments M_n(X) = int_-inf^X x^n exp(-x^2 / 2) dx:
// M0 = sqrt(pi / 2) erfc(-X / sqrt 2), M2 = M0 - X e, M4 = 3 M2 - X^3 e, e = exp(-X^2 / 2).
SG_FN real wide_S(real u, real v, real sigma) {
  real a2 = (v / sigma) * (v / sigma);
  real is2 = 1.0 / (sigma * sigma);
  real is4 = is2 * is2;
  real c0 = 1.0 + (a2 - 2.0) * is2 / 8.0 + (a2 * a2 - 8.0 * a2 + 8.0) * is4 / 192.0;
  real c2 = is2 / 8.0 + (2.0 * a2 - 8.0) * is4 / 192.0;
  real c4 = is4 / 192.0;
  real X = u / sigma;
  real e = exp(-0.5 * X * X);
  real m0 = kSqrtHalfPi * erfc(-X * kInvSqrtTwo);
  real m2 = m0 - X * e;
  real m4 = 3.0 * m2 - X * X * X * e;
  return 0.5 / sigma * exp(-0.5 * a2) * (c0 * m0 + c2 * m2 + c4 * m4);
}

// F(d, sigma) from the 2D table (sigma > sigma_max: the wide-Gaussian expansion).
SG_FN real disk_gaussian_table(IN(R32Texture2D) F, IN(PathTableInfo) t, real d, real sigma) {
  if (sigma > t.sigma_max) return disk_gaussian_wide(d, sigma);
  int k = 0;
  real w = 0.0;
  locate_sigma(t, sigma, k, w);
  return (1.0 - w) * f_slice(F, t, k, d) + w * f_slice(F, t, k + 1, d);
}

// S(u, v, sigma) from the 3D table (sigma > sigma_max: closed form of the expansion).
SG_FN real path_table_S(IN(R32Texture3D) S, IN(PathTableInfo) t, real u, real v, real sigma) {
  if (sigma > t.sigma_max) return wide_S(u, v, sigma);
  int k = 0;
  real w = 0.0;
  locate_sigma(t, sigma, k, w);
  return (1.0 - w) * s_slice(S, t, k, u, v) + w * s_slice(S, t, k + 1, u, v);
}

// The time average of F along the segment from (u0, v) to (u1, v) at constant speed:
// (S(u1) - S(u0)) / (u1 - u0) (Eq. 19 divided by the segment's length).
SG_FN real path_integral(IN(R32Texture2D) F, IN(R32Texture3D) S, IN(PathTableInfo) t, real u0,
                         real u1, real v, real sigma) {
  if (u1 < u0) {
    real tmp = u0;
    u0 = u1;
    u1 = tmp;
  }
  v = abs(v);
  if (sigma > t.sigma_max) {
    // Exact up to rounding, which the quotient amplifies by 1 / len: below 1e-6 sigma (in
    // double; 1e-2 sigma in float) the midpoint's error (len^2 F'' / 24) is smaller.
    real len = u1 - u0;
    real short_len = kDoublePrecision ? 1e-6 : 1e-2;
    if (len < short_len * sigma) return disk_gaussian_wide(length(vec2(0.5 * (u0 + u1), v)), sigma);
    return (wide_S(u1, v, sigma) - wide_S(u0, v, sigma)) / len;
  }
  int k = 0;
  real w = 0.0;
  locate_sigma(t, sigma, k, w);
  // The two slices about sigma (one where it falls on a slice) by one call in a loop: a GL
  // program holds path_slice's code once (docs/gpu.md).
  real a = 0.0;
  for (int j = 0; j < (w == 0.0 ? 1 : 2); ++j)
    a += (j == 0 ? 1.0 - w : w) * path_slice(F, S, t, k + j, u0, u1, v);
  return a;
}

// The time average over the straight segment p0 -> p1 of the light plane of the mass of
// N(p(t), sigma^2 I) inside the disk of radius R about the origin (Sec. 3.5): the segment
// rotated parallel to u and scaled by 1 / R; a segment of length <= 1e-12 disk radii (in
// double; 1e-6 in float) is a point (the 2D table).
SG_FN real path_average(IN(R32Texture2D) F, IN(R32Texture3D) S, IN(PathTableInfo) t, vec2 p0,
                        vec2 p1, real sigma, real R) {
  vec2 q0 = p0 / R;
  vec2 q1 = p1 / R;
  real s = sigma / R;
  vec2 dir = q1 - q0;
  real len = length(dir);
  real point_len = kDoublePrecision ? 1e-12 : 1e-6;
  if (!(len > point_len)) return disk_gaussian_table(F, t, length(0.5 * (q0 + q1)), s);
  vec2 u = dir / len;
  real u0 = dot(q0, u);
  real v = abs(q0.x * u.y - q0.y * u.x);
  return path_integral(F, S, t, u0, u0 + len, v, s);
}
