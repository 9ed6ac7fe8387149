#include "shading/rdf.h"

namespace sg {

vec3 reflect_about_ndf_point(const vec2& n, const vec3& v) {
  const vec3 m(n.x, 1.0, n.y);
  return (2.0 * dot(m, v) / dot(m, m)) * m - v;
}

vec2 ndf_to_light_plane(const vec2& n, const vec3& v, const LightModel& light) {
  return light.to_plane(reflect_about_ndf_point(n, v));
}

void reflection_derivatives(const vec2& n, const vec3& v, vec3& dr_dnx, vec3& dr_dnz) {
  const vec3 m(n.x, 1.0, n.y);
  const double mm = dot(m, m), mv = dot(m, v);
  // dr/dm_j = 2 [v_j m + (m.v) e_j] / (m.m) - 4 (m.v) m_j m / (m.m)^2, for j = x, z.
  auto dr = [&](int j) {
    vec3 e(0.0);
    e[j] = 1.0;
    return (2.0 / mm) * (v[j] * m + mv * e) - (4.0 * mv * m[j] / (mm * mm)) * m;
  };
  dr_dnx = dr(0);
  dr_dnz = dr(2);
}

mat2 ndf_to_light_plane_jacobian(const vec2& n, const vec3& v, const LightModel& light) {
  const vec3 r = reflect_about_ndf_point(n, v);
  vec3 dr_dnx, dr_dnz;
  reflection_derivatives(n, v, dr_dnx, dr_dnz);
  // P(r) = (r.e1, r.e2) / (r.L): dP = ((dr.e1) (r.L) - (r.e1)(dr.L)) / (r.L)^2, same for e2.
  const double rl = dot(r, light.L), r1 = dot(r, light.e1), r2 = dot(r, light.e2);
  auto dP = [&](const vec3& d) {
    const double dl = dot(d, light.L);
    return vec2((dot(d, light.e1) * rl - r1 * dl) / (rl * rl),
                (dot(d, light.e2) * rl - r2 * dl) / (rl * rl));
  };
  return mat2(dP(dr_dnx), dP(dr_dnz));
}

}  // namespace sg
