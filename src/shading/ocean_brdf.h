// The ocean BRDF and lighting of Bruneton, Neyret, Holzschuch 2010 ("Real-time Realistic
// Ocean Lighting using Seamless Transitions from Geometry to BRDF", docs/references.md,
// Sec. 4-5), the host's double wrappers of the kernel's (kernel/ocean_brdf.glsl, which
// `bruneton` shades with), checked against quadrature in ocean_brdf_test: the anisotropic Gaussian
// BRDF of Ross, Dion, Potvin 2005 with Smith shadowing, the reflected sun (Eq. 15), the
// effective Fresnel reflectance (Eqs. 24, 26) and the filtered environment (Eq. 27).
//
// Directions are given in the lobe's tangent frame (x = t_x, y = t_y, z = the mean normal
// n), unit length; sigma2 = (sigma_x^2, sigma_y^2) are the slope variances along t_x, t_y.
//
// Notes on the printed equations (this is what the code follows):
// - Eq. 9 prints a_i = (2 sigma_phi^2 tan(theta_i))^(-1/2); Smith's shadowing parameter
//   (and the authors' released shader, v = cos / sqrt((1 - cos^2) 2 sigma^2)) is
//   a = cot(theta) / sqrt(2 sigma_phi^2) = (2 sigma_phi^2 tan^2(theta))^(-1/2). The test
//   checks Eq. 8 with this a against Smith's definition by quadrature.
// - Eq. 13 prints 4 h_z^2 in the denominator. With the change of variables of Eq. 12,
//   d^2 zeta = d omega_l / (4 h_z^3 v.h), the BRDF whose cosine-weighted integral over the
//   light directions is the slope-space integral of q_vn (the visible, lit probability) is
//   q_vn F / (4 h_z^3 cos(theta_l) v.h), and only that one gives Eq. 15's h_z^4 (and the
//   authors' shader's zH2 * zH2). The code uses h_z^3; the test checks the two integrals
//   agree.
// - Eq. 14 prints (1 - v.h)^2; Eq. 15 and Schlick's formula have the fifth power.
#pragma once

#include "math/vec.h"

namespace sg {

// Eq. 7: the anisotropic Gaussian density of slopes zeta.
double slope_pdf(const vec2& zeta, const vec2& sigma2);

// Eq. 25: the slope variance in the azimuth of direction w, sigma_x^2 cos^2(phi) +
// sigma_y^2 sin^2(phi).
double slope_variance_toward(const vec3& w, const vec2& sigma2);

// Eq. 9 (with tan^2, see above): a = cot(theta) / sqrt(2 sigma_phi^2); the largest double
// at the zenith.
double smith_a(const vec3& w, const vec2& sigma2);

// Eq. 8: Smith's Lambda for Gaussian slopes, (exp(-a^2) - a sqrt(pi) erfc(a)) /
// (2 a sqrt(pi)).
double smith_lambda(double a);

// Eq. 10: q^e_vn, the density (per d^2 zeta) of the facets of slope zeta that the viewer
// sees; Eq. 11 says it integrates to 1.
double visible_slope_density(const vec2& zeta, const vec3& v, const vec2& sigma2);

// Eq. 13 (with 4 h_z^3): the BRDF for view v and light l (both above the tangent plane).
double ross_brdf(const vec3& v, const vec3& l, const vec2& sigma2, double F);

// Eq. 15 divided by L_sun F: the sun's reflected fraction, the BRDF at the sun's centre
// times its solid angle times cos(theta_l), Omega p(zeta_h) / (4 h_z^4 cos(theta_v)
// (1 + Lambda(a_v) + Lambda(a_l))). As the authors' shader does, cos(theta_v) and
// cos(theta_l) are clamped at 0.01 (grazing views and lights keep it finite).
double sun_reflectance(const vec3& v, const vec3& l, const vec2& sigma2, double solid_angle);

// Eq. 26: the fit of the effective Fresnel reflectance with R0 = 0.02,
// R + (1 - R) (1 - cos(theta_v))^(5 exp(-2.69 sigma_v)) / (1 + 22.7 sigma_v^1.5).
double effective_fresnel_fit(double cos_theta_v, double sigma_v);

// Eq. 24 by quadrature: R + (1 - R) int q^e_vn(zeta, v) (1 - v . f(zeta))^5 d^2 zeta, with f
// the facet normal (the half vector of v and its reflection). 40 x 40 Gauss-Legendre nodes
// in the view's azimuthal frame, where the visible region is the half-plane of slopes
// u < cot(theta_v).
double effective_fresnel_integral(const vec3& v, const vec2& sigma2);

// Eq. 27 with the stereographic map U(r) = (r.x, r.z) / (1 + r.y) (world y up; Sec. 5.2):
// the slope kernel p mapped to U's plane as the Gaussian of covariance
// J diag(sigma2) J^T about U(r(0)), J = dU/dzeta by finite differences (eps = 1e-3, as
// Algorithm 5.1). The horizon is U's unit circle, so the kernel's mass outside it
// (1 - gaussian_disk_mass) is the fraction of reflections below the horizon. v and the
// frame (n, tx, ty) in world coordinates.
double below_horizon_fraction(const vec3& v, const vec3& n, const vec3& tx, const vec3& ty,
                              const vec2& sigma2);

}  // namespace sg
