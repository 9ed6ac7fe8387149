// `--method reference`: the ground truth of every comparison, the scene spec's pixel value
// (the mean over the pixel square and the shutter interval) estimated by the kernel's
// reference estimator (kernel/reference.glsl): on flat water every spatial sample's time
// integral is computed exactly (the crossings of its gradient path with the light's conic
// and the horizon), so only spatial noise remains; on displaced water every sample has its
// own position and time stratum. The estimate comes in B independent batches, whose
// spread gives each pixel's variance: the method measures its own noise
// (pixel_variance(), image_standard_error()).
//
// `--samples SxSxT` (default 8x8x1): per batch S x S strata of the pixel, T samples in each;
// `--batches B` (default 2). Flat water costs one path of K + 1 instants per sample, K
// chosen per frame so that the path's interpolation error is at most 5e-5 of the light's
// radius (reference_time_split); a shutter too long for that with kMaxSegments instants
// (many periods of a fast wave) is cut into windows, each sample integrating one drawn at
// random. The stratified estimator of before remains as `supersample` (methods/stratified.h).
#pragma once

#include <cmath>
#include <memory>
#include <vector>

#include "methods/kernel_inputs.h"
#include "methods/method.h"

namespace sg {

// The revision of the reference estimator, part of every frame cache key (report/cache.h):
// raise it whenever the reference's images change, on either engine, so that a study never
// takes a cached frame of the estimator of before. 2: the GL engine renders the reference
// in passes (before, llvmpipe's loop limit dropped samples: docs/reference-renderer.md).
// 3: windows of the shutter where kMaxSegments sub-intervals cannot meet the path's
// bound (before, the path's interpolation was wrong there: docs/reference-renderer.md).
// 4: displaced water intersected with every wave by default (ReferenceSettings::
// intersect_tolerance; before, 0.25 pixels, which dropped the visible share of small
// steep waves' slopes at grazing views).
inline constexpr int kReferenceRevision = 4;

// The reference's defaults (docs/reference-renderer.md: the measured noise and cost).
inline constexpr SampleCounts kReferenceSamples{8, 8, 1};
inline constexpr int kReferenceBatches = 2;

// The pilot's margin (kernel/reference.glsl, reference_pixel_busy), in units of the
// reflection's spread over the pixel and step between instants.
inline constexpr double kReferencePilotMargin = 2.0;

struct ReferenceSettings {
  SampleCounts samples = kReferenceSamples;  // busy pixels (all without `adaptive`)
  int batches = kReferenceBatches;
  int only_batch = -1;  // render only this batch (a study's unit), or all (-1)
  // The batches the kernel renders, and the first of them.
  int kernel_batches() const { return only_batch >= 0 ? 1 : batches; }
  int first_batch() const { return only_batch >= 0 ? only_batch : 0; }
  bool adaptive = true;
  int quiet = 1;  // quiet pixels: quiet x quiet strata of T samples per batch
  double margin = kReferencePilotMargin;
  // The displaced intersection's bound in pixels (docs/ocean.md), applied per sample cell
  // (divided by the larger of S_x, S_y). 0 by default: every wave, the scene's exact
  // surface. Leaving waves out by their amplitude moves a hit by a fraction of the
  // footprint, but it also drops the share of each wave's slopes that the ray sees: the
  // facets turned towards a grazing view are met more often than those turned away
  // (kernel/visible_normals.glsl), whatever the wave's amplitude; on far water that moved
  // the reference by more than the methods' errors (docs/reference-renderer.md).
  double intersect_tolerance = 0.0;
};

// The settings `--method reference` gets from its flags (--samples when given, --batches,
// --adaptive, --quiet-samples, --intersect-tolerance when given), for either engine.
ReferenceSettings reference_settings(const MethodOptions& o);

// The split of the shutter for flat water's exact time integral: W windows of
// duration / W, each of K sub-intervals, with the cubic Hermite interpolation's error
// bound (duration / (W K))^4 / 384 * sum A |k| c^4 at most kReferencePathTolerance light
// radii: the smallest K (1 to kMaxSegments) with W = 1, else K = kMaxSegments and the
// smallest W (at most kReferenceMaxWindows, where the bound may stay unmet: windows of a
// 2^-20th of the shutter). W is 1 where samples are traced at their own times (displaced
// water, a moving camera).
inline constexpr double kReferencePathTolerance = 5e-5;
inline constexpr int kReferenceMaxWindows = 1 << 20;
struct ReferenceTimeSplit {
  int segments = 1;
  int windows = 1;
};
ReferenceTimeSplit reference_time_split(const SceneModel& m, double duration);
// Its K.
int reference_segments(const SceneModel& m, double duration);
// That bound for K sub-intervals, in gradient units.
double reference_path_error_bound(const SceneModel& m, double duration, int segments);

// A pixel's estimate: the mean weights and each batch's.
struct ReferencePixel {
  RadianceWeights weights{0.0};
  std::vector<RadianceWeights> batches;
  bool busy = true;  // the pilot's verdict
  // The variance of the mean of channel c's value (the radiances applied): the spread of
  // the batches, sum (v_b - v)^2 / (B (B - 1)).
  double variance(const Radiances& r, int c) const;
};

class ReferenceMethod final : public Method {
 public:
  explicit ReferenceMethod(ReferenceSettings settings, Precision precision = Precision::float64);
  std::string name() const override { return "reference"; }
  void begin_frame(const FrameContext& ctx) override;
  RadianceWeights weights(const FrameContext& ctx, int i, int j) const override;
  void shade_tile(const FrameContext& ctx, int x0, int y0, int x1, int y1,
                  Image& out) const override;
  // The variance of each pixel's estimate in the last frame rendered, per channel (as the
  // image's).
  const Image* pixel_variance() const override { return &variance_; }

  // Pixel (i, j) of ctx's frame.
  ReferencePixel pixel(const FrameContext& ctx, int i, int j) const;
  const ReferenceSettings& settings() const { return settings_; }
  // K and W of the current frame's inputs.
  int segments() const { return split_.segments; }
  int windows() const { return split_.windows; }

 private:
  const KernelFrameInputs& inputs(const FrameContext& ctx) const;
  void resize_variance(const FrameContext& ctx) const;

  ReferenceSettings settings_;
  Precision precision_;
  ReferenceTimeSplit split_{0, 0};
  std::unique_ptr<KernelFrameInputs> inputs_;  // built by begin_frame
  mutable Image variance_;
};

// The standard error of an image, sqrt(mean of the values' variances) over all channels of
// the pixels whose mask entry (one per pixel) is nonzero (all without a mask): the expected
// RMSE of the estimate against the exact image.
double image_standard_error(const Image& variance,
                            const std::vector<unsigned char>* mask = nullptr);
// The same over a sequence of frames (the RMSE's set: all frames' values).
double sequence_standard_error(const std::vector<Image>& variance,
                               const std::vector<unsigned char>* mask = nullptr);
// The same with a mask per frame (metrics/metrics.h, compare_sequences; null: every pixel).
double sequence_standard_error(const std::vector<Image>& variance,
                               const std::vector<const std::vector<unsigned char>*>& masks);
// A method's RMSE against the reference with the reference's own noise taken out:
// E[RMSE^2] = error^2 + se^2 for a reference whose noise is independent of the method's
// error, so sqrt(max(0, RMSE^2 - se^2)).
inline double noise_corrected_rmse(double rmse, double se) {
  const double d = rmse * rmse - se * se;
  return d > 0 ? std::sqrt(d) : 0.0;
}

}  // namespace sg
