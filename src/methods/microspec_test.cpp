// The micro-specular highlight: the selection of the brightest reflection, the result
// weighting, non-convex and crossing corner quads (handled by their convex hull), the zero-
// area fallback, the horizon, and calm water against the exact coverage of the mirrored
// disk per pixel.
#include "methods/microspec.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "engine/render.h"
#include "math/rng.h"
#include "shading/circle_polygon.h"
#include "shading/convex_polygon.h"
#include "testing/calm_water.h"
#include "testing/testing.h"
#include "testing/tiles.h"

namespace sg {
namespace {

const LightModel kLight(LightDesc{{0.0, 0.207912, -0.978148}, 0.27, Rgb(1.0), false});

// Corners whose reflections pass through the given light-plane points.
std::array<CornerReflection, 4> corners_at(const std::array<vec2, 4>& p) {
  std::array<CornerReflection, 4> c;
  for (int k = 0; k < 4; ++k) {
    c[k].hit = true;
    c[k].r = kLight.from_plane(p[k]);
    c[k].v = vec3(0, 0.2, 1);
  }
  return c;
}

// The light-plane point of a reflection.
vec2 plane(const vec3& r) {
  return kLight.to_plane(r);
}

TEST(Microspec, CentreInsideSelectsTheCentreAndWeightsByAreaRatio) {
  const double R = kLight.tan_radius;
  // A quad 10 R across around the centre: the disk lies inside it.
  const std::array<vec2, 4> q = {vec2(-4 * R, -5 * R), vec2(6 * R, -4 * R), vec2(5 * R, 5 * R),
                                 vec2(-5 * R, 4 * R)};
  for (MicrospecArea mode : {MicrospecArea::exact, MicrospecArea::approx}) {
    const MicrospecFractions f = microspec_fractions(kLight, corners_at(q), mode);
    EXPECT_LT(length(plane(f.brightest)), 1e-12);
    EXPECT_NEAR(f.in_light, kPi * R * R / polygon_area(q), 1e-9);
    EXPECT_EQ(f.below, 0.0);
    EXPECT_FALSE(f.degenerate);
  }
}

TEST(Microspec, CentreOutsideSelectsTheNearestEdgePoint) {
  const double R = kLight.tan_radius;
  // The nearest point is inside an edge: the quad's left edge x = 0.5 R (partial overlap),
  // then x = 2 R (no overlap).
  for (double x0 : {0.5, 2.0}) {
    const std::array<vec2, 4> q = {vec2(x0 * R, -3 * R), vec2(8 * R, -3 * R), vec2(8 * R, 3 * R),
                                   vec2(x0 * R, 2 * R)};
    const MicrospecFractions f = microspec_fractions(kLight, corners_at(q), MicrospecArea::exact);
    const vec2 p = plane(f.brightest);
    EXPECT_NEAR(p.x, x0 * R, 1e-12);
    EXPECT_NEAR(p.y, 0.0, 1e-12);
    const double shared = circle_polygon_area(vec2(0.0), R, q);
    EXPECT_NEAR(f.in_light, shared / polygon_area(q), 1e-12);
    if (x0 > 1) {
      EXPECT_EQ(f.in_light, 0.0);
    } else {
      EXPECT_GT(f.in_light, 0.01);
    }
  }
  // The nearest point is a vertex.
  const std::array<vec2, 4> q = {vec2(0.6 * R, 0.5 * R), vec2(5 * R, 0.7 * R), vec2(5 * R, 5 * R),
                                 vec2(0.8 * R, 4 * R)};
  const MicrospecFractions f = microspec_fractions(kLight, corners_at(q), MicrospecArea::exact);
  EXPECT_LT(length(plane(f.brightest) - q[0]), 1e-12);
}

TEST(Microspec, ApproxIsAnUpperBoundExactForOneCuttingEdgeOrAPolygonInside) {
  const double R = kLight.tan_radius;
  // One edge cuts the disk: approx equals exact.
  const std::array<vec2, 4> one = {vec2(0.3 * R, -5 * R), vec2(9 * R, -5 * R), vec2(9 * R, 5 * R),
                                   vec2(0.3 * R, 5 * R)};
  const double e1 = microspec_fractions(kLight, corners_at(one), MicrospecArea::exact).in_light;
  const double a1 = microspec_fractions(kLight, corners_at(one), MicrospecArea::approx).in_light;
  EXPECT_NEAR(a1, e1, 1e-12);
  EXPECT_NEAR(a1 * polygon_area(one), disk_half_plane_area(R, -0.3 * R), 1e-18);
  // A quad inside the disk (not holding its centre): approx equals exact (the whole quad).
  const std::array<vec2, 4> in = {vec2(0.2 * R, 0.1 * R), vec2(0.6 * R, 0.1 * R),
                                  vec2(0.6 * R, 0.5 * R), vec2(0.2 * R, 0.4 * R)};
  EXPECT_NEAR(microspec_fractions(kLight, corners_at(in), MicrospecArea::approx).in_light, 1.0,
              1e-12);
  // Random quads near the disk: approx >= exact.
  Pcg32 rng(8, 8);
  int strictly = 0;
  for (int k = 0; k < 500; ++k) {
    std::array<vec2, 4> q;
    for (auto& p : q)
      p = R * vec2(6 * rng.uniform() - 3, 6 * rng.uniform() - 3);
    const double ex = microspec_fractions(kLight, corners_at(q), MicrospecArea::exact).in_light;
    const double ap = microspec_fractions(kLight, corners_at(q), MicrospecArea::approx).in_light;
    EXPECT_GE(ap, ex - 1e-12);
    strictly += ap > ex + 1e-6;
  }
  EXPECT_GT(strictly, 10);  // the approximation differs where corners cut the disk
}

TEST(Microspec, NonConvexAndCrossingQuadsUseTheConvexHull) {
  const double R = kLight.tan_radius;
  // A bow tie: corners in the order 0, 2, 1, 3 of a convex quad give the same answer as the
  // convex order.
  const std::array<vec2, 4> convex = {vec2(-2 * R, -1 * R), vec2(2 * R, -1.5 * R),
                                      vec2(1.5 * R, 0.2 * R), vec2(-1 * R, 0.5 * R)};
  const std::array<vec2, 4> bowtie = {convex[0], convex[2], convex[1], convex[3]};
  for (MicrospecArea mode : {MicrospecArea::exact, MicrospecArea::approx}) {
    const MicrospecFractions a = microspec_fractions(kLight, corners_at(convex), mode);
    const MicrospecFractions b = microspec_fractions(kLight, corners_at(bowtie), mode);
    EXPECT_NEAR(a.in_light, b.in_light, 1e-12);
    EXPECT_LT(length(a.brightest - b.brightest), 1e-15);
    EXPECT_GT(a.in_light, 0.1);
  }
  // A dart: the fourth corner inside the triangle of the others; the reflection space is
  // that triangle (the fourth corner repeats a vertex there).
  const std::array<vec2, 4> dart = {vec2(-2 * R, -2 * R), vec2(3 * R, -1 * R), vec2(-1 * R, 3 * R),
                                    vec2(0.1 * R, 0.2 * R)};
  const std::array<vec2, 4> triangle = {dart[0], dart[1], dart[2], dart[2]};
  const MicrospecFractions d = microspec_fractions(kLight, corners_at(dart), MicrospecArea::exact);
  const MicrospecFractions t =
      microspec_fractions(kLight, corners_at(triangle), MicrospecArea::exact);
  EXPECT_NEAR(d.in_light, t.in_light, 1e-12);
  EXPECT_NEAR(d.in_light,
              kPi * R * R / polygon_area(std::array<vec2, 3>{dart[0], dart[1], dart[2]}), 1e-9);
}

TEST(Microspec, HullHoldsEveryBilinearReflection) {
  // The documented reason for the hull: every bilinear interpolation of the four corner
  // vectors projects inside the hull of their images, even for folded or crossed corners.
  Pcg32 rng(12, 1);
  for (int trial = 0; trial < 200; ++trial) {
    std::array<vec3, 4> r;
    std::array<vec2, 4> img;
    for (int k = 0; k < 4; ++k) {
      r[k] = kLight.from_plane(vec2(rng.uniform() - 0.5, rng.uniform() - 0.5));
      img[k] = kLight.to_plane(r[k]);
    }
    const ConvexPolygon hull = convex_hull(img);
    for (int s = 0; s < 50; ++s) {
      const double u = rng.uniform(), v = rng.uniform();
      const vec3 b =
          (1 - u) * (1 - v) * r[0] + u * (1 - v) * r[1] + u * v * r[2] + (1 - u) * v * r[3];
      const vec2 p = kLight.to_plane(b);
      EXPECT_LT(length(closest_point(hull, p) - p), 1e-12);
    }
  }
}

TEST(Microspec, ZeroAreaFallsBackToThePointTestAtTheClosestPoint) {
  const double R = kLight.tan_radius;
  for (double x : {0.5, 1.5}) {
    const vec2 p(x * R, 0.1 * R);
    const MicrospecFractions f =
        microspec_fractions(kLight, corners_at({p, p, p, p}), MicrospecArea::exact);
    EXPECT_TRUE(f.degenerate);
    EXPECT_EQ(f.in_light, x < 1 ? 1.0 : 0.0);
    EXPECT_EQ(f.below, 0.0);
  }
  // Collinear corners (zero area) crossing the disk: the point test at the nearest point,
  // the disk's centre.
  const MicrospecFractions f = microspec_fractions(
      kLight, corners_at({vec2(-3 * R, 0), vec2(-R, 0), vec2(R, 0), vec2(3 * R, 0)}),
      MicrospecArea::exact);
  EXPECT_TRUE(f.degenerate);
  EXPECT_EQ(f.in_light, 1.0);
}

TEST(Microspec, BelowHorizonFractionIsTheAreaBeyondTheHorizonLine) {
  // A quad 0.3 across straddling the horizon line (elevation_on_plane = 0); the below
  // fraction against Monte Carlo in the plane, with the spec's test r.y <= 0 on the
  // reflection through each sample point.
  const vec2 a(kLight.e1.y, kLight.e2.y);
  const vec2 on = -kLight.L.y * a / dot(a, a);  // a point of the horizon line
  const std::array<vec2, 4> q = {on + vec2(-0.1, -0.12), on + vec2(0.2, -0.1), on + vec2(0.15, 0.1),
                                 on + vec2(-0.12, 0.2)};
  const MicrospecFractions f = microspec_fractions(kLight, corners_at(q), MicrospecArea::exact);
  const ConvexPolygon hull = convex_hull(q);
  Pcg32 rng(2, 2);
  long in = 0, below = 0;
  const int n = 200000;
  for (int k = 0; k < n; ++k) {
    const vec2 p = on + vec2(0.4 * rng.uniform() - 0.2, 0.4 * rng.uniform() - 0.2);
    if (!contains(hull, p)) continue;
    ++in;
    below += kLight.from_plane(p).y <= 0;
  }
  const double fb = double(below) / in;
  EXPECT_NEAR(f.below, fb, 5 * std::sqrt(fb * (1 - fb) / in));
  EXPECT_GT(f.below, 0.2);
  EXPECT_LT(f.below, 0.8);
  EXPECT_EQ(f.in_light, 0.0);
}

TEST(Microspec, CornersFarFromTheLightAreClipped) {
  // Two corners more than 87 degrees from the light: finite fractions, no NaN, the light
  // seen through the remaining part with a small weight; all four far: no light.
  std::array<CornerReflection, 4> c =
      corners_at({vec2(-0.01, -0.01), vec2(0.01, -0.01), vec2(0.01, 0.01), vec2(-0.01, 0.01)});
  c[2].r = normalize(-kLight.L + 0.3 * kLight.e1 + 0.5 * vec3(0, 1, 0));
  c[3].r = normalize(kLight.e1 + 0.1 * vec3(0, 1, 0));
  const MicrospecFractions f = microspec_fractions(kLight, c, MicrospecArea::exact);
  EXPECT_TRUE(std::isfinite(f.in_light) && std::isfinite(f.below));
  EXPECT_GT(f.in_light, 0.0);
  EXPECT_LT(f.in_light, 1e-3);
  for (auto& k : c)
    k.r = normalize(-kLight.L + 0.5 * vec3(0, 1, 0));
  const MicrospecFractions g = microspec_fractions(kLight, c, MicrospecArea::exact);
  EXPECT_EQ(g.in_light, 0.0);
  EXPECT_EQ(g.below, 0.0);
}

TEST(Microspec, CalmWaterMatchesTheExactCoveragePerPixel) {
  // All amplitudes 0: the corner quad is the mirrored pixel, the disk is exact, and the
  // only approximation left is the paper's constant Jacobian of the map from pixel to
  // light plane (a projective map varies across a pixel). Per pixel the value must equal
  // the exact coverage to within 1e-3, and pixels entirely in or out exactly.
  Scene s = testing::small_scene({Wave{0.0, {0.3, -1.2}, 3.4, 0.0}}, 640, 360);
  s.light.angular_radius_deg = 0.6;
  SceneModel m(s);
  double cx, cy;
  ASSERT_TRUE(m.camera.project(vec3(m.light.L.x, -m.light.L.y, m.light.L.z), cx, cy));
  MicrospecMethod method(MicrospecOptions{});
  MicrospecMethod approx(MicrospecOptions{MicrospecArea::approx});
  FrameContext ctx{m, frame_time(s, 0), 0};
  method.begin_frame(ctx);
  approx.begin_frame(ctx);
  double worst = 0, worst_approx = 0, sum = 0, sum_exact = 0;
  int partial = 0;
  for (int j = static_cast<int>(cy) - 6; j <= static_cast<int>(cy) + 6; ++j) {
    for (int i = static_cast<int>(cx) - 6; i <= static_cast<int>(cx) + 6; ++i) {
      const double exact = testing::analytic_calm_coverage(m, i, j);
      const double v = method.shade(ctx, i, j);
      worst = std::max(worst, std::fabs(v - exact));
      worst_approx = std::max(worst_approx, std::fabs(approx.shade(ctx, i, j) - exact));
      if (exact == 0 || exact == 1) {
        EXPECT_EQ(v, exact) << i << "," << j;
      }
      partial += exact > 0 && exact < 1;
      sum += v;
      sum_exact += exact;
    }
  }
  std::printf("calm water: max |microspec - exact| = %.2e (approx %.2e), sums %.6f vs %.6f\n",
              worst, worst_approx, sum, sum_exact);
  EXPECT_GT(partial, 8);
  EXPECT_LT(worst, 1e-3);
  // approx: the arc inside a pixel is replaced by its tangent (pixel 1/10 of the disk's
  // diameter here): within 2% of a pixel (measured 1.2%).
  EXPECT_LT(worst_approx, 0.02);
  EXPECT_NEAR(sum, sum_exact, 1e-3 * sum_exact);
}

TEST(Microspec, TilesEqualPixels) {
  Scene s = testing::project_scene("medium");
  s.width = 64;
  s.height = 36;
  s.surface.geometry = Geometry::displaced;
  SceneModel m(s);
  MicrospecMethod method(MicrospecOptions{});
  testing::expect_tiles_equal_pixels(m, method, 3, 7);
}

}  // namespace
}  // namespace sg
