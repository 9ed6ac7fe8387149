// The temporal method (Podee et al. 2021, Sec. 3.3) against the reference where the wave
// is resolved: a telephoto view (1 degree field) of one long wave (63 m) moving fast, and
// a 4-degree light, so that the reflection varies by only ~0.07 degrees across a pixel
// (0.037 of view, 0.034 from the wave's curvature) but moves ~1 degree per frame and
// sweeps in and out of the disk.
#include "methods/staa_temporal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <new>

#include "methods/stratified.h"
#include "shading/aliasing.h"
#include "shading/radiance.h"
#include "shading/reflection_path.h"
#include "shading/water_geometry.h"
#include "testing/begun.h"
#include "testing/direct_waves.h"
#include "testing/testing.h"

namespace sg {
namespace {

Scene one_wave_telephoto() {
  Scene s = testing::small_scene({Wave{0.5, {0.0, -0.1}, 6.0, 0.3}}, 48, 27);
  s.camera = CameraDesc{{0, 2.5, 0}, {0, 0, -15}, {0, 1, 0}, 1.0, {}};
  const double e = std::atan(2.5 / 15);
  s.light = LightDesc{{0, std::sin(e), -std::cos(e)}, 4.0, Rgb(1.0), false};
  return s;
}

TEST(StaaTemporal, MatchesTheReferenceWhereTheWaveIsResolved) {
  Scene s = one_wave_telephoto();
  SceneModel m(s);
  // The wave is far below the Nyquist limit here.
  PixelFootprint fp = pixel_footprint(m, 24, 13, 0);
  ASSERT_LT(projected_frequency(vec2(0, -0.1), fp.xz_jacobian(), FrequencyNorm::max), 0.02);
  StaaTemporalMethod staa(8);
  double worst = 0, sum_err2 = 0, lit = 0;
  int n = 0;
  for (int frame = 3; frame < 9; ++frame) {
    // The reference's own noise: the spread of 4 seeds at 4x4x64.
    for (int j = 0; j < s.height; j += 3) {
      for (int i = 0; i < s.width; i += 6) {
        double mean = 0, mean2 = 0;
        for (uint64_t seed = 0; seed < 4; ++seed) {
          FrameContext c{m, frame_time(s, frame), seed};
          double v = grey_value(c.model, stratified_pixel(c, i, j, {{4, 4, 64}, false}));
          mean += v / 4;
          mean2 += v * v / 4;
        }
        const double se = std::sqrt(std::max(0.0, mean2 - mean * mean) / 3);
        FrameContext c{m, frame_time(s, frame), 0};
        const double v = testing::begun(staa, c).shade(c, i, j);
        // Within 5 standard errors of the reference's mean, plus 0.01 for the two models'
        // difference: the path is 8 great-circle arcs instead of the true curve, and the
        // pixel is one point instead of its ~0.07-degree spread of reflections (2% of the
        // disk's radius).
        EXPECT_NEAR(v, mean, 5 * se + 0.01) << "frame " << frame << " pixel " << i << "," << j;
        worst = std::max(worst, std::fabs(v - mean));
        sum_err2 += sqr(v - mean);
        lit += mean > 0.05 && mean < 0.95;
        ++n;
      }
    }
  }
  std::printf("staa-temporal vs reference: max %.4f, rms %.4f over %d pixels (%g partial)\n", worst,
              std::sqrt(sum_err2 / n), n, lit);
  EXPECT_GT(lit, 20);  // many pixels see the light for part of the shutter only
}

TEST(StaaTemporal, SegmentsConvergeToTheTimeIntegral) {
  // At one pixel, the time average computed by the temporal method with K sub-arcs tends
  // to the dense time average of the exact cone test at the pixel centre.
  Scene s = one_wave_telephoto();
  SceneModel m(s);
  int tested = 0;
  for (int frame = 0; frame < 30 && tested < 8; ++frame) {
    const FrameTime ft = frame_time(s, frame);
    for (int j = 0; j < s.height; j += 4) {
      PixelFootprint fp = pixel_footprint(m, 24.5, j + 0.5, ft.end);
      const int n = 200000;
      double dense = 0;
      for (int q = 0; q < n; ++q) {
        const double t = ft.start + (q + 0.5) / n * ft.duration();
        vec3 nn = water_normal(testing::direct_gradient(m.waves, fp.point.x, fp.point.z, t));
        dense += m.light.contains(reflect_view(nn, fp.view)) ? 1.0 / n : 0.0;
      }
      if (dense < 0.02 || dense > 0.98) continue;
      ++tested;
      ReflectionPath path;
      double e1 = 0, e32 = 0;
      for (int K : {1, 32}) {
        reflection_path(m, fp, ft, K, path);
        (K == 1 ? e1 : e32) = std::fabs(grey_value(m, temporal_weights(path)) - dense);
      }
      EXPECT_LT(e32, 2e-3) << j;  // 32 arcs follow the curved path closely
      EXPECT_LE(e32, e1 + 1e-9) << j;
    }
  }
  EXPECT_GT(tested, 2);
}

TEST(StaaTemporal, PathOfASecondSceneAtTheSameAddressIsItsOwn) {
  // Two scenes built one after the other in the same storage (as a study over several
  // scenes may): the path of the second must use the second's wave frequencies, not a
  // table this thread kept from the first.
  Scene a = one_wave_telephoto(), b = one_wave_telephoto();
  b.surface.waves[0].angular_frequency *= 2.7;
  alignas(SceneModel) unsigned char storage[sizeof(SceneModel)];
  ReflectionPath path;
  SceneModel* m = new (storage) SceneModel(a);
  const FrameTime fta = frame_time(a, 5);
  reflection_path(*m, pixel_footprint(*m, 24.5, 13.5, fta.end), fta, 2, path);
  m->~SceneModel();
  m = new (storage) SceneModel(b);
  const FrameTime ft = frame_time(b, 5);
  const PixelFootprint fp = pixel_footprint(*m, 24.5, 13.5, ft.end);
  reflection_path(*m, fp, ft, 2, path);
  for (int k = 0; k < 2; ++k) {
    const vec2 g = testing::direct_gradient(m->waves, fp.point.x, fp.point.z, path.times[k]);
    EXPECT_NEAR(path.gradients[k].x, g.x, 1e-12) << k;
    EXPECT_NEAR(path.gradients[k].y, g.y, 1e-12) << k;
  }
  m->~SceneModel();
}

}  // namespace
}  // namespace sg
