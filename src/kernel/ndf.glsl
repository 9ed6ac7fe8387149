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

// D over the footprint swept by the water point's motion Delta over the shutter
// (aliasing.glsl, swept_frequency): the phase along the swept footprint is Appendix A's
// theta + u, u uniform on [-D, D], plus the motion's k . Delta w, w uniform on
// [-1/2, 1/2], a uniform of half-width m = |k . Delta| / 2. The sum of the two has variance
// (D^2 + m^2) / 3; the uniform phase of the same variance, half-width sqrt(D^2 + m^2),
// goes into Eqs. 23-24 in place of D (its moments agree with the exact convolution's,
// cos(theta) sinc(D) sinc(m), to second order in D and m; both vanish as either grows).
SG_FN real swept_half_width(real D, vec2 k, vec2 delta) {
  real m = 0.5 * dot(k, delta);
  return sqrt(D * D + m * m);
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
  real sinc1 = sinc_from(D, sin_d);
  real sinc2 = sinc1 * cos_d;  // sinc(2 D) = sinc(D) cos(D)
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

// A wave's moments over cells of the footprint parallelogram, exactly (for the smooth
// terms, smooth_terms.glsl). The pixel square is cut into n x n cells (n <= 3); the
// footprint maps cell (iu, iv) to X + J (c_u, c_v) + J [-1/(2n), 1/(2n)]^2 with centres
// c = (2 i - (n - 1)) / (2n). With the half-phases h = (k . J_0, k . J_1) / 2 of the whole
// pixel along its two edges, x = h / n is a cell's, and the wave's phase at a cell's
// centre is theta + (2 iu - (n - 1)) x_0 + (2 iv - (n - 1)) x_1. The box mean over a cell of
// cos(phase + k . (u J_0 + v J_1)) is cos(phase) sinc(x_0) sinc(x_1), and of cos^2 it is
// (1 + cos(2 phase) sinc(2 x_0) sinc(2 x_1)) / 2, sinc(2x) = sinc(x) cos(x); so per cell
//     K = A cos(phase) sinc(x_0) sinc(x_1),  J = A^2 / 2 (1 + cos(2 phase) sinc(2 x_0) sinc(2
//     x_1)),
// mean -K k and covariance (J - K^2) k k^T, Appendix A's moments over the cell's box rather
// than along one line (Appendix A's line through the centre along k sees a phase
// half-width D = |k|^2 / (2 |J^-1 k|_max), which for an elongated footprint, at grazing
// view, and a wave oblique to it is far below the phase range the footprint spans). The
// cells' Gaussians together follow a wave that spans a fraction of a cycle in the pixel,
// whose slopes are far from Gaussian. The cells' phase offsets come from cos and sin of
// x by rotations, with no further trigonometry.
const int kMaxBoxSide = 3;
const int kMaxBoxCells = 9;

struct BoxCells {
  NdfMoments m[kMaxBoxCells];
};

SG_FN BoxCells box_cells_zero() {
  BoxCells b;
  for (int c = 0; c < kMaxBoxCells; ++c)
    b.m[c] = ndf_zero();
  return b;
}

// cos and sin of the first offset -(n - 1) x and of the step 2 x, from cos x and sin x.
SG_FN vec4 box_offset_rotations(int n, real cx, real sx) {
  real c2 = 2.0 * cx * cx - 1.0;
  real s2 = 2.0 * sx * cx;
  vec2 first = n == 1 ? vec2(1.0, 0.0) : (n == 2 ? vec2(cx, -sx) : vec2(c2, -s2));
  return vec4(first, c2, s2);
}

// `tf`: a third axis of the box, time (box_cells_add_swept), as its factors of the mean
// and of the second moment, (sinc(x_t), sinc(2 x_t)); (1, 1) where the phase holds still.
SG_FN void box_cells_add_factors(INOUT(BoxCells) b, int n, real A, vec2 k, real sin_t, real cos_t,
                                 vec2 h, vec2 tf) {
  vec2 x = h / real(n);
  // The half-phases reach millions of radians for a distant footprint: reduced to
  // [-pi, pi] before the sine and cosine (special.glsl), as GPUs' and the vectorised
  // sums' sine and cosine need; sinc then divides by the unreduced x.
  real rx0 = wrap_angle(x.x);
  real rx1 = wrap_angle(x.y);
  real cx0 = cos(rx0);
  real sx0 = sin(rx0);
  real cx1 = cos(rx1);
  real sx1 = sin(rx1);
  real f0 = sinc_from(x.x, sx0);
  real f1 = sinc_from(x.y, sx1);
  real g = f0 * cx0 * f1 * cx1 * tf.y;  // sinc(2 x_0) sinc(2 x_1) (sinc(2 x_t))
  real Af = A * f0 * f1 * tf.x;
  real J0 = 0.5 * A * A;
  vec3 kk = vec3(k.x * k.x, k.x * k.y, k.y * k.y);
  vec4 r0 = box_offset_rotations(n, cx0, sx0);
  vec4 r1 = box_offset_rotations(n, cx1, sx1);
  vec2 a = vec2(r0.x, r0.y);  // cos, sin of the u offset
  for (int iu = 0; iu < n; ++iu) {
    vec2 bv = vec2(r1.x, r1.y);
    for (int iv = 0; iv < n; ++iv) {
      real cab = a.x * bv.x - a.y * bv.y;
      real sab = a.y * bv.x + a.x * bv.y;
      real cp = cos_t * cab - sin_t * sab;  // cos of the phase at the cell's centre
      real K = Af * cp;
      real J = J0 * (1.0 + (2.0 * cp * cp - 1.0) * g);
      int c = iu * n + iv;
      b.m[c].mean -= K * k;
      b.m[c].cov += (J - K * K) * kk;
      bv = vec2(bv.x * r1.z - bv.y * r1.w, bv.y * r1.z + bv.x * r1.w);
    }
    a = vec2(a.x * r0.z - a.y * r0.w, a.y * r0.z + a.x * r0.w);
  }
}

// The wave's moments over the cells at one instant (theta the phase at the pixel's centre).
SG_FN void box_cells_add(INOUT(BoxCells) b, int n, real A, vec2 k, real sin_t, real cos_t, vec2 h) {
  box_cells_add_factors(b, n, A, k, sin_t, cos_t, h, vec2(1.0));
}

// The wave's moments over the cells and over an interval of time through which its phase at
// each cell turns uniformly by 2 x_t, ending at phase theta (sine sin_t, cosine cos_t) at the
// pixel's centre: a cell is then a box of three axes, its two edges and time, and the box
// means above take the third axis's factors, sinc(x_t) and sinc(2 x_t), about the phase at
// the interval's middle, theta - x_t. (A moving camera's pixel slides over the water through
// the shutter: `staa` takes there the waves that its path does not follow, staa_waves.glsl.)
SG_FN void box_cells_add_swept(INOUT(BoxCells) b, int n, real A, vec2 k, real sin_t, real cos_t,
                               vec2 h, real x_t) {
  real rt = wrap_angle(x_t);
  real ct = cos(rt);
  real st = sin(rt);
  real ft = sinc_from(x_t, st);
  vec2 mid = rotated_cos_sin(vec2(ct, st), sin_t, cos_t);  // (cos, sin) of theta - x_t
  box_cells_add_factors(b, n, A, k, mid.y, mid.x, h, vec2(ft, ft * ct));
}

SG_FN mat2 sym2(vec3 c) {
  return mat2(vec2(c.x, c.y), vec2(c.y, c.z));
}
