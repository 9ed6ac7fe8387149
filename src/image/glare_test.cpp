// The display pipeline: glare kernels carry unit energy and the glare moves light without
// creating it; the ACES fit has its published values and is monotone.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "image/display.h"
#include "image/glare.h"
#include "image/tonemap.h"

namespace sg {
namespace {

double sum(const Image& img) {
  return std::accumulate(img.data.begin(), img.data.end(), 0.0);
}

TEST(Glare, GaussianKernelHasUnitSumAndItsVariance) {
  for (double sigma : {0.7, 2.0, 5.5}) {
    const auto k = gaussian_kernel(sigma);
    const int r = static_cast<int>(k.size() / 2);
    double s = 0, var = 0;
    for (int t = -r; t <= r; ++t) {
      s += k[t + r];
      var += t * t * k[t + r];
      EXPECT_DOUBLE_EQ(k[t + r], k[r - t]);
    }
    EXPECT_NEAR(s, 1.0, 1e-12);
    // Truncation at 3 sigma and sampling change the variance by a few percent at most.
    EXPECT_NEAR(var, sigma * sigma, 0.04 * sigma * sigma + 0.1) << sigma;
  }
  EXPECT_EQ(gaussian_kernel(0).size(), 1u);
}

TEST(Glare, StreakKernelIsAnExponentialOfUnitSum) {
  const double L = 3.0;
  const auto k = streak_kernel(L);
  const int r = static_cast<int>(k.size() / 2);
  EXPECT_EQ(r, 12);
  EXPECT_NEAR(std::accumulate(k.begin(), k.end(), 0.0), 1.0, 1e-12);
  for (int t = 0; t < r; ++t)
    EXPECT_NEAR(k[r + t + 1] / k[r + t], std::exp(-1.0 / L), 1e-12);
}

TEST(Glare, BlursKeepTheEnergyOfAnInteriorImpulse) {
  Image img(81, 61);
  img.at(40, 30) = 5.0f;
  EXPECT_NEAR(sum(gaussian_blur(img, 4.0)), 5.0, 1e-4);
  const Image s = streak_blur(img, vec2(std::cos(0.3), std::sin(0.3)), 4.0);
  EXPECT_NEAR(sum(s), 5.0, 1e-4);
  // A horizontal streak stays on its row and follows the kernel.
  const Image hz = streak_blur(img, vec2(1, 0), 2.0);
  const auto k = streak_kernel(2.0);
  const int r = static_cast<int>(k.size() / 2);
  for (int i = 0; i < img.width; ++i) {
    const int t = i - 40;
    EXPECT_NEAR(hz.at(i, 30), std::abs(t) <= r ? 5.0 * k[t + r] : 0.0, 1e-6) << i;
    EXPECT_EQ(hz.at(i, 29), 0.0f);
  }
}

TEST(Glare, MovesLightAboveTheThresholdAndCreatesNone) {
  GlareSettings g;  // the defaults of the report
  Image img(200, 120);
  img.at(100, 60) = 40.0f;
  img.at(90, 70) = 3.0f;
  img.at(10, 10) = 0.5f;  // below the threshold: untouched
  const Image out = apply_glare(img, g);
  EXPECT_NEAR(sum(out), sum(img), 1e-3 * sum(img));
  EXPECT_FLOAT_EQ(out.at(10, 10), 0.5f);
  EXPECT_LT(out.at(100, 60), 40.0f);
  EXPECT_GT(out.at(100, 60), 1.0f);
  // The bloom reaches several pixels away, the star further along its streaks.
  EXPECT_GT(out.at(106, 60), 1e-4f);
  const double a = g.star_angle_deg * 3.14159265358979 / 180;
  const int sx = 100 + static_cast<int>(std::lround(12 * std::cos(a)));
  const int sy = 60 + static_cast<int>(std::lround(12 * std::sin(a)));
  EXPECT_GT(out.at(sx, sy), out.at(100, 72));  // on a streak vs off it, same distance
  // Nothing above the threshold: the image as it was.
  Image dim(20, 10, 0.3f);
  EXPECT_EQ(apply_glare(dim, g).data, dim.data);
}

TEST(Tonemap, AcesFitKnownValuesAndMonotone) {
  EXPECT_EQ(aces_filmic(0.0), 0.0);
  EXPECT_NEAR(aces_filmic(1.0), 2.54 / 3.16, 1e-12);
  EXPECT_NEAR(aces_filmic(0.5), 0.6425 / 1.0425, 1e-12);
  EXPECT_NEAR(aces_filmic(0.18), 0.18 * (2.51 * 0.18 + 0.03) / (0.18 * (2.43 * 0.18 + 0.59) + 0.14),
              1e-12);
  EXPECT_EQ(aces_filmic(8.0), 1.0);  // above x = 7.24 the fit exceeds 1: clamped
  EXPECT_EQ(aces_filmic(-1.0), 0.0);
  EXPECT_EQ(aces_filmic(INFINITY), 1.0);
  double prev = -1;
  for (double x = 0; x < 20; x += 0.01) {
    const double f = aces_filmic(x);
    EXPECT_GE(f, prev) << x;
    prev = f;
  }
  // The unclamped fit crosses 1 at x = (0.56 + sqrt(0.3584)) / 0.16.
  const double x1 = (0.56 + std::sqrt(0.3584)) / 0.16;
  EXPECT_LT(aces_filmic(x1 - 1e-6), 1.0);
  EXPECT_EQ(aces_filmic(x1 + 1e-6), 1.0);
}

TEST(Tonemap, DisplayPipelineWithoutGlare) {
  Image img(3, 1);
  img.at(0, 0) = 0.0f;
  img.at(1, 0) = 0.5f;
  img.at(2, 0) = NAN;
  DisplaySettings s;
  s.exposure = 1.0;  // 0.5 -> 1.0
  s.glare = false;
  const auto px = display_srgb8(img, s);
  EXPECT_EQ(px[0], 0);
  EXPECT_EQ(px[1], std::lround(255 * srgb_encode(2.54 / 3.16)));
  EXPECT_EQ(px[2], 255);
}

}  // namespace
}  // namespace sg
