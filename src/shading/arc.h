// The arc fraction of Podee et al. 2021, Sec. 3.3 ("the ratio of the angle of the light arc
// to that of the whole arc"), computed exactly on the unit sphere.
//
// Between two frames the reflection vector is assumed to move from r0 to r1 along the
// great-circle arc at constant angular speed (slerp). Along that arc, for any fixed vector X,
//   r(psi) = cos(psi) r0 + sin(psi) w,   r(psi) . X = A cos(psi) + B sin(psi),
// with w the unit tangent at r0, psi in [0, theta], theta = angle(r0, r1). A spherical cap
// {r : angle(r, X) <= rho} therefore meets the arc's circle in one interval of psi, centred
// on phi = atan2(B, A) with half-width alpha, where (beta = angle between X and the circle's
// plane, sin(beta) = n . X for the circle's unit normal n)
//   cos(alpha) = cos(rho) / cos(beta),   alpha = atan2(sqrt(sin^2 rho - sin^2 beta), cos rho).
// The second form keeps full relative precision for the sun's 0.27 degree disk, where
// acos(cos rho / cos beta) would lose half its digits. The light cone is the cap about L of
// radius rho; "below the horizon" (r.y <= 0) is the cap about -y of radius 90 degrees. The
// in-light fraction counts only time above the horizon (scene spec: r.y <= 0 sees the sea),
// so in_light = |cone| - |cone and below| and in_light + below <= 1.
//
// Degenerate arcs (|r0 x r1| <= 1e-12, i.e. the endpoints coincide or are antipodal to
// within about 1e-12 rad):
//  * r0 . r1 > 0: no motion. The direction is the midpoint normalize(r0 + r1) and each
//    fraction is 0 or 1 by the scene spec's tests on it.
//  * r0 . r1 < 0: antipodal, the great circle is undefined. We choose the half circle from
//    r0 through the zenith side: w = the unit component of +y orthogonal to r0 (for a
//    vertical r0, the horizontal component of L, or world x if L is vertical too). The
//    choice depends on the pair {r0, r1} only, so reversing the arc gives the same result.
#pragma once

#include "math/vec.h"
#include "scene/light.h"

namespace sg {

struct ArcFractions {
  double in_light = 0;  // fraction of the interval with angle(r, L) <= rho and r.y > 0
  double below = 0;     // fraction of the interval with r.y <= 0
};

// r0, r1: reflection directions at the start and end of the interval (any non-zero length;
// they are normalised). Throws sg::Error naming the argument if it is zero or not finite.
ArcFractions arc_fractions(const vec3& r0, const vec3& r1, const LightModel& light);

}  // namespace sg
