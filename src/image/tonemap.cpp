#include "image/tonemap.h"

#include <algorithm>
#include <cmath>

#include "image/display.h"

namespace sg {

double aces_filmic(double x) {
  if (std::isnan(x)) return 1.0;
  if (!(x > 0)) return 0.0;
  if (std::isinf(x)) return 1.0;
  // Narkowicz 2016: f(x) = x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14).
  const double f = x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14);
  return std::clamp(f, 0.0, 1.0);
}

namespace {

// The pipeline on one channel: 8-bit values, one per pixel.
std::vector<uint8_t> display_channel(const Image& img, const DisplaySettings& s) {
  const double scale = std::exp2(s.exposure);
  // A non-finite value (never a method's output) shows white and does not glare.
  Image x(img.width, img.height);
  for (size_t p = 0; p < img.size(); ++p)
    x.data[p] = std::isfinite(img.data[p]) ? static_cast<float>(img.data[p] * scale) : 0.0f;
  if (s.glare) x = apply_glare(x, s.glare_settings);
  std::vector<uint8_t> out(x.size());
  for (size_t p = 0; p < x.size(); ++p) {
    const double v = std::isfinite(img.data[p]) ? aces_filmic(x.data[p]) : 1.0;
    out[p] = static_cast<uint8_t>(std::lround(255.0 * srgb_encode(v)));
  }
  return out;
}

}  // namespace

std::vector<uint8_t> display_srgb8(const Image& img, const DisplaySettings& s) {
  if (img.channels == 1) return display_channel(img, s);
  std::vector<uint8_t> out(img.size());
  for (int c = 0; c < img.channels; ++c) {
    const std::vector<uint8_t> v = display_channel(img.channel(c), s);
    for (size_t p = 0; p < v.size(); ++p)
      out[p * img.channels + c] = v[p];
  }
  return out;
}

}  // namespace sg
