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

// A mask per frame: each frame's RMSE over its own pixels, each change over the later
// frame's pixels.
TEST(Metrics, MasksPerFrameTakeEachFramesOwnPixels) {
  // Two pixels; the test image errs by 0.1 on pixel 0 and 0.3 on pixel 1 in frame 0, by
  // 0.2 and 0.6 in frame 1 (the reference is 0): the changes differ (0.1 and 0.3), so the
  // temporal error tells which frame's mask it took.
  Image a0(2, 1), a1(2, 1);
  a0.data = {0.1f, 0.3f};
  a1.data = {0.2f, 0.6f};
  const std::vector<Image> a = {a0, a1}, ref(2, Image(2, 1, 0.0f));
  const std::vector<unsigned char> first = {1, 0}, second = {0, 1};
  const SequenceMetrics m = compare_sequences(a, ref, 1.0, {&first, &second});
  EXPECT_NEAR(m.frames[0].rmse, 0.1, 1e-7);
  EXPECT_NEAR(m.frames[1].rmse, 0.6, 1e-7);
  EXPECT_NEAR(m.rmse, std::sqrt((0.01 + 0.36) / 2), 1e-7);
  EXPECT_NEAR(m.temporal_error, 0.3, 1e-7);  // pixel 1's change, 0.3 -> 0.6
  // Null masks: every pixel, as the one-mask form.
  const SequenceMetrics all = compare_sequences(a, ref, 1.0, {nullptr, nullptr});
  EXPECT_DOUBLE_EQ(all.rmse, compare_sequences(a, ref).rmse);
  const std::vector<const std::vector<unsigned char>*> one = {&first};
  EXPECT_THROW(compare_sequences(a, ref, 1.0, one), Error);
}

// A grey image as three equal channels.
Image as_rgb(const Image& g) {
  Image c = Image::with_channels(g.width, g.height, 3);
  for (int k = 0; k < 3; ++k)
    c.set_channel(k, g);
  return c;
}

Image pattern(int w, int h, float phase) {
  Image img(w, h);
  for (size_t p = 0; p < img.size(); ++p)
    img.data[p] = 0.5f + 0.5f * std::sin(0.7f * p + phase) * (p % 3 == 0 ? 1.0f : 0.01f);
  return img;
}

TEST(Metrics, GreyAsOneOrThreeEqualChannelsGivesTheSameFigures) {
  const std::vector<Image> a = {pattern(9, 5, 0), pattern(9, 5, 1), pattern(9, 5, 2)};
  const std::vector<Image> b = {pattern(9, 5, 0.1f), pattern(9, 5, 0.9f), pattern(9, 5, 2.3f)};
  std::vector<Image> a3, b3;
  for (size_t f = 0; f < a.size(); ++f) {
    a3.push_back(as_rgb(a[f]));
    b3.push_back(as_rgb(b[f]));
  }
  std::vector<unsigned char> mask(45, 1);
  mask[3] = mask[17] = 0;
  using Mask = const std::vector<unsigned char>*;
  for (Mask m : {Mask(nullptr), Mask(&mask)}) {
    const ImageMetrics g = compare_images(a[1], b[1], 1.0, m);
    for (const Image* other :
         {static_cast<const Image*>(&b3[1]), &b[1]}) {  // 3 against 3, and 3 against a grey 1
      const ImageMetrics c = compare_images(a3[1], *other, 1.0, m);
      EXPECT_NEAR(c.rmse, g.rmse, 1e-15);
      EXPECT_NEAR(c.psnr, g.psnr, 1e-12);
      EXPECT_NEAR(c.mean_a, g.mean_a, 1e-15);
      EXPECT_NEAR(c.mean_b, g.mean_b, 1e-15);
      EXPECT_EQ(c.max_abs, g.max_abs);
      EXPECT_EQ(c.pixels, g.pixels);
      ASSERT_EQ(c.channels.size(), 3u);
      for (const ChannelMetrics& ch : c.channels)
        EXPECT_NEAR(ch.rmse, g.rmse, 1e-15);
    }
    ASSERT_EQ(g.channels.size(), 1u);
    EXPECT_EQ(g.channels[0].rmse, g.rmse);
    const SequenceMetrics gs = compare_sequences(a, b, 1.0, m);
    const SequenceMetrics cs = compare_sequences(a3, b3, 1.0, m);
    EXPECT_NEAR(cs.rmse, gs.rmse, 1e-15);
    EXPECT_NEAR(cs.temporal_error, gs.temporal_error, 1e-15);
    EXPECT_NEAR(cs.flicker_a, gs.flicker_a, 1e-15);
    EXPECT_NEAR(cs.flicker_b, gs.flicker_b, 1e-15);
    ASSERT_EQ(cs.channels.size(), 3u);
    for (const SequenceChannelMetrics& ch : cs.channels) {
      EXPECT_NEAR(ch.rmse, gs.rmse, 1e-15);
      EXPECT_NEAR(ch.temporal_error, gs.temporal_error, 1e-15);
    }
  }
}

TEST(Metrics, ColourIsTakenOverAllChannelsAndPerChannel) {
  // Differences 0.3 in R, 0 in G, -0.4 in B at one pixel of two.
  Image a = Image::with_channels(2, 1, 3), b = Image::with_channels(2, 1, 3);
  a.at(0, 0, 0) = 0.3f;
  b.at(0, 0, 2) = 0.4f;
  const ImageMetrics m = compare_images(a, b);
  EXPECT_NEAR(m.rmse, std::sqrt((0.09 + 0.16) / 6), 1e-7);  // over the 3 W H values
  EXPECT_NEAR(m.max_abs, 0.4, 1e-7);
  EXPECT_NEAR(m.mean_a, 0.3 / 6, 1e-8);
  ASSERT_EQ(m.channels.size(), 3u);
  EXPECT_NEAR(m.channels[0].rmse, std::sqrt(0.09 / 2), 1e-7);
  EXPECT_EQ(m.channels[1].rmse, 0.0);
  EXPECT_NEAR(m.channels[2].rmse, std::sqrt(0.16 / 2), 1e-7);
  EXPECT_NEAR(m.channels[2].mean_b, 0.2, 1e-7);
  // Temporal error per channel: only G changes, by 0.5, where the reference is still.
  Image g1 = a;
  g1.at(1, 0, 1) = 0.5f;
  const SequenceMetrics s = compare_sequences({a, g1}, {b, b});
  EXPECT_NEAR(s.temporal_error, std::sqrt(0.25 / 6), 1e-7);
  EXPECT_NEAR(s.channels[1].temporal_error, std::sqrt(0.25 / 2), 1e-7);
  EXPECT_EQ(s.channels[0].temporal_error, 0.0);
  EXPECT_NEAR(s.channels[1].flicker_a, 0.25, 1e-7);
  EXPECT_THROW(compare_images(a, Image::with_channels(3, 1, 3)), Error);
}

}  // namespace
}  // namespace sg
