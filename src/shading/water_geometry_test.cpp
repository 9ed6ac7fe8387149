// The water's geometry from the kernel (shading/water_geometry.h: kernel/intersect.glsl,
// kernel/footprint.glsl, kernel/waves.glsl). The displaced first hit is checked against a
// brute-force march with a fixed step far below the wavelengths, refined by bisection, on
// the direct sum of the waves (testing/direct_waves.h); the kernel's height, gradient and
// Hessian against that sum and against central differences of one another; footprints
// against finite differences of neighbouring pixel centres.
#include "shading/water_geometry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "base/error.h"
#include "math/rng.h"
#include "scene/camera.h"
#include "testing/direct_waves.h"
#include "testing/testing.h"

namespace sg {
namespace {

// First sign change of f along the ray, marching by `step`, then 100 bisections.
double brute_force_first_hit(const WaveField& w, vec3 o, vec3 d, double t, double s_max,
                             double step) {
  auto f = [&](double s) {
    vec3 p = o + s * d;
    return p.y - testing::direct_height(w, p.x, p.z, t);
  };
  double s0 = 0, f0 = f(0);
  for (double s = step; s <= s_max; s += step) {
    double fs = f(s);
    if (fs <= 0 && f0 > 0) {
      double lo = s0, hi = s;
      for (int k = 0; k < 100; ++k) {
        double mid = 0.5 * (lo + hi);
        (f(mid) > 0 ? lo : hi) = mid;
      }
      return 0.5 * (lo + hi);
    }
    s0 = s;
    f0 = fs;
  }
  return -1;
}

// The kernel's tolerances in double (kernel/intersect.glsl: graze_depth, root_tolerance).
constexpr double kGrazeDepth = 1e-6;
constexpr double kRootTolerance = 1e-9;

// A displaced model of `waves` seen by the small test camera, and its geometry at t = 0.
struct Water {
  SceneModel m;
  WaterGeometry g;
  explicit Water(const std::vector<Wave>& waves, int w = 64, int h = 36)
      : m(displaced(testing::small_scene(waves, w, h))), g(m, FrameTime{0, 0.0, 0.0}) {}
  // Displaced, the camera moved off the origin so that the conversions between world and
  // camera-relative coordinates are exercised.
  static Scene displaced(Scene s) {
    s.surface.geometry = Geometry::displaced;
    s.camera.position += vec3(37, 0, -11);
    s.camera.look_at += vec3(37, 0, -11);
    return s;
  }
};

TEST(WaterGeometry, FlatPlane) {
  RayHit h = intersect_flat(vec3(1, 2, 3), vec3(0.5, -1, -2));
  ASSERT_TRUE(h.hit);
  EXPECT_DOUBLE_EQ(h.s, 2.0);
  EXPECT_DOUBLE_EQ(h.point.x, 2.0);
  EXPECT_DOUBLE_EQ(h.point.z, -1.0);
  EXPECT_FALSE(intersect_flat(vec3(0, 2, 0), vec3(0, 0.1, -1)).hit);
  EXPECT_FALSE(intersect_flat(vec3(0, 2, 0), vec3(0, 0, -1)).hit);
}

TEST(WaterGeometry, DisplacedMatchesBruteForceMarch) {
  // The simple scene's waves made steep (x2.5 amplitude) so that crests occlude troughs,
  // seen along the camera rays of a 64x36 image, including grazing rays near the horizon.
  auto waves = testing::project_scene("simple").surface.waves;
  for (auto& wv : waves)
    wv.amplitude *= 2.5;
  const Water water(waves);
  const WaveField& w = water.m.waves;
  const CameraModel& cam = water.m.camera;
  int hits = 0, compared = 0;
  for (int j = 18; j < 36; j += 1) {
    for (int i = 0; i < 64; i += 3) {
      vec3 d = normalize(cam.direction(i + 0.5, j + 0.5));
      const double t = 0.37 * i;
      RayHit h = water.g.intersect(cam.position(), d, t);
      const double s_max = (cam.position().y + w.amplitude_bound()) / std::max(1e-3, -d.y);
      // Step 2 mm along the ray: 1/1500 of the shortest wavelength (3 m).
      double ref = brute_force_first_hit(w, cam.position(), d, t, s_max, 0.002);
      ++compared;
      ASSERT_EQ(h.hit, ref >= 0) << i << "," << j;
      if (!h.hit) continue;
      ++hits;
      // Both are refined to ~1e-9 m in height; the slope along the ray is >= |d.y|, so
      // they agree in s to 1e-9 / |d.y| plus rounding.
      EXPECT_NEAR(h.s, ref, 1e-6) << i << "," << j;
      // Stated error: the point lies on the surface within kRootTolerance.
      vec3 p = cam.position() + h.s * d;
      EXPECT_LT(length(h.point - p), 1e-9 * (1 + h.s)) << i << "," << j;
      EXPECT_LT(std::fabs(p.y - testing::direct_height(w, p.x, p.z, t)), 10 * kRootTolerance);
      EXPECT_NEAR(h.point.y, testing::direct_height(w, h.point.x, h.point.z, t), 1e-12);
    }
  }
  EXPECT_GT(hits, compared / 2);
}

TEST(WaterGeometry, NeverSkipsAThinCrest) {
  // A ray that passes through the top 5 mm of a crest and then leaves the wave: a march
  // with a large fixed step misses it; the Lipschitz march must not.
  const Water water({Wave{0.5, {1.0, 0.0}, 0.0, 0.0}});  // h = 0.5 sin(x)
  // Crest at x = pi/2, height 0.5. Horizontal ray at y = 0.495 moving along +x.
  vec3 o(-2.0, 0.495, 0.0), d(1.0, 0.0, 0.0);
  RayHit h = water.g.intersect(o, d, 0.0);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.point.x, std::asin(0.99), 1e-8);
  // A ray just above the crest misses.
  EXPECT_FALSE(water.g.intersect(vec3(-2.0, 0.5001, 0.0), vec3(1, 0, 0), 0.0).hit);
  // The same rays a second later, when the wave has moved (c = 1: the crest at pi/2 + 1).
  const Water moving({Wave{0.5, {1.0, 0.0}, 1.0, 0.0}});
  h = moving.g.intersect(o, d, -1.0);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.point.x, std::asin(0.99) + 1.0, 1e-8);
}

TEST(WaterGeometry, StatedGrazeDepthBoundsWhatCanBeMissed) {
  // A ray that dips below a crest by less than kGrazeDepth may be missed; one that dips by
  // 10 kGrazeDepth must be found.
  const Water water({Wave{0.5, {1.0, 0.0}, 0.0, 0.0}});
  EXPECT_TRUE(water.g.intersect(vec3(-2, 0.5 - 10 * kGrazeDepth, 0), vec3(1, 0, 0), 0).hit);
}

TEST(WaterGeometry, TheMarchIsBoundedWhateverTheRay) {
  // Two waves that cancel: the water is flat (h = 0) but the slab is |y| <= 0.2. A
  // horizontal ray at y = 0.1 stays in the slab forever and never meets the water: the
  // march stops after its bound of steps (kernel/intersect.glsl) and reports a miss.
  const Water water({Wave{0.1, {1.0, 0.0}, 0.0, 0.0}, Wave{0.1, {1.0, 0.0}, 0.0, kPi}});
  EXPECT_FALSE(water.g.intersect(vec3(0, 0.1, 0), vec3(1, 0, 0), 0).hit);
  // A ray that meets the slab's floor going down hits; one that leaves upwards misses.
  EXPECT_TRUE(water.g.intersect(vec3(0, 0.1, 0), vec3(1, -0.1, 0), 0).hit);
  EXPECT_FALSE(water.g.intersect(vec3(0, 0.1, 0), vec3(1, 0.1, 0), 0).hit);
}

TEST(WaterGeometry, HeightGradientAndHessianAreTheWaves) {
  auto waves = testing::project_scene("medium").surface.waves;
  const Water water(waves);
  Pcg32 rng(7, 1);
  auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * rng.uniform(); };
  for (int q = 0; q < 50; ++q) {
    const double x = uniform(-200, 200), z = uniform(-400, 0), t = uniform(-5, 5);
    EXPECT_NEAR(water.g.height(x, z, t), testing::direct_height(water.m.waves, x, z, t), 1e-12);
    const vec2 a = water.g.gradient(x, z, t), b = testing::direct_gradient(water.m.waves, x, z, t);
    EXPECT_NEAR(a.x, b.x, 1e-12);
    EXPECT_NEAR(a.y, b.y, 1e-12);
    const Hessian ha = water.g.hessian(x, z, t),
                  hb = testing::direct_hessian(water.m.waves, x, z, t);
    EXPECT_NEAR(ha.xx, hb.xx, 1e-12);
    EXPECT_NEAR(ha.xz, hb.xz, 1e-12);
    EXPECT_NEAR(ha.zz, hb.zz, 1e-12);
  }
}

TEST(WaterGeometry, DerivativesMatchCentralDifferences) {
  // The gradient against differences of the height, the Hessian against differences of
  // the gradient.
  const Water water(testing::project_scene("medium").surface.waves);
  const WaterGeometry& w = water.g;
  Pcg32 rng(1, 1);
  for (int k = 0; k < 500; ++k) {
    double x = 200 * rng.uniform() - 100, z = -200 * rng.uniform(), t = 10 * rng.uniform();
    const double h = 1e-5;
    vec2 fd((w.height(x + h, z, t) - w.height(x - h, z, t)) / (2 * h),
            (w.height(x, z + h, t) - w.height(x, z - h, t)) / (2 * h));
    vec2 g = w.gradient(x, z, t);
    // Central differences: truncation h^2/6 |h'''| ~ 1e-10 * sum A k^3 (< 1e-9); rounding
    // 1e-16 * |h| / h ~ 1e-11. 1e-8 leaves margin.
    EXPECT_NEAR(g.x, fd.x, 1e-8);
    EXPECT_NEAR(g.y, fd.y, 1e-8);
    vec2 gx = (w.gradient(x + h, z, t) - w.gradient(x - h, z, t)) / (2 * h);
    vec2 gz = (w.gradient(x, z + h, t) - w.gradient(x, z - h, t)) / (2 * h);
    Hessian H = w.hessian(x, z, t);
    EXPECT_NEAR(H.xx, gx.x, 1e-7);
    EXPECT_NEAR(H.xz, gx.y, 1e-7);
    EXPECT_NEAR(H.xz, gz.x, 1e-7);
    EXPECT_NEAR(H.zz, gz.y, 1e-7);
  }
}

TEST(WaterGeometry, NormalsAreUnitAndAlongMinusGradient) {
  const Water water(testing::project_scene("medium").surface.waves);
  Pcg32 rng(3, 1);
  for (int k = 0; k < 200; ++k) {
    double x = 50 * rng.uniform(), z = -50 * rng.uniform(), t = rng.uniform();
    vec2 g = water.g.gradient(x, z, t);
    vec3 n = water_normal(g);
    EXPECT_NEAR(length(n), 1.0, 1e-15);
    EXPECT_NEAR(-n.x / n.y, g.x, 1e-12);
    EXPECT_NEAR(-n.z / n.y, g.y, 1e-12);
  }
}

TEST(WaterGeometry, TheWavesBoundsHold) {
  const Water water(testing::project_scene("medium").surface.waves);
  const WaveField& w = water.m.waves;
  Pcg32 rng(4, 1);
  double hmax = 0, smax = 0;
  for (int k = 0; k < 20000; ++k) {
    double x = 500 * rng.uniform(), z = -500 * rng.uniform(), t = 30 * rng.uniform();
    hmax = std::max(hmax, std::fabs(water.g.height(x, z, t)));
    smax = std::max(smax, length(water.g.gradient(x, z, t)));
  }
  EXPECT_LE(hmax, w.amplitude_bound());
  EXPECT_LE(smax, w.slope_bound());
  EXPECT_GT(hmax, 0.3 * w.amplitude_bound());  // the bounds are not absurdly loose here
}

TEST(WaterGeometryFootprint, FlatMatchesNeighbouringRays) {
  SceneModel m(testing::project_scene("simple"));
  const WaterGeometry g(m, FrameTime{0, 0.0, 0.0});
  for (double py : {190.5, 250.5, 355.5}) {
    for (double px : {20.5, 320.5}) {
      PixelFootprint f = g.footprint(px, py, 0);
      ASSERT_TRUE(f.hit);
      const double h = 1e-3;
      vec3 fx = (g.footprint(px + h, py, 0).point - g.footprint(px - h, py, 0).point) / (2 * h);
      vec3 fy = (g.footprint(px, py + h, 0).point - g.footprint(px, py - h, 0).point) / (2 * h);
      EXPECT_LT(length(fx - f.dp_dpx), 1e-6 * length(fx));
      EXPECT_LT(length(fy - f.dp_dpy), 1e-6 * length(fy));
      EXPECT_NEAR(length(f.view), 1, 1e-15);
      EXPECT_GT(dot(f.view, m.camera.position() - f.point), 0);
    }
  }
  EXPECT_FALSE(g.footprint(320.5, 10.5, 0).hit);  // sky
}

TEST(WaterGeometryFootprint, DisplacedMatchesNeighbouringRaysToFirstOrder) {
  Scene s = testing::project_scene("simple");
  s.surface.geometry = Geometry::displaced;
  SceneModel m(s);
  const WaterGeometry g(m, FrameTime{0, 0.0, 0.4});
  for (double py : {250.5, 330.5}) {
    const double px = 300.5, h = 1e-4;
    PixelFootprint f = g.footprint(px, py, 0.4);
    ASSERT_TRUE(f.hit);
    vec3 fx = (g.footprint(px + h, py, 0.4).point - g.footprint(px - h, py, 0.4).point) / (2 * h);
    // The tangent-plane transfer is exact to first order; the surface's curvature adds
    // O(h) to the difference quotient.
    EXPECT_LT(length(fx - f.dp_dpx), 1e-3 * length(fx));
    // The hit lies on the surface.
    EXPECT_NEAR(f.point.y, testing::direct_height(m.waves, f.point.x, f.point.z, 0.4), 1e-8);
  }
}

TEST(WaterGeometryFootprint, RestPlaneIsTheFlatFootprintWhateverTheGeometry) {
  Scene s = testing::project_scene("simple");
  SceneModel flat(s);
  s.surface.geometry = Geometry::displaced;
  SceneModel displaced(s);
  const WaterGeometry gf(flat, FrameTime{0, 0.0, 0.7});
  const WaterGeometry gd(displaced, FrameTime{0, 0.0, 0.7});
  for (double py : {200.5, 300.5}) {
    const PixelFootprint a = rest_plane_footprint(displaced, 100.5, py);
    const PixelFootprint b = gf.footprint(100.5, py, 0.7);
    ASSERT_TRUE(a.hit);
    EXPECT_EQ(a.point, b.point);
    EXPECT_EQ(a.dp_dpx, b.dp_dpx);
    EXPECT_EQ(a.dp_dpy, b.dp_dpy);
    EXPECT_EQ(a.point.y, 0.0);
    EXPECT_NE(gd.footprint(100.5, py, 0.7).point.y, 0.0);
  }
}

}  // namespace
}  // namespace sg
