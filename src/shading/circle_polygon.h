// The area a disk shares with a polygon, for host code: the kernel's
// (kernel/convex_polygon.glsl: circle_polygon_area, exact for any simple polygon of at most
// 8 vertices from the kernel's disk_triangle_area, and disk_half_plane_area, the disk's
// area on one side of a line), the "result weighting" of the micro-specular highlight
// (Podee et al., "Micro-specular-highlight real-time rendering", Sec. 3.2) and the swept
// footprint's disk coverage (shading/swept_footprint.h).
#pragma once

#include <span>

#include "math/vec.h"

namespace sg {

// Area of the disk |p - centre| <= R inside the polygon `vertices` (signed by orientation;
// sg::Error past 8 vertices).
double circle_polygon_area(const vec2& centre, double R, std::span<const vec2> vertices);

// Area of the disk of radius R whose centre lies at signed distance d inside a half-plane
// (d > 0: centre inside; d < 0: outside): R^2 acos(-d/R) + d sqrt(R^2 - d^2), clamped to
// [0, pi R^2].
double disk_half_plane_area(double R, double d);

}  // namespace sg
