#include "shading/convex_polygon.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace sg {
namespace {

double cross2(const vec2& a, const vec2& b) {
  return a.x * b.y - a.y * b.x;
}

// Nearest point to p on the segment [a, b].
vec2 closest_on_segment(const vec2& a, const vec2& b, const vec2& p) {
  const vec2 d = b - a;
  const double dd = dot(d, d);
  if (dd <= 0) return a;
  return a + std::clamp(dot(p - a, d) / dd, 0.0, 1.0) * d;
}

}  // namespace

ConvexPolygon convex_hull(std::span<const vec2> points) {
  assert(points.size() <= ConvexPolygon::kCapacity);
  std::array<vec2, ConvexPolygon::kCapacity> p{};
  // Insertion sort by (x, y) (at most kCapacity points), dropping exact repeats.
  int n = 0;
  for (const vec2& q : points) {
    int k = n;
    while (k > 0 && (p[k - 1].x > q.x || (p[k - 1].x == q.x && p[k - 1].y > q.y))) {
      p[k] = p[k - 1];
      --k;
    }
    if (k > 0 && p[k - 1] == q) {  // a repeat: undo the shift
      for (int m = k; m < n; ++m)
        p[m] = p[m + 1];
      continue;
    }
    p[k] = q;
    ++n;
  }
  // Monotone chain: lower hull left to right, then upper hull right to left; a turn that is
  // not strictly counter-clockwise is popped, which drops repeats and collinear points.
  std::array<vec2, 2 * ConvexPolygon::kCapacity> h{};
  int k = 0;
  for (int i = 0; i < n; ++i) {
    while (k >= 2 && cross2(h[k - 1] - h[k - 2], p[i] - h[k - 2]) <= 0)
      --k;
    h[k++] = p[i];
  }
  for (int i = n - 2, lower = k + 1; i >= 0; --i) {
    while (k >= lower && cross2(h[k - 1] - h[k - 2], p[i] - h[k - 2]) <= 0)
      --k;
    h[k++] = p[i];
  }
  ConvexPolygon out;
  // The chain ends where it started (k - 1 vertices); a single point gives k = 1.
  out.n = n <= 1 ? n : k - 1;
  std::copy(h.begin(), h.begin() + out.n, out.v.begin());
  return out;
}

double polygon_area(std::span<const vec2> v) {
  double s = 0;
  for (size_t i = 0; i < v.size(); ++i)
    s += cross2(v[i], v[(i + 1) % v.size()]);
  return 0.5 * s;
}

bool contains(const ConvexPolygon& poly, const vec2& p) {
  if (poly.n < 3) return false;
  for (int i = 0; i < poly.n; ++i) {
    const vec2& a = poly.v[i];
    const vec2& b = poly.v[(i + 1) % poly.n];
    if (cross2(b - a, p - a) < 0) return false;
  }
  return true;
}

vec2 closest_boundary_point(const ConvexPolygon& poly, const vec2& p) {
  assert(poly.n >= 1);
  if (poly.n == 1) return poly.v[0];
  vec2 best = poly.v[0];
  double best_d2 = INFINITY;
  const int edges = poly.n == 2 ? 1 : poly.n;
  for (int i = 0; i < edges; ++i) {
    const vec2 q = closest_on_segment(poly.v[i], poly.v[(i + 1) % poly.n], p);
    const double d2 = dot(q - p, q - p);
    if (d2 < best_d2) {
      best_d2 = d2;
      best = q;
    }
  }
  return best;
}

vec2 closest_point(const ConvexPolygon& poly, const vec2& p) {
  return contains(poly, p) ? p : closest_boundary_point(poly, p);
}

ConvexPolygon clip_half_plane(const ConvexPolygon& poly, const vec2& a, double c) {
  ConvexPolygon out;
  for (int i = 0; i < poly.n; ++i) {
    const vec2& p = poly.v[i];
    const vec2& q = poly.v[(i + 1) % poly.n];
    const double fp = dot(a, p) + c, fq = dot(a, q) + c;
    if (fp >= 0) out.v[out.n++] = p;
    if ((fp >= 0) != (fq >= 0)) out.v[out.n++] = p + (fp / (fp - fq)) * (q - p);
  }
  return out;
}

}  // namespace sg
