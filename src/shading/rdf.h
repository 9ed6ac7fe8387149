// From normals to reflections (Podee et al. 2021, Sec. 3.4, Eqs. 8-16).
//
// A point n = (n_x, n_z) of the NDF plane is the normal m = (n_x, 1, n_z); it reflects the
// view direction v into
//     r(n) = 2 (n^ . v) n^ - v = 2 (m . v) / (m . m) m - v           (Eqs. 9-10)
// which meets the light plane at Phi(n) = r / (r . L) (Eq. 8), with 2D coordinates
// (r . e1, r . e2) / (r . L) in the light plane's frame (scene/light.h). Phi is
// linearised at the NDF's centre n_c (Eq. 11): Phi(n) ~ Phi(n_c) + J_c (n - n_c), with
// the 2x2 Jacobian J_c (Eq. 12) computed analytically here (chain rule through r and the
// projection; tested against finite differences). A Gaussian NDF of covariance Sigma then
// maps to a Gaussian RDF of covariance Sigma_r = J_c Sigma J_c^T (Eq. 16) centred at
// Phi(n_c).
#pragma once

#include "math/vec.h"
#include "scene/light.h"

namespace sg {

// The reflection r(n) (unit) of unit view direction v about the normal (n.x, 1, n.y).
vec3 reflect_about_ndf_point(const vec2& n, const vec3& v);

// dr/dn_x and dr/dn_z at n (the columns of the 3x2 Jacobian of r(n), Eqs. 9-10).
void reflection_derivatives(const vec2& n, const vec3& v, vec3& dr_dnx, vec3& dr_dnz);

// Phi(n) in light-plane coordinates (meaningful when r . L > 0).
vec2 ndf_to_light_plane(const vec2& n, const vec3& v, const LightModel& light);

// J_c = dPhi/dn at n (Eq. 12); columns are dPhi/dn_x and dPhi/dn_z.
mat2 ndf_to_light_plane_jacobian(const vec2& n, const vec3& v, const LightModel& light);

// The pieces of the chain rule, also used for the pixel-footprint term (footprint AA):
// d(light-plane point)/d(direction r), a 2x3 matrix (3 columns, 2 rows; any length of r);
glm::dmat3x2 light_plane_jacobian(const vec3& r, const LightModel& light);
// d r / d m for r = 2 (m.v)/(m.m) m - v with respect to the (unnormalised) normal m;
mat3 reflection_jacobian_normal(const vec3& m, const vec3& v);
// d r / d v with respect to the view direction v: 2 m m^T / (m.m) - I.
mat3 reflection_jacobian_view(const vec3& m);

// Eq. 16 (kernel/rdf.glsl).
inline mat2 rdf_covariance(const mat2& J, const mat2& ndf_cov) {
  return J * ndf_cov * glm::transpose(J);
}

}  // namespace sg
