// The CPU side of the kernel methods (point, supersample, reference, staa-temporal, staa,
// specaa): the frame's inputs to the shading kernel (shading/kernel_frame.h), built in
// begin_frame in the method's precision and read by every tile of the frame.
#pragma once

#include "methods/method.h"
#include "shading/kernel_frame.h"

namespace sg {

class KernelFrameInputs {
 public:
  // Inputs with K = segments path sub-arcs, in `precision`, with the displaced
  // intersection's tolerance in pixels (shading/kernel_frame.h; 0: every wave).
  // `windows`: the reference's windows of the shutter (kernel/interface.glsl).
  // `cascade_fields`: a scene's cascades as FFT fields where they apply
  // (shading/kernel_frame.h), else as sines among the waves; `reads`, what the method
  // reads of them (shading/cascade_fields.h).
  KernelFrameInputs(int segments, Precision precision,
                    double intersect_tolerance = kDefaultIntersectTolerance, int windows = 1,
                    bool cascade_fields = false, CascadeReads reads = CascadeReads::all)
      : precision_(precision),
        segments_(segments),
        windows_(windows),
        intersect_tolerance_(intersect_tolerance),
        cascade_fields_(cascade_fields),
        reads_(reads) {}
  // Builds the inputs of ctx's frame.
  void build(const FrameContext& ctx);
  // Checks that the inputs are ctx's frame's, as the engine's begin_frame built them
  // (engine/render.h); sg::Error when they are not (a caller that shades without
  // begin_frame): the shading threads only read them, nothing is built behind their back.
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
  bool cascade_fields_;
  CascadeReads reads_;
  KernelInputsD d_;
  KernelInputsF f_;
  uint64_t model_ = 0;
  int frame_ = 0;
  double start_ = 0, end_ = 0;
  uint64_t seed_ = 0;
  bool built_ = false;
};

// A kernel result in float or double as the host's weights.
inline RadianceWeights to_weights(const kd::vec4& w) {
  return w;
}
inline RadianceWeights to_weights(const kf::vec4& w) {
  return RadianceWeights(w);
}

}  // namespace sg
