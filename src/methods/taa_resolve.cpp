#include "methods/taa_resolve.h"

#include <algorithm>
#include <cmath>

namespace sg {

double halton(int index, int base) {
  double f = 1.0, r = 0.0;
  for (int i = index; i > 0; i /= base) {
    f /= base;
    r += f * (i % base);
  }
  return r;
}

vec2 taa_jitter(int frame, int count) {
  const int k = ((frame % count) + count) % count + 1;
  return vec2(halton(k, 2) - 0.5, halton(k, 3) - 0.5);
}

namespace {

double texel(const Image& img, int i, int j, int c) {
  return img.at(std::clamp(i, 0, img.width - 1), std::clamp(j, 0, img.height - 1), c);
}

// Catmull-Rom weights (Keys 1981, a = -1/2) of the taps at offsets -1, 0, 1, 2 for a
// fraction f in [0, 1).
void catmull_rom_weights(double f, double w[4]) {
  const double f2 = f * f, f3 = f2 * f;
  w[0] = -0.5 * f3 + f2 - 0.5 * f;
  w[1] = 1.5 * f3 - 2.5 * f2 + 1.0;
  w[2] = -1.5 * f3 + 2.0 * f2 + 0.5 * f;
  w[3] = 0.5 * f3 - 0.5 * f2;
}

}  // namespace

bool sample_history(const Image& h, const vec2& p, TaaHistoryFilter filter, double& value, int c) {
  if (!(p.x >= 0 && p.x <= h.width && p.y >= 0 && p.y <= h.height)) return false;
  const double u = p.x - 0.5, v = p.y - 0.5;
  const double fu = std::floor(u), fv = std::floor(v);
  const int i0 = static_cast<int>(fu), j0 = static_cast<int>(fv);
  const double a = u - fu, b = v - fv;
  const double t00 = texel(h, i0, j0, c), t10 = texel(h, i0 + 1, j0, c);
  const double t01 = texel(h, i0, j0 + 1, c), t11 = texel(h, i0 + 1, j0 + 1, c);
  if (filter == TaaHistoryFilter::bilinear) {
    value = (1 - b) * ((1 - a) * t00 + a * t10) + b * ((1 - a) * t01 + a * t11);
    return true;
  }
  double wu[4], wv[4];
  catmull_rom_weights(a, wu);
  catmull_rom_weights(b, wv);
  double sum = 0;
  for (int y = 0; y < 4; ++y) {
    double row = 0;
    for (int x = 0; x < 4; ++x)
      row += wu[x] * texel(h, i0 - 1 + x, j0 - 1 + y, c);
    sum += wv[y] * row;
  }
  value = std::clamp(sum, std::min({t00, t10, t01, t11}), std::max({t00, t10, t01, t11}));
  return true;
}

NeighbourhoodBox neighbourhood_box(const Image& img, int i, int j, TaaClamp mode, double gamma,
                                   int c) {
  double lo = INFINITY, hi = -INFINITY, s = 0, s2 = 0;
  int n = 0;
  for (int y = std::max(0, j - 1); y <= std::min(img.height - 1, j + 1); ++y) {
    for (int x = std::max(0, i - 1); x <= std::min(img.width - 1, i + 1); ++x) {
      const double v = img.at(x, y, c);
      lo = std::min(lo, v);
      hi = std::max(hi, v);
      s += v;
      s2 += v * v;
      ++n;
    }
  }
  if (mode == TaaClamp::none) return {-INFINITY, INFINITY};
  if (mode == TaaClamp::minmax) return {lo, hi};
  const double mu = s / n, sigma = std::sqrt(std::max(0.0, s2 / n - mu * mu));
  return {mu - gamma * sigma, mu + gamma * sigma};
}

}  // namespace sg
