#include "methods/specaa.h"

#include <vector>

#include "kernel/kernel_double.h"
#include "kernel/kernel_float.h"

namespace sg {
namespace {

// The kernel's specaa entry points in one precision.
struct SpecaaDouble {
  using Sample = kd::SpecaaSample;
  using Params = kd::SpecaaParams;
  static const KernelInputsD& in(const KernelFrameInputs& k) { return k.d(); }
  static Sample sample(const KernelInputsD& in, double px, double py) {
    return kd::specaa_sample(wave_buffer(in), in.frame, px, py);
  }
  static kd::FallbackResult shade(const KernelInputsD& in, const Params& p, const Sample& own,
                                  const Sample& nx, const Sample& ny, int i, int j) {
    return kd::specaa_shade(wave_buffer(in), in.frame, p, own, nx, ny, i, j);
  }
  static kd::FallbackResult pixel(const KernelInputsD& in, const Params& p, int i, int j) {
    return kd::specaa_pixel(wave_buffer(in), in.frame, p, i, j);
  }
};

struct SpecaaFloat {
  using Sample = kf::SpecaaSample;
  using Params = kf::SpecaaParams;
  static const KernelInputsF& in(const KernelFrameInputs& k) { return k.f(); }
  static Sample sample(const KernelInputsF& in, double px, double py) {
    return kf::float_specaa_sample(wave_buffer(in), in.frame, float(px), float(py));
  }
  static kf::FallbackResult shade(const KernelInputsF& in, const Params& p, const Sample& own,
                                  const Sample& nx, const Sample& ny, int i, int j) {
    return kf::float_specaa_shade(wave_buffer(in), in.frame, p, own, nx, ny, i, j);
  }
  static kf::FallbackResult pixel(const KernelInputsF& in, const Params& p, int i, int j) {
    return kf::float_specaa_pixel(wave_buffer(in), in.frame, p, i, j);
  }
};

}  // namespace

RadianceWeights SpecaaMethod::weights(const FrameContext& ctx, int i, int j) const {
  inputs_.check(ctx);
  auto result = [&](const auto& r) {
    if (r.fallback) count_fallback();
    return to_weights(r.weights);
  };
  if (inputs_.precision() == Precision::float32) {
    return result(
        SpecaaFloat::pixel(inputs_.f(), specaa_kernel_params<kf::SpecaaParams>(options_), i, j));
  }
  return result(
      SpecaaDouble::pixel(inputs_.d(), specaa_kernel_params<kd::SpecaaParams>(options_), i, j));
}

template <class K>
void SpecaaMethod::shade_tile_in(const FrameContext& ctx, int x0, int y0, int x1, int y1,
                                 Image& out) const {
  const auto& in = K::in(inputs_);
  const typename K::Params p = specaa_kernel_params<typename K::Params>(options_);
  // The quads that hold the tile: [x0 & ~1, (x1 - 1) | 1] x [y0 & ~1, (y1 - 1) | 1].
  const int qx0 = x0 & ~1, qy0 = y0 & ~1, qx1 = ((x1 - 1) | 1) + 1, qy1 = ((y1 - 1) | 1) + 1;
  const int w = qx1 - qx0;
  thread_local std::vector<typename K::Sample> grid;
  grid.resize(static_cast<size_t>(w) * (qy1 - qy0));
  for (int j = qy0; j < qy1; ++j) {
    for (int i = qx0; i < qx1; ++i)
      grid[(j - qy0) * w + (i - qx0)] = K::sample(in, i + 0.5, j + 0.5);
  }
  auto at = [&](int i, int j) -> const typename K::Sample& {
    return grid[(j - qy0) * w + (i - qx0)];
  };
  for (int j = y0; j < y1; ++j) {
    for (int i = x0; i < x1; ++i) {
      const auto r = K::shade(in, p, at(i, j), at(i ^ 1, j), at(i, j ^ 1), i, j);
      if (r.fallback) count_fallback();
      store_pixel(ctx, out, i, j, to_weights(r.weights));
    }
  }
}

void SpecaaMethod::shade_tile(const FrameContext& ctx, int x0, int y0, int x1, int y1,
                              Image& out) const {
  inputs_.check(ctx);
  if (options_.derivatives == SpecaaDerivatives::analytic) {
    Method::shade_tile(ctx, x0, y0, x1, y1, out);
    return;
  }
  if (inputs_.precision() == Precision::float32) {
    shade_tile_in<SpecaaFloat>(ctx, x0, y0, x1, y1, out);
  } else {
    shade_tile_in<SpecaaDouble>(ctx, x0, y0, x1, y1, out);
  }
}

}  // namespace sg
