// The display pipeline on the GPU (viewer/gpu_display.h) against the CPU's display_srgb8
// (image/tonemap.h), in a headless context: grey and colour images with bright spots
// that glare (Gaussians and star streaks, near the borders too), at several exposures,
// with and without glare, with non-finite values; every byte within 1/255 (float on the
// GPU, double on the CPU), most of them equal.
#include "viewer/gpu_display.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>

#include "testing/gl_context.h"
#include "viewer/view_image.h"

namespace sg::viewer {
namespace {

class GpuDisplayTest : public sg::testing::GlTest {};

// A dim gradient with a few spots far above the glare's threshold (one at a corner, one on
// an edge), deterministic.
Image test_image(int w, int h, int channels) {
  Image img = Image::with_channels(w, h, channels);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      for (int c = 0; c < channels; ++c)
        img.at(i, j, c) = 0.02f + 0.3f * float(i) / float(w) * float(c + 1) / 3 +
                          0.1f * float((i * 7 + j * 13 + c * 5) % 11) / 11;
  const int spots[][2] = {{w / 3, h / 2}, {0, 0}, {w - 1, h / 3}, {w / 2 + 3, h - 2}};
  float level = 40;
  for (const auto& s : spots) {
    for (int c = 0; c < channels; ++c)
      img.at(s[0], s[1], c) = level * float(c + 1);
    level *= 3;
  }
  return img;
}

struct Diff {
  int max = 0;
  long unequal = 0;
};
Diff compare(const Picture& a, const Picture& b) {
  Diff d;
  EXPECT_EQ(a.rgb.size(), b.rgb.size());
  for (size_t k = 0; k < std::min(a.rgb.size(), b.rgb.size()); ++k) {
    const int e = std::abs(int(a.rgb[k]) - int(b.rgb[k]));
    d.max = std::max(d.max, e);
    d.unequal += e != 0;
  }
  return d;
}

TEST_F(GpuDisplayTest, EqualsTheCpuPipeline) {
  GpuDisplay gpu;
  for (int channels : {1, 3}) {
    for (double exposure : {-1.0, 0.0, 2.5}) {
      for (bool glare : {true, false}) {
        const Image img = test_image(97, 61, channels);
        DisplaySettings s;
        s.exposure = exposure;
        s.glare = glare;
        const Picture cpu = display_picture(img, s);
        const Picture g = gpu.picture(img, s);
        const Diff d = compare(g, cpu);
        std::cout << channels << " channels, exposure " << exposure << ", glare " << glare
                  << ": max " << d.max << "/255, " << d.unequal << " of " << cpu.rgb.size()
                  << " bytes unequal\n";
        EXPECT_LE(d.max, 1) << channels << " channels, exposure " << exposure << ", glare "
                            << glare;
        EXPECT_LT(d.unequal, long(cpu.rgb.size() / 100)) << channels << " channels";
      }
    }
  }
}

TEST_F(GpuDisplayTest, GlareAndStreaksAreThere) {
  // The check above can fail: the glare changes this picture by far more than 1/255.
  const Image img = test_image(97, 61, 3);
  DisplaySettings on, off;
  off.glare = false;
  GpuDisplay gpu;
  EXPECT_GT(compare(gpu.picture(img, on), gpu.picture(img, off)).max, 30);
  // A star without Gaussians: still the CPU's.
  DisplaySettings star;
  star.glare_settings.blurs.clear();
  star.glare_settings.star_points = 4;
  EXPECT_LE(compare(gpu.picture(img, star), display_picture(img, star)).max, 1);
}

TEST_F(GpuDisplayTest, NonFiniteShowsWhiteAndDoesNotGlare) {
  Image img = test_image(40, 30, 3);
  img.at(5, 5, 0) = std::numeric_limits<float>::quiet_NaN();
  img.at(20, 10, 1) = std::numeric_limits<float>::infinity();
  img.at(30, 20, 2) = -std::numeric_limits<float>::infinity();
  const DisplaySettings s;
  GpuDisplay gpu;
  const Picture g = gpu.picture(img, s), cpu = display_picture(img, s);
  EXPECT_LE(compare(g, cpu).max, 1);
  EXPECT_EQ(g.rgb[3 * (5 * 40 + 5) + 0], 255);
  EXPECT_EQ(g.rgb[3 * (10 * 40 + 20) + 1], 255);
}

}  // namespace
}  // namespace sg::viewer
