#include "shading/ocean_brdf.h"

#include "kernel/kernel_double.h"

namespace sg {

// The kernel's (kernel/ocean_brdf.glsl), in double.
double slope_pdf(const vec2& z, const vec2& s2) {
  return kd::slope_pdf(z, s2);
}
double slope_variance_toward(const vec3& w, const vec2& s2) {
  return kd::slope_variance_toward(w, s2);
}
double smith_a(const vec3& w, const vec2& s2) {
  return kd::smith_a(w, s2);
}
double smith_lambda(double a) {
  return kd::smith_lambda(a);
}
double visible_slope_density(const vec2& zeta, const vec3& v, const vec2& s2) {
  return kd::visible_slope_density(zeta, v, s2);
}
double ross_brdf(const vec3& v, const vec3& l, const vec2& s2, double F) {
  return kd::ross_brdf(v, l, s2, F);
}
double sun_reflectance(const vec3& v, const vec3& l, const vec2& s2, double solid_angle) {
  return kd::sun_reflectance(v, l, s2, solid_angle);
}
double effective_fresnel_fit(double cos_theta_v, double sigma_v) {
  return kd::effective_fresnel_fit(cos_theta_v, sigma_v);
}
double effective_fresnel_integral(const vec3& v, const vec2& s2) {
  return kd::effective_fresnel_integral(v, s2);
}
double below_horizon_fraction(const vec3& v, const vec3& n, const vec3& tx, const vec3& ty,
                              const vec2& s2) {
  return kd::below_horizon_fraction(v, n, tx, ty, s2);
}

}  // namespace sg
