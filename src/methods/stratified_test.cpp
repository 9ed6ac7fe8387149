// The reference estimator (stratified.h) and point sampling.
//  - Calm water: the reference equals the analytic coverage of the mirrored light disk,
//    within its Monte-Carlo error.
//  - The product-grid fast path for flat water equals direct per-sample shading with the
//    same random numbers (the angle-addition rewrite is exact up to rounding).
//  - Convergence: the error against a high-sample render falls as 1/sqrt(N) or faster.
//  - Determinism: same seed, same values, whatever the threads; another seed differs.
#include "methods/stratified.h"
#include "kernel/kernel_double.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "engine/render.h"
#include "math/rng.h"
#include "methods/point.h"
#include "methods/supersample.h"
#include "shading/radiance.h"
#include "shading/water_geometry.h"
#include "testing/calm_water.h"
#include "testing/testing.h"

namespace sg {
namespace {

TEST(Stratified, CalmWaterEqualsAnalyticCoverageOfTheMirroredDisk) {
  Scene s = testing::small_scene({Wave{0.0, {0.3, -1.2}, 3.4, 0.0}}, 640, 360);
  s.light.angular_radius_deg = 0.6;  // a disk about 5 pixels across
  SceneModel m(s);
  double cx, cy;
  ASSERT_TRUE(m.camera.project(vec3(m.light.L.x, -m.light.L.y, m.light.L.z), cx, cy));
  const int i0 = static_cast<int>(cx) - 5, j0 = static_cast<int>(cy) - 5, n = 11;
  const int seeds = 8;
  double sum_mean = 0, sum_analytic = 0, var_sum = 0;
  int partial = 0;
  for (int j = j0; j < j0 + n; ++j) {
    for (int i = i0; i < i0 + n; ++i) {
      double mean = 0, mean2 = 0;
      for (int k = 0; k < seeds; ++k) {
        FrameContext ctx{m, frame_time(s, 3), static_cast<uint64_t>(k)};
        double v = grey_value(ctx.model,
                              stratified_pixel(ctx, i, j, StratifiedSettings{{12, 12, 2}, false}));
        mean += v / seeds;
        mean2 += v * v / seeds;
      }
      const double var = std::max(0.0, mean2 - mean * mean) * seeds / (seeds - 1);
      const double exact = testing::analytic_calm_coverage(m, i, j);
      // Within 5 standard errors of the mean of 8 seeds (pixels fully inside or outside
      // have no variance and must match to the quadrature's accuracy).
      EXPECT_NEAR(mean, exact, 5 * std::sqrt(var / seeds) + 1e-9) << i << "," << j;
      sum_mean += mean;
      sum_analytic += exact;
      var_sum += var / seeds;
      partial += exact > 0 && exact < 1;
    }
  }
  EXPECT_GT(partial, 8);        // the disk's edge crosses many pixels
  EXPECT_GT(sum_analytic, 10);  // and it covers ~20 pixels in all
  EXPECT_NEAR(sum_mean, sum_analytic, 5 * std::sqrt(var_sum));
}

// The generic path: every sample traced and shaded on its own, with the random numbers
// drawn in the estimator's documented order.
double direct_pixel(const FrameContext& ctx, int i, int j, const StratifiedSettings& s) {
  const SceneModel& m = ctx.model;
  Pcg32 rng = pixel_rng(ctx.seed, ctx.time.frame, i, j);
  std::vector<double> times(s.samples.st);
  for (int q = 0; q < s.samples.st; ++q) {
    times[q] = ctx.time.start + (q + rng.uniform()) / s.samples.st * ctx.time.duration();
  }
  double sum = 0;
  const WaterGeometry water(m, ctx.time);
  for (int cy = 0; cy < s.samples.sy; ++cy) {
    for (int cx = 0; cx < s.samples.sx; ++cx) {
      double px = i + (cx + rng.uniform()) / s.samples.sx;
      double py = j + (cy + rng.uniform()) / s.samples.sy;
      for (double t : times)
        sum += grey_value(
            m, weights_along_ray(water, m.camera.position(), m.camera.direction(px, py), t));
    }
  }
  return sum / (double(s.samples.st) * s.samples.sx * s.samples.sy);
}

TEST(Stratified, FlatFastPathEqualsDirectShading) {
  Scene s = testing::project_scene("simple");  // window (300..340, 270..300) holds glints
  s.light.radiance = Rgb(50);
  s.sky = SkyDesc::constant(Rgb(0.1));
  s.surface.sea_radiance = Rgb(0.05);
  s.surface.fresnel = FresnelMode::schlick;
  SceneModel m(s);
  FrameContext ctx{m, frame_time(s, 5), 11};
  StratifiedSettings st{{3, 2, 4}, false};
  double worst = 0;
  int lit = 0;
  for (int j = 270; j < 300; ++j) {
    for (int i = 300; i < 340; ++i) {
      double a = grey_value(ctx.model, stratified_pixel(ctx, i, j, st)),
             b = direct_pixel(ctx, i, j, st);
      worst = std::max(worst, std::fabs(a - b));
      lit += a > 0.5;
    }
  }
  // Values agree to rounding; a sample whose reflection lies within ~1e-12 rad of the
  // disk's edge could flip, which none of these 29k samples do.
  EXPECT_LT(worst, 1e-12);
  EXPECT_GT(lit, 0);
}

TEST(Stratified, SampleTimesAreStratifiedAndUniform) {
  // The kernel's sample times (kernel/sampling.glsl), offsets from the display time.
  kd::Frame f{};
  f.duration = 1.0 / 30;
  const int T = 8, bins = 10, streams = 20000;
  std::vector<int> hist(bins, 0);
  for (int k = 0; k < streams; ++k) {
    kd::Pcg32 rng = kd::pixel_rng(kd::uvec2(3, 0), 4, k, 0);
    const kd::SampleTimes times = kd::draw_sample_times(rng, f, kd::SampleCounts{1, 1, T, false});
    ASSERT_EQ(times.count, T);
    for (int q = 0; q < T; ++q) {
      const double x = (times.dt[q] + f.duration) / f.duration * T - q;  // position in stratum q
      ASSERT_GE(x, 0.0);
      ASSERT_LT(x, 1.0);
      hist[static_cast<int>(x * bins)]++;
    }
  }
  double chi2 = 0, expect = double(streams) * T / bins;
  for (int h : hist)
    chi2 += sqr(h - expect) / expect;
  EXPECT_LT(chi2, 27.9);  // 0.999 quantile of chi-square with 9 degrees of freedom
  kd::Pcg32 rng = kd::pixel_rng(kd::uvec2(0, 0), 0, 0, 0);
  const kd::SampleTimes one = kd::draw_sample_times(rng, f, kd::SampleCounts{1, 1, 1, true});
  EXPECT_EQ(one.count, 1);
  EXPECT_EQ(one.dt[0], 0.0);
}

TEST(Stratified, ErrorFallsAsSamplesGrow) {
  // A 12x8 window of the simple scene where glints are, against a 32x32x32 render.
  Scene s = testing::project_scene("simple");
  SceneModel m(s);
  const int i0 = 316, j0 = 286, w = 12, h = 8;
  auto render = [&](SampleCounts n, uint64_t seed) {
    std::vector<double> v;
    FrameContext ctx{m, frame_time(s, 0), seed};
    for (int j = j0; j < j0 + h; ++j) {
      for (int i = i0; i < i0 + w; ++i)
        v.push_back(grey_value(ctx.model, stratified_pixel(ctx, i, j, {n, false})));
    }
    return v;
  };
  const auto truth = render({32, 32, 32}, 1000);
  double truth_mean = 0;
  for (double v : truth)
    truth_mean += v / truth.size();
  ASSERT_GT(truth_mean, 0.005) << "the window must contain glints";
  std::vector<double> err;
  for (int n : {2, 4, 8}) {
    double se = 0;
    int count = 0;
    for (uint64_t seed = 0; seed < 4; ++seed) {
      auto v = render({n, n, n}, seed);
      for (size_t k = 0; k < v.size(); ++k, ++count)
        se += sqr(v[k] - truth[k]);
    }
    err.push_back(std::sqrt(se / count));
  }
  std::printf("RMS error vs 32x32x32: 2x2x2 %.5f  4x4x4 %.5f  8x8x8 %.5f\n", err[0], err[1],
              err[2]);
  // N grows 8x per step: 1/sqrt(N) would divide the error by 2.83. Require at least 2.2
  // (the truth's own error, ~err(8x8x8)/sqrt(64), is negligible).
  EXPECT_GT(err[0] / err[1], 2.2) << err[0] << " " << err[1];
  EXPECT_GT(err[1] / err[2], 2.2) << err[1] << " " << err[2];
}

TEST(Stratified, DeterministicAcrossThreadsAndSeeds) {
  Scene s = testing::project_scene("high");
  s.width = 80;
  s.height = 45;
  SceneModel m(s);
  MethodOptions o;
  o.samples = {3, 3, 3};
  StratifiedMethod ref("reference", {o.samples, false});
  RenderSettings one, two, other;
  one.threads = 1;
  two.threads = 2;
  two.tile = 7;
  other.seed = 1;
  Image a = render_frame(m, ref, 4, one), b = render_frame(m, ref, 4, two);
  Image c = render_frame(m, ref, 4, other);
  EXPECT_EQ(a.data, b.data);
  EXPECT_NE(a.data, c.data);
}

TEST(Point, CentreRayAtTheDisplayTime) {
  Scene s = testing::project_scene("smooth");
  SceneModel m(s);
  FrameContext ctx{m, frame_time(s, 7), 0};
  PointMethod p;
  p.begin_frame(ctx);
  const WaterGeometry water(m, ctx.time);
  for (int j : {200, 260, 300}) {
    for (int i : {100, 320}) {
      EXPECT_EQ(
          p.shade(ctx, i, j),
          grey_value(m, weights_along_ray(water, m.camera.position(),
                                          m.camera.direction(i + 0.5, j + 0.5), s.frame_time(7))));
    }
  }
}

TEST(Supersample, OneTimeSampleIsTheDisplayTime) {
  // With T = 1 supersample samples t_f: a 1x1x1 supersample equals a point sample moved to
  // its jittered position; its value does not change with the shutter length.
  Scene s = testing::project_scene("simple");
  SceneModel m(s);
  Scene s2 = s;
  s2.animation.shutter = 0.25;
  SceneModel m2(s2);
  StratifiedSettings st{{4, 4, 1}, true};
  for (int i = 300; i < 340; ++i) {
    FrameContext a{m, frame_time(s, 2), 0}, b{m2, frame_time(s2, 2), 0};
    EXPECT_EQ(grey_value(m, stratified_pixel(a, i, 270, st)),
              grey_value(m2, stratified_pixel(b, i, 270, st)));
  }
}

}  // namespace
}  // namespace sg
