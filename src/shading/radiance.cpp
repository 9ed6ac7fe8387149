#include "shading/radiance.h"

#include "scene/intersect.h"
#include "shading/kernel_frame.h"

namespace sg {

RadianceWeights weights_along_ray(const SceneModel& m, const vec3& origin, const vec3& dir,
                                  double t, RayHit* hit_out) {
  const vec3 d = normalize(dir);
  RayHit hit =
      m.displaced() ? intersect_displaced(m.waves, origin, d, t) : intersect_flat(origin, d);
  if (hit_out) *hit_out = hit;
  if (!hit.hit) return miss_weights(m, d);
  const vec3 n = normal_from_gradient(m.waves.gradient(hit.point.x, hit.point.z, t));
  return water_weights(m, n, -d);
}

RadianceWeights miss_pixel_weights(const SceneModel& m, int i, int j) {
  const double cover =
      kd::light_pixel_coverage(kernel_camera(m.camera), kernel_light(m.light), i, j);
  const vec3 d = normalize(m.camera.direction(i + 0.5, j + 0.5));
  return cover * light_weights() + (1.0 - cover) * sky_weights(m, d.y);
}

}  // namespace sg
