// The area a disk shares with a polygon: the "result weighting" of the micro-specular
// highlight (Podee et al., "Micro-specular-highlight real-time rendering", Sec. 3.2), where
// the light disk on the light plane meets the pixel's reflection space.
//
// circle_polygon_area: exact, from the kernel's disk_triangle_area
// (kernel/disk_coverage.glsl). The polygon is split into the triangles (c, a_k, a_{k+1})
// fanned from the disk's centre c; each triangle's intersection with the disk is found
// exactly (its edge a_k a_{k+1} crosses the circle at most twice; the pieces inside the
// circle contribute triangles, the pieces outside contribute circular sectors) and the
// signed pieces sum to the intersection area. Exact for any simple polygon, convex or not
// (positive for counter-clockwise vertices); for a self-intersecting one the sum is the
// winding-number-weighted area, which is why microspec passes the convex hull.
//
// disk_half_plane_area: the disk's area on one side of a line (a circular segment, or the
// disk minus one). The cheaper approximation of microspec cuts the disk by the reflection
// space's supporting line nearest the light centre.
#pragma once

#include <span>

#include "math/vec.h"

namespace sg {

// Area of the disk |p - centre| <= R inside the polygon `vertices` (signed by orientation).
double circle_polygon_area(const vec2& centre, double R, std::span<const vec2> vertices);

// Area of the disk of radius R whose centre lies at signed distance d inside a half-plane
// (d > 0: centre inside; d < 0: outside): R^2 acos(-d/R) + d sqrt(R^2 - d^2), clamped to
// [0, pi R^2].
double disk_half_plane_area(double R, double d);

}  // namespace sg
