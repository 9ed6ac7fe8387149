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

// The channels the comparison of a and b has: 1 when both are grey, else 3.
int check_shapes(const Image& a, const Image& b, const std::vector<unsigned char>* mask) {
  if (!a.same_size(b)) {
    throw Error("image sizes differ: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                " and " + std::to_string(b.width) + "x" + std::to_string(b.height));
  }
  for (const Image* x : {&a, &b}) {
    if (x->channels != 1 && x->channels != 3) {
      throw Error("an image has " + std::to_string(x->channels) + " channels (1 or 3 expected)");
    }
  }
  if (mask && mask->size() != a.pixels()) throw Error("mask size differs from the image size");
  return a.channels == 1 && b.channels == 1 ? 1 : 3;
}

}  // namespace

ImageMetrics compare_images(const Image& a, const Image& b, double peak,
                            const std::vector<unsigned char>* mask) {
  const int n = check_shapes(a, b, mask);
  ImageMetrics m;
  m.channels.resize(n);
  double se = 0, sa = 0, sb = 0;
  std::vector<double> cse(n, 0.0), csa(n, 0.0), csb(n, 0.0);
  for (size_t k = 0; k < a.pixels(); ++k) {
    if (mask && !(*mask)[k]) continue;
    for (int c = 0; c < n; ++c) {
      const double x = channel_value(a, k, c), y = channel_value(b, k, c), d = x - y;
      se += d * d;
      sa += x;
      sb += y;
      cse[c] += d * d;
      csa[c] += x;
      csb[c] += y;
      m.max_abs = std::max(m.max_abs, std::fabs(d));
      m.channels[c].max_abs = std::max(m.channels[c].max_abs, std::fabs(d));
    }
    ++m.pixels;
  }
  if (m.pixels > 0) {
    const double values = static_cast<double>(m.pixels) * n;
    m.rmse = std::sqrt(se / values);
    m.mean_a = sa / values;
    m.mean_b = sb / values;
    for (int c = 0; c < n; ++c) {
      m.channels[c].rmse = std::sqrt(cse[c] / m.pixels);
      m.channels[c].mean_a = csa[c] / m.pixels;
      m.channels[c].mean_b = csb[c] / m.pixels;
    }
  }
  m.psnr = psnr_from_rmse(m.rmse, peak);
  return m;
}

SequenceMetrics compare_sequences(const std::vector<Image>& a, const std::vector<Image>& b,
                                  double peak, const std::vector<unsigned char>* mask) {
  return compare_sequences(a, b, peak,
                           std::vector<const std::vector<unsigned char>*>(a.size(), mask));
}

SequenceMetrics compare_sequences(const std::vector<Image>& a, const std::vector<Image>& b,
                                  double peak,
                                  const std::vector<const std::vector<unsigned char>*>& masks) {
  if (masks.size() != a.size()) {
    throw Error("masks for " + std::to_string(masks.size()) + " frames, the sequence has " +
                std::to_string(a.size()));
  }
  if (a.size() != b.size()) {
    throw Error("sequences differ in length: " + std::to_string(a.size()) + " and " +
                std::to_string(b.size()) + " frames");
  }
  if (a.empty()) throw Error("empty sequence");
  SequenceMetrics s;
  double se = 0;
  long n = 0;
  int channels = 1;
  for (size_t f = 0; f < a.size(); ++f) {
    s.frames.push_back(compare_images(a[f], b[f], peak, masks[f]));
    const ImageMetrics& m = s.frames.back();
    const long values = m.pixels * static_cast<long>(m.channels.size());
    se += m.rmse * m.rmse * values;
    n += values;
    channels = std::max(channels, static_cast<int>(m.channels.size()));
  }
  s.rmse = n > 0 ? std::sqrt(se / n) : 0;
  s.channels.resize(channels);
  // Per channel over all frames; a grey frame counts as three equal channels.
  std::vector<double> cse(channels, 0.0), cte(channels, 0.0), cfa(channels, 0.0),
      cfb(channels, 0.0);
  long pixels = 0;
  for (const ImageMetrics& m : s.frames) {
    for (int c = 0; c < channels; ++c) {
      const ChannelMetrics& x = m.channels[std::min(c, static_cast<int>(m.channels.size()) - 1)];
      cse[c] += x.rmse * x.rmse * m.pixels;
    }
    pixels += m.pixels;
  }
  double te = 0, fa = 0, fb = 0;
  long pairs = 0;
  for (size_t f = 1; f < a.size(); ++f) {
    const std::vector<unsigned char>* mask = masks[f];
    for (size_t k = 0; k < a[f].pixels(); ++k) {
      if (mask && !(*mask)[k]) continue;
      for (int c = 0; c < channels; ++c) {
        const double da =
            static_cast<double>(channel_value(a[f], k, c)) - channel_value(a[f - 1], k, c);
        const double db =
            static_cast<double>(channel_value(b[f], k, c)) - channel_value(b[f - 1], k, c);
        te += (da - db) * (da - db);
        fa += std::fabs(da);
        fb += std::fabs(db);
        cte[c] += (da - db) * (da - db);
        cfa[c] += std::fabs(da);
        cfb[c] += std::fabs(db);
      }
      ++pairs;
    }
  }
  const double values = static_cast<double>(pairs) * channels;
  if (pairs > 0) {
    s.temporal_error = std::sqrt(te / values);
    s.flicker_a = fa / values;
    s.flicker_b = fb / values;
  }
  for (int c = 0; c < channels; ++c) {
    SequenceChannelMetrics& o = s.channels[c];
    o.rmse = pixels > 0 ? std::sqrt(cse[c] / pixels) : 0;
    if (pairs > 0) {
      o.temporal_error = std::sqrt(cte[c] / pairs);
      o.flicker_a = cfa[c] / pairs;
      o.flicker_b = cfb[c] / pairs;
    }
  }
  return s;
}

}  // namespace sg
