#include "methods/lean.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "base/error.h"
#include "kernel/cpu/wave_sums.h"
#include "kernel/kernel_float.h"

namespace sg {

void validate_lean_options(const LeanOptions& o) {
  if (o.size < 2 || o.size > 8192 || (o.size & (o.size - 1)) != 0) {
    throw Error("--lean-size: must be a power of two in [2, 8192] (got " + std::to_string(o.size) +
                ")");
  }
  if (!(o.far >= 0) || !std::isfinite(o.far)) {
    throw Error("--lean-far: must be a finite distance >= 0 (0: automatic)");
  }
  if (o.max_aniso < 1 || o.max_aniso > 64) throw Error("--lean-max-aniso: must be in [1, 64]");
}

kd::LeanParams lean_frame_params(const LeanMapRegion& region, const LeanOptions& o, int size,
                                 std::span<const kd::Wave> waves, const vec2& camera_xz) {
  kd::LeanParams p{};
  p.origin = region.origin - camera_xz;
  p.texel = region.texel;
  p.size = size;
  p.levels = kd::lean_level_count(size);
  p.empty = region.empty;
  p.aniso = o.filter == LeanFilter::aniso;
  p.max_aniso = o.max_aniso;
  // The border (the mapped waves' Eq. 3, LEAN's order xx, zz, xz) and the base term (the
  // others', ndf.glsl's order xx, xz, zz).
  kd::NdfMoments mapped = kd::ndf_zero(), base = kd::ndf_zero();
  for (const kd::Wave& w : waves) {
    const bool in_map = kd::lean_wave_amplitude(w, p.texel) != kd::vec2(0.0) || w.A == 0.0;
    kd::ndf_add_uniform(in_map ? mapped : base, w.A, kd::vec2(w.a, w.b));
  }
  p.border = kd::vec3(mapped.cov.x, mapped.cov.z, mapped.cov.y);
  p.base = base.cov;
  return p;
}

kf::LeanParams lean_params_float(const kd::LeanParams& p) {
  kf::LeanParams f{};
  f.origin = kf::vec2(p.origin);
  f.texel = static_cast<float>(p.texel);
  f.size = p.size;
  f.levels = p.levels;
  f.empty = p.empty;
  f.aniso = p.aniso;
  f.max_aniso = p.max_aniso;
  f.border = kf::vec3(p.border);
  f.base = kf::vec3(p.base);
  return f;
}

void fill_lean_map(LeanMap& map, const kd::LeanParams& p, std::span<const kd::Wave> waves) {
  const int n = map.size();
  LeanTexel* texels = map.level0();
  // The mapped waves and their slope amplitudes (lean_wave_amplitude).
  std::vector<kd::Wave> mapped;
  std::vector<double> amplitude;
  for (const kd::Wave& w : waves) {
    const kd::vec2 a = kd::lean_wave_amplitude(w, p.texel);
    if (a == kd::vec2(0.0)) continue;
    mapped.push_back(w);
    amplitude.push_back(a.x);
    amplitude.push_back(a.y);
  }
  const int nk = static_cast<int>(mapped.size());
  if (nk == 0) {
    std::fill(texels, texels + static_cast<size_t>(n) * n, LeanTexel{});
    return;
  }
  // Columns in blocks of `bw` (padded to the lanes' multiple, `width`): the (cos, sin) of each
  // wave's column phase as [block][k][column], so that one block's table (at most 24 KiB)
  // stays in the L1 cache while the rows of a task run over it.
  int bw = 8;
  while (bw < 128 && static_cast<size_t>(2 * bw) * nk * 2 * sizeof(double) <= 24576)
    bw *= 2;
  bw = std::min(n, bw);
  const int pad = wave_simd::kLanePadding;
  const int width = (bw + pad - 1) / pad * pad;
  const int blocks = n / bw;
  std::vector<double> col_c(static_cast<size_t>(blocks) * nk * width, 0.0);
  std::vector<double> col_s(col_c.size(), 0.0);
  tbb::parallel_for(0, blocks, [&](int blk) {
    for (int k = 0; k < nk; ++k) {
      for (int q = 0; q < bw; ++q) {
        const double x = kd::lean_texel_centre(p, blk * bw + q, 0).x;
        const double th = kd::lean_column_phase(mapped[k], x);
        const size_t at = (static_cast<size_t>(blk) * nk + k) * width + q;
        col_c[at] = std::cos(th);
        col_s[at] = std::sin(th);
      }
    }
  });
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 32), [&](const tbb::blocked_range<int>& r) {
    const int rows = r.end() - r.begin();
    // Per row: the (cos, sin) of each wave's row phase.
    std::vector<double> row(static_cast<size_t>(rows) * nk * 2);
    for (int jr = 0; jr < rows; ++jr) {
      const double z = kd::lean_texel_centre(p, 0, r.begin() + jr).y;
      for (int k = 0; k < nk; ++k) {
        const double th = kd::lean_row_phase(mapped[k], z);
        row[(static_cast<size_t>(jr) * nk + k) * 2] = std::cos(th);
        row[(static_cast<size_t>(jr) * nk + k) * 2 + 1] = std::sin(th);
      }
    }
    std::vector<double> out(static_cast<size_t>(2) * rows * width);
    for (int blk = 0; blk < blocks; ++blk) {
      const size_t off = static_cast<size_t>(blk) * nk * width;
      kd::lean_block_slopes(amplitude.data(), nk, row.data(), rows, col_c.data() + off,
                            col_s.data() + off, width, out.data());
      for (int jr = 0; jr < rows; ++jr) {
        LeanTexel* dst = texels + static_cast<size_t>(r.begin() + jr) * n + blk * bw;
        const double* gx = out.data() + static_cast<size_t>(2 * jr) * width;
        const double* gz = gx + width;
        for (int q = 0; q < bw; ++q)
          dst[q] = to_texel(kd::lean_moments_of_slope(kd::vec2(gx[q], gz[q])));
      }
    }
  });
}

LeanMethod::LeanMethod(const LeanOptions& o, Precision precision, bool cascade_fields)
    : options_(o),
      fields_(1, precision, 0.0, 1, cascade_fields, cascade_reads_of("lean")),
      waves_(1, precision, 0.0, 1, false) {
  validate_lean_options(o);
}

void LeanMethod::begin_frame(const FrameContext& ctx) {
  const SceneModel& m = ctx.model;
  inputs_ = m.displaced() ? &waves_ : &fields_;
  inputs_->build(ctx);
  reset_fallbacks();
  const bool dbl = inputs_->precision() == Precision::float64;
  const std::vector<kd::Wave> waves =
      dbl ? kernel_frame_waves(inputs_->d()) : kernel_frame_waves(inputs_->f());
  const glm::dvec3 origin = dbl ? inputs_->d().origin : inputs_->f().origin;
  region_ = lean_map_region(m, options_.size, options_.far);
  params_ = lean_frame_params(region_, options_, options_.size, waves, vec2(origin.x, origin.z));
  params_f_ = lean_params_float(params_);
  map_.allocate(options_.size);
  map_.set_border(params_.border);
  if (region_.empty) return;  // no visible water: the map is never looked up
  fill_lean_map(map_, params_, waves);
  map_.build_mips();
}

int LeanMethod::mapped_wave_count() const {
  int n = 0;
  for (const kd::Wave& w : kernel_frame_waves(inputs()))
    n += kd::lean_wave_amplitude(w, params_.texel) != kd::vec2(0.0);
  return n;
}

LeanMoments LeanMethod::lookup(const kd::Footprint& fp) const {
  return kd::lean_footprint_moments(map_.texels(), params_, fp);
}

RadianceWeights LeanMethod::weights(const FrameContext& ctx, int i, int j) const {
  inputs_->check(ctx);
  auto result = [&](const auto& r) {
    if (r.fallback) count_fallback();
    return to_weights(r.weights);
  };
  const kd::MapTexels map = map_.texels();
  if (inputs_->precision() == Precision::float32) {
    const KernelInputsF& in = inputs_->f();
    return result(kf::float_lean_pixel(wave_buffer(in), in.frame, map, params_f_, i, j));
  }
  const KernelInputsD& in = inputs_->d();
  return result(kd::lean_pixel(wave_buffer(in), in.frame, map, params_, i, j));
}

}  // namespace sg
