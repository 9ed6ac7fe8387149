#include "shading/rdf.h"

namespace sg {

vec3 reflect_about_ndf_point(const vec2& n, const vec3& v) {
  const vec3 m(n.x, 1.0, n.y);
  return (2.0 * dot(m, v) / dot(m, m)) * m - v;
}

vec2 ndf_to_light_plane(const vec2& n, const vec3& v, const LightModel& light) {
  return light.to_plane(reflect_about_ndf_point(n, v));
}

glm::dmat3x2 light_plane_jacobian(const vec3& r, const LightModel& light) {
  // P(r) = (r.e1, r.e2) / (r.L): dP_i/dr = (e_i (r.L) - (r.e_i) L) / (r.L)^2.
  const double rl = dot(r, light.L), inv = 1.0 / (rl * rl);
  const vec3 row1 = (light.e1 * rl - dot(r, light.e1) * light.L) * inv;
  const vec3 row2 = (light.e2 * rl - dot(r, light.e2) * light.L) * inv;
  return glm::dmat3x2(vec2(row1.x, row2.x), vec2(row1.y, row2.y), vec2(row1.z, row2.z));
}

mat3 reflection_jacobian_normal(const vec3& m, const vec3& v) {
  // dr/dm_j = 2 [v_j m + (m.v) e_j] / (m.m) - 4 (m.v) m_j m / (m.m)^2
  const double mm = dot(m, m), mv = dot(m, v);
  mat3 J(0.0);
  for (int j = 0; j < 3; ++j) {
    vec3 e(0.0);
    e[j] = 1.0;
    J[j] = (2.0 / mm) * (v[j] * m + mv * e) - (4.0 * mv * m[j] / (mm * mm)) * m;
  }
  return J;
}

mat3 reflection_jacobian_view(const vec3& m) {
  return (2.0 / dot(m, m)) * glm::outerProduct(m, m) - mat3(1.0);
}

void reflection_derivatives(const vec2& n, const vec3& v, vec3& dr_dnx, vec3& dr_dnz) {
  const mat3 J = reflection_jacobian_normal(vec3(n.x, 1.0, n.y), v);
  dr_dnx = J[0];
  dr_dnz = J[2];
}

mat2 ndf_to_light_plane_jacobian(const vec2& n, const vec3& v, const LightModel& light) {
  const vec3 m(n.x, 1.0, n.y);
  const vec3 r = (2.0 * dot(m, v) / dot(m, m)) * m - v;
  const glm::dmat3x2 JP = light_plane_jacobian(r, light) * reflection_jacobian_normal(m, v);
  return mat2(JP[0], JP[2]);  // columns for m.x = n.x and m.z = n.y
}

}  // namespace sg
