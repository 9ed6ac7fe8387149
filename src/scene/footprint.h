// How a pixel maps onto the water: the point seen through the pixel centre, the view
// direction there, and the derivatives of that point with respect to the image-plane
// coordinates (the ray differentials of camera.h transferred to the water surface,
// Igehy 1999). To first order, the pixel square [i, i+1] x [j, j+1] covers the
// parallelogram  centre + u dP/dpx + v dP/dpy,  u, v in [-1/2, 1/2], on the water.
//
// On flat water the surface is the plane y = 0. On displaced water the point is the first
// hit of the height field at time t and the differentials are transferred to its tangent
// plane (the waves' local slope); their horizontal parts are what the aliasing
// classification and the per-pixel NDF use. The kernel computes it
// (kernel/footprint.glsl); shading/water_geometry.h gives it to host code in world
// coordinates.
#pragma once

#include "math/vec.h"

namespace sg {

struct PixelFootprint {
  bool hit = false;
  vec3 point{0};   // on the water
  vec3 view{0};    // unit, from the point towards the camera
  vec3 dp_dpx{0};  // d point / d px
  vec3 dp_dpy{0};  // d point / d py
  double distance = 0;
  // The camera is under the displaced surface at this instant (possible only within the
  // waves' amplitude of the water): by the spec's convention the ray hits at the camera
  // itself, the view is the ray's reverse and the footprint is a point (dP = 0).
  bool at_camera = false;

  // The 2x2 map from image-plane offsets (px, py) to horizontal offsets (x, z).
  mat2 xz_jacobian() const { return mat2(vec2(dp_dpx.x, dp_dpx.z), vec2(dp_dpy.x, dp_dpy.z)); }
};

}  // namespace sg
