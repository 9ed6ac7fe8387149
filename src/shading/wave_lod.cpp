#include "shading/wave_lod.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "shading/aliasing.h"

namespace sg {

double lod_weight(double a, double b, double x) {
  const double t = std::clamp((x - a) / (b - a), 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

void wave_lod_weights(const WaveField& waves, const mat2& J, double n_min, double n_max,
                      std::vector<double>& w) {
  w.resize(waves.size());
  for (size_t i = 0; i < waves.size(); ++i) {
    const double f = projected_frequency(vec2(waves.a[i], waves.b[i]), J, FrequencyNorm::max);
    w[i] = f > 0 ? lod_weight(n_min, n_max, 1.0 / f) : 1.0;
  }
}

double smallest_singular_value(const mat2& m) {
  const double t = dot(m[0], m[0]) + dot(m[1], m[1]);
  const double det = std::fabs(determinant(m));
  const double smax = std::sqrt(0.5 * (t + std::sqrt(std::max(t * t - 4 * det * det, 0.0))));
  return smax > 0 ? det / smax : 0;
}

SortedWaves::SortedWaves(const WaveField& w) {
  const size_t n = w.size();
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](size_t p, size_t q) {
    return std::hypot(w.a[p], w.b[p]) < std::hypot(w.a[q], w.b[q]);
  });
  std::vector<Wave> sorted(n);
  k_.resize(n);
  for (size_t q = 0; q < n; ++q) {
    const size_t i = order[q];
    sorted[q] = Wave{w.A[i], vec2(w.a[i], w.b[i]), w.c[i], w.phi[i]};
    k_[q] = std::hypot(w.a[i], w.b[i]);
  }
  for (size_t size = 16; size < n; size *= 2)
    prefixes_.emplace_back(std::vector<Wave>(sorted.begin(), sorted.begin() + long(size)));
  prefixes_.emplace_back(sorted);
  suffix_cov_.assign(n + 1, vec3(0));
  for (size_t q = n; q-- > 0;) {
    const double e = 0.5 * sorted[q].amplitude * sorted[q].amplitude;
    const vec2 k = sorted[q].wave_vector;
    suffix_cov_[q] = suffix_cov_[q + 1] + e * vec3(k.x * k.x, k.x * k.y, k.y * k.y);
  }
}

size_t SortedWaves::filtered_from(const mat2& J, double n_min) const {
  const double sigma = smallest_singular_value(J);
  if (!(sigma > 0)) return size();
  // 1.001: the bound's rounding.
  const double k = 1.001 * kTwoPi * std::sqrt(2.0) / (n_min * sigma);
  return size_t(std::lower_bound(k_.begin(), k_.end(), k) - k_.begin());
}

const WaveField& SortedWaves::prefix(size_t n) const {
  for (const WaveField& p : prefixes_)
    if (p.size() >= n) return p;
  return prefixes_.back();
}

mat2 SortedWaves::suffix_covariance(size_t i) const {
  const vec3 c = suffix_cov_[std::min(i, size())];
  return mat2(vec2(c.x, c.y), vec2(c.y, c.z));
}

}  // namespace sg
