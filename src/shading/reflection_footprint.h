// How the reflection of the resolved waves moves across a pixel: the derivatives of its
// light-plane position P with respect to the image-plane coordinates (px, py).
//
// The pixel centre sees water point X(px, py) (scene/footprint.h: dX/dpx, dX/dpy from the
// camera's ray differentials). There the resolved waves (amplitudes weighted by w_i) have
// gradient g(X), so the NDF-plane point is n = -g + shift and the normal m = (n.x, 1, n.y);
// the view direction is v = (C - X) / |C - X|; the reflection r = 2 (m.v)/(m.m) m - v
// meets the light plane at P = Phi(r) (Podee et al. 2021, Eqs. 8-10). By the chain rule
//     dP/dpx = dP/dr [ dr/dm dm/dpx + dr/dv dv/dpx ],
//     dm/dpx = -(H (dX/dpx)_xz) in the x and z slots,  H = Hessian of the weighted waves,
//     dv/dpx = -(I - v v^T) (dX/dpx) / |C - X|,
// (shading/rdf.h gives dP/dr, dr/dm, dr/dv). To first order the pixel square maps to the
// parallelogram P + [dP/dpx dP/dpy] [-1/2, 1/2]^2 on the light plane: the "reflection
// quad" of the micro-specular highlight (Podee et al., micro-specular paper), linearised
// at the pixel centre.
#pragma once

#include <span>

#include "math/vec.h"
#include "scene/footprint.h"
#include "scene/model.h"

namespace sg {

struct ReflectionFootprint {
  bool valid = false;  // false when the reflection points away from the light (r.L <= 0)
  vec2 P{0};           // light-plane position of the centre reflection
  mat2 D{0.0};         // columns dP/dpx, dP/dpy
};

ReflectionFootprint reflection_footprint(const SceneModel& m, const PixelFootprint& fp,
                                         std::span<const double> weights, double t,
                                         const vec2& ndf_shift = vec2(0));
// The same with the waves' phases at the point and time already evaluated.
ReflectionFootprint reflection_footprint(const SceneModel& m, const PixelFootprint& fp,
                                         std::span<const double> weights, const WavePhases& phases,
                                         const vec2& ndf_shift);

}  // namespace sg
