// Point sampling (`--method point`, the paper's "No AA"): one camera ray through the
// pixel centre at the frame's display time t_f, shaded with the radiance of the scene
// spec (kernel/sampling.glsl, point_pixel). It aliases in space (glints smaller than a
// pixel are hit or missed) and in time (a glint that crosses the pixel between frames is
// seen or not).
#pragma once

#include "methods/kernel_inputs.h"
#include "methods/method.h"

namespace sg {

class PointMethod final : public Method {
 public:
  explicit PointMethod(Precision precision = Precision::float64,
                       double intersect_tolerance = 0.0,  // every wave (intersect_tolerance_for)
                       bool cascade_fields = true)
      : inputs_(1, precision, intersect_tolerance, 1, cascade_fields, cascade_reads_of("point")) {}
  std::string name() const override { return "point"; }
  void begin_frame(const FrameContext& ctx) override { inputs_.build(ctx); }
  RadianceWeights weights(const FrameContext& ctx, int i, int j) const override;

 private:
  KernelFrameInputs inputs_;
};

}  // namespace sg
