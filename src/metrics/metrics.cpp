#include "metrics/metrics.h"

#include <cmath>
#include <limits>

#include "base/error.h"

namespace sg {

double psnr_from_rmse(double rmse, double peak) {
  if (rmse <= 0) return std::numeric_limits<double>::infinity();
  return 20.0 * std::log10(peak / rmse);
}

namespace {

void check_sizes(const Image& a, const Image& b, const std::vector<unsigned char>* mask) {
  if (!a.same_size(b)) {
    throw Error("image sizes differ: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                " and " + std::to_string(b.width) + "x" + std::to_string(b.height));
  }
  if (mask && mask->size() != a.size()) throw Error("mask size differs from the image size");
}

}  // namespace

ImageMetrics compare_images(const Image& a, const Image& b, double peak,
                            const std::vector<unsigned char>* mask) {
  check_sizes(a, b, mask);
  ImageMetrics m;
  double se = 0, sa = 0, sb = 0;
  for (size_t k = 0; k < a.size(); ++k) {
    if (mask && !(*mask)[k]) continue;
    const double x = a.data[k], y = b.data[k], d = x - y;
    se += d * d;
    sa += x;
    sb += y;
    m.max_abs = std::max(m.max_abs, std::fabs(d));
    ++m.pixels;
  }
  if (m.pixels > 0) {
    m.rmse = std::sqrt(se / m.pixels);
    m.mean_a = sa / m.pixels;
    m.mean_b = sb / m.pixels;
  }
  m.psnr = psnr_from_rmse(m.rmse, peak);
  return m;
}

SequenceMetrics compare_sequences(const std::vector<Image>& a, const std::vector<Image>& b,
                                  double peak, const std::vector<unsigned char>* mask) {
  if (a.size() != b.size()) {
    throw Error("sequences differ in length: " + std::to_string(a.size()) + " and " +
                std::to_string(b.size()) + " frames");
  }
  if (a.empty()) throw Error("empty sequence");
  SequenceMetrics s;
  double se = 0;
  long n = 0;
  for (size_t f = 0; f < a.size(); ++f) {
    s.frames.push_back(compare_images(a[f], b[f], peak, mask));
    se += s.frames.back().rmse * s.frames.back().rmse * s.frames.back().pixels;
    n += s.frames.back().pixels;
  }
  s.rmse = n > 0 ? std::sqrt(se / n) : 0;
  double te = 0, fa = 0, fb = 0;
  long pairs = 0;
  for (size_t f = 1; f < a.size(); ++f) {
    for (size_t k = 0; k < a[f].size(); ++k) {
      if (mask && !(*mask)[k]) continue;
      const double da = static_cast<double>(a[f].data[k]) - a[f - 1].data[k];
      const double db = static_cast<double>(b[f].data[k]) - b[f - 1].data[k];
      te += (da - db) * (da - db);
      fa += std::fabs(da);
      fb += std::fabs(db);
      ++pairs;
    }
  }
  if (pairs > 0) {
    s.temporal_error = std::sqrt(te / pairs);
    s.flicker_a = fa / pairs;
    s.flicker_b = fb / pairs;
  }
  return s;
}

}  // namespace sg
