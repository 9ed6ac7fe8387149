// Ocean lighting with seamless transitions from geometry to BRDF (`--method bruneton`):
// Bruneton, Neyret, Holzschuch 2010 (docs/references.md), Sec. 3-5
// and Algorithm 5.1 in Fig. 9,, on the sum of sines of the scene spec.
// The shading math lives in shading/wave_lod.h (Sec. 3.2) and shading/ocean_brdf.h
// (Sec. 4-5); this file puts them together per pixel, at the frame time t_f.
//
// 1. Filter weights (Sec. 3.2, N_min = 1, N_max = 2.5 as Sec. 7.1: --bruneton-nmin/nmax).
//    The paper projects a screen-space grid on the water at rest; here the grid cell is the
//    pixel, so the projected cell size L and the projected pixel size l are one footprint
//    on the plane y = 0 (rest_plane_footprint), and w_p = w_n = w(N_min, N_max, lambda/l)
//    per wave (l along the wave's direction, wave_lod.h). As the paper's Sec. 7.1, the sums
//    run over the waves that can have w > 0 only: sorted by |k|, a prefix certain from the
//    pixel's footprint (wave_lod.h, SortedWaves), so the cost follows the waves kept.
// 2. Position (displaced geometry). Eq. 2 displaces the grid by trochoids; a sine wave
//    has no horizontal displacement, so the position filter scales the waves' heights: the
//    camera ray is intersected with the field of amplitudes w_p A_i. Flat geometry: the
//    plane y = 0, as the spec says.
// 3. Normal (Eq. 3): from the gradient of the waves weighted by w_n; a normal facing away
//    from the viewer is mirrored, n <- n - 2 (n . v) v (Sec. 3.2).
// 4. BRDF variance (Eq. 4 for sines). The filtered-out part w_r = 1 - w_n of a sine wave of
//    amplitude A and wave vector k has slope covariance (w_r A)^2 / 2 k k^T (variance
//    (w_r A)^2 |k|^2 / 2; the trochoid's 1 - sqrt(1 - k^2 h^2) tends to k^2 h^2 / 2 for
//    small steepness), summed over waves (shading/ndf.h, uniform_ndf_covariance; the
//    waves past the prefix from a suffix sum). The paper
//    uses the wind and cross-wind axes, the principal axes of the Cox-Munk ellipse; these
//    scenes have no wind, so the axes are the principal axes of this covariance: sigma_x^2,
//    sigma_y^2 are its eigenvalues, and no correlation is dropped (the Ross BRDF takes
//    axis-aligned variances). As the paper does (Sec. 5.1), the world-space variances are
//    used in the tangent frame of n, t_x the major axis projected on the tangent plane.
// 5. Sun (Eq. 15): L_sun Omega_sun p(zeta_h) F(v . h) / (4 h_z^4 cos(theta_v) (1 + Lambda_v
//    + Lambda_l)), with Omega_sun = 2 pi (1 - cos(rho)) and F the spec's Fresnel (1 for
//    `none`, Schlick for `schlick`). For a sun smaller than the lobe the paper clamps the
//    variances "to a minimum value" (Sec. 5.1) without printing it; the authors' released
//    shader uses max(sigmaSq, 2e-5), the default of --bruneton-min-variance. (That value is
//    where Eq. 15's peak over a flat mirror, Omega / (8 pi sigma^2 cos(theta_v)), equals the
//    sun's radiance at cos(theta_v) ~ 0.14: a sun 12 degrees high seen near the horizon.)
//    The sun hides the sky behind it (scene spec): the sun term adds F(v . h) x (L_sun -
//    L_sky) for the fraction x of Eq. 15.
// 6. Sky and sea. The spec's sky and sea are constants, and a reflection below the horizon
//    sees the sea. Sec. 5.2 writes the reflected environment as F-bar L-bar and the refracted
//    light as L_sea (1 - F-bar) (Eq. 28), with L-bar the environment filtered by the slope
//    kernel p (Eq. 22, Heaviside dropped as the paper does) and, as in Sec. 6, a non-zero
//    environment below the horizon: here the sea radiance. With the stereographic map of
//    Sec. 5.2 the horizon is the unit circle, so L-bar = (1 - b) L_sky + b L_sea, b the
//    kernel's mass beyond it (below_horizon_fraction, Eq. 27's elliptical footprint), and
//    F-bar L-bar + (1 - F-bar) L_sea is exactly combine_radiance(F-bar, 0, b). F-bar is 1
//    for `fresnel: none`; for `schlick`, the fit of Eq. 26 (default) or the integral of
//    Eq. 24 (--bruneton-fresnel integral).
// A pixel whose ray misses the water (on the rest plane) sees the sky (miss_radiance).
// Lattice cascades on flat water (`--cascades fields`, methods/host_cascades.h): the
// filtered normal takes each cascade's mean slope over the pixel's footprint and the
// variance its covariance there (LEAN's box filter of the FFT chain, in the place of the
// per-wave weights w_n, w_r of steps 1 and 4); the explicit waves as above.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>

#include "methods/host_cascades.h"
#include "methods/host_method.h"
#include "methods/method.h"
#include "shading/wave_lod.h"

namespace sg {

// Fallback (methods/host_method.h): where the camera is under the filtered surface (the hit is the
// camera: no view direction) or the BRDF's value is not finite, the pixel gets the spec's radiance
// along its centre ray (what `point` returns) and is counted.
class BrunetonMethod final : public Method, public HostMethod {
 public:
  explicit BrunetonMethod(BrunetonOptions o, bool cascade_fields = true)
      : options_(o), cascades_(cascade_fields) {}
  std::string name() const override { return "bruneton"; }
  void begin_frame(const FrameContext& ctx) override;
  RadianceWeights weights(const FrameContext& ctx, int i, int j) const override;

 private:
  // The waves the method sums (the scene's, or its explicit ones when the cascades are
  // fields: host_cascades.h) sorted by |k| (wave_lod.h), built once per scene model.
  const SortedWaves& sorted_waves(const SceneModel& m) const;

  BrunetonOptions options_;
  HostCascades cascades_;
  std::unique_ptr<SortedWaves> sorted_;
  mutable std::atomic<uint64_t> sorted_model_{~uint64_t(0)};
  bool sorted_fields_ = false;
};

}  // namespace sg
