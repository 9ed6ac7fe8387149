// The micro-specular highlight (`--method microspec`): Podee, Max, Iwasaki, Dobashi,
// "Micro-specular-highlight real-time rendering" (docs/references.md),
// Sec. 3, on the water of the scene spec.
//
// Reflection vector selection (Sec. 3.1). At the frame time t_f, the camera rays through
// the pixel's four corners meet the water (flat or displaced, as the scene says); each
// point's analytic normal mirrors its view into a corner reflection r_k. Projected on the
// light plane (LightModel::to_plane, origin at the light's centre, the disk of radius
// tan(rho) about it) they bound the reflection space. The point of that space nearest the
// light centre gives the brightest reflection: the centre itself when inside, else the
// nearest point of its edges (shading/convex_polygon.h). The reflection space is the convex
// hull of the projected corners (a fold or a crossing of the corners is handled there; see
// convex_polygon.h for why the hull holds every interpolated reflection).
//
// Result weighting (Sec. 3.2). The light along the brightest reflection (the light's
// radiance when it lies in the disk, else the sky), weighted by
// area(disk and reflection space) / area(reflection space): with the paper's assumption
// of a constant Jacobian of the bilinear map, that ratio is the fraction of the pixel that
// mirrors the disk. `--microspec-area exact` computes the shared area exactly
// (shading/circle_polygon.h); `approx` is the cheaper approximation described below.
//
// The paper's cheaper approximation ("we approximate the projected light source by a
// circle, and the reflection space with a quad") names the two shapes the weighting
// intersects, and says what is approximated: "the areas of the projected light source
// and/or the shape of the reflection space". Here circle and quad are not approximations:
// the light plane is perpendicular to L, so the gnomonic image of the light's cone is
// exactly a circle, and an edge between two corner reflections (a linear interpolation of
// two directions, a great circle) projects to a straight segment, so the reflection space
// is a polygon. What remains costly is clipping the circle by every edge (a quadratic and
// up to two arctangents per edge). `approx` instead replaces each shape by a straight line
// where it meets the other: the disk is cut by the polygon's supporting line at the point
// nearest the light centre (the nearest edge's line when the centre is inside; the
// closest-point search has found it), one circular segment; and the polygon is cut by the
// disk's tangent line facing the polygon's vertex mean, one half-plane clip. Both are upper
// bounds of the shared area (the polygon lies in the first half-plane, the disk in the
// second), so their minimum is too: `approx` never gives less light than `exact`. It is
// exact when one edge cuts the disk (a polygon larger than the disk) and when the polygon
// lies inside the disk, and its error vanishes as the polygon shrinks against the disk
// (the arc inside it straightens); it is coarsest where a corner of a polygon about the
// disk's size cuts the disk.
//
// Choices the paper leaves open:
// - Fresnel (surface.fresnel: schlick): F at the brightest reflection r*, whose normal is the
//   half vector of r* and the view, so n . v = sqrt((1 + r* . v) / 2), with v the mean of the
//   corners' views. One F serves the light, the sky and the sea (combine_radiance).
// - Sky and sea: the rest of the reflection space sees the sky, and its part below the
//   horizon (r.y <= 0) the sea: the horizon is a line of the light plane
//   (LightModel::elevation_on_plane), so the below fraction is the polygon's area beyond
//   that line, exactly, and the disk is intersected with the part above it.
// - Zero area: when the reflection space's area is below 1e-9 tan^2(rho) (all corners
//   reflect one direction, e.g. a pixel on a flat stretch seen edge-on), the ratio is
//   undefined; the value is then the point test of the spec at the closest point (light or
//   sky, or sea below the horizon).
// - Corners more than acos(0.05) = 87 degrees from the light have no image on the light
//   plane: the reflection space is then the part of the corners' hull with r . L >= 0.05
//   (edges and diagonals clipped where they cross it); when no corner reaches it the pixel
//   sees no light, and its below fraction is the share of corners whose reflection points
//   below the horizon.
// - A pixel whose corner ray misses the water (it straddles the horizon line of the image)
//   is point sampled at its centre, as `point` does.
#pragma once

#include <array>

#include "methods/host_method.h"
#include "methods/method.h"

namespace sg {

// The reflection at one corner: the water point seen through image-plane point (px, py) at
// time t, its analytic normal, and the mirrored view.
struct CornerReflection {
  bool hit = false;
  bool at_camera = false;  // the camera is under the surface: the hit is the camera itself
  vec3 r{0};               // unit reflected direction
  vec3 v{0};               // unit view direction (towards the camera)
};
CornerReflection corner_reflection(const WaterGeometry& water, double px, double py, double t);

// What the reflection space of a pixel sees: the fraction mirroring the light (gated by
// the brightest reflection lying in the disk), the fraction below the horizon, and the
// brightest reflection itself.
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

// The pixel value from its four corners (combine_radiance of the fractions).
RadianceWeights microspec_weights(const SceneModel& m,
                                  const std::array<CornerReflection, 4>& corners,
                                  MicrospecArea area);

// Fallback (methods/host_method.h): where the camera is under the surface at a corner (the corner's
// reflection is not a point of the water seen from above) or the value is not finite,
// the pixel gets the spec's radiance along its centre ray (what `point` returns) and is
// counted.
class MicrospecMethod final : public Method, public HostMethod {
 public:
  explicit MicrospecMethod(MicrospecOptions o) : options_(o) {}
  std::string name() const override { return "microspec"; }
  void begin_frame(const FrameContext& ctx) override { begin_host_frame(ctx); }
  RadianceWeights weights(const FrameContext& ctx, int i, int j) const override;
  // Neighbouring pixels share corners: a tile traces its (w+1) x (h+1) corners once.
  void shade_tile(const FrameContext& ctx, int x0, int y0, int x1, int y1,
                  Image& out) const override;

 private:
  RadianceWeights shade_corners(const FrameContext& ctx, int i, int j,
                                const std::array<CornerReflection, 4>& c) const;
  MicrospecOptions options_;
};

}  // namespace sg
