#include "methods/staa_temporal.h"

#include "scene/footprint.h"
#include "shading/radiance.h"
#include "shading/reflection_path.h"

namespace sg {

RadianceWeights StaaTemporalMethod::weights(const FrameContext& ctx, int i, int j) const {
  const SceneModel& m = ctx.model;
  const PixelFootprint fp = pixel_footprint(m, i + 0.5, j + 0.5, ctx.time.end);
  if (!fp.hit) return miss_weights(m, normalize(m.camera.direction(i + 0.5, j + 0.5)));
  thread_local ReflectionPath path;
  reflection_path(m, fp, ctx.time, segments_, {}, path);
  return temporal_weights(m, path);
}

}  // namespace sg
