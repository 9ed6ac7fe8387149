#include "shading/reflection_path.h"

#include "kernel/kernel_double.h"
#include "shading/radiance.h"
#include "shading/water_geometry.h"

namespace sg {

void reflection_path(const SceneModel& m, const PixelFootprint& fp, const FrameTime& ft,
                     int segments, ReflectionPath& path) {
  const int K = std::max(1, segments);
  build_kernel_inputs(m, ft, K, 0, path.inputs);
  path.view = fp.view;
  path.xz = vec2(fp.point.x, fp.point.z);
  path.kernel_path = kd::path_gradients(wave_buffer(path.inputs), path.inputs.frame,
                                        to_camera_relative(m, fp.point));
  path.times.resize(K + 1);
  path.gradients.resize(K + 1);
  path.normals.resize(K + 1);
  path.reflections.resize(K + 1);
  for (int k = 0; k <= K; ++k) {
    path.times[k] = ft.start + ft.duration() * k / K;
    path.gradients[k] = path.kernel_path.g[k];
    path.normals[k] = water_normal(path.gradients[k]);
    path.reflections[k] = reflect_view(path.normals[k], path.view);
  }
}

PathShares temporal_shares(const ReflectionPath& path) {
  const kd::PathShares k = kd::temporal_shares(path.inputs.frame, path.kernel_path, path.view);
  PathShares s;
  s.in_light = k.in_light;
  s.below = k.below;
  s.fresnel = k.fresnel;
  s.weights = k.weights;
  return s;
}

}  // namespace sg
