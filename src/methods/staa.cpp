#include "methods/staa.h"

#include <algorithm>
#include <vector>

#include "kernel/kernel_float.h"
#include "shading/kernel_table.h"
#include "shading/path_table.h"
#include "shading/swept_footprint.h"

namespace sg {

template <class P>
P staa_kernel_params(const StaaOptions& o) {
  using R = decltype(P{}.alias_start);
  const AliasRange range = alias_range(o);
  P p{};
  p.per_pixel_ndf = o.ndf == NdfMode::per_pixel;
  p.ndf_mean_shift = o.ndf_mean_shift;
  p.kernels = o.kernels;
  p.elongation_threshold = R(o.elongation_threshold);
  p.fallback_riemann = o.fallback == FallbackMode::riemann;
  p.fallback_along_path = o.fallback_along_path;
  p.riemann_cells = o.riemann_cells;
  p.alias_start = R(range.start);
  p.alias_end = R(range.end);
  p.nyquist_max = o.nyquist_max_axis;
  p.footprint = o.footprint == FootprintMode::none       ? 0
                : o.footprint == FootprintMode::gaussian ? 1
                                                         : 2;
  p.curvature_limit = R(o.curvature_limit);
  p.wave_remainder = o.wave_remainder;
  p.smooth_cells = o.smooth_over_normals ? o.smooth_cells : 0;
  return p;
}
template kd::StaaParams staa_kernel_params<kd::StaaParams>(const StaaOptions&);
template kf::StaaParams staa_kernel_params<kf::StaaParams>(const StaaOptions&);

namespace {

template <class Result>
StaaMethod::Shares to_shares(const Result& r) {
  StaaMethod::Shares s;
  s.hit = r.hit;
  s.aliasing = r.aliasing;
  s.temporal = r.temporal;
  s.fallback = r.fallback;
  s.in_light = r.in_light;
  s.below = r.below;
  s.fresnel = r.fresnel;
  s.sky_y = r.sky_y;
  s.weights = RadianceWeights(r.weights);
  return s;
}

// `--footprint exact` on a pixel without aliasing waves: the swept parallelogram
// (shading/swept_footprint.h) for the light; the horizon's share and the smooth terms as
// the Gaussian term has them (over the normals when the kernel took them, else the
// moment-matched parallelogram on the light plane).
template <class Result, class Path>
void finish_exact(const kd::Frame& f, int K, const Result& r, const Path& path,
                  StaaMethod::Shares& s) {
  std::vector<vec2> centre(K + 1);
  std::vector<char> valid(K + 1);
  for (int k = 0; k <= K; ++k) {
    centre[k] = vec2(path.centre[k]);
    valid[k] = path.valid[k];
  }
  const mat2 D(r.exact_D);
  const double R = f.light.tan_radius;
  s.in_light = swept_parallelogram_share(centre, valid, D, R);
  if (r.terms_valid) {
    kd::SmoothTerms smooth;
    smooth.f_above = r.terms.f_above;
    smooth.f_zenith = r.terms.f_zenith;
    smooth.f_horizon = r.terms.f_horizon;
    smooth.above = r.terms.above;
    s.below = 1.0 - smooth.above;
    s.in_light = std::clamp(s.in_light, 0.0, 1.0 - s.below);
    s.weights = RadianceWeights(kd::smooth_weights(f, smooth, s.fresnel, s.in_light));
    return;
  }
  const mat2 cov_fp = D * glm::transpose(D) / 12.0;
  double below = 0;
  int counted = 0;
  for (int k = 0; k <= K; ++k) {
    if (!valid[k]) continue;
    below += kd::horizon_share(f.light, centre[k], cov_fp);
    ++counted;
  }
  s.below = below / counted;
  s.in_light = std::clamp(s.in_light, 0.0, 1.0 - s.below);
  s.weights = RadianceWeights(kd::combine_weights(f, s.fresnel, s.in_light, s.below, s.sky_y));
}

}  // namespace

StaaMethod::StaaMethod(const StaaOptions& o, const PathTables& tables, Precision precision,
                       double intersect_tolerance, bool cascade_fields)
    : o_(o),
      precision_(precision),
      tables_(&tables),
      inputs_(o.segments, precision, intersect_tolerance, 1, cascade_fields),
      params_(staa_kernel_params<kd::StaaParams>(o)),
      params_float_(staa_kernel_params<kf::StaaParams>(o)) {}

void StaaMethod::begin_frame(const FrameContext& ctx) {
  inputs_.build(ctx);
}

StaaMethod::Shares StaaMethod::shares(const FrameContext& ctx, int i, int j) const {
  inputs_.check(ctx);
  const KernelFitTexture& fits = kernel_fit_texture();
  if (precision_ == Precision::float32) {
    kf::StaaPath path;
    const kf::StaaResult r =
        kf::float_staa_pixel(wave_buffer(inputs_.f()), tables_->f_texture(), tables_->s_texture(),
                             tables_->kernel_info_float(), fits.view(), fits.info_float,
                             inputs_.f().frame, params_float_, i, j, path);
    Shares s = to_shares(r);
    if (r.exact_pending) finish_exact(widen(inputs_.f().frame), o_.segments, r, path, s);
    return s;
  }
  kd::StaaPath path;
  const kd::StaaResult r = kd::staa_pixel(wave_buffer(inputs_.d()), tables_->f_texture(),
                                          tables_->s_texture(), tables_->kernel_info(), fits.view(),
                                          fits.info, inputs_.d().frame, params_, i, j, path);
  Shares s = to_shares(r);
  if (r.exact_pending) finish_exact(inputs_.d().frame, o_.segments, r, path, s);
  return s;
}

RadianceWeights StaaMethod::weights(const FrameContext& ctx, int i, int j) const {
  return shares(ctx, i, j).weights;
}

}  // namespace sg
