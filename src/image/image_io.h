// Reading and writing images. The format follows the file extension:
//   .exr  OpenEXR, 32-bit float channels (linear), ZIP-compressed: "Y" for a grey image,
//         "R", "G", "B" for a colour one; read back (Y, else R G B, else the first channel).
//   .pfm  Portable Float Map, little-endian: "Pf" for a grey image, "PF" for a colour one;
//         both read back (either byte order).
//   .png  8-bit sRGB picture for viewing, grey or RGB like the image: exposure in stops and
//         a clamp, or the display pipeline of the study (image/tonemap.h: glare, filmic
//         curve); written only.
// Every write goes through a temporary file and a rename (base/atomic_file.h). A pixel that
// is not finite (NaN, infinite) never reaches a file: write_image fails instead, since
// every method returns finite values on every valid scene, such a pixel is a bug.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "image/image.h"
#include "image/tonemap.h"

namespace sg {

enum class ImageFormat { exr, pfm, png };

// The format of `path` by extension; throws sg::Error naming the path if unknown.
ImageFormat image_format_of(const std::string& path);

struct WriteOptions {
  double exposure = 0.0;  // stops, PNG only
  // PNG only: the display pipeline (its own exposure, glare, filmic curve) instead of the
  // plain exposure and clamp.
  std::optional<DisplaySettings> display;
};

// Throws sg::Error naming `path` ("internal error: N of M pixels are not finite") and
// writes nothing when a pixel is NaN or infinite.
void write_image(const std::string& path, const Image& img, const WriteOptions& opt = {});
Image read_image(const std::string& path);

// The number of pixels that are NaN or infinite.
size_t count_nonfinite(const Image& img);

// An 8-bit RGB picture (rows top to bottom) as PNG.
void write_png_rgb8(const std::string& path, int width, int height,
                    const std::vector<uint8_t>& rgb);

// PFM in memory (used by the writer and by tests).
std::string encode_pfm(const Image& img);
Image decode_pfm(const std::string& bytes, const std::string& name_for_errors);

}  // namespace sg
