// The ocean BRDF and lighting of Bruneton, Neyret, Holzschuch 2010 ("Real-time Realistic
// Ocean Lighting using Seamless Transitions from Geometry to BRDF", docs/references.md,
// Sec. 4-5): the anisotropic Gaussian BRDF of Ross, Dion, Potvin 2005 with Smith shadowing,
// the reflected sun (Eq. 15), the effective Fresnel reflectance (Eqs. 24, 26) and the
// filtered environment (Eq. 27). `bruneton` (bruneton.glsl) shades with them; the host's
// shading/ocean_brdf.h is this file in double, which its test checks against quadrature.
//
// Directions are given in the lobe's tangent frame (x = t_x, y = t_y, z = the mean normal
// n), unit length; sigma2 = (sigma_x^2, sigma_y^2) are the slope variances along t_x, t_y.
//
// Notes on the printed equations (this is what the code follows):
// - Eq. 9 prints a_i = (2 sigma_phi^2 tan(theta_i))^(-1/2); Smith's shadowing parameter
//   (and the authors' released shader, v = cos / sqrt((1 - cos^2) 2 sigma^2)) is
//   a = cot(theta) / sqrt(2 sigma_phi^2) = (2 sigma_phi^2 tan^2(theta))^(-1/2).
// - Eq. 13 prints 4 h_z^2 in the denominator. With the change of variables of Eq. 12,
//   d^2 zeta = d omega_l / (4 h_z^3 v.h), the BRDF whose cosine-weighted integral over the
//   light directions is the slope-space integral of q_vn (the visible, lit probability) is
//   q_vn F / (4 h_z^3 cos(theta_l) v.h), and only that one gives Eq. 15's h_z^4 (and the
//   authors' shader's zH2 * zH2). The code uses h_z^3.
// - Eq. 14 prints (1 - v.h)^2; Eq. 15 and Schlick's formula have the fifth power.

// Cosines below this are clamped in Eq. 15 (the authors' shader: max(zV, 0.01)).
const real kBrunetonMinCos = 0.01;

// The 40-point Gauss-Legendre rule on [-1, 1]: the 20 positive nodes and their weights
// (Boost.Math's gauss<double, 40>). Eq. 24's integral takes it on both axes: 30 points left
// it 5e-7 off adaptive quadrature at grazing views (shading/ocean_brdf_test.cpp).
const real kGauss40Node[20] =
    SG_ARRAY(real, 20,
             (0.038772417506050823, 0.11608407067525521, 0.19269758070137111, 0.26815218500725369,
              0.34199409082575849, 0.41377920437160498, 0.4830758016861787, 0.54946712509512818,
              0.61255388966798019, 0.67195668461417957, 0.7273182551899271, 0.77830565142651942,
              0.8246122308333117, 0.86595950321225945, 0.90209880696887434, 0.93281280827867652,
              0.95791681921379168, 0.9772599499837743, 0.99072623869945697, 0.99823770971055925));
const real kGauss40Weight[20] = SG_ARRAY(
    real, 20,
    (0.077505947978424805, 0.077039818164247972, 0.076110361900626256, 0.074723169057968261,
     0.072886582395804048, 0.07061164739128678, 0.067912045815233912, 0.064804013456601028,
     0.061306242492928924, 0.057439769099391552, 0.053227846983936816, 0.048695807635072225,
     0.043870908185673262, 0.038782167974472037, 0.03346019528254783, 0.027937006980023396,
     0.022245849194166955, 0.016421058381907848, 0.010498284531152841, 0.0045212770985331111));

// Eq. 7: the anisotropic Gaussian density of slopes zeta.
SG_FN real slope_pdf(vec2 z, vec2 s2) {
  return exp(-0.5 * (z.x * z.x / s2.x + z.y * z.y / s2.y)) / (kTwoPi * sqrt(s2.x * s2.y));
}

// Eq. 25: the slope variance in the azimuth of direction w, sigma_x^2 cos^2(phi) +
// sigma_y^2 sin^2(phi); at the zenith (no azimuth, where the value does not matter) sigma_x^2.
SG_FN real slope_variance_toward(vec3 w, vec2 s2) {
  real r2 = w.x * w.x + w.y * w.y;
  if (!(r2 > 0.0)) return s2.x;
  return (s2.x * w.x * w.x + s2.y * w.y * w.y) / r2;
}

// Eq. 9 (with tan^2, see above): a = cot(theta) / sqrt(2 sigma_phi^2); the largest real at
// the zenith (no shadowing: smith_lambda gives 0 there).
SG_FN real smith_a(vec3 w, vec2 s2) {
  real sin_t = length(vec2(w.x, w.y));
  if (!(sin_t > 0.0)) return kRealMax;
  return w.z / (sin_t * sqrt(2.0 * slope_variance_toward(w, s2)));
}

// Eq. 8: Smith's Lambda for Gaussian slopes, (exp(-a^2) - a sqrt(pi) erfc(a)) /
// (2 a sqrt(pi)); 0 past a = 26 (exp(-a^2) < 1e-293: no shadowing).
SG_FN real smith_lambda(real a) {
  if (!(a < 26.0)) return 0.0;
  real sqrt_pi = 1.0 / kInvSqrtPi;
  real lambda = (exp(-a * a) - a * sqrt_pi * erfc(a)) / (2.0 * a * sqrt_pi);
  return max(0.0, lambda);
}

// Eq. 10: q^e_vn, the density (per d^2 zeta) of the facets of slope zeta that the viewer
// sees; Eq. 11 says it integrates to 1. max(v . f, 0) / f_z = max(v.z - zeta . v.xy, 0)
// with f = (-zeta, 1) / |(-zeta, 1)|.
SG_FN real visible_slope_density(vec2 zeta, vec3 v, vec2 s2) {
  real vf = v.z - zeta.x * v.x - zeta.y * v.y;
  if (!(vf > 0.0) || !(v.z > 0.0)) return 0.0;
  real lambda_v = smith_lambda(smith_a(v, s2));
  return slope_pdf(zeta, s2) * vf / ((1.0 + lambda_v) * v.z);
}

// The direction of w's azimuth with zenith cosine c (the shadowing of a clamped direction).
SG_FN vec3 ross_clamped_direction(vec3 w, real c) {
  real s = sqrt(max(0.0, 1.0 - c * c));
  real r = length(vec2(w.x, w.y));
  return r > 0.0 ? vec3(s * w.x / r, s * w.y / r, c) : vec3(0.0, 0.0, 1.0);
}

// p(zeta_h) / (4 h_z^4 cv (1 + Lambda(a_v) + Lambda(a_l))) with the cosines of the view and
// light zenith angles given (clamped or not by the caller): Eq. 15's factor, shared by
// Eq. 13 and Eq. 15.
SG_FN real ross_factor(vec3 v, vec3 l, vec2 s2, real cv, real cl) {
  vec3 h = normalize(v + l);
  if (!(h.z > 0.0)) return 0.0;
  vec2 zeta_h = -vec2(h.x, h.y) / h.z;
  real lv = smith_lambda(smith_a(ross_clamped_direction(v, cv), s2));
  real ll = smith_lambda(smith_a(ross_clamped_direction(l, cl), s2));
  real hz2 = h.z * h.z;
  return slope_pdf(zeta_h, s2) / (4.0 * hz2 * hz2 * cv * (1.0 + lv + ll));
}

// Eq. 13 (with 4 h_z^3): the BRDF for view v and light l (both above the tangent plane).
SG_FN real ross_brdf(vec3 v, vec3 l, vec2 s2, real F) {
  if (!(v.z > 0.0) || !(l.z > 0.0)) return 0.0;
  return F * ross_factor(v, l, s2, v.z, l.z) / l.z;
}

// Eq. 15 divided by L_sun F: the sun's reflected fraction, the BRDF at the sun's centre
// times its solid angle times cos(theta_l), Omega p(zeta_h) / (4 h_z^4 cos(theta_v)
// (1 + Lambda(a_v) + Lambda(a_l))). As the authors' shader does, cos(theta_v) and
// cos(theta_l) are clamped at 0.01 (grazing views and lights keep it finite).
SG_FN real sun_reflectance(vec3 v, vec3 l, vec2 s2, real solid_angle) {
  return solid_angle * ross_factor(v, l, s2, max(v.z, kBrunetonMinCos), max(l.z, kBrunetonMinCos));
}

// Eq. 26: the fit of the effective Fresnel reflectance with R0 = 0.02,
// R + (1 - R) (1 - cos(theta_v))^(5 exp(-2.69 sigma_v)) / (1 + 22.7 sigma_v^1.5).
SG_FN real effective_fresnel_fit(real cos_theta_v, real sigma_v) {
  real c = clamp(1.0 - cos_theta_v, 0.0, 1.0);
  return kSchlickR0 +
         (1.0 - kSchlickR0) * pow(c, 5.0 * exp(-2.69 * sigma_v)) / (1.0 + 22.7 * pow(sigma_v, 1.5));
}

// Eq. 24 by quadrature: R + (1 - R) int q^e_vn(zeta, v) (1 - v . f(zeta))^5 d^2 zeta, with f
// the facet normal (the half vector of v and its reflection). In the view's azimuthal frame
// (u along the azimuth, w across it) the Gaussian has variances var_u (Eq. 25), var_w and
// covariance cov, v . f / f_z = ct - st u, and the visible region is the half-plane
// u < cot(theta_v): the integral over u in [-9 s_u, min(9 s_u, cot(theta_v))] of u's
// marginal times the integral over w in +-9 of its conditional's deviations, each by the
// 40-point Gauss-Legendre rule (40 x 40 nodes).
SG_FN real effective_fresnel_integral(vec3 v, vec2 s2_given) {
  real ct = v.z;
  real st = length(vec2(v.x, v.y));
  if (!(ct > 0.0)) return kSchlickR0;  // nothing visible
  vec2 s2 = max(s2_given, vec2(1e-14));
  real c = st > 0.0 ? v.x / st : 1.0;
  real s = st > 0.0 ? v.y / st : 0.0;
  real var_u = s2.x * c * c + s2.y * s * s;
  real var_w = s2.x * s * s + s2.y * c * c;
  real cov = (s2.y - s2.x) * s * c;
  real su = sqrt(var_u);
  real sw = sqrt(max(var_w - cov * cov / var_u, 0.0));
  real lambda_v = smith_lambda(smith_a(v, s2));
  real u_hi = st > 0.0 ? min(9.0 * su, ct / st) : 9.0 * su;
  if (!(u_hi > -9.0 * su)) return kSchlickR0;
  real u_mid = 0.5 * (u_hi - 9.0 * su);
  real u_half = 0.5 * (u_hi + 9.0 * su);
  real outer = 0.0;
  SG_COUNT(nodes, sw > 0.0 ? 1600 : 40);
  for (int a = 0; a < 40; ++a) {
    real u = u_mid + (a < 20 ? 1.0 : -1.0) * u_half * kGauss40Node[a % 20];
    real vis = ct - st * u;  // > 0 on the range
    real mu = cov / var_u * u;
    real inner = 0.0;
    if (sw > 0.0) {
      // w = mu + sw z, z in [-9, 9]: the conditional's density phi(z) / sw times dw = sw dz.
      for (int b = 0; b < 40; ++b) {
        real z = (b < 20 ? 9.0 : -9.0) * kGauss40Node[b % 20];
        real w = mu + sw * z;
        real m = 1.0 - vis / sqrt(1.0 + u * u + w * w);
        real m2 = m * m;
        inner += kGauss40Weight[b % 20] * exp(-0.5 * z * z) * kInvSqrtTwoPi * m2 * m2 * m;
      }
      inner *= 9.0;
    } else {
      real m = 1.0 - vis / sqrt(1.0 + u * u + mu * mu);
      real m2 = m * m;
      inner = m2 * m2 * m;
    }
    outer += kGauss40Weight[a % 20] * exp(-0.5 * sqr(u / su)) * kInvSqrtTwoPi / su * vis * inner;
  }
  return kSchlickR0 + (1.0 - kSchlickR0) * u_half * outer / ((1.0 + lambda_v) * ct);
}

// Algorithm 5.1's U(zeta): the facet normal of slope zeta in world space, the reflected
// view, and its stereographic coordinates (r.x, r.z) / (1 + r.y) (world y up; Sec. 5.2);
// z = 0 where the reflection points straight down (the map's pole), else 1.
SG_FN vec3 horizon_map_point(vec3 v, vec3 n, vec3 tx, vec3 ty, vec2 zeta) {
  vec3 facet = normalize(-zeta.x * tx - zeta.y * ty + n);
  vec3 r = reflect_view(facet, v);
  return vec3(vec2(r.x, r.z) / max(1.0 + r.y, 1e-9), 1.0 + r.y < 1e-9 ? 0.0 : 1.0);
}

// Eq. 27 with the stereographic map U: the slope kernel p mapped to U's plane as the
// Gaussian of covariance J diag(sigma2) J^T about U(r(0)), J = dU/dzeta by finite
// differences (eps = 1e-3, as Algorithm 5.1). The horizon is U's unit circle, so the
// kernel's mass outside it (1 - gaussian_disk_mass) is the fraction of reflections below
// the horizon. v and the frame (n, tx, ty) in world coordinates.
SG_FN real below_horizon_fraction(vec3 v, vec3 n, vec3 tx, vec3 ty, vec2 s2) {
  real eps = 1e-3;
  vec3 u0 = horizon_map_point(v, n, tx, ty, vec2(0.0));
  vec3 ux = horizon_map_point(v, n, tx, ty, vec2(eps, 0.0));
  vec3 uy = horizon_map_point(v, n, tx, ty, vec2(0.0, eps));
  if (u0.z * ux.z * uy.z == 0.0) return 1.0;
  mat2 J = mat2((vec2(ux.x, ux.y) - vec2(u0.x, u0.y)) / eps,
                (vec2(uy.x, uy.y) - vec2(u0.x, u0.y)) / eps);
  mat2 cov = J * mat2(vec2(s2.x, 0.0), vec2(0.0, s2.y)) * transpose(J);
  return clamp(1.0 - gaussian_disk_mass(vec2(u0.x, u0.y), cov, 1.0), 0.0, 1.0);
}
