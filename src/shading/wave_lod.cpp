#include "shading/wave_lod.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "kernel/kernel_double.h"

namespace sg {

double lod_weight(double a, double b, double x) {
  return kd::lod_weight(a, b, x);
}

void wave_lod_weights(const WaveField& waves, const mat2& J, double n_min, double n_max,
                      std::vector<double>& w) {
  w.resize(waves.size());
  for (size_t i = 0; i < waves.size(); ++i)
    w[i] = kd::wave_lod_weight(vec2(waves.a[i], waves.b[i]), J, n_min, n_max);
}

double smallest_singular_value(const mat2& m) {
  return kd::smallest_singular_value(m);
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
  const double k = kd::lod_cutoff_wavenumber(J, n_min);
  if (!(k < kd::kRealMax)) return size();
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
