// The light: a sphere at infinity, seen as a disk of directions of angular radius rho
// around the unit vector L (scene spec). Directions are compared with it exactly:
// angle(r, L) <= rho  <=>  r . L >= cos(rho) for unit r.
//
// The light plane (Podee et al. 2021, Fig. 6 and Eq. 8) is the plane perpendicular to L at
// unit distance along it, with an orthonormal frame (e1, e2). A direction r with r . L > 0
// maps to Phi(r) = r / (r . L), whose coordinates are (r . e1, r . e2) / (r . L). This is
// the gnomonic projection: great circles map to straight lines, and the light's cone maps
// exactly to the disk of radius tan(rho) about the origin.
#pragma once

#include "math/vec.h"
#include "scene/scene.h"

namespace sg {
namespace kd {
struct Light;  // kernel/interface.glsl, in double (kernel/kernel_types.h)
}

struct LightModel {
  vec3 L{0, 0, -1};   // unit, towards the light
  vec3 e1{1, 0, 0};   // light-plane frame: e1 horizontal (e1.y = 0 unless L is vertical)
  vec3 e2{0, 1, 0};   // e2 = L x e1, so that e1 x e2 = L
  double radius = 0;  // angular radius, radians
  double cos_radius = 1;
  double tan_radius = 0;  // radius of the disk on the light plane
  double sin_radius = 0;
  double chord2 = 0;  // 4 sin^2(radius / 2): |r - L|^2 for a unit r on the disk's rim
  bool visible = false;

  LightModel() = default;
  explicit LightModel(const LightDesc& d);

  // The kernel's light (kernel/interface.glsl, Light) in double, every field: what the
  // frames carry (shading/kernel_frame.h narrows it to float) and the queries below take.
  kd::Light kernel_light() const;

  // Whether unit direction r lies in the disk: the kernel's test (kernel/light.glsl,
  // light_contains), |r - L|^2 <= chord2.
  bool contains(const vec3& unit_dir) const;

  // The light plane, by the kernel's formulas (kernel/light.glsl, light_to_plane,
  // elevation_on_plane; kernel/microspec.glsl, light_from_plane):
  // light-plane coordinates of direction r (any length, r . L > 0);
  vec2 to_plane(const vec3& r) const;
  // the unit direction through light-plane point p;
  vec3 from_plane(const vec2& p) const;
  // the height (y) of L + p.x e1 + p.y e2, the direction through p scaled to r . L = 1. Its
  // sign is that of r.y, so the horizon is the straight line elevation_on_plane(p) = 0 of
  // the light plane (a great circle maps to a line) and reflections with
  // elevation_on_plane(p) <= 0 point below it.
  double elevation_on_plane(const vec2& p) const;
};

}  // namespace sg
