#include "methods/microspec.h"

#include <vector>

#include "kernel/kernel_double.h"
#include "kernel/kernel_float.h"
#include "shading/kernel_frame.h"

namespace sg {
namespace {

// The kernel's microspec entry points in one precision.
struct MicrospecDouble {
  using Corner = kd::CornerReflection;
  using Corners = kd::PixelCorners;
  using Params = kd::MicrospecParams;
  static const KernelInputsD& in(const KernelFrameInputs& k) { return k.d(); }
  static Corner corner(const KernelInputsD& in, double px, double py) {
    return kd::microspec_corner(wave_buffer(in), in.frame, px, py);
  }
  static kd::FallbackResult shade(const KernelInputsD& in, const Params& p,
                                  const kd::PixelCorners& c, int i, int j) {
    return kd::microspec_shade(wave_buffer(in), in.frame, p, c, i, j);
  }
  static kd::FallbackResult pixel(const KernelInputsD& in, const Params& p, int i, int j) {
    return kd::microspec_pixel(wave_buffer(in), in.frame, p, i, j);
  }
};

struct MicrospecFloat {
  using Corner = kf::CornerReflection;
  using Corners = kf::PixelCorners;
  using Params = kf::MicrospecParams;
  static const KernelInputsF& in(const KernelFrameInputs& k) { return k.f(); }
  static Corner corner(const KernelInputsF& in, double px, double py) {
    return kf::float_microspec_corner(wave_buffer(in), in.frame, float(px), float(py));
  }
  static kf::FallbackResult shade(const KernelInputsF& in, const Params& p,
                                  const kf::PixelCorners& c, int i, int j) {
    return kf::float_microspec_shade(wave_buffer(in), in.frame, p, c, i, j);
  }
  static kf::FallbackResult pixel(const KernelInputsF& in, const Params& p, int i, int j) {
    return kf::float_microspec_pixel(wave_buffer(in), in.frame, p, i, j);
  }
};

}  // namespace

MicrospecFractions microspec_fractions(const LightModel& light,
                                       const std::array<CornerReflection, 4>& corners,
                                       MicrospecArea area) {
  kd::PixelCorners c;
  for (int k = 0; k < 4; ++k) {
    c.c[k].hit = corners[k].hit;
    c.c[k].at_camera = corners[k].at_camera;
    c.c[k].r = corners[k].r;
    c.c[k].v = corners[k].v;
  }
  const kd::MicrospecFractions k =
      kd::microspec_fractions(light.kernel_light(), c, area == MicrospecArea::exact);
  MicrospecFractions f;
  f.in_light = k.in_light;
  f.below = k.below;
  f.brightest = k.brightest;
  f.degenerate = k.degenerate;
  return f;
}

RadianceWeights MicrospecMethod::weights(const FrameContext& ctx, int i, int j) const {
  inputs_.check(ctx);
  auto result = [&](const auto& r) {
    if (r.fallback) count_fallback();
    return to_weights(r.weights);
  };
  if (inputs_.precision() == Precision::float32) {
    return result(MicrospecFloat::pixel(
        inputs_.f(), microspec_kernel_params<kf::MicrospecParams>(options_), i, j));
  }
  return result(MicrospecDouble::pixel(
      inputs_.d(), microspec_kernel_params<kd::MicrospecParams>(options_), i, j));
}

template <class K>
void MicrospecMethod::shade_tile_in(const FrameContext& ctx, int x0, int y0, int x1, int y1,
                                    Image& out) const {
  const auto& in = K::in(inputs_);
  const typename K::Params p = microspec_kernel_params<typename K::Params>(options_);
  thread_local std::vector<typename K::Corner> grid;
  const int w = x1 - x0 + 1;
  grid.resize(static_cast<size_t>(w) * (y1 - y0 + 1));
  for (int j = y0; j <= y1; ++j) {
    for (int i = x0; i <= x1; ++i)
      grid[(j - y0) * w + (i - x0)] = K::corner(in, i, j);
  }
  for (int j = y0; j < y1; ++j) {
    for (int i = x0; i < x1; ++i) {
      const typename K::Corner* row = &grid[(j - y0) * w + (i - x0)];
      typename K::Corners c;
      c.c[0] = row[0];
      c.c[1] = row[1];
      c.c[2] = row[w + 1];
      c.c[3] = row[w];
      const auto r = K::shade(in, p, c, i, j);
      if (r.fallback) count_fallback();
      store_pixel(ctx, out, i, j, to_weights(r.weights));
    }
  }
}

void MicrospecMethod::shade_tile(const FrameContext& ctx, int x0, int y0, int x1, int y1,
                                 Image& out) const {
  inputs_.check(ctx);
  if (inputs_.precision() == Precision::float32) {
    shade_tile_in<MicrospecFloat>(ctx, x0, y0, x1, y1, out);
  } else {
    shade_tile_in<MicrospecDouble>(ctx, x0, y0, x1, y1, out);
  }
}

}  // namespace sg
