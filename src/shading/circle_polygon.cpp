// Host wrappers of the kernel's disk-polygon areas (kernel/convex_polygon.glsl).
#include "shading/circle_polygon.h"

#include "base/error.h"
#include "kernel/kernel_double.h"

namespace sg {

double circle_polygon_area(const vec2& centre, double R, std::span<const vec2> v) {
  if (v.size() > size_t(kd::kPolygonCapacity)) {
    throw Error("circle_polygon_area: " + std::to_string(v.size()) + " vertices (at most " +
                std::to_string(kd::kPolygonCapacity) + ")");
  }
  kd::ConvexPolygon k = kd::polygon_none();
  for (const vec2& p : v)
    k.v[k.n++] = p;
  return kd::circle_polygon_area(centre, R, k);
}

double disk_half_plane_area(double R, double d) {
  return kd::disk_half_plane_area(R, d);
}

}  // namespace sg
