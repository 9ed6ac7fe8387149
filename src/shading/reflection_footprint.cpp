// Host wrapper of the kernel's reflection footprint (kernel/reflection_footprint.glsl): the
// resolved waves' gradient and Hessian summed on the host, the derivatives in the kernel.
#include "shading/reflection_footprint.h"

#include "kernel/kernel_double.h"
#include "shading/kernel_frame.h"

namespace sg {

ReflectionFootprint reflection_footprint(const SceneModel& m, const PixelFootprint& fp,
                                         std::span<const double> weights, double t,
                                         const vec2& shift) {
  WavePhases ph;
  m.waves.phases(fp.point.x, fp.point.z, t, ph);
  return reflection_footprint(m, fp, weights, ph, shift);
}

ReflectionFootprint reflection_footprint(const SceneModel& m, const PixelFootprint& fp,
                                         std::span<const double> weights, const WavePhases& ph,
                                         const vec2& shift) {
  const vec2 g = m.waves.gradient(ph, weights);
  const Hessian H = m.waves.hessian(ph, weights);
  const kd::ReflectionFootprint k = kd::reflection_footprint(
      kernel_light(m.light), kernel_footprint(m, fp), g, vec3(H.xx, H.xz, H.zz), shift);
  ReflectionFootprint out;
  out.valid = k.valid;
  out.P = k.P;
  out.D = k.D;
  return out;
}

}  // namespace sg
