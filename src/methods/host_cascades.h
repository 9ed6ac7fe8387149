// A scene's lattice cascades for the baseline shaded on the host (`lean`; `specaa` and
// `bruneton` read them in the kernel, kernel/specaa.glsl, kernel/bruneton.glsl): per frame,
// the cascades' FFT fields and LEAN chains built by the kernel's frame inputs
// (shading/cascade_fields.h), read per pixel through the kernel's functions
// (kernel/cascade_fields.glsl), so that the method costs a few fetches per cascade instead
// of a sum over every lattice sine. The explicit waves stay the method's own.
//
// What the baseline takes from them, at the display time (docs/ocean.md, "Shading from
// the cascades"):
//   lean            the slopes' mean and covariance over the pixel's footprint (LEAN's
//                   filtered moments, Olano and Baker 2010, Sec. 3), added to those of the
//                   explicit waves (cascade_footprint_moments).
// They apply on flat water with `--cascades fields` (the default); elsewhere (displaced
// water, `--cascades waves`) `active()` is false and the cascades are their lattice's
// sines among the model's waves, exactly.
#pragma once

#include "methods/kernel_inputs.h"
#include "scene/footprint.h"
#include "scene/waves.h"

namespace sg {

class HostCascades {
 public:
  explicit HostCascades(bool enabled)
      : enabled_(enabled),
        inputs_(1, Precision::float64, kDefaultIntersectTolerance, 1, enabled,
                CascadeReads::display_chain) {}

  // Builds frame ctx's fields where they apply (the method's begin_frame).
  void build(const FrameContext& ctx);
  bool active() const { return active_; }
  // The waves the method sums itself: the explicit ones when the cascades are fields,
  // else every wave of the model (the lattices' sines included).
  const WaveField& waves(const SceneModel& m) const { return active_ ? *explicit_ : m.waves; }

  struct Moments {
    vec2 mean{0};
    mat2 cov{0};
  };
  // Over the footprint J (d(x, z) / d(px, py)) about world point p.
  Moments moments(const vec3& p, const mat2& J) const;

 private:
  kd::vec2 relative(const vec3& p) const { return kd::vec2(p.x - origin_.x, p.z - origin_.y); }

  bool enabled_;
  bool active_ = false;
  KernelFrameInputs inputs_;
  const WaveField* explicit_ = nullptr;
  vec2 origin_{0};  // the camera's world (x, z) at the display time: the kernel's origin
};

}  // namespace sg
