// LEAN mapping (`--method lean`): Olano and Baker 2010, "LEAN Mapping", I3D, as Podee et al.
// 2021 compared it (Sec. 5: "We generated a 4K normal map from sine wave data for LEAN
// mapping for each frame"; Table 1's "LEAN" row).
//
// Per frame, at the display time t_f (LEAN filters space, not the shutter: like `point`,
// the frame is an instant):
//  1. The map (lean_map.h). The slope (dh/dx, dh/dz) of the waves (scene/waves.h, Podee
//     Eq. 1 differentiated) is point-sampled at the centre of each level-0 texel, as a
//     normal map generated from sine data, and stored with its second moments: B =
//     (b_x, b_z), M = (b_x^2, b_z^2, b_x b_z) (lean_map.h). Sampling uses angle addition
//     over the texel grid, cos(theta_j + a x_i) = cos theta_j cos a x_i - sin theta_j sin
//     a x_i, with the vectorised sums of math/simd_trig.h (tested equal to
//     WaveField::gradient). Built in parallel (oneTBB); the MIP chain is the 2 x 2 box mean
//     of each level from the previous one.
//  2. Waves the grid cannot sample, above 0.5 cycles per texel along x or z
//     (shading/aliasing.h's projected frequency of the texel grid), are left out of the
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
//  4. Per pixel: the footprint of the pixel centre (scene/footprint.h: the water point,
//     the view, dP/dpx and dP/dpy) gives the texel position and derivatives; the map is
//     filtered there (`--lean-filter trilinear`, the default: GL level of detail; `aniso`:
//     GL anisotropic probes along the footprint's longer side, `--lean-max-aniso`; aniso
//     follows the footprint more closely but did not pay against the reference, which
//     also integrates the shutter: docs/baselines-lean-taa.md). The
//     filtered moments give the Gaussian slope distribution of LEAN, mean B and covariance
//     Sigma = M - B B^T (+ the base term), with correlation (Chermain et al. 2021, Sec. 5).
//     Its NDF-plane centre is n_c = -B (shading/ndf.h). shading/ndf_radiance.h maps it to
//     the light plane (Jacobian at the centre, Sigma_r = J Sigma J^T, Podee Eqs. 11-16),
//     takes its mass in the light disk (radius tan rho) as the light fraction, the
//     linearised mass below the horizon as the sea fraction, Fresnel at the centre normal,
//     and combines them (combine_radiance). A camera ray that misses the water sees the sky.
//
// Lattice cascades on flat water (`--cascades fields`, methods/host_cascades.h): a cascade
// is periodic, and its FFT chain is already a LEAN map of it (the means of s and s s^T over
// 2^l blocks of its grid, shading/cascade_fields.h); the map above holds the explicit waves
// alone, and each pixel adds every cascade's filtered mean and covariance over its
// footprint (the kernel's filter: up to 4 boxes along the footprint's longer axis).
//
// Storage: 5 floats (20 bytes) per texel, N^2 4/3 texels: 447 MB at N = 4096 (kept between
// frames; the output does not depend on earlier frames). docs/baselines-lean-taa.md has
// the build time and the measured quality.
#pragma once

#include <span>

#include "methods/host_cascades.h"
#include "methods/host_method.h"
#include "methods/lean_coverage.h"
#include "methods/lean_map.h"
#include "methods/method.h"
#include "scene/footprint.h"

namespace sg {

// Fallback (methods/host_method.h): where the camera is under the surface (a point footprint, no
// map footprint to filter) or the NDF's shading is not finite, the pixel gets the spec's radiance
// along its centre ray (what `point` returns) and is counted.
class LeanMethod final : public Method, public HostMethod {
 public:
  // Throws sg::Error naming the flag for a bad option.
  explicit LeanMethod(const LeanOptions& options, bool cascade_fields = true);
  std::string name() const override { return "lean"; }
  void begin_frame(const FrameContext& ctx) override;
  RadianceWeights weights(const FrameContext& ctx, int i, int j) const override;

  // The frame's map and what shading adds to it (valid after begin_frame).
  const LeanMap& map() const { return map_; }
  const LeanMapRegion& region() const { return region_; }
  const mat2& base_covariance() const { return base_cov_; }
  // 1 for the waves in the map, 0 for those in the base term.
  const std::vector<double>& mapped_waves() const { return mapped_; }
  // The filtered moments at a pixel footprint (without the base term).
  LeanMoments lookup(const PixelFootprint& fp) const;

 private:
  LeanOptions options_;
  LeanMap map_;
  LeanMapRegion region_;
  mat2 base_cov_{0.0};
  std::vector<double> mapped_;
  HostCascades cascades_;
};

// Level 0 of `map` from the waves weighted by `weights` at time t: texel (i, j) holds the
// slope at (x, z) = region.origin + (i + 1/2, j + 1/2) region.texel.
void fill_lean_map_from_waves(LeanMap& map, const LeanMapRegion& region, const WaveField& waves,
                              std::span<const double> weights, double t);

}  // namespace sg
