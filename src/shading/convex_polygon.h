// Small convex polygons in the plane: the reflection space of the micro-specular highlight
// (Podee, Max, Iwasaki, Dobashi, "Micro-specular-highlight real-time rendering", Sec. 3.1):
// the four corner reflections of a pixel projected on the light plane.
//
// The four projected corners need not form a convex quad: across a wave crest the corner
// reflections can fold (a dart) or cross (a bow tie). Every reflection the paper's bilinear
// model interpolates is a convex combination of the four corner vectors, and the gnomonic
// projection maps a convex combination of directions with r . L > 0 to a convex combination
// of their images (Phi(sum w_k r_k) = sum [w_k (r_k . L) / sum_j w_j (r_j . L)] Phi(r_k)), so
// the reflection space always lies in the convex hull of the projected corners. The method
// therefore works on that hull: for a convex quad it is the quad itself; for a fold or a
// crossing it is the smallest convex set that holds every interpolated reflection.
//
// Vertices are counter-clockwise, without repeats or collinear points; a polygon of fewer
// than three vertices (coincident or collinear corners) has zero area, and closest_point
// then works on its segment or point.
#pragma once

#include <array>
#include <span>

#include "math/vec.h"

namespace sg {

struct ConvexPolygon {
  static constexpr int kCapacity = 8;  // a quad's hull clipped by two lines has at most 6
  std::array<vec2, kCapacity> v{};
  int n = 0;

  std::span<const vec2> vertices() const { return {v.data(), static_cast<size_t>(n)}; }
};

// The convex hull of up to kCapacity points (Andrew's monotone chain).
ConvexPolygon convex_hull(std::span<const vec2> points);

// Signed area of a closed polygon (shoelace): positive when counter-clockwise.
double polygon_area(std::span<const vec2> vertices);

// True when p lies in the polygon or on its boundary (false for fewer than 3 vertices).
bool contains(const ConvexPolygon& poly, const vec2& p);

// The point of the polygon's boundary (its edges; its segment or point when degenerate)
// nearest to p.
vec2 closest_boundary_point(const ConvexPolygon& poly, const vec2& p);

// The point of the polygon nearest to p: p itself when inside (Sec. 3.1: "If the center is
// in the reflection space, the closest point is the center. Otherwise, the closest point is
// the point on the reflection space edge with the closest distance to the center").
vec2 closest_point(const ConvexPolygon& poly, const vec2& p);

// The part of the polygon where dot(a, p) + c >= 0 (Sutherland-Hodgman against one line).
ConvexPolygon clip_half_plane(const ConvexPolygon& poly, const vec2& a, double c);

}  // namespace sg
