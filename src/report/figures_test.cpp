// Pictures of the report: crops find the glints inside their region, grids are laid out
// as asked, error scales ignore the pixels that agree; videos are encoded by ffmpeg to
// the same bytes every time.
#include <gtest/gtest.h>

#include <filesystem>

#include "base/atomic_file.h"
#include "base/error.h"
#include "report/figures.h"
#include "report/video.h"
#include "testing/paths.h"

namespace sg {
namespace {
namespace fs = std::filesystem;

TEST(Figures, BestCropHoldsTheBrightestPartOfItsRegion) {
  Image img(40, 20);
  std::vector<unsigned char> top(img.size(), 0), bottom(img.size(), 0);
  for (int j = 0; j < 20; ++j) {
    for (int i = 0; i < 40; ++i)
      (j < 10 ? top : bottom)[size_t(j) * 40 + i] = 1;
  }
  img.at(30, 3) = 1.0f;  // in the top region
  img.at(5, 15) = 0.5f;  // in the bottom region
  img.at(6, 16) = 0.5f;
  const CropBox a = best_crop(img, top, 8, 4);
  EXPECT_TRUE(a.x <= 30 && 30 < a.x + 8 && a.y <= 3 && 3 < a.y + 4);
  const CropBox b = best_crop(img, bottom, 8, 4, &a);
  EXPECT_TRUE(b.x <= 5 && 6 < b.x + 8 && b.y <= 15 && 16 < b.y + 4);
  EXPECT_EQ(b.width, 8);
  // A window that avoids `a` when one exists.
  const CropBox c = best_crop(img, top, 8, 4, &a);
  EXPECT_TRUE(c.x + 8 <= a.x || a.x + 8 <= c.x || c.y + 4 <= a.y || a.y + 4 <= c.y);
}

TEST(Figures, GridZoomAndErrorScale) {
  Picture p(4, 2, 10);
  p.at(1, 1)[0] = 200;
  const Picture z = zoomed_crop(p, CropBox{1, 1, 2, 1}, 3, 8, 5, 0);
  EXPECT_EQ(z.width, 8);
  EXPECT_EQ(z.at(1, 1)[0], 200);  // (8-6)/2 = 1, (5-3)/2 = 1
  EXPECT_EQ(z.at(3, 3)[0], 200);
  EXPECT_EQ(z.at(4, 1)[0], 10);
  EXPECT_EQ(z.at(0, 0)[0], 0);
  const Picture g = compose_grid({{p, p, p}, {p, p, p}}, 2, 7);
  EXPECT_EQ(g.width, 3 * 4 + 2 * 2);
  EXPECT_EQ(g.height, 2 * 2 + 2);
  EXPECT_EQ(g.at(4, 0)[0], 7);
  EXPECT_EQ(g.at(7, 1)[0], 200);
  EXPECT_THROW(compose_grid({{p}, {Picture(3, 2)}}, 1, 0), Error);

  Image a(10, 10), b(10, 10);
  a.at(1, 1) = 0.5f;
  a.at(2, 2) = 0.25f;
  const std::vector<unsigned char> all(100, 1);
  EXPECT_FLOAT_EQ(error_scale(a, b, all, 1.0), 0.5f);
  EXPECT_FLOAT_EQ(error_scale(a, b, all, 0.0), 0.25f);
  EXPECT_EQ(error_scale(b, b, all, 0.98), 0.0);
}

TEST(Video, SameBytesEveryTimeAndAClearErrorWithoutFfmpeg) {
  const fs::path dir = fs::path(sg::testing::binary_dir()) / "test_out/video";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::vector<std::vector<uint8_t>> frames;
  for (int f = 0; f < 5; ++f) {
    std::vector<uint8_t> px(size_t(33) * 17);
    for (size_t k = 0; k < px.size(); ++k)
      px[k] = static_cast<uint8_t>((k * 7 + f * 40) % 256);
    frames.push_back(px);
  }
  const std::string a = (dir / "a.mp4").string(), b = (dir / "b.mp4").string();
  encode_h264(a, 33, 17, 30, frames);
  encode_h264(b, 33, 17, 30, frames);
  const std::string bytes = read_file(a);
  EXPECT_GT(bytes.size(), 100u);
  EXPECT_EQ(bytes.substr(4, 4), "ftyp");
  EXPECT_EQ(bytes, read_file(b));
  try {
    encode_h264((dir / "c.mp4").string(), 33, 17, 30, frames, "sunglint-no-such-ffmpeg");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("sunglint-no-such-ffmpeg: not found"), std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "c.mp4"));
  // RGB frames: three bytes per pixel, also the same bytes every time.
  std::vector<std::vector<uint8_t>> rgb;
  for (const auto& f : frames) {
    std::vector<uint8_t> px;
    for (uint8_t v : f)
      px.insert(px.end(), {v, static_cast<uint8_t>(255 - v), static_cast<uint8_t>(v / 2)});
    rgb.push_back(px);
  }
  encode_h264_rgb((dir / "d.mp4").string(), 33, 17, 30, rgb);
  encode_h264_rgb((dir / "e.mp4").string(), 33, 17, 30, rgb);
  EXPECT_EQ(read_file((dir / "d.mp4").string()), read_file((dir / "e.mp4").string()));
  EXPECT_NE(read_file((dir / "d.mp4").string()), bytes);
  EXPECT_THROW(encode_h264_rgb((dir / "f.mp4").string(), 33, 17, 30, frames), Error);  // grey
}

// Colour pictures: display values of three channels become RGB pixels as they are; crops
// enlarge each pixel to a kCropScale x kCropScale block.
TEST(Figures, ColourPicturesAndEnlargedCrops) {
  const std::vector<uint8_t> v = {10, 20, 30, 40, 50, 60};
  const Picture p = to_picture(2, 1, 3, v);
  EXPECT_EQ(p.rgb, v);
  const Picture g = to_picture(2, 1, 1, {7, 9});
  EXPECT_EQ(g.at(1, 0)[2], 9);
  const Picture c = enlarged_crop(p, CropBox{1, 0, 1, 1}, 2);
  ASSERT_EQ(c.width, 2);
  ASSERT_EQ(c.height, 2);
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 2; ++i)
      EXPECT_EQ(c.at(i, j)[1], 50);
  }
  // A colour image's energy (best_crop) and error scale count every channel.
  Image a = Image::with_channels(4, 1, 3), b = Image::with_channels(4, 1, 3);
  a.at(3, 0, 2) = 1.0f;
  const std::vector<unsigned char> all(4, 1);
  EXPECT_EQ(best_crop(a, all, 1, 1).x, 3);
  EXPECT_FLOAT_EQ(error_scale(a, b, all, 1.0), 1.0f / 3);
}

}  // namespace
}  // namespace sg
