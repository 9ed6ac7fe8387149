// The kernel's functions in float precision (kernel/kernel_float.h), and its passes over
// the waves in SIMD lanes (kernel/cpu/lane_passes.inc), compiled for each instruction set
// Highway targets and dispatched at run time. This translation unit is compiled with
// -fsingle-precision-constant (src/CMakeLists.txt): it must include nothing but glm,
// Highway and the kernel, whose literals are then floats, as in GLSL.
#ifndef SG_KERNEL_FLOAT_CPP_ONCE
#define SG_KERNEL_FLOAT_CPP_ONCE
#include "kernel/kernel_float.h"
#include "kernel/cpu/wave_sums.h"

namespace sg::kf {

#define SG_CPU_WAVE_SUMS
#include "kernel/kernel.glsl"
#undef SG_CPU_WAVE_SUMS

vec4 float_point_pixel(const WaveBuffer& waves, const Frame& f, int i, int j) {
  return point_pixel(waves, f, i, j);
}
vec4 float_stratified_pixel(const WaveBuffer& waves, const Frame& f, const SampleCounts& n, int i,
                            int j) {
  return stratified_pixel(waves, f, n, i, j);
}
ReferenceResult float_reference_pixel(const WaveBuffer& waves, const Frame& f,
                                      const ReferenceParams& n, int i, int j) {
  return reference_pixel(waves, f, n, i, j);
}
vec4 float_staa_temporal_pixel(const WaveBuffer& waves, const Frame& f, int i, int j) {
  return staa_temporal_pixel(waves, f, i, j);
}
SpecaaSample float_specaa_sample(const WaveBuffer& waves, const Frame& f, real px, real py) {
  return specaa_sample(waves, f, px, py);
}
FallbackResult float_specaa_shade(const WaveBuffer& waves, const Frame& f, const SpecaaParams& p,
                                  const SpecaaSample& own, const SpecaaSample& nx,
                                  const SpecaaSample& ny, int i, int j) {
  return specaa_shade(waves, f, p, own, nx, ny, i, j);
}
FallbackResult float_specaa_pixel(const WaveBuffer& waves, const Frame& f, const SpecaaParams& p,
                                  int i, int j) {
  return specaa_pixel(waves, f, p, i, j);
}
CornerReflection float_microspec_corner(const WaveBuffer& waves, const Frame& f, real px, real py) {
  return microspec_corner(waves, f, px, py);
}
FallbackResult float_microspec_shade(const WaveBuffer& waves, const Frame& f,
                                     const MicrospecParams& p, const PixelCorners& c, int i,
                                     int j) {
  return microspec_shade(waves, f, p, c, i, j);
}
FallbackResult float_microspec_pixel(const WaveBuffer& waves, const Frame& f,
                                     const MicrospecParams& p, int i, int j) {
  return microspec_pixel(waves, f, p, i, j);
}
FallbackResult float_bruneton_pixel(const WaveBuffer& waves, const Frame& f,
                                    const BrunetonParams& p, int i, int j) {
  return bruneton_pixel(waves, f, p, i, j);
}
FallbackResult float_lean_pixel(const WaveBuffer& waves, const Frame& f, const MapTexels& map,
                                const LeanParams& p, int i, int j) {
  return lean_pixel(waves, f, map, p, i, j);
}
TaaSample float_taa_sample(const WaveBuffer& waves, const Frame& f, const TaaParams& p, int i,
                           int j) {
  return taa_sample(waves, f, p, i, j);
}
TaaResolved float_taa_resolve_pixel(const ImagePlanes& current, const ImagePlanes& history,
                                    const TaaResolveParams& p, bool has_history, vec2 motion, int i,
                                    int j) {
  return taa_resolve_pixel(current, history, p, has_history, motion, i, j);
}
StaaResult float_staa_pixel(const WaveBuffer& waves, const R32Texture2D& table_f,
                            const R32Texture3D& table_s, const PathTableInfo& tinfo,
                            const R32Texture2D& fits, const KernelFitInfo& finfo, const Frame& f,
                            const StaaParams& p, int i, int j, StaaPath& path) {
  return staa_pixel(waves, table_f, table_s, tinfo, fits, finfo, f, p, i, j, path);
}
StaaResult float_staa_exact_result(const Frame& f, const StaaPath& path, const StaaResult& r,
                                   real in_light) {
  return staa_exact_result(f, path, r, in_light);
}
bool float_staa_frame_terms(const Frame& f) {
  return staa_frame_terms(f);
}
bool float_staa_frame_light_sets(const Frame& f) {
  return staa_frame_light_sets(f);
}
bool float_staa_frame_swept_cells(const Frame& f) {
  return staa_frame_swept_cells(f);
}
real float_erfc(real x) {
  return erfc(x);
}
real float_exp_minus_one(real u) {
  return exp_minus_one(u);
}
vec2 float_sky_shares(const Frame& f, real y) {
  return sky_shares(f, y);
}
real float_normal_quantile(real p) {
  return normal_quantile(p);
}
SmoothTerms float_smooth_terms(const Frame& f, vec2 mu, mat2 cov, vec3 v) {
  return smooth_terms(f, mu, cov, v);
}
real float_gaussian_disk_mass_along(vec2 a, vec2 b, mat2 cov, real R) {
  return gaussian_disk_mass_along(a, b, cov, R);
}
real float_light_pixel_coverage(const Camera& c, const Light& l, int i, int j) {
  return light_pixel_coverage(c, l, i, j);
}
real float_water_height(const WaveBuffer& waves, const Frame& f, real x, real z, real dt) {
  return water_height(waves, f, x, z, dt);
}
vec2 float_water_gradient(const WaveBuffer& waves, const Frame& f, real x, real z, real dt) {
  return water_gradient(waves, f, x, z, dt);
}
vec2 float_water_height_slope(const WaveBuffer& waves, const Frame& f, int lo, int hi, real x,
                              real z, real dt, real ux, real uz) {
  return water_height_slope(waves, f, lo, hi, x, z, dt, ux, uz);
}

void float_path_gradients(const WaveBuffer& waves, const Frame& f, vec3 point, const vec2* points,
                          vec2* g) {
  PathGradients p;
  if (points == nullptr) {
    p = path_gradients(waves, f, point);
  } else {
    PathViews v = path_views_fixed(point, vec3(0.0, 1.0, 0.0));
    v.moving = true;
    for (int k = 0; k < f.segments; ++k)
      v.point[k] = points[k];
    p = path_gradients_moving(waves, f, v);
  }
  for (int k = 0; k <= f.segments; ++k)
    g[k] = p.g[k];
}

void float_path_derivatives(const WaveBuffer& waves, const Frame& f, vec3 point, real dt, vec2* g,
                            vec2* dg) {
  const PathDerivatives p = path_derivatives(waves, f, point, dt);
  for (int k = 0; k <= f.segments; ++k) {
    g[k] = p.g[k];
    dg[k] = p.dg[k];
  }
}

}  // namespace sg::kf
#endif

// Highway's per-target compilation (kernel/cpu/lane_targets.inc): this file is included
// again once per instruction set.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "kernel/cpu/kernel_float.cpp"
#define SG_LANE_KERNEL kf
#define SG_LANE_REAL float
#include "kernel/cpu/lane_targets.inc"
