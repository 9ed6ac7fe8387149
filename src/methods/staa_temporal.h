// `--method staa-temporal`: the temporal method of Podee et al. 2021 (Sec. 3.3) for every
// pixel (kernel/sampling.glsl, staa_temporal_pixel): the surface point at the pixel
// centre, its reflection path over the frame's shutter interval (all waves treated as
// resolved), and the fraction of that time during which the reflection lies in the light
// disk, computed exactly on the sphere for each of `--segments K` great-circle sub-arcs
// (kernel/reflection_path.glsl, kernel/arc.glsl). It removes flicker for the waves the
// pixel grid resolves; it still samples space at the pixel centre only, so waves above
// the Nyquist limit alias (the full method, `staa`, handles them). Under a moving camera
// (format /3) each instant of the path has the water point and view of the pixel's ray
// from the camera at that instant (docs/method.md, "A moving camera").
#pragma once

#include "methods/kernel_inputs.h"
#include "methods/method.h"

namespace sg {

class StaaTemporalMethod final : public Method {
 public:
  explicit StaaTemporalMethod(
      int segments, Precision precision = Precision::float64,
      double intersect_tolerance = 0.0,  // every wave (intersect_tolerance_for)
      bool cascade_fields = true)
      : inputs_(segments, precision, intersect_tolerance, 1, cascade_fields,
                cascade_reads_of("staa-temporal")) {}
  std::string name() const override { return "staa-temporal"; }
  void begin_frame(const FrameContext& ctx) override { inputs_.build(ctx); }
  RadianceWeights weights(const FrameContext& ctx, int i, int j) const override;

 private:
  KernelFrameInputs inputs_;
};

}  // namespace sg
