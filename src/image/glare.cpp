#include "image/glare.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sg {

std::vector<double> gaussian_kernel(double sigma_px) {
  if (!(sigma_px > 0)) return {1.0};
  const int r = static_cast<int>(std::ceil(3 * sigma_px));
  std::vector<double> k(2 * r + 1);
  double sum = 0;
  for (int t = -r; t <= r; ++t)
    sum += k[t + r] = std::exp(-0.5 * t * t / (sigma_px * sigma_px));
  for (double& v : k)
    v /= sum;
  return k;
}

std::vector<double> streak_kernel(double length_px) {
  if (!(length_px > 0)) return {1.0};
  const int r = static_cast<int>(std::ceil(4 * length_px));
  std::vector<double> k(2 * r + 1);
  double sum = 0;
  for (int t = -r; t <= r; ++t)
    sum += k[t + r] = std::exp(-std::abs(t) / length_px);
  for (double& v : k)
    v /= sum;
  return k;
}

Image gaussian_blur(const Image& img, double sigma_px) {
  const std::vector<double> k = gaussian_kernel(sigma_px);
  const int r = static_cast<int>(k.size() / 2), w = img.width, h = img.height;
  // Rows, then columns; zero outside the image.
  Image tmp(w, h), out(w, h);
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      double s = 0;
      for (int t = std::max(-r, -i); t <= std::min(r, w - 1 - i); ++t)
        s += k[t + r] * img.at(i + t, j);
      tmp.at(i, j) = static_cast<float>(s);
    }
  }
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      double s = 0;
      for (int t = std::max(-r, -j); t <= std::min(r, h - 1 - j); ++t)
        s += k[t + r] * tmp.at(i, j + t);
      out.at(i, j) = static_cast<float>(s);
    }
  }
  return out;
}

Image streak_blur(const Image& img, vec2 dir, double length_px) {
  const std::vector<double> k = streak_kernel(length_px);
  const int r = static_cast<int>(k.size() / 2), w = img.width, h = img.height;
  std::vector<double> acc(img.size(), 0.0);
  auto splat = [&](int i, int j, double v) {
    if (i >= 0 && i < w && j >= 0 && j < h) acc[static_cast<size_t>(j) * w + i] += v;
  };
  // Scatter from the (few) nonzero pixels: the bright part of a glint image is sparse.
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      const double v = img.at(i, j);
      if (v == 0) continue;
      for (int t = -r; t <= r; ++t) {
        const double x = i + t * dir.x, y = j + t * dir.y;
        const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
        const double fx = x - x0, fy = y - y0, e = v * k[t + r];
        splat(x0, y0, e * (1 - fx) * (1 - fy));
        splat(x0 + 1, y0, e * fx * (1 - fy));
        splat(x0, y0 + 1, e * (1 - fx) * fy);
        splat(x0 + 1, y0 + 1, e * fx * fy);
      }
    }
  }
  Image out(w, h);
  for (size_t p = 0; p < acc.size(); ++p)
    out.data[p] = static_cast<float>(acc[p]);
  return out;
}

Image apply_glare(const Image& x, const GlareSettings& g) {
  Image b(x.width, x.height);
  bool any = false;
  for (size_t p = 0; p < x.size(); ++p) {
    const double v = std::isfinite(x.data[p]) ? x.data[p] : 0.0;
    b.data[p] = static_cast<float>(std::max(0.0, v - g.threshold));
    any = any || b.data[p] > 0;
  }
  if (!any) return x;
  std::vector<double> out(x.data.begin(), x.data.end());
  double total_weight = 0;
  auto add = [&](const Image& blurred, double weight) {
    for (size_t p = 0; p < out.size(); ++p)
      out[p] += weight * blurred.data[p];
    total_weight += weight;
  };
  const double px = x.height;  // sizes are fractions of the image height
  for (const GlareBlur& blur : g.blurs)
    add(gaussian_blur(b, blur.sigma * px), blur.weight);
  if (g.star_points > 0 && g.star_weight > 0) {
    const int streaks = g.star_points / 2;
    for (int s = 0; s < streaks; ++s) {
      const double a = (g.star_angle_deg + 180.0 * s / streaks) * std::numbers::pi / 180.0;
      add(streak_blur(b, vec2(std::cos(a), std::sin(a)), g.star_length * px),
          g.star_weight / streaks);
    }
  }
  Image result(x.width, x.height);
  for (size_t p = 0; p < out.size(); ++p)
    result.data[p] = static_cast<float>(out[p] - total_weight * b.data[p]);
  return result;
}

}  // namespace sg
