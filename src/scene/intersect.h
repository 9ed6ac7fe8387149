// Where a camera ray meets the water (scene spec, "Radiance along a camera ray", 1).
//
// flat: the plane y = 0 (the waves bend the normal only).
// displaced: the first intersection with the height field y = h(x, z, t). The ray is
// marched inside the slab |y| <= sum |A_i| that bounds the surface. Along the ray,
// f(s) = y(s) - h(x(s), z(s), t) changes at most at the rate
//     Lip = |d.y| + (sum_i A_i |k_i|) |d.xz|
// so a step of f(s) / Lip cannot pass a zero of f: the first crossing is never skipped.
// Steps are at least kGrazeDepth / Lip, so the only intersections that can be missed are
// grazes that dip less than kGrazeDepth (1e-6 m) below the surface before leaving it. The
// bracketed root is then refined with TOMS 748 (Boost.Math) to |f| <= kRootTolerance
// (1e-9 m), or to a bracket of relative width 2^-50. Both figures are tested.
//
// Bounded work: at most kMaxMarchSteps steps (one height evaluation, a sum over the waves,
// each) plus 100 root-refinement steps per ray, whatever the ray. The bound is reached
// only by a ray that runs inside the slab nearly parallel to the water for its whole
// length (a horizontal ray from a camera below the crests, whose slab never ends); such
// a ray is reported as a miss (it sees the sky) with `exhausted` set. With the scene
// limits (scene_limits.h: the sum of slopes at most 1000) a step is at least
// kGrazeDepth / 1000 m long.
#pragma once

#include "math/vec.h"
#include "scene/waves.h"

namespace sg {

inline constexpr double kGrazeDepth = 1e-6;     // metres
inline constexpr double kRootTolerance = 1e-9;  // metres
inline constexpr long kMaxMarchSteps = 2000000;

struct RayHit {
  bool hit = false;
  bool exhausted = false;  // displaced: the march ran kMaxMarchSteps steps without a hit
  double s = 0;            // ray parameter: point = origin + s * dir
  vec3 point{0};
};

// Plane y = 0. `dir` need not be unit length.
RayHit intersect_flat(const vec3& origin, const vec3& dir);

// First intersection with y = h(x, z, t). Also reports the number of wave-field
// evaluations it used (for benchmarks) when `evaluations` is not null.
RayHit intersect_displaced(const WaveField& waves, const vec3& origin, const vec3& dir, double t,
                           long* evaluations = nullptr);

}  // namespace sg
