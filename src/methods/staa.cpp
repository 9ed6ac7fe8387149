#include "methods/staa.h"

#include <algorithm>
#include <vector>

#include "kernel/kernel_double.h"
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
  p.per_pixel_ndf = per_pixel_ndf(o);
  p.ndf_mean_shift = o.ndf_mean_shift;
  p.kernels = rdf_kernels(o);
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
  p.fold_cells = R(o.fold_cells);
  p.wave_remainder = o.wave_remainder;
  p.smooth_cells = o.smooth_over_normals ? o.smooth_cells : 0;
  p.rdf_at_light = rdf_at_light(o);
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

// `--footprint exact` on a pixel without aliasing waves: the light's share of the swept
// parallelogram (shading/swept_footprint.h), in double; the kernel ends the pixel
// (staa.glsl, staa_exact_result).
template <class Path>
double exact_light_share(double tan_radius, int K, const mat2& D, const Path& path) {
  std::vector<vec2> centre(K + 1);
  std::vector<char> valid(K + 1);
  for (int k = 0; k <= K; ++k) {
    centre[k] = vec2(path.centre[k]);
    valid[k] = path.valid[k];
  }
  return swept_parallelogram_share(centre, valid, D, tan_radius);
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
    if (!r.exact_pending) return to_shares(r);
    const kf::Frame& f = inputs_.f().frame;
    const double in_light =
        exact_light_share(f.light.tan_radius, o_.segments, mat2(r.exact_D), path);
    return to_shares(kf::float_staa_exact_result(f, path, r, kf::real(in_light)));
  }
  kd::StaaPath path;
  const kd::StaaResult r = kd::staa_pixel(wave_buffer(inputs_.d()), tables_->f_texture(),
                                          tables_->s_texture(), tables_->kernel_info(), fits.view(),
                                          fits.info, inputs_.d().frame, params_, i, j, path);
  if (!r.exact_pending) return to_shares(r);
  const kd::Frame& f = inputs_.d().frame;
  return to_shares(kd::staa_exact_result(
      f, path, r, exact_light_share(f.light.tan_radius, o_.segments, mat2(r.exact_D), path)));
}

RadianceWeights StaaMethod::weights(const FrameContext& ctx, int i, int j) const {
  return shares(ctx, i, j).weights;
}

}  // namespace sg
