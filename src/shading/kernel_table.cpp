#include "shading/kernel_table.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "base/error.h"

namespace sg {
namespace {
#include "shading/kernel_table.inc"
}  // namespace

double ratio_to_t(double ratio) {
  return std::sqrt(std::max(0.0, (ratio - 1) * (ratio + 1)));
}

double table_ratio(double max_ratio, int intervals, int j) {
  if (j >= intervals) return max_ratio;
  const double t = ratio_to_t(max_ratio) * j / intervals;
  return std::sqrt(1 + t * t);
}

SymmetricKernels scale_to_ratio(const SymmetricKernels& p, double from, double to) {
  const double f = ratio_to_t(to) / ratio_to_t(from);
  SymmetricKernels q = p;
  q.center_sigma = 1 + f * (p.center_sigma - 1);
  for (KernelPair& k : q.pairs) {
    k.distance *= f;
    k.sigma = 1 + f * (k.sigma - 1);
  }
  return q;
}

namespace {

SymmetricKernels row_params(const KernelTable& table, int j) {
  const double* v = table.values.data() + static_cast<size_t>(j) * table.columns();
  SymmetricKernels p;
  p.center_weight = v[1];
  p.center_sigma = v[2];
  for (int i = 0; i < table.pairs; ++i)
    p.pairs.push_back({v[3 + 3 * i], v[4 + 3 * i], v[5 + 3 * i]});
  return p;
}

}  // namespace

SymmetricKernels interpolate(const KernelTable& table, double ratio) {
  const int n = table.intervals, first = table.first_solved, c = table.columns();
  auto value = [&](int i, int k) { return table.values[static_cast<size_t>(i) * c + k]; };
  const double u = std::clamp(ratio_to_t(ratio) / ratio_to_t(table.max_ratio), 0.0, 1.0) * n;
  if (first > 0 && u <= first)
    return scale_to_ratio(row_params(table, first), value(first, 0), std::max(1.0, ratio));
  const int j = std::min(static_cast<int>(u), n - 1);
  const double f = u - j;
  // Catmull-Rom weights of rows j - 1, j, j + 1, j + 2 (a cubic Hermite spline whose slopes
  // are central differences); they sum to 1.
  const double f2 = f * f, f3 = f2 * f;
  const double b0 = -0.5 * f3 + f2 - 0.5 * f;
  const double b1 = 1.5 * f3 - 2.5 * f2 + 1;
  const double b2 = -1.5 * f3 + 2 * f2 + 0.5 * f;
  const double b3 = 0.5 * f3 - 0.5 * f2;
  // A row past the solved ones, from the nearest rows going inwards (a, a + step, ...):
  // quadratic extrapolation (weights 3, -3, 1, which sum to 1), or linear with only two.
  auto beyond = [&](int a, int step, int k) {
    const int d = a + 2 * step;
    if (d >= first && d <= n) return 3 * value(a, k) - 3 * value(a + step, k) + value(d, k);
    return 2 * value(a, k) - value(a + step, k);
  };
  auto at = [&](int k) {
    const double p0 = j - 1 >= first ? value(j - 1, k) : beyond(j, 1, k);
    const double p3 = j + 2 <= n ? value(j + 2, k) : beyond(j + 1, -1, k);
    return b0 * p0 + b1 * value(j, k) + b2 * value(j + 1, k) + b3 * p3;
  };
  SymmetricKernels p;
  p.center_weight = at(1);
  p.center_sigma = at(2);
  for (int i = 0; i < table.pairs; ++i)
    p.pairs.push_back({at(3 + 3 * i), at(4 + 3 * i), at(5 + 3 * i)});
  return p;
}

const KernelTable& compiled_kernel_table(int count) {
  static const KernelTable t3{1,
                              kKernelTableIntervals,
                              kKernelTableMaxRatio,
                              kKernelTableFirstSolved3,
                              {&kKernelTable3[0][0], std::size(kKernelTable3) * 6}};
  static const KernelTable t5{2,
                              kKernelTableIntervals,
                              kKernelTableMaxRatio,
                              kKernelTableFirstSolved5,
                              {&kKernelTable5[0][0], std::size(kKernelTable5) * 9}};
  static const KernelTable t9{4,
                              kKernelTableIntervals,
                              kKernelTableMaxRatio,
                              kKernelTableFirstSolved9,
                              {&kKernelTable9[0][0], std::size(kKernelTable9) * 15}};
  switch (count) {
    case 3:
      return t3;
    case 5:
      return t5;
    case 9:
      return t9;
  }
  throw Error("compiled_kernel_table: no table for " + std::to_string(count) +
              " kernels (3, 5 or 9)");
}

const KernelFitTexture& kernel_fit_texture() {
  static const KernelFitTexture t = [] {
    KernelFitTexture k;
    const int counts[3] = {3, 5, 9};
    const int rows = kKernelTableIntervals + 1;
    k.texels.assign(static_cast<size_t>(15) * 3 * rows, 0.0f);
    for (int c = 0; c < 3; ++c) {
      const KernelTable& table = compiled_kernel_table(counts[c]);
      for (int j = 0; j < rows; ++j) {
        for (int col = 0; col < table.columns(); ++col) {
          k.texels[(static_cast<size_t>(c) * rows + j) * 15 + col] =
              static_cast<float>(table.values[static_cast<size_t>(j) * table.columns() + col]);
        }
      }
    }
    k.info.intervals = kKernelTableIntervals;
    k.info.max_ratio = kKernelTableMaxRatio;
    k.info.first_solved3 = kKernelTableFirstSolved3;
    k.info.first_solved5 = kKernelTableFirstSolved5;
    k.info.first_solved9 = kKernelTableFirstSolved9;
    k.info_float.intervals = k.info.intervals;
    k.info_float.max_ratio = static_cast<float>(k.info.max_ratio);
    k.info_float.first_solved3 = k.info.first_solved3;
    k.info_float.first_solved5 = k.info.first_solved5;
    k.info_float.first_solved9 = k.info.first_solved9;
    return k;
  }();
  return t;
}

}  // namespace sg
