#include "methods/fallback.h"

#include "shading/radiance.h"

namespace sg {

RadianceWeights centre_ray_weights(const FrameContext& ctx, int i, int j) {
  const SceneModel& m = ctx.model;
  return weights_along_ray(m, m.camera.position(), m.camera.direction(i + 0.5, j + 0.5),
                           ctx.time.end);
}

}  // namespace sg
