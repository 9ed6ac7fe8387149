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

kd::Light LightModel::kernel_light() const {
  kd::Light l{};
  l.L = L;
  l.e1 = e1;
  l.e2 = e2;
  l.radius = radius;
  l.cos_radius = cos_radius;
  l.sin_radius = sin_radius;
  l.tan_radius = tan_radius;
  l.chord2 = chord2;
  l.visible = visible;
  return l;
}

bool LightModel::contains(const vec3& unit_dir) const {
  return kd::light_contains(kernel_light(), unit_dir);
}

vec2 LightModel::to_plane(const vec3& r) const {
  return kd::light_to_plane(kernel_light(), r);
}

vec3 LightModel::from_plane(const vec2& p) const {
  return kd::light_from_plane(kernel_light(), p);
}

double LightModel::elevation_on_plane(const vec2& p) const {
  return kd::elevation_on_plane(kernel_light(), p);
}

}  // namespace sg
