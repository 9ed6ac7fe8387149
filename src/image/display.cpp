#include "image/display.h"

#include <algorithm>
#include <cmath>

namespace sg {

double srgb_encode(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

std::vector<uint8_t> tonemap_srgb8(const Image& img, double exposure_stops) {
  const double scale = std::exp2(exposure_stops);
  std::vector<uint8_t> out(img.size());
  for (size_t k = 0; k < img.size(); ++k) {
    double v = std::isfinite(img.data[k]) ? img.data[k] * scale : 1.0;
    out[k] = static_cast<uint8_t>(std::lround(255.0 * srgb_encode(v)));
  }
  return out;
}

std::array<uint8_t, 3> diverging_colour(double t) {
  // Control points of Moreland's cool-to-warm map (sRGB, 0..255), at t = -1, -0.5, 0, 0.5, 1.
  static const double kStops[5][3] = {
      {59, 76, 192}, {141, 176, 254}, {221, 221, 221}, {244, 154, 123}, {180, 4, 38}};
  t = std::clamp(std::isfinite(t) ? t : 1.0, -1.0, 1.0);
  double x = (t + 1.0) * 2.0;  // 0..4
  int k = std::min(3, static_cast<int>(x));
  double f = x - k;
  std::array<uint8_t, 3> c{};
  for (int ch = 0; ch < 3; ++ch) {
    c[ch] = static_cast<uint8_t>(std::lround(kStops[k][ch] * (1 - f) + kStops[k + 1][ch] * f));
  }
  return c;
}

std::vector<uint8_t> difference_rgb8(const Image& a, const Image& b, double range) {
  std::vector<uint8_t> out(a.pixels() * 3);
  const double inv = range > 0 ? 1.0 / range : 0.0;
  for (size_t k = 0; k < a.pixels(); ++k) {
    auto c = diverging_colour(mean_difference(a, b, k) * inv);
    std::copy(c.begin(), c.end(), out.begin() + 3 * k);
  }
  return out;
}

}  // namespace sg
