// The two stratified-sampling methods (the estimator: kernel/sampling.glsl,
// stratified_pixel; methods/stratified.h):
//   reference    the ground truth: S x S positions x T times over the shutter (8x8x8 by
//                default; at least 12x12x8 for published figures).
//   supersample  the same estimator at a budget the user picks. With T = 1 its one time
//                is the display time t_f, so `--samples 6x6x1` is spatial-only
//                supersampling with 36 samples, the paper's "32x MSAA"-like baseline;
//                with T > 1 it samples the shutter like the reference.
// Their samples see every wave, and on displaced water they intersect every wave by
// default (the scene's exact surface). With --intersect-tolerance given, the intersection
// leaves out the shortest waves as kernel/intersect.glsl allows, the tolerance taken per
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

// `supersample`'s intersection tolerance under `o` for one sample of its S_x x S_y x T
// (pixels; 0, every wave, unless --intersect-tolerance is given: intersect_tolerance_for).
inline double stratified_intersect_tolerance(const MethodOptions& o) {
  return intersect_tolerance_for(o, "supersample") / std::max({o.samples.sx, o.samples.sy, 1});
}

class StratifiedMethod final : public Method {
 public:
  StratifiedMethod(std::string name, StratifiedSettings settings,
                   Precision precision = Precision::float64,
                   double intersect_tolerance = 0.0,  // every wave (intersect_tolerance_for)
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
