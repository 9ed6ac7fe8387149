#include "methods/reference.h"

#include <algorithm>
#include <cmath>

#include "base/error.h"
#include "kernel/kernel_double.h"
#include "kernel/kernel_float.h"

namespace sg {

double reference_path_error_bound(const SceneModel& m, double duration, int segments) {
  const WaveField& w = m.waves;
  double b4 = 0;
  for (size_t i = 0; i < w.size(); ++i)
    b4 += std::abs(w.A[i]) * std::hypot(w.a[i], w.b[i]) * std::pow(w.c[i], 4);
  const double h = duration / segments;
  return b4 * std::pow(h, 4) / 384.0;
}

ReferenceTimeSplit reference_time_split(const SceneModel& m, double duration) {
  const double tolerance = kReferencePathTolerance * m.light.radius;
  for (int k = 1; k <= kd::kMaxSegments; ++k) {
    if (reference_path_error_bound(m, duration, k) <= tolerance) return {k, 1};
  }
  ReferenceTimeSplit s{kd::kMaxSegments, 1};
  if (m.displaced() || m.scene.camera.moving()) return s;
  // The bound falls as (W K)^-4: start from the root, then step past its rounding.
  const double b = reference_path_error_bound(m, duration, kd::kMaxSegments);
  const double w = std::ceil(std::pow(b / tolerance, 0.25));
  s.windows = static_cast<int>(std::clamp(w, 2.0, double(kReferenceMaxWindows)));
  while (s.windows < kReferenceMaxWindows &&
         reference_path_error_bound(m, duration / s.windows, kd::kMaxSegments) > tolerance) {
    ++s.windows;
  }
  return s;
}

int reference_segments(const SceneModel& m, double duration) {
  return reference_time_split(m, duration).segments;
}

ReferenceSettings reference_settings(const MethodOptions& o) {
  ReferenceSettings rs;
  rs.samples = o.samples_given ? o.samples : kReferenceSamples;
  rs.batches = o.batches;
  rs.only_batch = o.only_batch;
  rs.adaptive = o.adaptive;
  rs.quiet = o.quiet_samples;
  rs.intersect_tolerance = intersect_tolerance_for(o, "reference");
  return rs;
}

double ReferencePixel::variance(const Radiances& r, int c) const {
  const int b = static_cast<int>(batches.size());
  if (b < 2) return 0;
  const double mean = r.apply(weights, c);
  double sum = 0;
  for (const auto& w : batches)
    sum += sqr(r.apply(w, c) - mean);
  return sum / (double(b) * double(b - 1));
}

ReferenceMethod::ReferenceMethod(ReferenceSettings settings, Precision precision)
    : settings_(settings), precision_(precision) {
  if (settings_.batches < 2 || settings_.batches > kd::kMaxBatches) {
    throw Error("--batches: must be in [2, " + std::to_string(kd::kMaxBatches) + "]");
  }
  if (settings_.only_batch < -1 || settings_.only_batch >= settings_.batches) {
    throw Error("--batches: batch " + std::to_string(settings_.only_batch) + " is not one of " +
                std::to_string(settings_.batches));
  }
}

void ReferenceMethod::begin_frame(const FrameContext& ctx) {
  // K and W depend on the waves and the shutter only (reference_time_split).
  const ReferenceTimeSplit k = reference_time_split(ctx.model, ctx.time.duration());
  if (!inputs_ || k.segments != split_.segments || k.windows != split_.windows) {
    inputs_ = std::make_unique<KernelFrameInputs>(
        k.segments, precision_,
        settings_.intersect_tolerance / std::max({settings_.samples.sx, settings_.samples.sy, 1}),
        k.windows);
    split_ = k;
  }
  inputs_->build(ctx);
  resize_variance(ctx);
}

void ReferenceMethod::resize_variance(const FrameContext& ctx) const {
  const int c = ctx.model.scene.grey() ? 1 : 3;
  if (variance_.width != ctx.model.width() || variance_.height != ctx.model.height() ||
      variance_.channels != c) {
    variance_ = Image::with_channels(ctx.model.width(), ctx.model.height(), c);
  }
}

const KernelFrameInputs& ReferenceMethod::inputs(const FrameContext& ctx) const {
  if (!inputs_) {
    throw Error("reference: frame " + std::to_string(ctx.time.frame) +
                " shaded before begin_frame (engine/render.h)");
  }
  inputs_->check(ctx);
  return *inputs_;
}

ReferencePixel ReferenceMethod::pixel(const FrameContext& ctx, int i, int j) const {
  const KernelFrameInputs& in = inputs(ctx);
  ReferencePixel p;
  const SampleCounts& s = settings_.samples;
  if (in.precision() == Precision::float32) {
    kf::ReferenceParams n;
    n.sx = s.sx;
    n.sy = s.sy;
    n.nt = s.st;
    n.batches = settings_.kernel_batches();
    n.first_batch = settings_.first_batch();
    n.adaptive = settings_.adaptive;
    n.quiet_sx = n.quiet_sy = settings_.quiet;
    n.margin = float(settings_.margin);
    const kf::ReferenceResult r =
        kf::float_reference_pixel(wave_buffer(in.f()), in.f().frame, n, i, j);
    p.weights = to_weights(r.weights);
    p.busy = r.busy;
    for (int b = 0; b < n.batches; ++b)
      p.batches.push_back(to_weights(r.batch[b]));
  } else {
    kd::ReferenceParams n;
    n.sx = s.sx;
    n.sy = s.sy;
    n.nt = s.st;
    n.batches = settings_.kernel_batches();
    n.first_batch = settings_.first_batch();
    n.adaptive = settings_.adaptive;
    n.quiet_sx = n.quiet_sy = settings_.quiet;
    n.margin = settings_.margin;
    const kd::ReferenceResult r = kd::reference_pixel(wave_buffer(in.d()), in.d().frame, n, i, j);
    p.weights = r.weights;
    p.busy = r.busy;
    for (int b = 0; b < n.batches; ++b)
      p.batches.push_back(r.batch[b]);
  }
  return p;
}

RadianceWeights ReferenceMethod::weights(const FrameContext& ctx, int i, int j) const {
  return pixel(ctx, i, j).weights;
}

void ReferenceMethod::shade_tile(const FrameContext& ctx, int x0, int y0, int x1, int y1,
                                 Image& out) const {
  // variance_ has ctx's size: begin_frame sized it (pixel() refuses a frame it did not
  // begin).
  for (int j = y0; j < y1; ++j) {
    for (int i = x0; i < x1; ++i) {
      const ReferencePixel p = pixel(ctx, i, j);
      store_pixel(ctx, out, i, j, p.weights);
      for (int c = 0; c < variance_.channels; ++c)
        variance_.at(i, j, c) = static_cast<float>(p.variance(ctx.model.radiances, c));
    }
  }
}

namespace {

void add_variance(const Image& variance, const std::vector<unsigned char>* mask, double& sum,
                  long& n) {
  const size_t c = static_cast<size_t>(variance.channels);
  for (size_t k = 0; k < variance.size(); ++k) {
    if (mask && !(*mask)[k / c]) continue;
    sum += variance.data[k];
    ++n;
  }
}

}  // namespace

double image_standard_error(const Image& variance, const std::vector<unsigned char>* mask) {
  double sum = 0;
  long n = 0;
  add_variance(variance, mask, sum, n);
  return n > 0 ? std::sqrt(sum / double(n)) : 0.0;
}

double sequence_standard_error(const std::vector<Image>& variance,
                               const std::vector<unsigned char>* mask) {
  double sum = 0;
  long n = 0;
  for (const Image& v : variance)
    add_variance(v, mask, sum, n);
  return n > 0 ? std::sqrt(sum / double(n)) : 0.0;
}

double sequence_standard_error(const std::vector<Image>& variance,
                               const std::vector<const std::vector<unsigned char>*>& masks) {
  if (masks.size() != variance.size()) throw Error("one mask per frame expected");
  double sum = 0;
  long n = 0;
  for (size_t f = 0; f < variance.size(); ++f)
    add_variance(variance[f], masks[f], sum, n);
  return n > 0 ? std::sqrt(sum / double(n)) : 0.0;
}

}  // namespace sg
