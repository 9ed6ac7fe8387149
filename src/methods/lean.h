// LEAN mapping (`--method lean`): Olano and Baker 2010, "LEAN Mapping", I3D, as Podee et al.
// 2021 compared it (Sec. 5: "We generated a 4K normal map from sine wave data for LEAN
// mapping for each frame"; Table 1's "LEAN" row).
//
// Per frame, at the display time t_f (LEAN filters space, not the shutter: like `point`,
// the frame is an instant):
//  1. The map (lean_map.h, kernel/lean.glsl). The slope (dh/dx, dh/dz) of the waves (Podee
//     Eq. 1 differentiated) is point-sampled at the centre of each level-0 texel, as a
//     normal map generated from sine data, and stored with its second moments: B =
//     (b_x, b_z), M = (b_x^2, b_z^2, b_x b_z). Sampling uses angle addition over the
//     texel grid, cos(theta_j + a x_i) = cos theta_j cos a x_i - sin theta_j sin a x_i
//     (kernel/lean_waves.glsl); the MIP chain is the 2 x 2 box mean of each level from the
//     previous one.
//  2. Waves the grid cannot sample, above 0.5 cycles per texel along x or z
//     (kernel/lean_waves.glsl, lean_wave_amplitude: the projected frequency of the texel
//     grid, kernel/aliasing.glsl), are left out of the
//     map: point samples would alias them into a false pattern. Their covariance (Podee
//     Eq. 3) is added to every lookup, in the place of LEAN's base roughness (Olano and
//     Baker add the base BRDF's own Beckmann variance to M): the slopes finer than a texel.
//  3. Coverage of the unbounded plane (lean_coverage.h). The map is a square over the
//     water visible within a far distance D (`--lean-far`, metres; 0, the default, picks
//     the texel equal to the smallest pixel footprint of the frame and D as far as N
//     texels reach). Beyond the map, lookups return the border moments (GL's
//     CLAMP_TO_BORDER): B = 0, M = Eq. 3 of the mapped waves, the moments of the waves
//     averaged over an unbounded region (the cross terms of different waves average to
//     zero). A pixel beyond the map therefore gets the uniform NDF of Podee Eq. 3 (all
//     waves, with the base term), the limit the coarsest MIP level approaches as the map
//     grows; a lookup that straddles the edge blends the two at the scale of its level,
//     so the edge is a transition one footprint wide, not a seam. Our waves share no
//     common period, so tiling the map would repeat a wrong pattern; a warped (perspective)
//     map would not be a texture on the surface as LEAN assumes.
//  4. Per pixel (kernel/lean.glsl, lean_pixel): the footprint of the pixel centre
//     (kernel/footprint.glsl: the water point, the view, dP/dpx and dP/dpy) gives the texel
//     position and derivatives; the map is filtered there (`--lean-filter trilinear`, the
//     default: GL level of detail; `aniso`: GL anisotropic probes along the footprint's
//     longer side, `--lean-max-aniso`; aniso follows the footprint more closely but did not
//     pay against the reference, which also integrates the shutter:
//     docs/baselines-lean-taa.md). The filtered moments give the Gaussian slope
//     distribution of LEAN, mean B and covariance Sigma = M - B B^T (+ the base term), with
//     correlation (Chermain et al. 2021, Sec. 5). Its NDF-plane centre is n_c = -B; it is
//     shaded as the kernel shades a Gaussian NDF (kernel/ndf_lobe.glsl: Podee Eqs. 11-16,
//     the light disk's mass, the share beyond the horizon, Fresnel at the centre normal).
//     A camera ray that misses the water sees the sky.
//
// Lattice cascades on flat water (`--cascades fields`, shading/cascade_fields.h): a cascade
// is periodic, and its FFT chain is already a LEAN map of it (the means of s and s s^T over
// 2^l blocks of its grid); the map above holds the explicit waves alone, and each pixel adds
// every cascade's filtered mean and covariance over its footprint (the kernel's filter: up
// to 4 boxes along the footprint's longer axis). On displaced water the cascades are their
// lattices' sines among the waves, as for every method that intersects them.
//
// On the kernel (kernel/lean.glsl): the texels, the MIP chain, the filters and the pixel are
// the kernel's functions on both engines. The host places the map (lean_coverage.h) and
// sorts the waves into the map's and the base term's (lean_frame_params); the CPU fills
// level 0 over SIMD lanes (kernel/lean_waves.glsl's terms by angle addition over the texel
// grid: per texel and wave four products, the tables of a block of columns held in the L1
// cache) and the chain in parallel (oneTBB); the GL engine runs the same terms one texel
// an invocation (gl_engine/lean_map_gl.h).
//
// Storage: 5 floats (20 bytes) per texel, N^2 4/3 texels: 447 MB at N = 4096 (kept between
// frames; the output does not depend on earlier frames). docs/baselines-lean-taa.md has
// the build time and the measured quality.
#pragma once

#include <span>
#include <vector>

#include "kernel/kernel_double.h"
#include "methods/fallback.h"
#include "methods/kernel_inputs.h"
#include "methods/lean_coverage.h"
#include "methods/lean_map.h"
#include "methods/method.h"

namespace sg {

// Throws sg::Error naming the flag for a bad option.
void validate_lean_options(const LeanOptions& o);

// The frame's map parameters (kernel/interface.glsl, LeanParams) for the map `region` of
// `waves` (the kernel frame's, of which A, a and b are read; `camera_xz` the frame camera's
// world (x, z), the kernel's origin): the waves the texel grid samples go into the map, the
// others' covariance (Podee Eq. 3) into the base term; the border holds Eq. 3 of the mapped
// ones.
kd::LeanParams lean_frame_params(const LeanMapRegion& region, const LeanOptions& o, int size,
                                 std::span<const kd::Wave> waves, const vec2& camera_xz);
// The kernel frame's waves, in its order (either precision's inputs, read in double).
template <class Inputs>
std::vector<kd::Wave> kernel_frame_waves(const Inputs& in) {
  std::vector<kd::Wave> w(static_cast<size_t>(in.frame.wave_count));
  for (size_t k = 0; k < w.size(); ++k)
    w[k] = kd::Wave{in.A[k], in.a[k], in.b[k], in.theta0[k], in.c[k], in.k[k], in.slope[k]};
  return w;
}
// The parameters in float, for the GL engine and the float kernel.
kf::LeanParams lean_params_float(const kd::LeanParams& p);

// Level 0 of `map` from the frame's waves (kernel/lean_waves.glsl in SIMD lanes): texel (i,
// j) holds the slope of the mapped waves at lean_texel_centre(p, i, j) at the display time.
void fill_lean_map(LeanMap& map, const kd::LeanParams& p, std::span<const kd::Wave> waves);

// Fallback (counted): where the camera is under the surface (a point footprint, no map
// footprint to filter) or the NDF's shading is not finite, the pixel gets the spec's
// radiance along its centre ray (what `point` returns).
class LeanMethod final : public Method, public FallbackCount {
 public:
  // Throws sg::Error naming the flag for a bad option.
  // `precision`: the pixel's kernel (the map is float in either, as a GPU's texture).
  explicit LeanMethod(const LeanOptions& options, Precision precision = Precision::float64,
                      bool cascade_fields = true);
  std::string name() const override { return "lean"; }
  void begin_frame(const FrameContext& ctx) override;
  RadianceWeights weights(const FrameContext& ctx, int i, int j) const override;

  // The frame's map and its parameters (valid after begin_frame).
  const LeanMap& map() const { return map_; }
  const LeanMapRegion& region() const { return region_; }
  const kd::LeanParams& params() const { return params_; }
  // The kernel's inputs of the frame (its waves, camera-relative; --precision double).
  const KernelInputsD& inputs() const { return inputs_->d(); }
  // How many of the frame's waves the map holds (the others are in the base term).
  int mapped_wave_count() const;
  // The filtered moments at a pixel's footprint (without the base term).
  LeanMoments lookup(const kd::Footprint& fp) const;

 private:
  LeanOptions options_;
  KernelFrameInputs fields_, waves_;
  KernelFrameInputs* inputs_ = &fields_;
  LeanMap map_;
  LeanMapRegion region_;
  kd::LeanParams params_{};
  kf::LeanParams params_f_{};
};

}  // namespace sg
