// The CPU side of the kernel methods (point, supersample, reference, staa-temporal,
// staa): the frame's inputs to the shading kernel (shading/kernel_frame.h), built in
// begin_frame in the method's precision and read by every tile of the frame.
#pragma once

#include <mutex>

#include "methods/method.h"
#include "shading/kernel_frame.h"

namespace sg {

class KernelFrameInputs {
 public:
  // Inputs with K = segments path sub-arcs, in `precision`, with the displaced
  // intersection's tolerance in pixels (shading/kernel_frame.h; 0: every wave).
  // `windows`: the reference's windows of the shutter (kernel/interface.glsl).
  KernelFrameInputs(int segments, Precision precision,
                    double intersect_tolerance = kDefaultIntersectTolerance, int windows = 1)
      : precision_(precision),
        segments_(segments),
        windows_(windows),
        intersect_tolerance_(intersect_tolerance) {}
  // Builds the inputs of ctx's frame.
  void build(const FrameContext& ctx);
  // Makes sure the inputs are ctx's frame's: the engine's begin_frame has built them, so
  // this is a comparison; a caller that shades without begin_frame (a test, one thread)
  // gets them built here.
  void check(const FrameContext& ctx) const;

  Precision precision() const { return precision_; }
  const KernelInputsD& d() const { return d_; }
  const KernelInputsF& f() const { return f_; }

 private:
  bool current(const FrameContext& ctx) const;

  Precision precision_;
  int segments_;
  int windows_;
  double intersect_tolerance_;
  KernelInputsD d_;
  KernelInputsF f_;
  uint64_t model_ = 0;
  int frame_ = 0;
  double start_ = 0, end_ = 0;
  uint64_t seed_ = 0;
  bool built_ = false;
  mutable std::mutex lazy_;
};

// A kernel result in float or double as the host's weights.
inline RadianceWeights to_weights(const kd::vec4& w) {
  return w;
}
inline RadianceWeights to_weights(const kf::vec4& w) {
  return RadianceWeights(w);
}

}  // namespace sg
