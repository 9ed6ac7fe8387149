// Metrics on hand-made images with known answers.
#include "metrics/metrics.h"

#include <gtest/gtest.h>

#include <cmath>

#include "base/error.h"

namespace sg {
namespace {

TEST(Metrics, KnownImages) {
  Image a(2, 2, 0.0f), b(2, 2, 0.0f);
  a.at(0, 0) = 0.5f;  // differences: 0.5, -0.25, 0, 0
  b.at(1, 0) = 0.25f;
  ImageMetrics m = compare_images(a, b);
  EXPECT_DOUBLE_EQ(m.rmse, std::sqrt((0.25 + 0.0625) / 4));
  EXPECT_DOUBLE_EQ(m.max_abs, 0.5);
  EXPECT_DOUBLE_EQ(m.mean_a, 0.125);
  EXPECT_DOUBLE_EQ(m.mean_b, 0.0625);
  EXPECT_EQ(m.pixels, 4);
  EXPECT_NEAR(m.psnr, 20 * std::log10(1.0 / m.rmse), 1e-12);
  EXPECT_NEAR(compare_images(a, b, 2.0).psnr, m.psnr + 20 * std::log10(2.0), 1e-12);
  EXPECT_TRUE(std::isinf(compare_images(a, a).psnr));
  std::vector<unsigned char> mask = {1, 0, 0, 0};
  EXPECT_DOUBLE_EQ(compare_images(a, b, 1.0, &mask).rmse, 0.5);
  EXPECT_THROW(compare_images(a, Image(3, 2)), Error);
}

TEST(Metrics, TemporalErrorAndFlicker) {
  // Reference: constant 0.5. Test sequence alternates 0.4, 0.6, 0.4: its per-frame change
  // is +-0.2 where the reference has none.
  std::vector<Image> ref(3, Image(2, 1, 0.5f));
  std::vector<Image> img = {Image(2, 1, 0.4f), Image(2, 1, 0.6f), Image(2, 1, 0.4f)};
  SequenceMetrics s = compare_sequences(img, ref);
  EXPECT_NEAR(s.temporal_error, 0.2, 1e-7);
  EXPECT_NEAR(s.flicker_a, 0.2, 1e-7);
  EXPECT_DOUBLE_EQ(s.flicker_b, 0.0);
  EXPECT_NEAR(s.rmse, 0.1, 1e-7);
  ASSERT_EQ(s.frames.size(), 3u);
  // A sequence that changes exactly as the reference has no temporal error but flickers.
  std::vector<Image> moving = {Image(1, 1, 0.0f), Image(1, 1, 1.0f)};
  std::vector<Image> shifted = {Image(1, 1, 0.5f), Image(1, 1, 1.5f)};
  SequenceMetrics t = compare_sequences(shifted, moving);
  EXPECT_NEAR(t.temporal_error, 0.0, 1e-12);
  EXPECT_NEAR(t.flicker_a, 1.0, 1e-12);
  EXPECT_NEAR(t.rmse, 0.5, 1e-12);
  EXPECT_THROW(compare_sequences(img, std::vector<Image>(2, Image(2, 1))), Error);
}

}  // namespace
}  // namespace sg
