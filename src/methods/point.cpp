#include "methods/point.h"

#include "shading/radiance.h"

namespace sg {

RadianceWeights PointMethod::weights(const FrameContext& ctx, int i, int j) const {
  const SceneModel& m = ctx.model;
  return weights_along_ray(m, m.camera.position(), m.camera.direction(i + 0.5, j + 0.5),
                           ctx.time.end);
}

}  // namespace sg
