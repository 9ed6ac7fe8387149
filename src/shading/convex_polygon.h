// Small convex polygons in the plane for host code: the kernel's (kernel/convex_polygon.glsl,
// where the micro-specular highlight's reflection space and the reason it is a convex hull
// are described), on std::array and spans. Vertices are counter-clockwise, without repeats
// or collinear points; at most kCapacity of them.
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
