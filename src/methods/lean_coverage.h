// Which part of the unbounded water plane the LEAN map covers (methods/lean.h states the
// decision; this file computes it).
//
// The map is a square of N x N texels on the water plane, axis-aligned in (x, z), over the
// water the frame sees within a horizontal distance D of the camera:
//  - visible_water_bounds: the bounding box of {(x, z): (x, y0, z) inside the camera's
//    view pyramid, |(x, z) - camera_xz| <= D}. The pyramid's four side planes (through the
//    camera and the image's edges) cut the plane y = y0 in four half-planes; a polygon
//    circumscribing the disk of radius D (1024 sides, so never smaller than the disk) is
//    clipped by them (Sutherland-Hodgman) and its bounding box taken. On displaced water the
//    hits lie between y = -sum A_i and y = +sum A_i: the box of both planes.
//  - min_footprint_side: the shortest side |dP/dpx| or |dP/dpy| (horizontal parts) of the
//    footprint of any pixel centre on the plane y = 0 (footprint.h's ray differentials):
//    the finest detail the frame resolves.
//  - lean_map_region: with D given (`--lean-far`), the square is the box's longer side,
//    texel = side / N. With D = 0 (auto), texel = min_footprint_side, so no pixel's
//    footprint is smaller than a texel (no magnification, a level of detail >= 0 for every
//    pixel, trilinear or anisotropic), and D is the largest distance whose box fits in N
//    texels (bisection on log D; when the whole visible water fits, the texel shrinks to
//    side / N instead). The square holds the box; any room left over on an axis is put on
//    the side away from the camera (where the water continues).
#pragma once

#include "math/vec.h"
#include "scene/model.h"

namespace sg {

struct LeanMapRegion {
  vec2 origin{0, 0};   // (x, z) of the map's corner at texel coordinates (0, 0)
  double texel = 1;    // metres per level-0 texel
  double far = 0;      // D, metres (infinity when all visible water fits)
  bool empty = false;  // no water visible within D (then the map is never looked up)

  // Level-0 texel coordinates of water point (x, z), and of a horizontal offset.
  vec2 to_texels(const vec2& xz) const { return (xz - origin) / texel; }
};

// False when no water is visible within D on the plane y = y0.
bool visible_water_bounds(const SceneModel& m, double y0, double D, vec2& lo, vec2& hi);

double min_footprint_side(const SceneModel& m);

LeanMapRegion lean_map_region(const SceneModel& m, int size, double far);

}  // namespace sg
