#include "shading/radiance.h"

#include "scene/intersect.h"

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

}  // namespace sg
