#include "shading/specular_aa.h"

#include <algorithm>
#include <cmath>

#include "shading/gaussian_disk.h"

namespace sg {

ShadingFrame water_shading_frame(const vec2& g) {
  ShadingFrame f;
  f.n = normal_from_gradient(g);
  f.t = normalize(vec3(1.0, g.x, 0.0));
  f.b = cross(f.n, f.t);
  return f;
}

vec2 projected_half_vector(const ShadingFrame& f, const vec3& v, const vec3& L) {
  const vec3 h = normalize(v + L);
  return vec2(dot(h, f.t), dot(h, f.b));
}

vec2 projected_half_vector_derivative(const vec3& camera, const vec3& P, const vec2& g,
                                      const Hessian& H, const vec3& dP, const vec3& L) {
  // d normalize(x) = (dx - u (u . dx)) / |x| with u = normalize(x).
  auto dnormalize = [](const vec3& x, const vec3& dx) {
    const double l = length(x);
    const vec3 u = x / l;
    return (dx - u * dot(u, dx)) / l;
  };
  const vec3 e = camera - P;
  const vec3 v = normalize(e), dv = dnormalize(e, -dP);
  const vec3 s = v + L;
  const vec3 h = normalize(s), dh = dnormalize(s, dv);
  const vec2 dg(H.xx * dP.x + H.xz * dP.z, H.xz * dP.x + H.zz * dP.z);
  const vec3 T(1.0, g.x, 0.0), N(-g.x, 1.0, -g.y);
  const vec3 t = normalize(T), dt = dnormalize(T, vec3(0.0, dg.x, 0.0));
  const vec3 n = normalize(N), dn = dnormalize(N, vec3(-dg.x, 0.0, -dg.y));
  const vec3 b = cross(n, t), db = cross(dn, t) + cross(n, dt);
  return vec2(dot(dh, t) + dot(h, dt), dot(dh, b) + dot(h, db));
}

mat2 filtering_kernel_covariance(const vec2& ddx, const vec2& ddy, double sigma2, double kappa,
                                 KernelShape shape) {
  if (shape == KernelShape::rect) {
    // fwidth, then alpha^2 = min(2 sigma^2 b^2, kappa) per axis; slope variance alpha^2 / 2.
    const vec2 bounds = glm::abs(ddx) + glm::abs(ddy);
    const double vx = 0.5 * std::min(2 * sigma2 * bounds.x * bounds.x, kappa);
    const double vy = 0.5 * std::min(2 * sigma2 * bounds.y * bounds.y, kappa);
    return mat2(vec2(vx, 0), vec2(0, vy));
  }
  // sigma^2 D D^T (columns of D: ddx, ddy), principal variances clamped at kappa / 2.
  const mat2 D(ddx, ddy);
  const mat2 C = sigma2 * D * glm::transpose(D);
  const PrincipalAxes p = principal_axes(C);
  const double l1 = std::min(p.s1 * p.s1, 0.5 * kappa), l2 = std::min(p.s2 * p.s2, 0.5 * kappa);
  const vec2 u = p.u, w(-u.y, u.x);
  return l1 * glm::outerProduct(u, u) + l2 * glm::outerProduct(w, w);
}

mat2 tangent_slope_to_ndf_plane(const ShadingFrame& f) {
  // q(m) = (m.x, m.z) / m.y with m = n - s_x t - s_y b: dq/ds for a tangent direction d is
  // -((d.x n.y - n.x d.y), (d.z n.y - n.z d.y)) / n.y^2.
  const vec3& n = f.n;
  auto col = [&](const vec3& d) {
    return -vec2(d.x * n.y - n.x * d.y, d.z * n.y - n.z * d.y) / (n.y * n.y);
  };
  return mat2(col(f.t), col(f.b));
}

}  // namespace sg
