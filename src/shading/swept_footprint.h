// The light's share of a pixel whose reflections fill a parallelogram on the light plane
// that moves during the shutter (the exact form of the footprint term, docs/method.md).
//
// Linearised at the pixel centre, the pixel's reflections at time t fill
//     Q(t) = P(t) + D [-1/2, 1/2]^2
// (kernel/reflection_footprint.glsl: D = [dP/dpx dP/dpy]), and the reflection path moves
// P(t) along straight sub-segments between the instants of a ReflectionPath. The light's
// share is the time average of area(disk & Q(t)) / area(Q): the area is exact
// (shading/circle_polygon.h), the time average is 8-point Gauss-Legendre on pieces of
// each sub-segment no longer than a fifth of the disk-plus-parallelogram size, which
// resolves the piecewise-smooth area to ~1e-6 (tested against Monte Carlo).
#pragma once

#include <vector>

#include "math/vec.h"

namespace sg {

// `centre`: the light-plane positions of P at the path's instants; sub-segments whose two
// ends are not both `valid` (reflection away from the light) contribute nothing. R: the
// disk's radius (tan of the light's angular radius). A degenerate D (zero area) gives the
// fraction of time P spends inside the disk, by the same quadrature.
double swept_parallelogram_share(const std::vector<vec2>& centre, const std::vector<char>& valid,
                                 const mat2& D, double R);

}  // namespace sg
