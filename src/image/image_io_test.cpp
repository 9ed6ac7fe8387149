// Image files: EXR and PFM round trips, PFM of other writers, PNG encoding, and writes
// that are whole or nothing.
#include "image/image_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>

#include "base/atomic_file.h"
#include "base/error.h"
#include "image/display.h"
#include "image/sequence.h"
#include "testing/paths.h"

namespace sg {
namespace {
namespace fs = std::filesystem;

Image ramp(int w, int h) {
  Image img(w, h);
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i)
      img.at(i, j) = 0.001f * i + 0.5f * j + (i == 3 ? 1e-7f : 0.0f);
  }
  return img;
}

class ImageIo : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(sg::testing::binary_dir()) / "test_out" /
           ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(ImageIo, ExrAndPfmRoundTripBitExactly) {
  Image a = ramp(7, 5);
  for (const char* name : {"a.exr", "a.pfm"}) {
    write_image(path(name), a);
    Image b = read_image(path(name));
    ASSERT_EQ(b.width, 7);
    ASSERT_EQ(b.height, 5);
    EXPECT_EQ(0, std::memcmp(a.data.data(), b.data.data(), a.size() * sizeof(float))) << name;
  }
}

// A colour image: three channels that differ in every pixel, bits that a float-to-half or
// a channel mix-up would lose.
Image colour_ramp(int w, int h) {
  Image img = Image::with_channels(w, h, 3);
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      img.at(i, j, 0) = 0.001f * i + 0.5f * j + 1e-7f;
      img.at(i, j, 1) = 3.0f + 0.25f * i - 0.125f * j;
      img.at(i, j, 2) = 1e-5f * (i + 1) * (j + 2);
    }
  }
  return img;
}

TEST_F(ImageIo, ColourExrAndPfmRoundTripBitExactly) {
  const Image a = colour_ramp(7, 5);
  for (const char* name : {"c.exr", "c.pfm"}) {
    write_image(path(name), a);
    const Image b = read_image(path(name));
    ASSERT_EQ(b.width, 7);
    ASSERT_EQ(b.height, 5);
    ASSERT_EQ(b.channels, 3) << name;
    EXPECT_EQ(0, std::memcmp(a.data.data(), b.data.data(), a.size() * sizeof(float))) << name;
  }
  // A grey image stays one channel ("Y", "Pf") in both.
  write_image(path("g.exr"), ramp(3, 2));
  write_image(path("g.pfm"), ramp(3, 2));
  EXPECT_EQ(read_image(path("g.exr")).channels, 1);
  EXPECT_EQ(read_file(path("g.pfm")).substr(0, 2), "Pf");
  EXPECT_EQ(read_file(path("c.pfm")).substr(0, 2), "PF");
  EXPECT_EQ(encode_pfm(a).size(), std::string("PF\n7 5\n-1.0\n").size() + 7 * 5 * 3 * 4);
}

TEST_F(ImageIo, PfmRowsRunBottomToTop) {
  Image a(2, 2);
  a.at(0, 0) = 1;  // top-left
  std::string bytes = encode_pfm(a);
  const size_t header = std::string("Pf\n2 2\n-1.0\n").size();
  float first;
  std::memcpy(&first, bytes.data() + header, 4);
  EXPECT_EQ(first, 0.0f);  // the first stored row is the bottom row
  float third;
  std::memcpy(&third, bytes.data() + header + 8, 4);
  EXPECT_EQ(third, 1.0f);
}

TEST_F(ImageIo, ReadsBigEndianAndColourPfm) {
  std::string be = "PF\n1 1\n1.0\n";
  for (float f : {0.25f, 0.5f, 0.75f}) {
    uint32_t u;
    std::memcpy(&u, &f, 4);
    u = __builtin_bswap32(u);
    be.append(reinterpret_cast<const char*>(&u), 4);
  }
  Image img = decode_pfm(be, "x.pfm");
  ASSERT_EQ(img.channels, 3);  // colour stays colour: no mean of the channels
  EXPECT_EQ(img.at(0, 0, 0), 0.25f);
  EXPECT_EQ(img.at(0, 0, 1), 0.5f);
  EXPECT_EQ(img.at(0, 0, 2), 0.75f);
  EXPECT_THROW(decode_pfm("P6\n1 1\n255\n", "x.pfm"), Error);
  EXPECT_THROW(decode_pfm("Pf\n4 4\n-1.0\nabc", "x.pfm"), Error);
}

TEST_F(ImageIo, PngIsWrittenAndTonemapped) {
  WriteOptions exposed;
  exposed.exposure = 1.0;
  write_image(path("a.png"), ramp(4, 3), exposed);
  std::string bytes = read_file(path("a.png"));
  ASSERT_GT(bytes.size(), 8u);
  EXPECT_EQ(bytes.substr(1, 3), "PNG");
  EXPECT_NEAR(srgb_encode(0.5), 0.7353569830524495, 1e-12);
  Image one(1, 1, 0.25f);
  EXPECT_EQ(tonemap_srgb8(one, 2.0)[0], 255);  // 0.25 * 2^2 = 1
  EXPECT_EQ(tonemap_srgb8(one, -20.0)[0], 0);
  EXPECT_THROW(read_image(path("a.png")), Error);
  // Colour: three values per pixel, each channel alone.
  Image c = Image::with_channels(1, 1, 3);
  c.at(0, 0, 0) = 0.25f;
  c.at(0, 0, 2) = 1.0f;
  const auto rgb = tonemap_srgb8(c, 2.0);
  ASSERT_EQ(rgb.size(), 3u);
  EXPECT_EQ(rgb[0], 255);
  EXPECT_EQ(rgb[1], 0);
  EXPECT_EQ(rgb[2], 255);
  write_image(path("c.png"), c);
  // PNG colour type (byte 25 of the IHDR chunk): 2 = RGB, 0 = grey.
  EXPECT_EQ(read_file(path("c.png"))[25], 2);
  EXPECT_EQ(read_file(path("a.png"))[25], 0);
}

TEST_F(ImageIo, UnknownExtensionAndMissingDirectoryAreClearErrors) {
  try {
    write_image(path("a.tiff"), ramp(2, 2));
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("unknown image format '.tiff'"), std::string::npos);
  }
  try {
    write_image(path("no/such/dir/a.exr"), ramp(2, 2));
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos);
  }
  EXPECT_THROW(read_image(path("missing.exr")), Error);
  EXPECT_THROW(read_image(path("missing.pfm")), Error);
}

TEST_F(ImageIo, FailedWritesLeaveNoPartialFileAndKeepTheOldOne) {
  write_file_atomic(path("f.txt"), "old");
  EXPECT_THROW(write_file_atomic_with(path("f.txt"),
                                      [](const std::string& tmp) {
                                        write_file_atomic(tmp, "partial");
                                        throw Error("disk full");
                                      }),
               Error);
  EXPECT_EQ(read_file(path("f.txt")), "old");
  int files = 0;
  for (auto& e : fs::directory_iterator(dir_)) {
    (void)e;
    ++files;
  }
  EXPECT_EQ(files, 1);  // no temporary left behind
}

TEST_F(ImageIo, NonFinitePixelsFailTheWriteAndLeaveNoFile) {
  for (float bad : {std::nanf(""), std::numeric_limits<float>::infinity(),
                    -std::numeric_limits<float>::infinity()}) {
    Image a = ramp(4, 3);
    a.at(2, 1) = bad;
    a.at(3, 2) = bad;
    for (const char* name : {"n.exr", "n.pfm", "n.png"}) {
      try {
        write_image(path(name), a);
        FAIL() << name << " written with " << bad;
      } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  path(name) +
                      ": internal error: 2 of 12 pixels are not finite (NaN or infinite); "
                      "nothing written");
      }
      EXPECT_FALSE(fs::exists(path(name))) << name;
    }
  }
  EXPECT_TRUE(fs::is_empty(dir_));  // no temporary either
  EXPECT_EQ(count_nonfinite(ramp(4, 3)), 0u);
  WriteOptions nan_exposure;
  nan_exposure.exposure = std::nan("");
  EXPECT_THROW(write_image(path("e.png"), ramp(4, 3), nan_exposure), Error);
}

TEST_F(ImageIo, ReadingADeviceOrAFolderFailsAtOnce) {
  for (const char* name : {"/dev/zero.pfm", "/dev/zero.exr"}) {
    // /dev/zero under an image name: a symbolic link to the device.
    const std::string link = path(fs::path(name).filename().string());
    fs::create_symlink("/dev/zero", link);
    try {
      read_image(link);
      FAIL() << link;
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()),
                link + ": cannot read: not a regular file (a device, fifo or socket)");
    }
  }
  fs::create_directory(path("folder.exr"));
  EXPECT_THROW(read_image(path("folder.exr")), Error);
}

TEST_F(ImageIo, SequencePatterns) {
  EXPECT_EQ(format_frame_path("out/frame_%04d.exr", 7), "out/frame_0007.exr");
  EXPECT_EQ(format_frame_path("f%d_100%%.pfm", 12), "f12_100%.pfm");
  EXPECT_EQ(format_frame_path("f%3d.pfm", 5), "f  5.pfm");
  EXPECT_TRUE(is_frame_pattern("a_%04d.exr"));
  EXPECT_FALSE(is_frame_pattern("a.exr"));
  EXPECT_FALSE(is_frame_pattern("a_%s.exr"));
  EXPECT_THROW(format_frame_path("a_%s.exr", 1, "--out"), Error);
  EXPECT_THROW(format_frame_path("a_%d_%d.exr", 1, "--out"), Error);
  EXPECT_THROW(format_frame_path("a.exr", 1, "--out"), Error);
  for (int f = 2; f <= 4; ++f)
    write_image(format_frame_path(path("s_%02d.pfm"), f), Image(3, 2, f));
  auto seq = read_sequence(path("s_%02d.pfm"), 2, 4);
  ASSERT_EQ(seq.size(), 3u);
  EXPECT_EQ(seq[2].at(1, 1), 4.0f);
}

TEST(Display, DivergingMapEndsAndCentre) {
  auto lo = diverging_colour(-1), mid = diverging_colour(0), hi = diverging_colour(1);
  EXPECT_GT(lo[2], lo[0]);  // blue
  EXPECT_GT(hi[0], hi[2]);  // red
  EXPECT_EQ(mid[0], mid[1]);
  EXPECT_EQ(mid[1], mid[2]);
}

}  // namespace
}  // namespace sg
