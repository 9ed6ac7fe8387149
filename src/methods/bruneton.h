// Ocean lighting with seamless transitions from geometry to BRDF (`--method bruneton`):
// Bruneton, Neyret, Holzschuch 2010 (docs/references.md), Sec. 3-5
// and Algorithm 5.1 in Fig. 9, on the sum of sines of the scene spec.
// The method runs on the shading kernel (kernel/bruneton.glsl, the pixel; kernel/ocean_brdf.glsl,
// the BRDF and lighting of Sec. 4-5), so both engines run it, in double or float; this file
// gives it the frame's kernel inputs. What it does per pixel, at the display time:
//
// 1. Filter weights (Sec. 3.2, N_min = 1, N_max = 2.5 as Sec. 7.1: --bruneton-nmin/nmax).
//    The paper projects a screen-space grid on the water at rest; here the grid cell is the
//    pixel, so the projected cell size L and the projected pixel size l are one footprint
//    on the plane y = 0 (rest_plane_footprint), and w_p = w_n = w(N_min, N_max, lambda/l)
//    per wave (l along the wave's direction). As the paper's Sec. 7.1, the sums run over
//    the waves that can have w > 0 only: the kernel's wave buffer is sorted by |k|, and a
//    prefix is certain from the pixel's footprint, so the cost follows the waves kept.
// 2. Position (displaced geometry). Eq. 2 displaces the grid by trochoids; a sine wave
//    has no horizontal displacement, so the position filter scales the waves' heights: the
//    camera ray is intersected with the field of amplitudes w_p A_i (the kernel's march with
//    the filtered amplitudes' bounds). Flat geometry: the plane y = 0, as the spec says.
// 3. Normal (Eq. 3): from the gradient of the waves weighted by w_n; a normal facing away
//    from the viewer is mirrored, n <- n - 2 (n . v) v (Sec. 3.2).
// 4. BRDF variance (Eq. 4 for sines). The filtered-out part w_r = 1 - w_n of a sine wave of
//    amplitude A and wave vector k has slope covariance (w_r A)^2 / 2 k k^T (variance
//    (w_r A)^2 |k|^2 / 2; the trochoid's 1 - sqrt(1 - k^2 h^2) tends to k^2 h^2 / 2 for
//    small steepness), summed over waves (kernel/ndf.glsl, ndf_add_uniform; the waves past
//    the prefix from the wave buffer's suffix sums). The paper
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
//    Eq. 24 (--bruneton-fresnel integral: 40 x 40 Gauss-Legendre nodes).
// A pixel whose ray misses the water (on the rest plane) sees the sky (miss_radiance).
// Lattice cascades on flat water (`--cascades fields`, shading/cascade_fields.h): the
// filtered normal takes each cascade's mean slope over the pixel's footprint and the
// variance its covariance there (LEAN's box filter of the FFT chain, in the place of the
// per-wave weights w_n, w_r of steps 1 and 4); the explicit waves as above. On displaced
// water the lattices are sines among the waves, each filtered by its own weight.
// Fallback (methods/fallback.h, FallbackCount): where the camera is under the filtered
// surface (the hit is the camera: no view direction) or the shading is not finite, the
// pixel gets the spec's radiance along its centre ray (what `point` returns) and is counted.
#pragma once

#include "methods/fallback.h"
#include "methods/kernel_inputs.h"
#include "methods/method.h"
#include "methods/options.h"

namespace sg {

template <class P>
P bruneton_kernel_params(const BrunetonOptions& o) {
  P p{};
  p.n_min = static_cast<decltype(p.n_min)>(o.n_min);
  p.n_max = static_cast<decltype(p.n_max)>(o.n_max);
  p.min_variance = static_cast<decltype(p.min_variance)>(o.min_variance);
  p.fresnel_integral = o.fresnel == BrunetonFresnel::integral;
  return p;
}

class BrunetonMethod final : public Method, public FallbackCount {
 public:
  explicit BrunetonMethod(BrunetonOptions o, Precision precision = Precision::float64,
                          bool cascade_fields = true)
      : options_(o),
        fields_(1, precision, 0.0, 1, cascade_fields, cascade_reads_of("bruneton")),
        waves_(1, precision, 0.0, 1, false) {}
  std::string name() const override { return "bruneton"; }
  // The cascades from their fields on flat water only (shading/cascade_fields.h).
  void begin_frame(const FrameContext& ctx) override {
    inputs_ = ctx.model.displaced() ? &waves_ : &fields_;
    inputs_->build(ctx);
    reset_fallbacks();
  }
  RadianceWeights weights(const FrameContext& ctx, int i, int j) const override;

 private:
  BrunetonOptions options_;
  KernelFrameInputs fields_, waves_;
  KernelFrameInputs* inputs_ = &fields_;
};

}  // namespace sg
