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

bool LightModel::contains(const vec3& unit_dir) const {
  kd::Light l;
  l.L = L;
  l.chord2 = chord2;
  return kd::light_contains(l, unit_dir);
}

}  // namespace sg
