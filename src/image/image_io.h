// Reading and writing images. The format follows the file extension:
//   .exr  OpenEXR, one 32-bit float channel "Y" (linear), ZIP-compressed; read back.
//   .pfm  Portable Float Map, "Pf" (grey), little-endian; read back ("PF" colour files are
//         read too, as the mean of their three channels).
//   .png  8-bit sRGB picture for viewing (exposure in stops); written only.
// Every write goes through a temporary file and a rename (base/atomic_file.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"

namespace sg {

enum class ImageFormat { exr, pfm, png };

// The format of `path` by extension; throws sg::Error naming the path if unknown.
ImageFormat image_format_of(const std::string& path);

struct WriteOptions {
  double exposure = 0.0;  // stops, PNG only
};

void write_image(const std::string& path, const Image& img, const WriteOptions& opt = {});
Image read_image(const std::string& path);

// An 8-bit RGB picture (rows top to bottom) as PNG.
void write_png_rgb8(const std::string& path, int width, int height,
                    const std::vector<uint8_t>& rgb);

// PFM in memory (used by the writer and by tests).
std::string encode_pfm(const Image& img);
Image decode_pfm(const std::string& bytes, const std::string& name_for_errors);

}  // namespace sg
