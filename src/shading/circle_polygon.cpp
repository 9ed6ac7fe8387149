#include "shading/circle_polygon.h"

#include <algorithm>
#include <cmath>

#include "kernel/kernel_double.h"

namespace sg {

double circle_polygon_area(const vec2& centre, double R, std::span<const vec2> v) {
  if (v.size() < 3 || !(R > 0)) return 0.0;
  double area = 0;
  for (size_t k = 0; k < v.size(); ++k) {
    area += kd::disk_triangle_area(v[k] - centre, v[(k + 1) % v.size()] - centre, R);
  }
  return area;
}

double disk_half_plane_area(double R, double d) {
  if (d >= R) return kPi * R * R;
  if (d <= -R) return 0.0;
  return std::clamp(R * R * std::acos(-d / R) + d * std::sqrt(R * R - d * d), 0.0, kPi * R * R);
}

}  // namespace sg
