#include "scene/light.h"

#include <cmath>

#include "kernel/kernel_double.h"

namespace sg {

LightModel::LightModel(const LightDesc& d) {
  L = normalize(d.direction);
  // e1: horizontal and perpendicular to L; for a light at the zenith, world x.
  vec3 h = cross(vec3(0, 1, 0), L);
  e1 = length(h) > 1e-9 ? normalize(h) : vec3(1, 0, 0);
  e2 = cross(L, e1);
  radius = radians(d.angular_radius_deg);
  cos_radius = std::cos(radius);
  tan_radius = std::tan(radius);
  sin_radius = std::sin(radius);
  chord2 = 4 * std::sin(0.5 * radius) * std::sin(0.5 * radius);
  visible = d.visible;
}

namespace {

// The kernel's light for the queries below: the direction, its plane's frame and the chord.
kd::Light kernel_of(const LightModel& m) {
  kd::Light l{};
  l.L = m.L;
  l.e1 = m.e1;
  l.e2 = m.e2;
  l.chord2 = m.chord2;
  return l;
}

}  // namespace

bool LightModel::contains(const vec3& unit_dir) const {
  return kd::light_contains(kernel_of(*this), unit_dir);
}

vec2 LightModel::to_plane(const vec3& r) const {
  return kd::light_to_plane(kernel_of(*this), r);
}

vec3 LightModel::from_plane(const vec2& p) const {
  return kd::light_from_plane(kernel_of(*this), p);
}

double LightModel::elevation_on_plane(const vec2& p) const {
  return kd::elevation_on_plane(kernel_of(*this), p);
}

}  // namespace sg
