// Host wrappers of the kernel's normal-to-reflection maps (kernel/rdf.glsl).
#include "shading/rdf.h"

#include "kernel/kernel_double.h"
#include "shading/kernel_frame.h"

namespace sg {

vec3 reflect_about_ndf_point(const vec2& n, const vec3& v) {
  return kd::reflect_about_ndf_point(n, v);
}

vec2 ndf_to_light_plane(const vec2& n, const vec3& v, const LightModel& light) {
  return light.to_plane(reflect_about_ndf_point(n, v));
}

glm::dmat3x2 light_plane_jacobian(const vec3& r, const LightModel& light) {
  return kd::light_plane_jacobian(r, light.kernel_light());
}

mat3 reflection_jacobian_normal(const vec3& m, const vec3& v) {
  return kd::reflection_jacobian_normal(m, v);
}

mat3 reflection_jacobian_view(const vec3& m) {
  return kd::reflection_jacobian_view(m);
}

void reflection_derivatives(const vec2& n, const vec3& v, vec3& dr_dnx, vec3& dr_dnz) {
  const mat3 J = reflection_jacobian_normal(vec3(n.x, 1.0, n.y), v);
  dr_dnx = J[0];
  dr_dnz = J[2];
}

mat2 ndf_to_light_plane_jacobian(const vec2& n, const vec3& v, const LightModel& light) {
  return kd::ndf_to_light_plane_jacobian(n, v, light.kernel_light());
}

}  // namespace sg
