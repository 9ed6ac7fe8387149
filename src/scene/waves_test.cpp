// The wave field: analytic derivatives against finite differences, unit normals, and the
// bounds that the displaced intersection relies on.
#include "scene/waves.h"

#include <gtest/gtest.h>

#include <cmath>

#include "math/rng.h"
#include "testing/testing.h"

namespace sg {
namespace {

WaveField medium_field() {
  return WaveField(testing::project_scene("medium").surface.waves);
}

TEST(Waves, GradientMatchesCentralDifferences) {
  WaveField w = medium_field();
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
  }
}

TEST(Waves, HessianMatchesDifferencesOfTheGradient) {
  WaveField w = medium_field();
  Pcg32 rng(2, 1);
  for (int k = 0; k < 500; ++k) {
    double x = 200 * rng.uniform() - 100, z = -200 * rng.uniform(), t = 10 * rng.uniform();
    const double h = 1e-5;
    vec2 gx = (w.gradient(x + h, z, t) - w.gradient(x - h, z, t)) / (2 * h);
    vec2 gz = (w.gradient(x, z + h, t) - w.gradient(x, z - h, t)) / (2 * h);
    Hessian H = w.hessian(x, z, t);
    EXPECT_NEAR(H.xx, gx.x, 1e-7);
    EXPECT_NEAR(H.xz, gx.y, 1e-7);
    EXPECT_NEAR(H.xz, gz.x, 1e-7);
    EXPECT_NEAR(H.zz, gz.y, 1e-7);
  }
}

TEST(Waves, WeightsScaleEachWave) {
  auto waves = testing::project_scene("simple").surface.waves;
  WaveField all(waves);
  std::vector<double> weights = {1.0, 0.0, 0.25, 1.0, 0.5};
  for (size_t i = 0; i < waves.size(); ++i)
    waves[i].amplitude *= weights[i];
  WaveField scaled(waves);
  for (double x : {-3.0, 0.5, 17.0}) {
    vec2 a = all.gradient_weighted(x, -20, 1.3, weights), b = scaled.gradient(x, -20, 1.3);
    EXPECT_NEAR(a.x, b.x, 1e-15);
    EXPECT_NEAR(a.y, b.y, 1e-15);
    Hessian ha = all.hessian_weighted(x, -20, 1.3, weights), hb = scaled.hessian(x, -20, 1.3);
    EXPECT_NEAR(ha.xx, hb.xx, 1e-15);
    EXPECT_NEAR(ha.xz, hb.xz, 1e-15);
    EXPECT_NEAR(ha.zz, hb.zz, 1e-15);
  }
}

TEST(Waves, NormalsAreUnitAndAlongMinusGradient) {
  WaveField w = medium_field();
  Pcg32 rng(3, 1);
  for (int k = 0; k < 200; ++k) {
    double x = 50 * rng.uniform(), z = -50 * rng.uniform(), t = rng.uniform();
    vec2 g = w.gradient(x, z, t);
    vec3 n = normal_from_gradient(g);
    EXPECT_NEAR(length(n), 1.0, 1e-15);
    EXPECT_NEAR(-n.x / n.y, g.x, 1e-12);
    EXPECT_NEAR(-n.z / n.y, g.y, 1e-12);
  }
}

TEST(Waves, ShiftedPhasesEqualDirectEvaluation) {
  WaveField w = medium_field();
  WavePhases now, earlier, direct;
  std::vector<double> rc, rs;
  w.phases(12.0, -40.0, 2.5, now);
  w.rotation(1.0 / 30, rc, rs);
  w.shift_phases(now, rc, rs, earlier);
  w.phases(12.0, -40.0, 2.5 - 1.0 / 30, direct);
  // The phases reach ~500 rad here; their own rounding is ~500 * 2^-53 = 6e-14.
  for (size_t i = 0; i < w.size(); ++i) {
    EXPECT_NEAR(earlier.s[i], direct.s[i], 2e-13);
    EXPECT_NEAR(earlier.c[i], direct.c[i], 2e-13);
  }
  const vec2 g1 = w.gradient(earlier), g2 = w.gradient(12.0, -40.0, 2.5 - 1.0 / 30);
  EXPECT_NEAR(g1.x, g2.x, 1e-13);
  EXPECT_NEAR(g1.y, g2.y, 1e-13);
}

TEST(Waves, BoundsHold) {
  WaveField w = medium_field();
  Pcg32 rng(4, 1);
  double hmax = 0, smax = 0;
  for (int k = 0; k < 20000; ++k) {
    double x = 500 * rng.uniform(), z = -500 * rng.uniform(), t = 30 * rng.uniform();
    hmax = std::max(hmax, std::fabs(w.height(x, z, t)));
    smax = std::max(smax, length(w.gradient(x, z, t)));
  }
  EXPECT_LE(hmax, w.amplitude_bound());
  EXPECT_LE(smax, w.slope_bound());
  EXPECT_GT(hmax, 0.3 * w.amplitude_bound());  // the bounds are not absurdly loose here
}

TEST(Waves, WeightedFieldScalesAmplitudesAndBounds) {
  WaveField w({Wave{0.3, {0.5, -1.0}, 2.0, 0.1}, Wave{0.1, {2.0, 0.5}, 3.0, 0.7},
               Wave{0.05, {-3.0, 1.0}, 4.0, 2.0}});
  const std::vector<double> k = {0.5, 0.0, 1.0};
  const WaveField f = w.weighted(k);
  for (double x : {-3.0, 0.4, 7.0}) {
    const vec2 g = f.gradient(x, -2 * x, 0.3), gw = w.gradient_weighted(x, -2 * x, 0.3, k);
    EXPECT_NEAR(g.x, gw.x, 1e-15);
    EXPECT_NEAR(g.y, gw.y, 1e-15);
  }
  EXPECT_NEAR(f.amplitude_bound(), 0.15 + 0.05, 1e-15);
  EXPECT_NEAR(f.slope_bound(), 0.15 * std::sqrt(1.25) + 0.05 * std::sqrt(10.0), 1e-15);
}

}  // namespace
}  // namespace sg
