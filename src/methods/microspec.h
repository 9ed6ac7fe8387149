// The micro-specular highlight (`--method microspec`): Podee, Max, Iwasaki, Dobashi,
// "Micro-specular-highlight real-time rendering" (docs/references.md), Sec. 3, on the water
// of the scene spec. The method is the kernel's (kernel/microspec.glsl: the corners, the
// reflection space, the brightest reflection, the result weighting, the choices the paper
// leaves open; kernel/convex_polygon.glsl: the reflection space as a convex polygon and the
// disk's area in it), so both engines run it; this class is the CPU engine's side, whose
// tiles trace each corner once for the four pixels that share it.
//
// Why `approx` is what it is. The paper's cheaper approximation ("we approximate the
// projected light source by a circle, and the reflection space with a quad") names the two
// shapes the weighting intersects, and says what is approximated: "the areas of the
// projected light source and/or the shape of the reflection space". Here circle and quad
// are not approximations: the light plane is perpendicular to L, so the gnomonic image of
// the light's cone is exactly a circle, and an edge between two corner reflections (a
// linear interpolation of two directions, a great circle) projects to a straight segment,
// so the reflection space is a polygon. What remains costly is clipping the circle by every
// edge (a quadratic and up to two arctangents per edge). `approx` instead replaces each
// shape by a straight line where it meets the other: the disk is cut by the polygon's
// supporting line at the point nearest the light centre (the nearest edge's line when the
// centre is inside; the closest-point search has found it), one circular segment; and the
// polygon is cut by the disk's tangent line facing the polygon's vertex mean, one
// half-plane clip. Both are upper bounds of the shared area (the polygon lies in the first
// half-plane, the disk in the second), so their minimum is too: `approx` never gives less
// light than `exact`. It is exact when one edge cuts the disk (a polygon larger than the
// disk) and when the polygon lies inside the disk, and its error vanishes as the polygon
// shrinks against the disk (the arc inside it straightens); it is coarsest where a corner
// of a polygon about the disk's size cuts the disk.
//
// Fallback (methods/fallback.h): where the camera is under the surface at a corner (the
// corner's reflection is not a point of the water seen from above) or the value is not
// finite, the pixel gets the spec's radiance along its centre ray (what `point` returns)
// and is counted; a pixel with a corner off the water (it straddles the image's horizon
// line) gets that value too, uncounted: the method point samples it, as the paper does.
// The cascades of a scene are their lattice's sines here (`--cascades` does not apply).
#pragma once

#include <array>

#include "methods/fallback.h"
#include "methods/kernel_inputs.h"
#include "methods/method.h"
#include "methods/options.h"
#include "scene/light.h"

namespace sg {

// The reflection at one corner (the kernel's CornerReflection, with defaults for tests).
struct CornerReflection {
  bool hit = false;
  bool at_camera = false;  // the camera is under the surface: the hit is the camera itself
  vec3 r{0};               // unit reflected direction
  vec3 v{0};               // unit view direction (towards the camera)
};

// What the reflection space of a pixel sees: the fraction mirroring the light (gated by
// the brightest reflection lying in the disk), the fraction below the horizon, and the
// brightest reflection itself (kernel/microspec.glsl, microspec_fractions).
struct MicrospecFractions {
  double in_light = 0;
  double below = 0;
  vec3 brightest{0};
  bool degenerate = false;  // zero area: the point test at the closest point
};

// Corners in order (i, j), (i+1, j), (i+1, j+1), (i, j+1); all must hit the water.
MicrospecFractions microspec_fractions(const LightModel& light,
                                       const std::array<CornerReflection, 4>& corners,
                                       MicrospecArea area);

// The kernel's parameters for these options (kd::MicrospecParams or kf::MicrospecParams).
template <class P>
P microspec_kernel_params(const MicrospecOptions& o) {
  P p{};
  p.exact_area = o.area == MicrospecArea::exact;
  return p;
}

class MicrospecMethod final : public Method, public FallbackCount {
 public:
  explicit MicrospecMethod(MicrospecOptions o, Precision precision = Precision::float64,
                           double intersect_tolerance = 0.0)
      : options_(o), inputs_(1, precision, intersect_tolerance, 1, false) {}
  std::string name() const override { return "microspec"; }
  void begin_frame(const FrameContext& ctx) override {
    inputs_.build(ctx);
    reset_fallbacks();
  }
  RadianceWeights weights(const FrameContext& ctx, int i, int j) const override;
  // Neighbouring pixels share corners: a tile traces its (w+1) x (h+1) corners once.
  void shade_tile(const FrameContext& ctx, int x0, int y0, int x1, int y1,
                  Image& out) const override;

 private:
  template <class K>
  void shade_tile_in(const FrameContext& ctx, int x0, int y0, int x1, int y1, Image& out) const;
  MicrospecOptions options_;
  KernelFrameInputs inputs_;
};

}  // namespace sg
