// Ray-water intersection. The displaced first hit is checked against a brute-force march
// with a fixed step far below the wavelengths, refined by bisection.
#include "scene/intersect.h"

#include <gtest/gtest.h>

#include <cmath>

#include "math/rng.h"
#include "scene/camera.h"
#include "testing/testing.h"

namespace sg {
namespace {

// First sign change of f along the ray, marching by `step`, then 100 bisections.
double brute_force_first_hit(const WaveField& w, vec3 o, vec3 d, double t, double s_max,
                             double step) {
  auto f = [&](double s) {
    vec3 p = o + s * d;
    return p.y - w.height(p.x, p.z, t);
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

TEST(Intersect, FlatPlane) {
  RayHit h = intersect_flat(vec3(1, 2, 3), vec3(0.5, -1, -2));
  ASSERT_TRUE(h.hit);
  EXPECT_DOUBLE_EQ(h.s, 2.0);
  EXPECT_DOUBLE_EQ(h.point.x, 2.0);
  EXPECT_DOUBLE_EQ(h.point.z, -1.0);
  EXPECT_FALSE(intersect_flat(vec3(0, 2, 0), vec3(0, 0.1, -1)).hit);
  EXPECT_FALSE(intersect_flat(vec3(0, 2, 0), vec3(0, 0, -1)).hit);
}

TEST(Intersect, DisplacedMatchesBruteForceMarch) {
  // The simple scene's waves made steep (x2.5 amplitude) so that crests occlude troughs,
  // seen along the camera rays of a 64x36 image, including grazing rays near the horizon.
  auto waves = testing::project_scene("simple").surface.waves;
  for (auto& wv : waves)
    wv.amplitude *= 2.5;
  WaveField w(waves);
  Scene s = testing::small_scene(waves, 64, 36);
  CameraModel cam(s.camera, s.width, s.height);
  int hits = 0, compared = 0;
  for (int j = 18; j < 36; j += 1) {
    for (int i = 0; i < 64; i += 3) {
      vec3 d = normalize(cam.direction(i + 0.5, j + 0.5));
      const double t = 0.37 * i;
      long evals = 0;
      RayHit h = intersect_displaced(w, cam.position(), d, t, &evals);
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
      EXPECT_LT(std::fabs(p.y - w.height(p.x, p.z, t)), 10 * kRootTolerance);
      EXPECT_LT(evals, 20000);
    }
  }
  EXPECT_GT(hits, compared / 2);
}

TEST(Intersect, NeverSkipsAThinCrest) {
  // A ray that passes through the top 5 mm of a crest and then leaves the wave: a march
  // with a large fixed step misses it; the Lipschitz march must not.
  std::vector<Wave> waves = {Wave{0.5, {1.0, 0.0}, 0.0, 0.0}};  // h = 0.5 sin(x)
  WaveField w(waves);
  // Crest at x = pi/2, height 0.5. Horizontal ray at y = 0.495 moving along +x.
  vec3 o(-2.0, 0.495, 0.0), d(1.0, 0.0, 0.0);
  RayHit h = intersect_displaced(w, o, d, 0.0);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.point.x, std::asin(0.99), 1e-8);
  // A ray just above the crest misses.
  EXPECT_FALSE(intersect_displaced(w, vec3(-2.0, 0.5001, 0.0), vec3(1, 0, 0), 0.0).hit);
}

TEST(Intersect, StatedGrazeDepthBoundsWhatCanBeMissed) {
  // A ray that dips below a crest by less than kGrazeDepth may be missed; one that dips by
  // 10 kGrazeDepth must be found.
  std::vector<Wave> waves = {Wave{0.5, {1.0, 0.0}, 0.0, 0.0}};
  WaveField w(waves);
  EXPECT_TRUE(intersect_displaced(w, vec3(-2, 0.5 - 10 * kGrazeDepth, 0), vec3(1, 0, 0), 0).hit);
}

TEST(Intersect, TheMarchIsBoundedWhateverTheRay) {
  // Two waves that cancel: the water is flat (h = 0) but the slab is |y| <= 0.2. A
  // horizontal ray at y = 0.1 stays in the slab forever and never meets the water: the
  // march stops after kMaxMarchSteps steps and says so.
  WaveField w({Wave{0.1, {1.0, 0.0}, 0.0, 0.0}, Wave{0.1, {1.0, 0.0}, 0.0, kPi}});
  long evals = 0;
  const RayHit r = intersect_displaced(w, vec3(0, 0.1, 0), vec3(1, 0, 0), 0, &evals);
  EXPECT_FALSE(r.hit);
  EXPECT_TRUE(r.exhausted);
  EXPECT_LE(evals, kMaxMarchSteps + 1);
  // A ray that meets the water, or leaves the slab, is not exhausted.
  EXPECT_FALSE(intersect_displaced(w, vec3(0, 0.1, 0), vec3(1, -0.1, 0), 0).exhausted);
  EXPECT_FALSE(intersect_displaced(w, vec3(0, 0.1, 0), vec3(1, 0.1, 0), 0).exhausted);
}

}  // namespace
}  // namespace sg
