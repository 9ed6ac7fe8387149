#include "shading/reflection_footprint.h"

#include "shading/rdf.h"

namespace sg {

ReflectionFootprint reflection_footprint(const SceneModel& m, const PixelFootprint& fp,
                                         std::span<const double> weights, double t,
                                         const vec2& shift) {
  thread_local WavePhases ph;
  m.waves.phases(fp.point.x, fp.point.z, t, ph);
  return reflection_footprint(m, fp, weights, ph, shift);
}

ReflectionFootprint reflection_footprint(const SceneModel& m, const PixelFootprint& fp,
                                         std::span<const double> weights, const WavePhases& ph,
                                         const vec2& shift) {
  ReflectionFootprint out;
  const vec2 g = m.waves.gradient(ph, weights);
  const Hessian H = m.waves.hessian(ph, weights);
  const vec3 nm(-g.x + shift.x, 1.0, -g.y + shift.y);
  const vec3 v = fp.view;
  const vec3 r = (2.0 * dot(nm, v) / dot(nm, nm)) * nm - v;
  if (dot(r, m.light.L) <= 0) return out;
  out.valid = true;
  out.P = m.light.to_plane(r);
  const glm::dmat3x2 dPdr = light_plane_jacobian(r, m.light);
  const mat3 drdm = reflection_jacobian_normal(nm, v), drdv = reflection_jacobian_view(nm);
  const double dist = fp.distance;
  const mat3 proj = mat3(1.0) - glm::outerProduct(v, v);
  auto column = [&](const vec3& dX) {
    const vec3 dm(-(H.xx * dX.x + H.xz * dX.z), 0.0, -(H.xz * dX.x + H.zz * dX.z));
    const vec3 dv = -(proj * dX) / dist;
    return dPdr * (drdm * dm + drdv * dv);
  };
  out.D = mat2(column(fp.dp_dpx), column(fp.dp_dpy));
  return out;
}

}  // namespace sg
