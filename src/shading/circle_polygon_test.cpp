// Planar geometry of the micro-specular highlight: the disk-polygon area against Monte
// Carlo for random convex polygons and disks in every relation (disjoint, disk inside,
// polygon inside, partial), for a non-convex polygon, and for the half-plane segment; the
// convex hull, the closest point and the half-plane clip against brute force.
#include "shading/circle_polygon.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "math/rng.h"
#include "shading/convex_polygon.h"

namespace sg {
namespace {

// Point in a simple polygon (even-odd rule), for the brute-force references.
bool inside_simple(const std::vector<vec2>& v, const vec2& p) {
  bool in = false;
  for (size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    if ((v[i].y > p.y) != (v[j].y > p.y) &&
        p.x < (v[j].x - v[i].x) * (p.y - v[i].y) / (v[j].y - v[i].y) + v[i].x)
      in = !in;
  }
  return in;
}

// Monte-Carlo estimate of the area of {p : |p - c| <= R and inside(p)} over the box
// [lo, hi], with its standard error.
template <typename Inside>
void mc_area(const vec2& lo, const vec2& hi, const vec2& c, double R, Inside inside, int n,
             Pcg32& rng, double& area, double& se) {
  long hits = 0;
  for (int k = 0; k < n; ++k) {
    const vec2 p(lo.x + (hi.x - lo.x) * rng.uniform(), lo.y + (hi.y - lo.y) * rng.uniform());
    if (dot(p - c, p - c) <= R * R && inside(p)) ++hits;
  }
  const double box = (hi.x - lo.x) * (hi.y - lo.y), f = double(hits) / n;
  area = box * f;
  se = box * std::sqrt(std::max(f * (1 - f), 1.0 / n) / n);
}

ConvexPolygon random_convex(Pcg32& rng, const vec2& centre, double size) {
  const int m = 3 + static_cast<int>(rng.uniform() * 6);  // 3..8 points
  std::vector<vec2> pts;
  for (int k = 0; k < m; ++k)
    pts.push_back(centre + size * vec2(rng.uniform() - 0.5, rng.uniform() - 0.5));
  return convex_hull(pts);
}

TEST(CirclePolygon, MatchesMonteCarloInEveryRelation) {
  Pcg32 rng(5, 1);
  int disjoint = 0, disk_inside = 0, poly_inside = 0, partial = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const ConvexPolygon poly = random_convex(rng, vec2(0.0), 2.0);
    if (poly.n < 3) continue;
    const double R = 0.02 * std::pow(75.0, rng.uniform());  // 0.02 .. 1.5
    const vec2 c(3 * (rng.uniform() - 0.5), 3 * (rng.uniform() - 0.5));
    const double exact = circle_polygon_area(c, R, poly.vertices());
    const double pa = polygon_area(poly.vertices()), da = kPi * R * R;
    // Classify by exact quantities.
    bool all_in = true;
    for (const vec2& p : poly.vertices())
      all_in = all_in && dot(p - c, p - c) <= R * R;
    const double dist = length(closest_boundary_point(poly, c) - c);
    const bool c_in = contains(poly, c);
    if (all_in) {
      ++poly_inside;
      EXPECT_NEAR(exact, pa, 1e-12 * pa) << trial;
    } else if (c_in && dist >= R) {
      ++disk_inside;
      EXPECT_NEAR(exact, da, 1e-12 * da) << trial;
    } else if (!c_in && dist >= R) {
      ++disjoint;
      EXPECT_NEAR(exact, 0.0, 1e-12) << trial;
    } else {
      ++partial;
      double area, se;
      const vec2 lo = c - vec2(R), hi = c + vec2(R);
      mc_area(
          lo, hi, c, R, [&](const vec2& p) { return contains(poly, p); }, 40000, rng, area, se);
      EXPECT_NEAR(exact, area, 5 * se + 1e-12) << trial;
      EXPECT_GE(exact, 0.0);
      EXPECT_LE(exact, std::min(pa, da) * (1 + 1e-12));
    }
  }
  // Every relation was exercised.
  EXPECT_GT(disjoint, 10);
  EXPECT_GT(disk_inside, 5);
  EXPECT_GT(poly_inside, 10);
  EXPECT_GT(partial, 80);
}

TEST(CirclePolygon, OrientationAndTinyPolygons) {
  const std::vector<vec2> ccw = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<vec2> cw = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  const double a = circle_polygon_area(vec2(0.2, 0.3), 0.7, ccw);
  EXPECT_NEAR(circle_polygon_area(vec2(0.2, 0.3), 0.7, cw), -a, 1e-15);
  // A polygon 1e-6 across, well inside the disk and away from its centre: its own area to
  // 1e-6 relative (a fan from the centre must not cancel terms of size R^2).
  std::vector<vec2> tiny;
  for (const vec2& p : ccw)
    tiny.push_back(vec2(0.3, -0.2) + 1e-6 * p);
  EXPECT_NEAR(circle_polygon_area(vec2(0.0), 1.0, tiny), 1e-12, 1e-18);
}

TEST(CirclePolygon, NonConvexSimplePolygonMatchesMonteCarlo) {
  // An L shape and an arrow (dart): the fan decomposition is exact for any simple polygon.
  const std::vector<std::vector<vec2>> shapes = {
      {{0, 0}, {2, 0}, {2, 0.6}, {0.6, 0.6}, {0.6, 2}, {0, 2}},
      {{0, 0}, {2, 1}, {0, 2}, {0.7, 1}},
  };
  Pcg32 rng(9, 2);
  for (const auto& shape : shapes) {
    for (const vec2 c : {vec2(0.5, 0.5), vec2(1.2, 0.9), vec2(0.3, 1.4)}) {
      for (double R : {0.3, 0.8, 1.6}) {
        double area, se;
        mc_area(
            c - vec2(R), c + vec2(R), c, R, [&](const vec2& p) { return inside_simple(shape, p); },
            60000, rng, area, se);
        EXPECT_NEAR(circle_polygon_area(c, R, shape), area, 5 * se + 1e-12);
      }
    }
  }
}

TEST(CirclePolygon, DiskHalfPlaneAreaMatchesClipping) {
  // The half-plane y >= -d (the disk's centre at signed distance d inside) as a huge square.
  for (double R : {0.01, 1.0}) {
    for (double d : {-1.5, -1.0, -0.7, -0.2, 0.0, 0.3, 0.99, 1.0, 2.0}) {
      const double D = d * R, B = 1e3 * R;
      const std::vector<vec2> half = {{-B, -D}, {B, -D}, {B, B}, {-B, B}};
      EXPECT_NEAR(disk_half_plane_area(R, D), circle_polygon_area(vec2(0.0), R, half),
                  1e-12 * R * R)
          << R << " " << d;
    }
  }
}

TEST(ConvexPolygon, HullHoldsAllPointsAndDropsRepeatsAndCollinearPoints) {
  Pcg32 rng(3, 3);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<vec2> pts;
    for (int k = 0; k < 8; ++k)
      pts.push_back(vec2(rng.uniform(), rng.uniform()));
    const ConvexPolygon h = convex_hull(pts);
    EXPECT_GT(polygon_area(h.vertices()), 0.0);
    for (const vec2& p : pts) {
      for (int i = 0; i < h.n; ++i) {  // every point left of (or on) every edge
        const vec2 e = h.v[(i + 1) % h.n] - h.v[i], q = p - h.v[i];
        EXPECT_GE(e.x * q.y - e.y * q.x, -1e-15);
      }
    }
  }
  const std::vector<vec2> line = {{0, 0}, {1, 1}, {2, 2}, {1, 1}};
  EXPECT_EQ(convex_hull(line).n, 2);
  const std::vector<vec2> same = {{0.5, 0.5}, {0.5, 0.5}, {0.5, 0.5}, {0.5, 0.5}};
  EXPECT_EQ(convex_hull(same).n, 1);
  const std::vector<vec2> square_with_midpoint = {{0, 0}, {1, 0}, {0.5, 0}, {1, 1}, {0, 1}};
  EXPECT_EQ(convex_hull(square_with_midpoint).n, 4);
}

TEST(ConvexPolygon, ClosestPointMatchesBruteForce) {
  Pcg32 rng(17, 4);
  for (int trial = 0; trial < 100; ++trial) {
    const ConvexPolygon poly = random_convex(rng, vec2(0.0), 2.0);
    if (poly.n < 3) continue;
    const vec2 p(3 * (rng.uniform() - 0.5), 3 * (rng.uniform() - 0.5));
    const vec2 q = closest_point(poly, p);
    if (contains(poly, p)) {
      EXPECT_EQ(q, p);
      continue;
    }
    // Brute force: densely sampled edges.
    double best = INFINITY;
    for (int i = 0; i < poly.n; ++i) {
      for (int s = 0; s <= 2000; ++s) {
        const vec2 e = mix(poly.v[i], poly.v[(i + 1) % poly.n], s / 2000.0);
        best = std::min(best, length(e - p));
      }
    }
    EXPECT_LE(length(q - p), best + 1e-12);
    EXPECT_GE(length(q - p), best - 2.5e-3);  // the sampling step
  }
  // Degenerate polygons: a segment and a point.
  ConvexPolygon seg = convex_hull(std::vector<vec2>{{0, 0}, {2, 0}});
  EXPECT_EQ(closest_point(seg, vec2(1, 1)), vec2(1, 0));
  EXPECT_EQ(closest_point(seg, vec2(3, 1)), vec2(2, 0));
  ConvexPolygon pt = convex_hull(std::vector<vec2>{{0.5, 0.25}});
  EXPECT_EQ(closest_point(pt, vec2(3, 1)), vec2(0.5, 0.25));
}

TEST(ConvexPolygon, HalfPlaneClipAreaMatchesMonteCarlo) {
  Pcg32 rng(23, 5);
  for (int trial = 0; trial < 50; ++trial) {
    const ConvexPolygon poly = random_convex(rng, vec2(0.0), 2.0);
    if (poly.n < 3) continue;
    const double ang = kTwoPi * rng.uniform();
    const vec2 a(std::cos(ang), std::sin(ang));
    const double c = rng.uniform() - 0.5;
    const ConvexPolygon clipped = clip_half_plane(poly, a, c);
    const double area = clipped.n >= 3 ? polygon_area(clipped.vertices()) : 0.0;
    long hits = 0;
    const int n = 40000;
    for (int k = 0; k < n; ++k) {
      const vec2 p(2 * rng.uniform() - 1, 2 * rng.uniform() - 1);
      hits += contains(poly, p) && dot(a, p) + c >= 0;
    }
    const double f = double(hits) / n;
    EXPECT_NEAR(area, 4 * f, 4 * 5 * std::sqrt(std::max(f * (1 - f), 1.0 / n) / n));
  }
}

}  // namespace
}  // namespace sg
