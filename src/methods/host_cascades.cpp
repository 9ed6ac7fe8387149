#include "methods/host_cascades.h"

#include "kernel/kernel_double.h"
#include "shading/cascade_fields.h"

namespace sg {

void HostCascades::build(const FrameContext& ctx) {
  const SceneModel& m = ctx.model;
  // Flat water only: these methods intersect displaced water on the host, over the
  // model's waves.
  active_ = enabled_ && cascade_fields_apply(m) && !m.displaced();
  explicit_ = nullptr;
  if (!active_) return;
  inputs_.build(ctx);
  explicit_ = &inputs_.d().cascades->explicit_waves(m);
  // The kernel frame's camera-relative coordinates (shading/kernel_frame.cpp): a frame
  // model holds a moving camera at the display time.
  origin_ = vec2(m.camera.position().x, m.camera.position().z);
}

HostCascades::Moments HostCascades::moments(const vec3& p, const mat2& J) const {
  if (!active_) return Moments{};
  const kd::CascadeMoments r =
      kd::cascade_footprint_moments(wave_buffer(inputs_.d()), inputs_.d().frame, relative(p), J);
  return Moments{r.mean, mat2(r.cov.x, r.cov.y, r.cov.y, r.cov.z)};
}

}  // namespace sg
