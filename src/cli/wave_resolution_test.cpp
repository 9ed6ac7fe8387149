// The resolution table of `sunglint info` on scenes whose answer is known by hand.
#include "cli/wave_resolution.h"

#include <gtest/gtest.h>

#include <cmath>

#include "math/vec.h"
#include "testing/testing.h"

namespace sg {
namespace {

// A camera 10 m above the water looking straight down with a 2 degree field of view on
// 90 x 90 pixels: every pixel covers 2 * 10 * tan(1 deg) / 90 = 3.879 mm of water in x
// (image right) and z (image down), to 0.1% over the image. A wave of wave vector k along
// x then has f = |k| * 3.879 mm / 2 pi cycles per pixel.
Scene top_down(const std::vector<double>& fx, const std::vector<double>& fdiag) {
  const double m = 2 * 10 * std::tan(radians(1.0)) / 90;
  std::vector<Wave> waves;
  for (double f : fx)
    waves.push_back(Wave{0.001, vec2(kTwoPi * f / m, 0), 1, 0});
  for (double f : fx)
    waves.push_back(Wave{0.001, vec2(0, kTwoPi * f / m), 1, 0});
  // Diagonal: each axis sees |k| / sqrt(2).
  for (double f : fdiag)
    waves.push_back(Wave{0.001, vec2(kTwoPi * f / m, kTwoPi * f / m), 1, 0});
  Scene s = testing::small_scene(waves, 90, 90);
  s.camera = CameraDesc{{0, 10, 0}, {0, 0, 0}, {0, 0, -1}, 2, {}};
  return s;
}

TEST(WaveResolution, CountsOfAViewStraightDown) {
  // Axis frequencies: 0.1, 0.29 resolved; 0.31, 0.5, 0.78 in transition; 0.82, 3 aliasing.
  const Scene s = top_down({0.1, 0.29, 0.31, 0.5, 0.78, 0.82, 3.0}, {0.25});
  AliasingParams p;
  p.start = 0.3;
  p.end = 0.8;
  const WaveResolution r = wave_resolution(s, 3, p);
  EXPECT_EQ(r.water_row_first, 0);
  ASSERT_EQ(r.bands.size(), 3u);
  for (int b = 0; b < 3; ++b) {
    EXPECT_EQ(r.bands[b].row_first, 30 * b);
    EXPECT_EQ(r.bands[b].row_last, 30 * b + 29);
    // Twice (x and z) 2 resolved, 3 in transition, 2 aliasing; the diagonal's larger axis
    // frequency is 0.25: resolved under the max-axis norm.
    EXPECT_DOUBLE_EQ(r.bands[b].resolved, 5);
    EXPECT_DOUBLE_EQ(r.bands[b].transition, 6);
    EXPECT_DOUBLE_EQ(r.bands[b].aliasing, 4);
    EXPECT_NEAR(r.bands[b].distance_first, 10, 0.01);
    // staa visits every wave below 2 pi 1.001 16 / (2 pi) = 2.55 cycles per pixel (the
    // per-pixel NDF's remainder, kernel/staa.glsl): all but the two waves at 3.
    EXPECT_DOUBLE_EQ(r.bands[b].visited, 13);
  }
  // Under the Euclidean norm the diagonal has f = 0.25 sqrt(2) = 0.354: in transition.
  p.norm = FrequencyNorm::norm;
  const WaveResolution e = wave_resolution(s, 1, p);
  ASSERT_EQ(e.bands.size(), 1u);
  EXPECT_DOUBLE_EQ(e.bands[0].resolved, 4);
  EXPECT_DOUBLE_EQ(e.bands[0].transition, 7);
  // Twice the image size halves every frequency: 0.29 -> 0.145 stays resolved, 0.31 and
  // 0.5 become resolved, 0.78 -> 0.39 stays in transition, 0.82 -> 0.41 joins it, 3 -> 1.5
  // still aliases.
  Scene big = s;
  set_image_size(big, 180, 180);
  p.norm = FrequencyNorm::max;
  const WaveResolution b = wave_resolution(big, 3, p);
  EXPECT_DOUBLE_EQ(b.bands[1].resolved, 2 * 4 + 1);
  EXPECT_DOUBLE_EQ(b.bands[1].transition, 2 * 2);
  EXPECT_DOUBLE_EQ(b.bands[1].aliasing, 2 * 1);
}

TEST(WaveResolution, OnlyRowsBelowTheHorizonAndFewerResolvedFarAway) {
  // The shared view: camera 2.5 m high looking at (0, 0, -60), 40 degree field of view,
  // 360 rows. The horizon is at tan(atan(2.5 / 60)) / tan(20 deg) = 0.1145 of the half
  // height above the centre, row 180 (1 - 0.1145) = 159.39: row 159's centre (159.5) is
  // the first below it.
  Scene s = testing::project_scene("medium");
  AliasingParams p;
  p.start = 0.3;
  p.end = 0.8;
  const WaveResolution r = wave_resolution(s, 3, p);
  EXPECT_EQ(r.water_row_first, 159);
  ASSERT_EQ(r.bands.size(), 3u);
  EXPECT_EQ(r.bands[0].row_first, 159);
  EXPECT_EQ(r.bands[2].row_last, 359);
  const double n = static_cast<double>(s.surface.waves.size());
  for (int b = 0; b < 3; ++b) {
    EXPECT_NEAR(r.bands[b].resolved + r.bands[b].transition + r.bands[b].aliasing, n, 1e-9);
    EXPECT_GT(r.bands[b].distance_first, r.bands[b].distance_last);  // top rows are farther
    // staa visits the resolved waves and those in transition, and fewer than all far away.
    EXPECT_GE(r.bands[b].visited, r.bands[b].resolved + r.bands[b].transition);
    EXPECT_LE(r.bands[b].visited, n);
    EXPECT_LE(r.bands[b].intersect, n);
  }
  EXPECT_LT(r.bands[0].visited, n);
  EXPECT_LE(r.bands[0].intersect, r.bands[2].intersect);
  EXPECT_LT(r.bands[0].resolved, r.bands[2].resolved);
  EXPECT_GT(r.bands[0].aliasing, r.bands[2].aliasing);
  // A camera looking up sees no water.
  s.camera.look_at = vec3(0, 50, -60);
  s.camera.vfov_deg = 10;
  EXPECT_EQ(wave_resolution(s, 3, p).water_row_first, -1);
}

}  // namespace
}  // namespace sg
