// The shading kernel compiled as C++ in float precision (`--precision float`: what a GPU
// computes), reached through these entry points. Their definitions are in
// kernel/cpu/kernel_float.cpp, the one translation unit that includes the kernel's
// functions in float, compiled with -fsingle-precision-constant so that every literal is
// a float there, as in GLSL; the structs are those of kernel/kernel_types.h.
#pragma once

#include "kernel/kernel_types.h"

namespace sg::kf {

vec4 float_point_pixel(const WaveBuffer& waves, const Frame& f, int i, int j);
vec4 float_stratified_pixel(const WaveBuffer& waves, const Frame& f, const SampleCounts& n, int i,
                            int j);
ReferenceResult float_reference_pixel(const WaveBuffer& waves, const Frame& f,
                                      const ReferenceParams& n, int i, int j);
vec4 float_staa_temporal_pixel(const WaveBuffer& waves, const Frame& f, int i, int j);
// `specaa` (kernel/specaa.glsl): a sample, a pixel from its sample and its quad
// neighbours', a pixel alone.
SpecaaSample float_specaa_sample(const WaveBuffer& waves, const Frame& f, real px, real py);
FallbackResult float_specaa_shade(const WaveBuffer& waves, const Frame& f, const SpecaaParams& p,
                                  const SpecaaSample& own, const SpecaaSample& nx,
                                  const SpecaaSample& ny, int i, int j);
FallbackResult float_specaa_pixel(const WaveBuffer& waves, const Frame& f, const SpecaaParams& p,
                                  int i, int j);
// `microspec` (kernel/microspec.glsl): a corner, a pixel from its corners, a pixel alone.
CornerReflection float_microspec_corner(const WaveBuffer& waves, const Frame& f, real px, real py);
FallbackResult float_microspec_shade(const WaveBuffer& waves, const Frame& f,
                                     const MicrospecParams& p, const PixelCorners& c, int i, int j);
FallbackResult float_microspec_pixel(const WaveBuffer& waves, const Frame& f,
                                     const MicrospecParams& p, int i, int j);
// `bruneton` (kernel/bruneton.glsl): a pixel.
FallbackResult float_bruneton_pixel(const WaveBuffer& waves, const Frame& f,
                                    const BrunetonParams& p, int i, int j);
// `lean` (kernel/lean.glsl): a pixel from the frame's map.
FallbackResult float_lean_pixel(const WaveBuffer& waves, const Frame& f, const MapTexels& map,
                                const LeanParams& p, int i, int j);
// `taa` (kernel/taa.glsl): a pixel's sample and motion; a pixel's resolve.
TaaSample float_taa_sample(const WaveBuffer& waves, const Frame& f, const TaaParams& p, int i,
                           int j);
TaaResolved float_taa_resolve_pixel(const ImagePlanes& current, const ImagePlanes& history,
                                    const TaaResolveParams& p, bool has_history, vec2 motion, int i,
                                    int j);
StaaResult float_staa_pixel(const WaveBuffer& waves, const R32Texture2D& table_f,
                            const R32Texture3D& table_s, const PathTableInfo& tinfo,
                            const R32Texture2D& fits, const KernelFitInfo& finfo, const Frame& f,
                            const StaaParams& p, int i, int j, StaaPath& path);
StaaResult float_staa_exact_result(const Frame& f, const StaaPath& path, const StaaResult& r,
                                   real in_light);
// Whether frame f's water needs staa's smooth terms (kernel/staa.glsl, staa_frame_terms):
// the GL engine compiles staa's program for the answer (gl_engine/kernel_program.h).
bool float_staa_frame_terms(const Frame& f);
// Whether frame f's light disk reaches below the horizon (kernel/staa.glsl,
// staa_frame_light_sets): likewise compiled in.
bool float_staa_frame_light_sets(const Frame& f);
// Whether frame f's camera moves through a shutter (kernel/staa.glsl,
// staa_frame_swept_cells): likewise compiled in.
bool float_staa_frame_swept_cells(const Frame& f);
// For the tests: the replacements of functions GLSL lacks, and the sums over the waves
// (vectorised when the buffer carries arrays, else the kernel's loops).
real float_erfc(real x);
real float_normal_quantile(real p);
real float_exp_minus_one(real u);
vec2 float_sky_shares(const Frame& f, real y);
SmoothTerms float_smooth_terms(const Frame& f, vec2 mu, mat2 cov, vec3 v);
real float_gaussian_disk_mass_along(vec2 a, vec2 b, mat2 cov, real R);
real float_light_pixel_coverage(const Camera& c, const Light& l, int i, int j);
real float_water_height(const WaveBuffer& waves, const Frame& f, real x, real z, real dt);
vec2 float_water_gradient(const WaveBuffer& waves, const Frame& f, real x, real z, real dt);
vec2 float_water_height_slope(const WaveBuffer& waves, const Frame& f, int lo, int hi, real x,
                              real z, real dt, real ux, real uz);
// The reflection path's gradients g[0..K] at `point` (kernel/reflection_path.glsl); with
// `points`, the instants' own points p_0 .. p_{K-1} (a moving camera, displaced water).
void float_path_gradients(const WaveBuffer& waves, const Frame& f, vec3 point, const vec2* points,
                          vec2* g);
// The reference's path (kernel/reference.glsl): g[0..K] and dg[0..K].
void float_path_derivatives(const WaveBuffer& waves, const Frame& f, vec3 point, real dt, vec2* g,
                            vec2* dg);

}  // namespace sg::kf
