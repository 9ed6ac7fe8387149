// The two stratified-sampling methods (the estimator: kernel/sampling.glsl,
// stratified_pixel; methods/stratified.h):
//   reference    the ground truth: S x S positions x T times over the shutter (8x8x8 by
//                default; at least 12x12x8 for published figures).
//   supersample  the same estimator at a budget the user picks. With T = 1 its one time
//                is the display time t_f, so `--samples 6x6x1` is spatial-only
//                supersampling with 36 samples, the paper's "32x MSAA"-like baseline;
//                with T > 1 it samples the shutter like the reference.
// Their samples see every wave; on displaced water the intersection leaves out the
// shortest waves as kernel/intersect.glsl allows, with --intersect-tolerance taken per
// sample cell (divided by the larger of S_x, S_y: stratified_intersect_tolerance), so that
// a hit moves by at most that fraction of the cell its sample stands for.
// `supersample` with T = 1 reads a scene's lattice cascades from their FFT fields at the
// display time, as `point` does (`--cascades fields`, kernel/cascade_fields.glsl); with
// T > 1 its samples take times the fields are not built for, and the cascades are their
// lattice's sines among the waves, exactly.
#pragma once

#include <algorithm>

#include "methods/kernel_inputs.h"
#include "methods/method.h"
#include "methods/stratified.h"

namespace sg {

// --intersect-tolerance of `o` for one sample of its S_x x S_y x T (pixels).
inline double stratified_intersect_tolerance(const MethodOptions& o) {
  return o.intersect_tolerance / std::max({o.samples.sx, o.samples.sy, 1});
}

class StratifiedMethod final : public Method {
 public:
  StratifiedMethod(std::string name, StratifiedSettings settings,
                   Precision precision = Precision::float64,
                   double intersect_tolerance = kDefaultIntersectTolerance,
                   bool cascade_fields = false)
      : name_(std::move(name)),
        settings_(settings),
        inputs_(1, precision, intersect_tolerance, 1, cascade_fields,
                cascade_reads_of("supersample")) {}
  std::string name() const override { return name_; }
  void begin_frame(const FrameContext& ctx) override { inputs_.build(ctx); }
  RadianceWeights weights(const FrameContext& ctx, int i, int j) const override {
    inputs_.check(ctx);
    return stratified_pixel(inputs_, i, j, settings_);
  }
  const StratifiedSettings& settings() const { return settings_; }

 private:
  std::string name_;
  StratifiedSettings settings_;
  KernelFrameInputs inputs_;
};

}  // namespace sg
