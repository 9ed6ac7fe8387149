#include "image/image_io.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <stb_image_write.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <sstream>

#include "base/atomic_file.h"
#include "base/error.h"
#include "image/display.h"

namespace sg {

ImageFormat image_format_of(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (ext == ".exr") return ImageFormat::exr;
  if (ext == ".pfm") return ImageFormat::pfm;
  if (ext == ".png") return ImageFormat::png;
  throw Error(path + ": unknown image format '" + ext + "' (use .exr, .pfm or .png)");
}

// ---------------------------------------------------------------------------------- PFM
std::string encode_pfm(const Image& img) {
  static_assert(std::endian::native == std::endian::little, "PFM writer assumes little endian");
  std::ostringstream out;
  out << (img.channels == 3 ? "PF" : "Pf") << "\n" << img.width << " " << img.height << "\n-1.0\n";
  std::string bytes = out.str();
  const size_t row = static_cast<size_t>(img.width) * img.channels;  // floats per row
  bytes.reserve(bytes.size() + row * sizeof(float) * img.height);
  for (int j = img.height - 1; j >= 0; --j) {  // PFM rows run bottom to top
    bytes.append(reinterpret_cast<const char*>(&img.data[static_cast<size_t>(j) * row]),
                 row * sizeof(float));
  }
  return bytes;
}

Image decode_pfm(const std::string& bytes, const std::string& name) {
  std::istringstream in(bytes);
  std::string magic;
  long w = 0, h = 0;
  double scale = 0;
  in >> magic >> w >> h >> scale;
  if (!in || (magic != "Pf" && magic != "PF")) throw Error(name + ": not a PFM file");
  if (w <= 0 || h <= 0 || w > 65536 || h > 65536) throw Error(name + ": bad PFM size");
  in.get();  // the single whitespace byte after the scale
  const int channels = magic == "PF" ? 3 : 1;
  const size_t count = static_cast<size_t>(w) * h * channels;
  const size_t offset = static_cast<size_t>(in.tellg());
  if (bytes.size() < offset + count * sizeof(float)) throw Error(name + ": truncated PFM data");
  Image img = Image::with_channels(static_cast<int>(w), static_cast<int>(h), channels);
  const size_t row = static_cast<size_t>(w) * channels;
  for (int j = 0; j < img.height; ++j) {  // PFM rows run bottom to top
    std::memcpy(&img.data[static_cast<size_t>(j) * row],
                bytes.data() + offset + static_cast<size_t>(img.height - 1 - j) * row * 4, row * 4);
  }
  if (scale > 0) {  // big-endian data
    for (float& f : img.data) {
      uint32_t u;
      std::memcpy(&u, &f, 4);
      u = __builtin_bswap32(u);
      std::memcpy(&f, &u, 4);
    }
  }
  return img;
}

// ---------------------------------------------------------------------------------- EXR
namespace {

// Channel "Y" for a grey image, "R", "G", "B" for a colour one.
std::vector<std::string> exr_channel_names(int channels) {
  return channels == 3 ? std::vector<std::string>{"R", "G", "B"} : std::vector<std::string>{"Y"};
}

void write_exr(const std::string& path, const Image& img) {
  write_file_atomic_with(path, [&](const std::string& tmp) {
    Imf::Header header(img.width, img.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    const std::vector<std::string> names = exr_channel_names(img.channels);
    for (const auto& n : names)
      header.channels().insert(n, Imf::Channel(Imf::FLOAT));
    Imf::OutputFile file(tmp.c_str(), header, 1);
    Imf::FrameBuffer fb;
    const size_t px = sizeof(float) * img.channels;
    for (size_t c = 0; c < names.size(); ++c) {
      fb.insert(names[c], Imf::Slice(Imf::FLOAT, (char*)(img.data.data() + c), px, px * img.width));
    }
    file.setFrameBuffer(fb);
    file.writePixels(img.height);
  });
}

Image read_exr(const std::string& path) {
  try {
    Imf::InputFile file(path.c_str(), 1);
    const Imath::Box2i dw = file.header().dataWindow();
    const int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
    const Imf::ChannelList& ch = file.header().channels();
    std::vector<std::string> names;
    if (ch.findChannel("Y")) {
      names = {"Y"};
    } else if (ch.findChannel("R") && ch.findChannel("G") && ch.findChannel("B")) {
      names = {"R", "G", "B"};
    } else if (ch.begin() != ch.end()) {
      names = {ch.begin().name()};
    } else {
      throw Error("no channels");
    }
    const int channels = static_cast<int>(names.size());
    Image img = Image::with_channels(w, h, channels);
    const ptrdiff_t px = static_cast<ptrdiff_t>(sizeof(float)) * channels;
    Imf::FrameBuffer fb;
    for (int c = 0; c < channels; ++c) {
      char* base = reinterpret_cast<char*>(img.data.data() + c) -
                   (static_cast<ptrdiff_t>(dw.min.x) + static_cast<ptrdiff_t>(dw.min.y) * w) * px;
      fb.insert(names[c], Imf::Slice(Imf::FLOAT, base, px, px * w));
    }
    file.setFrameBuffer(fb);
    file.readPixels(dw.min.y, dw.max.y);
    return img;
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(path + ": cannot read OpenEXR: " + e.what());
  }
}

void stb_append(void* ctx, void* data, int size) {
  static_cast<std::string*>(ctx)->append(static_cast<const char*>(data), size);
}

void write_png_bytes(const std::string& path, int w, int h, int comp, const uint8_t* px) {
  std::string bytes;
  if (!stbi_write_png_to_func(stb_append, &bytes, w, h, comp, px, w * comp)) {
    throw Error(path + ": PNG encoding failed");
  }
  write_file_atomic(path, bytes);
}

}  // namespace

void write_png_rgb8(const std::string& path, int width, int height,
                    const std::vector<uint8_t>& rgb) {
  write_png_bytes(path, width, height, 3, rgb.data());
}

size_t count_nonfinite(const Image& img) {
  size_t n = 0;
  for (float v : img.data)
    n += std::isfinite(v) ? 0 : 1;
  return n;
}

void write_image(const std::string& path, const Image& img, const WriteOptions& opt) {
  if (img.width <= 0 || img.height <= 0) throw Error(path + ": cannot write an empty image");
  if (const size_t bad = count_nonfinite(img)) {
    throw Error(path + ": internal error: " + std::to_string(bad) + " of " +
                std::to_string(img.size()) +
                " pixels are not finite (NaN or infinite); nothing written");
  }
  if (!std::isfinite(opt.exposure)) throw Error(path + ": the exposure must be finite");
  switch (image_format_of(path)) {
    case ImageFormat::exr:
      write_exr(path, img);
      return;
    case ImageFormat::pfm:
      write_file_atomic(path, encode_pfm(img));
      return;
    case ImageFormat::png: {
      auto px = opt.display ? display_srgb8(img, *opt.display) : tonemap_srgb8(img, opt.exposure);
      write_png_bytes(path, img.width, img.height, img.channels, px.data());
      return;
    }
  }
}

Image read_image(const std::string& path) {
  switch (image_format_of(path)) {
    case ImageFormat::exr:
      check_readable_file(path);  // a missing file, a folder, a device or a fifo
      return read_exr(path);
    case ImageFormat::pfm:
      return decode_pfm(read_file(path), path);
    case ImageFormat::png:
      throw Error(path + ": PNG files are pictures for viewing; compare .exr or .pfm files");
  }
  throw Error(path + ": unknown format");
}

}  // namespace sg
