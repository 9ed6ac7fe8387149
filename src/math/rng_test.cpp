// The sampling streams: uniform on [0, 1), independent between pixels, reproducible.
#include "math/rng.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace sg {
namespace {

TEST(Rng, UniformMomentsAndRange) {
  Pcg32 rng(42, 7);
  const int n = 200000;
  double sum = 0, sum2 = 0;
  std::vector<int> bins(20, 0);
  for (int k = 0; k < n; ++k) {
    double u = rng.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
    sum2 += u * u;
    bins[static_cast<int>(u * 20)]++;
  }
  EXPECT_NEAR(sum / n, 0.5, 4 * std::sqrt(1.0 / 12 / n));
  EXPECT_NEAR(sum2 / n - (sum / n) * (sum / n), 1.0 / 12, 1e-3);
  // Chi-square over 20 bins, 19 degrees of freedom: 43.8 is the 0.999 quantile.
  double chi2 = 0, expect = n / 20.0;
  for (int b : bins)
    chi2 += (b - expect) * (b - expect) / expect;
  EXPECT_LT(chi2, 43.8);
}

TEST(Rng, PixelStreamsAreReproducibleAndDistinct) {
  Pcg32 a = pixel_rng(1, 3, 10, 20), b = pixel_rng(1, 3, 10, 20);
  for (int k = 0; k < 10; ++k)
    EXPECT_EQ(a.next_u32(), b.next_u32());
  // Neighbouring pixels, frames and seeds give uncorrelated first draws.
  const int n = 4000;
  double sxy = 0;
  for (int i = 0; i < n; ++i) {
    double x = pixel_rng(1, 3, i, 0).uniform() - 0.5;
    double y = pixel_rng(1, 3, i + 1, 0).uniform() - 0.5;
    double z = pixel_rng(1, 4, i, 0).uniform() - 0.5;
    double w = pixel_rng(2, 3, i, 0).uniform() - 0.5;
    sxy += x * y + x * z + x * w;
  }
  EXPECT_NEAR(sxy / (3 * n), 0.0, 4 * (1.0 / 12) / std::sqrt(3.0 * n));
  EXPECT_NE(pixel_rng(1, 3, 5, 6).next_u32(), pixel_rng(1, 3, 6, 5).next_u32());
}

}  // namespace
}  // namespace sg
