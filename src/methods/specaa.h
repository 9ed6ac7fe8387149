// Geometric specular anti-aliasing (`--method specaa`): the filtering kernel of Kaplanyan,
// Hill, Patney, Lefohn 2016 (HPG) with the projected-half-vector derivatives of Tokuyoshi
// and Kaplanyan 2019 (I3D), as Chermain et al. 2021 use them (Sec. 4.1,
// 6.1, Eqs. 7, 20-21; docs/references.md). The kernel
// itself, its constants and its conversion to the NDF plane: shading/specular_aa.h.
//
// Per pixel, at the frame time t_f (stateless: one frame, no history):
// 1. The water point seen through the pixel centre (flat or displaced), its view v and
//    analytic normal n; the half vector h between v and the light's centre direction L,
//    in the shading frame of n; its projected form h_perp (Chermain Eq. 21).
// 2. The screen-space derivatives of h_perp, as `--specaa-derivatives` says:
//    quad      as a GPU takes them (Chermain Eqs. 20-21 use dFdx/dFdy): in the 2x2 pixel
//              quad holding (i, j), ddx = h_perp(i1 + 1, j) - h_perp(i1, j), i1 = i & ~1,
//              and ddy likewise within the column (fine derivatives: each row and column
//              of the quad has its own). A quad neighbour whose ray misses the water (the
//              quad straddles the horizon line) leaves the pixel to the analytic form.
//    analytic  from the pixel's ray differentials transferred to the water (footprint.h)
//              and the Hessian of the height field (WaveField::hessian), by the chain rule
//              (projected_half_vector_derivative).
//    The default is `quad`: it is the method as published and as a real-time renderer
//    runs it, the baseline users compare against. `analytic` is the derivative at the
//    pixel centre itself, free of the quad's one-sided differences.
// 3. The kernel (`--specaa-sigma2`, `--specaa-kappa`, `--specaa-kernel`) is the covariance of
//    a Gaussian slope lobe about n: the water is a mirror (zero base roughness), so the
//    kernel alone widens it. Mapped to the NDF plane (J_G), reflected about v and
//    linearised on the light plane (shading/rdf.h: Phi(n_c), J_c, Sigma_r = J_c Sigma
//    J_c^T), its mass in the light disk of radius tan(rho) (shading/gaussian_disk.h) is
//    the fraction of the pixel that mirrors the light.
// 4. Sky and sea: the lobe's mass below the horizon (a line of the light plane,
//    LightModel::elevation_on_plane; a half-plane mass of the same Gaussian) sees the sea,
//    the rest the sky; combine_radiance with F = Fresnel at n . v (the lobe's centre).
//    A centre reflection more than 87 degrees from the light (r . L < 0.05) has no light
//    plane image: the light's mass is then taken as 0 (a lobe within the kappa clamp puts
//    less than 1e-6 of its mass that far) and the below fraction is the centre's point
//    test.
// A pixel whose centre ray misses the water sees the sky (miss_radiance), as `point`.
#pragma once

#include "methods/host_cascades.h"
#include "methods/host_method.h"
#include "methods/method.h"
#include "scene/footprint.h"
#include "shading/specular_aa.h"

namespace sg {

// What specaa knows of one pixel centre.
struct SpecaaSample {
  bool hit = false;
  PixelFootprint footprint;
  vec2 g{0};  // height gradient at the point
  ShadingFrame frame;
  vec2 h_perp{0};
};
// The sample at image-plane point (px, py) on `water` (shading/water_geometry.h).
// `cascades`: the frame's cascade fields (methods/host_cascades.h) where they are active,
// else every wave of the model is summed.
SpecaaSample specaa_sample(const WaterGeometry& water, double px, double py, double t,
                           const HostCascades* cascades = nullptr);

// The analytic derivatives (dh_perp/dpx, dh_perp/dpy) at a sample.
void specaa_analytic_derivatives(const WaterGeometry& water, const SpecaaSample& s, double t,
                                 vec2& ddx, vec2& ddy, const HostCascades* cascades = nullptr);

// The pixel value for a centre sample and its derivatives.
RadianceWeights specaa_weights(const SceneModel& m, const SpecaaSample& s, const vec2& ddx,
                               const vec2& ddy, const SpecaaOptions& o);

// Fallback (methods/host_method.h): where the camera is under the surface (no footprint, no
// derivatives) or the lobe's shading is not finite, the pixel gets the spec's radiance along its
// centre ray (what `point` returns) and is counted.
class SpecaaMethod final : public Method, public HostMethod {
 public:
  explicit SpecaaMethod(SpecaaOptions o, bool cascade_fields = true)
      : options_(o), cascades_(cascade_fields) {}
  std::string name() const override { return "specaa"; }
  void begin_frame(const FrameContext& ctx) override {
    begin_host_frame(ctx);
    cascades_.build(ctx);
  }
  RadianceWeights weights(const FrameContext& ctx, int i, int j) const override;
  // Quad derivatives share samples: a tile samples its quad-aligned cover once.
  void shade_tile(const FrameContext& ctx, int x0, int y0, int x1, int y1,
                  Image& out) const override;

 private:
  // Value of pixel (i, j) given its sample and its quad neighbours in x and in y.
  RadianceWeights shade_pixel(const FrameContext& ctx, int i, int j, const SpecaaSample& own,
                              const SpecaaSample& nx, const SpecaaSample& ny) const;
  SpecaaOptions options_;
  HostCascades cascades_;
};

}  // namespace sg
