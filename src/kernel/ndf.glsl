// The normal distribution of the aliasing waves within a pixel, as a 2D Gaussian on the
// NDF plane (Podee et al. 2021, Sec. 3.4, Eqs. 2-7 and Appendix A).
//
// The NDF plane is y = 1: the normal (-h_x, 1, -h_z) meets it at n = (-h_x, -h_z), so the
// NDF is the distribution of minus the slope. For a sum of waves, covariances add and so
// do mean slopes (independent waves). Each wave's contribution is written here; the sums
// are taken in the pixel's one pass over the waves (staa.glsl).
//
// uniform (Eq. 3): every aliasing wave spans whole cycles in the pixel; mean 0 and
//   covariance (A^2 / 2) [a^2, ab; ab, b^2].
// per-pixel (Eqs. 4-7, Appendix A): the wave's phase runs from p1 to p2 across the pixel
//   along its direction; with theta the phase at the pixel centre and D = (p2 - p1) / 2:
//     K = A cos(theta) sin(D) / D,  J = A^2 / 2 (1 + cos(2 theta) sin(2D) / (2D))
//   (Eq. 23 prints sin(2(.)) in K; the mean of A cos over [p1, p2] has sin(.), tested
//   against numerical integration of Eq. 5), mean slope (a, b) K, second moments
//   (a^2, ab, b^2) J, covariance M - B B^T (Eq. 4).
//   p1, p2 (Appendix A): the line through the footprint's centre along the wave direction
//   crosses the footprint parallelogram at centre +- s k / |k|, s = 1/2 / max(|u|, |v|) with
//   (u, v) = J^-1 k / |k| in pixel units, so D = |k|^2 / (2 max(|q.x|, |q.y|)), q = J^-1 k.

// The NDF's moments: mean (a shift from the centre normal) and covariance (xx, xz, zz).
struct NdfMoments {
  vec2 mean;
  vec3 cov;
};

SG_FN NdfMoments ndf_zero() {
  NdfMoments m;
  m.mean = vec2(0.0);
  m.cov = vec3(0.0);
  return m;
}

// D for wave vector k and the inverse of the footprint's Jacobian (0 for k = 0).
SG_FN real footprint_half_width(vec2 k, mat2 Jinv) {
  vec2 q = Jinv * k;
  real m = max(abs(q.x), abs(q.y));
  return 0.5 * dot(k, k) / max(m, 1e-30);
}

// Eq. 3's term of a wave of (aliasing) amplitude A.
SG_FN void ndf_add_uniform(INOUT(NdfMoments) m, real A, vec2 k) {
  real e = 0.5 * A * A;
  m.cov += e * vec3(k.x * k.x, k.x * k.y, k.y * k.y);
}

// Eqs. 23-24 for a wave of amplitude A with phase theta at the pixel centre (cos_theta its
// cosine) and half-width D, sin_d and cos_d the sine and cosine of D: the mean slope
// factor K and the second-moment factor J (the slope is (a, b) A cos(phase)).
SG_FN vec2 wave_moment_factors(real A, real cos_theta, real D, real sin_d, real cos_d) {
  real inv_d = 1.0 / max(D, 1e-4);
  real sinc1 = D < 1e-4 ? 1.0 - D * D / 6.0 : sin_d * inv_d;
  real sinc2 = D < 1e-4 ? 1.0 - 2.0 * D * D / 3.0 : sin_d * cos_d * inv_d;
  real cos_2t = 2.0 * cos_theta * cos_theta - 1.0;
  return vec2(A * cos_theta * sinc1, 0.5 * A * A * (1.0 + cos_2t * sinc2));
}

// Appendix A's term of a wave of (aliasing) amplitude A (wave_moment_factors' arguments).
SG_FN void ndf_add_per_pixel(INOUT(NdfMoments) m, real A, vec2 k, real cos_theta, real D,
                             real sin_d, real cos_d) {
  vec2 KJ = wave_moment_factors(A, cos_theta, D, sin_d, cos_d);
  real K = KJ.x;
  real J = KJ.y;
  m.mean -= K * k;  // NDF-plane coordinates are minus the slope
  real v = J - K * K;
  m.cov += v * vec3(k.x * k.x, k.x * k.y, k.y * k.y);
}

SG_FN mat2 sym2(vec3 c) {
  return mat2(vec2(c.x, c.y), vec2(c.y, c.z));
}
