// Host wrappers of the kernel's convex polygons (kernel/convex_polygon.glsl).
#include "shading/convex_polygon.h"

#include <cassert>

#include "kernel/kernel_double.h"

namespace sg {
namespace {

kd::ConvexPolygon to_kernel(std::span<const vec2> points) {
  assert(points.size() <= ConvexPolygon::kCapacity);
  kd::ConvexPolygon k = kd::polygon_none();
  for (const vec2& p : points)
    k.v[k.n++] = p;
  return k;
}

ConvexPolygon from_kernel(const kd::ConvexPolygon& k) {
  ConvexPolygon p;
  p.n = k.n;
  for (int i = 0; i < k.n; ++i)
    p.v[i] = k.v[i];
  return p;
}

}  // namespace

static_assert(ConvexPolygon::kCapacity == kd::kPolygonCapacity);

ConvexPolygon convex_hull(std::span<const vec2> points) {
  return from_kernel(kd::convex_hull(to_kernel(points)));
}

double polygon_area(std::span<const vec2> v) {
  return kd::polygon_area(to_kernel(v));
}

bool contains(const ConvexPolygon& poly, const vec2& p) {
  return kd::polygon_contains(to_kernel(poly.vertices()), p);
}

vec2 closest_boundary_point(const ConvexPolygon& poly, const vec2& p) {
  assert(poly.n >= 1);
  return kd::polygon_closest_boundary_point(to_kernel(poly.vertices()), p);
}

vec2 closest_point(const ConvexPolygon& poly, const vec2& p) {
  return kd::polygon_closest_point(to_kernel(poly.vertices()), p);
}

ConvexPolygon clip_half_plane(const ConvexPolygon& poly, const vec2& a, double c) {
  return from_kernel(kd::polygon_clip_half_plane(to_kernel(poly.vertices()), a, c));
}

}  // namespace sg
