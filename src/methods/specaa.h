// Geometric specular anti-aliasing (`--method specaa`): the filtering kernel of Kaplanyan,
// Hill, Patney, Lefohn 2016 (HPG) with the projected-half-vector derivatives of Tokuyoshi
// and Kaplanyan 2019 (I3D), as Chermain et al. 2021 use them (Sec. 4.1, 6.1, Eqs. 7, 20-21;
// docs/references.md). The method is the kernel's (kernel/specaa.glsl: the kernel, its
// constants, its conversion to the NDF plane, the pixel), so both engines run it; this
// class is the CPU engine's side.
//
// Per pixel, at the frame's display time (stateless: one frame, no history):
// 1. The water point seen through the pixel centre (flat or displaced), its view v and
//    analytic normal n (the waves, and a scene's cascades from their fields where they
//    apply, as `point` reads them); the half vector h between v and the light's centre
//    direction L, in the shading frame of n; its projected form h_perp (Chermain Eq. 21).
// 2. The screen-space derivatives of h_perp, as `--specaa-derivatives` says:
//    quad      as a GPU takes them (Chermain Eqs. 20-21 use dFdx/dFdy): in the 2x2 pixel
//              quad holding (i, j), ddx = h_perp(i1 + 1, j) - h_perp(i1, j), i1 = i & ~1,
//              and ddy likewise within the column (fine derivatives: each row and column
//              of the quad has its own). A quad neighbour whose ray misses the water (the
//              quad straddles the horizon line) leaves the pixel to the analytic form.
//              A tile here shares its quads' samples; the GL engine's workgroup shares them
//              in shared memory (gl_engine/shaders/main.glsl).
//    analytic  from the pixel's ray differentials transferred to the water
//              (kernel/footprint.glsl) and the height's Hessian, by the chain rule.
//    The default is `quad`: it is the method as published and as a real-time renderer
//    runs it, the baseline users compare against. `analytic` is the derivative at the
//    pixel centre itself, free of the quad's one-sided differences.
// 3. The kernel (`--specaa-sigma2`, `--specaa-kappa`, `--specaa-kernel`) is the covariance of
//    a Gaussian slope lobe about n: the water is a mirror (zero base roughness), so the
//    kernel alone widens it. Mapped to the NDF plane, reflected about v and linearised on
//    the light plane (kernel/rdf.glsl), its mass in the light disk is the fraction of the
//    pixel that mirrors the light.
// 4. Sky and sea: the lobe's mass beyond the horizon's line on the light plane sees the sea,
//    the rest the sky; F = Fresnel at n . v (the lobe's centre). A centre reflection more
//    than 87 degrees from the light has no light-plane image: the light's mass is 0 there
//    and the below share is the centre's point test.
// A pixel whose centre ray misses the water sees the sky and the light's share of the pixel
// (kernel/disk_coverage.glsl). Fallback (methods/fallback.h): where the camera is under
// the surface (no footprint, no derivatives) or the lobe's shading is not finite, the pixel
// gets the centre ray's radiance (what `point` returns) and is counted.
#pragma once

#include "methods/fallback.h"
#include "methods/kernel_inputs.h"
#include "methods/method.h"
#include "methods/options.h"

namespace sg {

// The kernel's parameters for these options (kd::SpecaaParams or kf::SpecaaParams).
template <class P>
P specaa_kernel_params(const SpecaaOptions& o) {
  P p{};
  p.sigma2 = static_cast<decltype(p.sigma2)>(o.sigma2);
  p.kappa = static_cast<decltype(p.kappa)>(o.kappa);
  p.full_kernel = o.kernel == KernelShape::full;
  p.quad = o.derivatives == SpecaaDerivatives::quad;
  return p;
}

class SpecaaMethod final : public Method, public FallbackCount {
 public:
  explicit SpecaaMethod(SpecaaOptions o, Precision precision = Precision::float64,
                        double intersect_tolerance = 0.0, bool cascade_fields = true)
      : options_(o),
        inputs_(1, precision, intersect_tolerance, 1, cascade_fields, cascade_reads_of("specaa")) {}
  std::string name() const override { return "specaa"; }
  void begin_frame(const FrameContext& ctx) override {
    inputs_.build(ctx);
    reset_fallbacks();
  }
  RadianceWeights weights(const FrameContext& ctx, int i, int j) const override;
  // Quad derivatives share samples: a tile samples its quad-aligned cover once.
  void shade_tile(const FrameContext& ctx, int x0, int y0, int x1, int y1,
                  Image& out) const override;

 private:
  template <class K>
  void shade_tile_in(const FrameContext& ctx, int x0, int y0, int x1, int y1, Image& out) const;
  SpecaaOptions options_;
  KernelFrameInputs inputs_;
};

}  // namespace sg
