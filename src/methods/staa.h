// `--method staa`: the spatio-temporal anti-aliasing of Podee, Max, Iwasaki and Dobashi
// 2021, "Temporal and spatial anti-aliasing for rendering reflections on water waves".
//
// Per pixel (Fig. 2 and 5):
//  1. The water point seen through the pixel centre and its footprint (scene/footprint.h).
//  2. Each wave's projected frequency splits it into a resolved share (1 - alpha) and an
//     aliasing share alpha (Sec. 3.2, 3.7, Eq. 20; shading/aliasing.h).
//  3. No aliasing share anywhere: the temporal method exactly (Sec. 3.3), the fraction of
//     the shutter during which the reflection path lies in the light disk
//     (shading/reflection_path.h).
//  4. Otherwise the aliasing waves become a Gaussian NDF (Sec. 3.4: uniform Eq. 3 or
//     per-pixel Eqs. 4-7; shading/ndf.h) centred on the resolved waves' normal, mapped to
//     the light plane as a Gaussian RDF of covariance J Sigma J^T (Eqs. 8-16,
//     shading/rdf.h), whose centre moves along the resolved waves' reflection path
//     between the start and the end of the shutter (K straight sub-segments on the light
//     plane). The time-averaged mass of the RDF inside the light disk (Eq. 17) is the
//     light's share:
//       - the RDF as 1 (the equal-area circle, Sec. 3.5), 3, 5 or 9 circular Gaussians
//         along its major axis (Sec. 3.6, Appendix C; shading/kernel_fit.h), each
//         integrated along the path offset by its centre (Fig. 10) with the path tables
//         (Eqs. 18-19; shading/path_table.h), weights combined;
//       - past the elongation threshold (axis ratio > kernel count), the fallback: the
//         RDF's mass in the disk at the display time, by quadrature or by the paper's
//         Riemann sum (shading/gaussian_disk.h).
//     J and Sigma are those of the display time (the paper assumes they change little
//     within a frame). The share of the RDF below the horizon (seeing the sea) is the
//     Gaussian's mass beyond the horizon's line on the light plane.
//  5. The spec's radiance weights: the light's share at the Fresnel factor of the centre
//     normal; Fresnel times the sky, the sea and the share below the horizon integrated
//     over the normals' Gaussian (kernel/smooth_terms.glsl), or with --smooth-terms mean
//     at the centre normal with the horizon's share on the light plane (combine_weights).
// All of it is the shading kernel's (kernel/staa.glsl), run here per pixel on the CPU in
// the chosen precision; `--footprint exact` (the swept parallelogram of pixels without
// aliasing waves) is integrated on the host (shading/swept_footprint.h) and is CPU-only.
// As the aliasing shares fall to 0 the NDF's covariance does too, and the path integral
// tends to the fraction of the path inside the disk: the transition to step 3 is
// continuous (no arcs, Fig. 11).
// A camera that moves over the shutter (format /3): each instant of the path takes the
// pixel's ray from the camera at that instant, its own water point and view, and Eq. 20
// and the per-pixel NDF the footprint swept by the point's motion (docs/method.md, "A
// moving camera"; kernel/reflection_path.glsl, PathViews).
#pragma once

#include "methods/kernel_inputs.h"
#include "methods/method.h"

namespace sg {

class PathTables;

// The kernel's StaaParams (kd:: or kf::) for the options; `footprint` 2 is `exact`, which
// the host finishes (the GL engine refuses it).
template <class P>
P staa_kernel_params(const StaaOptions& o);
extern template kd::StaaParams staa_kernel_params<kd::StaaParams>(const StaaOptions&);
extern template kf::StaaParams staa_kernel_params<kf::StaaParams>(const StaaOptions&);

class StaaMethod final : public Method {
 public:
  // `tables`: the path tables (the caller's, MethodOptions::path_tables), which outlive the
  // method.
  StaaMethod(const StaaOptions& o, const PathTables& tables,
             Precision precision = Precision::float64,
             double intersect_tolerance = kDefaultIntersectTolerance, bool cascade_fields = true);
  std::string name() const override { return "staa"; }
  void begin_frame(const FrameContext& ctx) override;
  RadianceWeights weights(const FrameContext& ctx, int i, int j) const override;

  // The light, sky and sea shares of a pixel, for tests and diagnostics.
  struct Shares {
    bool hit = false;
    bool aliasing = false;  // some alpha > 0
    bool temporal = false;  // step 3: the temporal method, exactly
    bool fallback = false;  // past the elongation threshold
    double in_light = 0, below = 0, fresnel = 1;
    double sky_y = 1;              // the height of the centre reflection
    RadianceWeights weights{0.0};  // the pixel's weights
  };
  Shares shares(const FrameContext& ctx, int i, int j) const;

 private:
  StaaOptions o_;
  Precision precision_;
  const PathTables* tables_;
  KernelFrameInputs inputs_;
  kd::StaaParams params_{};
  kf::StaaParams params_float_{};
};

}  // namespace sg
