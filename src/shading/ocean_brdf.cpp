#include "shading/ocean_brdf.h"

#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>

#include "shading/gaussian_disk.h"
#include "shading/radiance.h"

namespace sg {
namespace {

constexpr double kSqrtPi = 1.7724538509055160273;
// Cosines below this are clamped in Eq. 15 (the authors' shader: max(zV, 0.01)).
constexpr double kMinCos = 0.01;

// p(zeta_h) / (4 h_z^4 cv (1 + Lambda(a_v) + Lambda(a_l))) with the cosines of the view and
// light zenith angles given (clamped or not by the caller): Eq. 15's factor, shared by
// Eq. 13 and Eq. 15.
double ross_factor(const vec3& v, const vec3& l, const vec2& sigma2, double cv, double cl) {
  const vec3 h = normalize(v + l);
  if (!(h.z > 0)) return 0.0;
  const vec2 zeta_h = -vec2(h.x, h.y) / h.z;
  auto clamped = [](const vec3& w, double c) {
    // The same azimuth with the zenith cosine c (the shadowing of a clamped direction).
    const double s = std::sqrt(std::max(0.0, 1 - c * c)), r = std::hypot(w.x, w.y);
    return r > 0 ? vec3(s * w.x / r, s * w.y / r, c) : vec3(0, 0, 1);
  };
  const double lv = smith_lambda(smith_a(clamped(v, cv), sigma2));
  const double ll = smith_lambda(smith_a(clamped(l, cl), sigma2));
  const double hz2 = h.z * h.z;
  return slope_pdf(zeta_h, sigma2) / (4 * hz2 * hz2 * cv * (1 + lv + ll));
}

}  // namespace

double slope_pdf(const vec2& z, const vec2& s2) {
  return std::exp(-0.5 * (z.x * z.x / s2.x + z.y * z.y / s2.y)) / (kTwoPi * std::sqrt(s2.x * s2.y));
}

double slope_variance_toward(const vec3& w, const vec2& s2) {
  const double r2 = w.x * w.x + w.y * w.y;
  if (!(r2 > 0)) return s2.x;  // the zenith: no azimuth (the value does not matter there)
  return (s2.x * w.x * w.x + s2.y * w.y * w.y) / r2;
}

double smith_a(const vec3& w, const vec2& s2) {
  const double sin_t = std::hypot(w.x, w.y);
  if (!(sin_t > 0)) return INFINITY;
  return w.z / (sin_t * std::sqrt(2 * slope_variance_toward(w, s2)));
}

double smith_lambda(double a) {
  if (!(a < 26)) return 0.0;  // exp(-a^2) < 1e-293: no shadowing (and a = +inf)
  const double L = (std::exp(-a * a) - a * kSqrtPi * std::erfc(a)) / (2 * a * kSqrtPi);
  return std::max(0.0, L);
}

double visible_slope_density(const vec2& zeta, const vec3& v, const vec2& s2) {
  // max(v . f, 0) / f_z = max(v.z - zeta . v.xy, 0) with f = (-zeta, 1) / |(-zeta, 1)|.
  const double vf = v.z - zeta.x * v.x - zeta.y * v.y;
  if (!(vf > 0) || !(v.z > 0)) return 0.0;
  const double lambda_v = smith_lambda(smith_a(v, s2));
  return slope_pdf(zeta, s2) * vf / ((1 + lambda_v) * v.z);
}

double ross_brdf(const vec3& v, const vec3& l, const vec2& s2, double F) {
  if (!(v.z > 0) || !(l.z > 0)) return 0.0;
  return F * ross_factor(v, l, s2, v.z, l.z) / l.z;
}

double sun_reflectance(const vec3& v, const vec3& l, const vec2& s2, double solid_angle) {
  return solid_angle * ross_factor(v, l, s2, std::max(v.z, kMinCos), std::max(l.z, kMinCos));
}

double effective_fresnel_fit(double cos_theta_v, double sigma_v) {
  const double c = std::clamp(1.0 - cos_theta_v, 0.0, 1.0);
  return kSchlickR0 + (1 - kSchlickR0) * std::pow(c, 5 * std::exp(-2.69 * sigma_v)) /
                          (1 + 22.7 * std::pow(sigma_v, 1.5));
}

double effective_fresnel_integral(const vec3& v, const vec2& s2_in) {
  const double ct = v.z, st = std::hypot(v.x, v.y);
  if (!(ct > 0)) return kSchlickR0;  // nothing visible
  const vec2 s2 = glm::max(s2_in, vec2(1e-14));
  // The view's azimuthal frame: u along the azimuth, w across it. In it the Gaussian has
  // variances var_u (Eq. 25), var_w and covariance cov; f = (-u, -w, 1) / |.| in that frame,
  // so v . f / f_z = ct - st u and |zeta|^2 = u^2 + w^2.
  const double c = st > 0 ? v.x / st : 1.0, s = st > 0 ? v.y / st : 0.0;
  const double var_u = s2.x * c * c + s2.y * s * s, var_w = s2.x * s * s + s2.y * c * c;
  const double cov = (s2.y - s2.x) * s * c;
  const double su = std::sqrt(var_u), sw = std::sqrt(std::max(var_w - cov * cov / var_u, 0.0));
  const double lambda_v = smith_lambda(smith_a(v, s2));
  using GL = boost::math::quadrature::gauss<double, 40>;
  auto outer = [&](double u) {
    const double vis = ct - st * u;  // > 0 on the integration range
    const double mu = cov / var_u * u;
    auto inner = [&](double w) {
      const double vf = vis / std::sqrt(1 + u * u + w * w);
      const double m = 1 - vf, m2 = m * m;
      const double pw = sw > 0 ? std::exp(-0.5 * sqr((w - mu) / sw)) / (sw * std::sqrt(kTwoPi)) : 1;
      return pw * m2 * m2 * m;
    };
    const double inner_int = sw > 0 ? GL::integrate(inner, mu - 9 * sw, mu + 9 * sw) : inner(mu);
    return std::exp(-0.5 * sqr(u / su)) / (su * std::sqrt(kTwoPi)) * vis * inner_int;
  };
  const double u_hi = st > 0 ? std::min(9 * su, ct / st) : 9 * su;
  const double integral = u_hi > -9 * su ? GL::integrate(outer, -9 * su, u_hi) : 0.0;
  return kSchlickR0 + (1 - kSchlickR0) * integral / ((1 + lambda_v) * ct);
}

double below_horizon_fraction(const vec3& v, const vec3& n, const vec3& tx, const vec3& ty,
                              const vec2& s2) {
  // Algorithm 5.1's U(zeta): the facet normal in world space, the reflected view, and its
  // stereographic coordinates.
  bool finite = true;
  auto U = [&](const vec2& zeta) {
    const vec3 f = normalize(-zeta.x * tx - zeta.y * ty + n);
    const vec3 r = reflect_view(f, v);
    if (1 + r.y < 1e-9) finite = false;  // straight down: the map's pole
    return vec2(r.x, r.z) / std::max(1 + r.y, 1e-9);
  };
  const double eps = 1e-3;
  const vec2 u0 = U(vec2(0.0));
  const mat2 J((U(vec2(eps, 0)) - u0) / eps, (U(vec2(0, eps)) - u0) / eps);
  if (!finite) return 1.0;
  const mat2 cov = J * mat2(vec2(s2.x, 0), vec2(0, s2.y)) * glm::transpose(J);
  return std::clamp(1.0 - gaussian_disk_mass(u0, cov, 1.0), 0.0, 1.0);
}

}  // namespace sg
