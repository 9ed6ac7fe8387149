#include "shading/circle_polygon.h"

#include <algorithm>
#include <cmath>

namespace sg {
namespace {

double cross2(const vec2& a, const vec2& b) {
  return a.x * b.y - a.y * b.x;
}

// Signed area of the sector of radius R from direction a to direction b (turning by the
// signed angle between them, |angle| < pi).
double sector(const vec2& a, const vec2& b, double R) {
  return 0.5 * R * R * std::atan2(cross2(a, b), dot(a, b));
}

// Signed area of the disk |p| <= R inside the triangle (0, a, b).
double disk_triangle_area(const vec2& a, const vec2& b, double R) {
  const vec2 d = b - a;
  const double A = dot(d, d);
  if (A <= 0) return 0.0;
  // |a + s d|^2 = R^2:  A s^2 + B s + C = 0.
  const double B = 2 * dot(a, d), C = dot(a, a) - R * R;
  const double disc = B * B - 4 * A * C;
  if (disc <= 0) return sector(a, b, R);  // the edge's line misses the circle
  const double sq = std::sqrt(disc);
  // Stable roots (no cancellation between -B and sq).
  const double q = -0.5 * (B + std::copysign(sq, B));
  double s1 = q / A, s2 = q != 0 ? C / q : -s1;
  if (s1 > s2) std::swap(s1, s2);
  if (s2 <= 0 || s1 >= 1) return sector(a, b, R);  // the chord lies beyond the edge
  const double t1 = std::max(s1, 0.0), t2 = std::min(s2, 1.0);
  const vec2 p1 = a + t1 * d, p2 = a + t2 * d;
  // a..p1 outside (a sector), p1..p2 inside (a triangle), p2..b outside (a sector). The
  // triangle's area is cross(p1, p2 - p1) / 2: no cancellation between terms of size
  // |p1| |p2| when the polygon is small against its distance to the centre.
  double area = 0.5 * cross2(p1, (t2 - t1) * d);
  if (t1 > 0) area += sector(a, p1, R);
  if (t2 < 1) area += sector(p2, b, R);
  return area;
}

}  // namespace

double circle_polygon_area(const vec2& centre, double R, std::span<const vec2> v) {
  if (v.size() < 3 || !(R > 0)) return 0.0;
  double area = 0;
  for (size_t k = 0; k < v.size(); ++k) {
    area += disk_triangle_area(v[k] - centre, v[(k + 1) % v.size()] - centre, R);
  }
  return area;
}

double disk_half_plane_area(double R, double d) {
  if (d >= R) return kPi * R * R;
  if (d <= -R) return 0.0;
  return std::clamp(R * R * std::acos(-d / R) + d * std::sqrt(R * R - d * d), 0.0, kPi * R * R);
}

}  // namespace sg
