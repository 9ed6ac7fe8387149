#include "methods/host_method.h"

#include "base/error.h"
#include "shading/radiance.h"

namespace sg {

RadianceWeights centre_ray_weights(const FrameContext& ctx, const WaterGeometry& water, int i,
                                   int j) {
  const SceneModel& m = ctx.model;
  return weights_along_ray(water, m.camera.position(), m.camera.direction(i + 0.5, j + 0.5),
                           ctx.time.end);
}

void HostMethod::begin_host_frame(const FrameContext& ctx) {
  reset_fallbacks();
  if (!water_.is_for(ctx.model, ctx.time)) water_ = WaterGeometry(ctx.model, ctx.time);
}

const WaterGeometry& HostMethod::water(const FrameContext& ctx) const {
  if (!water_.is_for(ctx.model, ctx.time)) {
    throw Error("frame " + std::to_string(ctx.time.frame) +
                " shaded without begin_frame (methods/method.h)");
  }
  return water_;
}

}  // namespace sg
