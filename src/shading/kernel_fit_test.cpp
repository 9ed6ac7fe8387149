// The circular-kernel approximation of an elliptical Gaussian (Podee et al. 2021, Sec. 3.6,
// Appendix C): every closed form against brute-force quadrature (Boost.Math), the paper's
// Eq. 28 against our general form, and the compiled-in table: mass, ordering, error falling
// with the kernel count, error against the ellipse, and the runtime entry point.
//
// Quadrature: nested adaptive Gauss-Kronrod (61 points, relative tolerance 1e-9, depth 12)
// over a box 12 standard deviations beyond every Gaussian in play, where the tails are
// below e^-72. On the cases below it agrees with the closed forms to better than 1e-11
// relative (measured by tightening the tolerances); those of 1e-8 leave a factor of 1000.
#include "shading/kernel_fit.h"

#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/minima.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "base/error.h"
#include "math/rng.h"
#include "math/vec.h"
#include "shading/kernel_table.h"

namespace sg {
namespace {

using boost::math::quadrature::gauss_kronrod;

// The integral of f(x, y) over the plane, for f negligible 12 stds beyond the kernels and
// the ellipse (sigma_minor, sigma_major).
template <class F>
double integrate_plane(F f, std::span<const CircularKernel> kernels, double sigma_minor,
                       double sigma_major) {
  double x_half = 12 * sigma_minor, y_half = 12 * sigma_major;
  for (const CircularKernel& k : kernels) {
    x_half = std::max(x_half, 12 * k.sigma);
    y_half = std::max(y_half, std::abs(k.offset) + 12 * k.sigma);
  }
  auto inner = [&](double y) {
    return gauss_kronrod<double, 61>::integrate([&](double x) { return f(x, y); }, -x_half, x_half,
                                                12, 1e-9);
  };
  return gauss_kronrod<double, 61>::integrate(inner, -y_half, y_half, 12, 1e-9);
}

// Eq. 25 by quadrature: the integral of (G - C)^2.
double quadrature_error(std::span<const CircularKernel> k, double sigma_minor, double sigma_major) {
  return integrate_plane(
      [&](double x, double y) {
        return sqr(ellipse_density(x, y, sigma_minor, sigma_major) - mixture_density(k, x, y));
      },
      k, sigma_minor, sigma_major);
}

// Eq. 28 as printed, for three kernels and the ellipse (1, sigma_y), with `b` for the
// paper's b. It is 4 pi epsilon when b = w_1.
double eq28(double wa, double sa, double w1, double s1, double d1, double sy, double b) {
  const double sa2 = sa * sa, s12 = s1 * s1, sy2 = sy * sy, d2 = d1 * d1;
  return wa * wa / sa2 + 8 * wa * w1 * std::exp(-d2 / (2 * (sa2 + s12))) / (sa2 + s12) -
         4 * wa / std::sqrt((sa2 + 1) * (sa2 + sy2)) + 2 * b * b * (std::exp(-d2 / s12) + 1) / s12 -
         8 * w1 * std::exp(-d2 / (2 * (s12 + sy2))) / std::sqrt((s12 + 1) * (s12 + sy2)) + 1 / sy;
}

// Random symmetric parameters with N pairs for the ellipse (1, ratio), from a fixed stream.
SymmetricKernels random_kernels(Pcg32& rng, int pairs, double ratio) {
  SymmetricKernels p;
  p.center_weight = 0.1 + 0.8 * rng.uniform();
  p.center_sigma = 0.5 + ratio * rng.uniform();
  double d = 0;
  for (int i = 0; i < pairs; ++i) {
    d += 0.2 + ratio * rng.uniform();
    p.pairs.push_back({d, 0.5 + ratio * rng.uniform(), 0.3 * rng.uniform()});
  }
  return p;
}

double total_weight(std::span<const CircularKernel> k) {
  double w = 0;
  for (const CircularKernel& c : k)
    w += c.weight;
  return w;
}

// A row of a KernelTable: ratio (left 0 here), w_a, sigma_a, then d_i, sigma_i, w_i.
std::vector<double> flatten(const SymmetricKernels& p) {
  std::vector<double> v{0.0, p.center_weight, p.center_sigma};
  for (const KernelPair& q : p.pairs)
    v.insert(v.end(), {q.distance, q.sigma, q.weight});
  return v;
}

double rel_error(int count, double ratio) {
  return relative_l2_error(expand(tabulated_kernels(count, ratio)), 1.0, ratio);
}

// ---------------------------------------------------------------------------- closed forms

TEST(KernelFit, EllipseDensityAndNormMatchQuadrature) {
  const double a = 0.7, b = 3.1;
  const std::vector<CircularKernel> none;
  EXPECT_NEAR(
      integrate_plane([&](double x, double y) { return ellipse_density(x, y, a, b); }, none, a, b),
      1.0, 1e-10);
  EXPECT_NEAR(integrate_plane([&](double x, double y) { return sqr(ellipse_density(x, y, a, b)); },
                              none, a, b) /
                  ellipse_norm_sq(a, b),
              1.0, 1e-10);
}

// Eq. 28 with its b^2 read as w_1^2 is 4 pi times our epsilon for N = 1, and both are the
// quadrature of Eq. 25. Read literally with b = w_a (the only other weight), it is not.
TEST(KernelFit, Eq28CorrectedMatchesGeneralFormAndQuadrature) {
  Pcg32 rng(28, 1);
  for (int trial = 0; trial < 6; ++trial) {
    const double sy = 1 + 8 * rng.uniform();
    const SymmetricKernels p = random_kernels(rng, 1, sy);
    const KernelPair& q = p.pairs[0];
    const std::vector<CircularKernel> k = expand(p);
    const double general = mixture_error(k, 1.0, sy);
    const double paper =
        eq28(p.center_weight, p.center_sigma, q.weight, q.sigma, q.distance, sy, q.weight);
    const double quad = quadrature_error(k, 1.0, sy);
    // Two closed forms of the same sum: they differ by rounding only.
    EXPECT_NEAR(paper / (4 * kPi), general, 1e-13 * ellipse_norm_sq(1.0, sy)) << trial;
    EXPECT_NEAR(general / quad, 1.0, 1e-8) << trial;
    const double literal =
        eq28(p.center_weight, p.center_sigma, q.weight, q.sigma, q.distance, sy, p.center_weight);
    EXPECT_GT(std::abs(literal / (4 * kPi) / quad - 1), 1e-3) << trial;
  }
}

// The general closed form for 5 and 9 symmetric kernels and for kernels in no order.
TEST(KernelFit, GeneralFormMatchesQuadrature) {
  Pcg32 rng(25, 2);
  for (int pairs : {2, 4}) {
    for (int trial = 0; trial < 4; ++trial) {
      const double ratio = 1 + 10 * rng.uniform();
      const std::vector<CircularKernel> k = expand(random_kernels(rng, pairs, ratio));
      EXPECT_NEAR(mixture_error(k, 1.0, ratio) / quadrature_error(k, 1.0, ratio), 1.0, 1e-8)
          << pairs << " pairs, trial " << trial;
    }
  }
  // Any minor std, any offsets, negative weights.
  const std::vector<CircularKernel> k = {{-1.3, 0.8, 0.4}, {2.2, 1.7, -0.2}, {0.4, 0.6, 0.9}};
  EXPECT_NEAR(mixture_error(k, 0.7, 2.5) / quadrature_error(k, 0.7, 2.5), 1.0, 1e-8);
}

TEST(KernelFit, InnerProductMatchesQuadrature) {
  // Neither list symmetric, so that a sign error in an offset difference shows.
  const std::vector<CircularKernel> a = {{0.3, 1.2, 0.5}, {2.0, 0.9, 0.25}, {-1.6, 0.7, 0.25}};
  const std::vector<CircularKernel> b = {{0.7, 1.5, 0.6}, {-3.1, 0.8, 0.4}};
  std::vector<CircularKernel> both = a;
  both.insert(both.end(), b.begin(), b.end());
  const double quad = integrate_plane(
      [&](double x, double y) { return mixture_density(a, x, y) * mixture_density(b, x, y); }, both,
      1.0, 1.0);
  EXPECT_NEAR(mixture_inner_product(a, b) / quad, 1.0, 1e-9);
}

TEST(KernelFit, MixtureDensityIntegratesToTotalWeight) {
  const std::vector<CircularKernel> k = {{0.0, 1.2, 0.5}, {2.0, 0.9, 0.25}, {-2.0, 0.9, 0.125}};
  const double quad =
      integrate_plane([&](double x, double y) { return mixture_density(k, x, y); }, k, 1, 1);
  EXPECT_NEAR(quad, 0.875, 1e-10);
}

// The analytic gradient against central differences (step 1e-6: truncation ~1e-12, rounding
// ~1e-16 / 1e-6 relative to epsilon; 1e-6 relative leaves room for both).
TEST(KernelFit, GradientMatchesFiniteDifferences) {
  Pcg32 rng(7, 3);
  const double ratio = 4.5;
  std::vector<CircularKernel> k = expand(random_kernels(rng, 2, ratio));
  k[2].offset += 0.3;  // break the symmetry, so that every partial derivative is exercised
  std::vector<CircularKernel> g(k.size()), ge(k.size());
  const double eps = mixture_error(k, 0.8, ratio, g);
  EXPECT_NEAR(mixture_error_extended(k, 0.8, ratio, ge) / eps, 1.0, 1e-13);
  const double h = 1e-6;
  auto central = [&](size_t i, double CircularKernel::*field) {
    std::vector<CircularKernel> up = k, down = k;
    up[i].*field += h;
    down[i].*field -= h;
    return (mixture_error(up, 0.8, ratio) - mixture_error(down, 0.8, ratio)) / (2 * h);
  };
  double scale = 0;
  for (const CircularKernel& c : g)
    scale = std::max({scale, std::abs(c.offset), std::abs(c.sigma), std::abs(c.weight)});
  for (size_t i = 0; i < k.size(); ++i) {
    EXPECT_NEAR(g[i].offset, central(i, &CircularKernel::offset), 1e-6 * scale) << i;
    EXPECT_NEAR(g[i].sigma, central(i, &CircularKernel::sigma), 1e-6 * scale) << i;
    EXPECT_NEAR(g[i].weight, central(i, &CircularKernel::weight), 1e-6 * scale) << i;
    EXPECT_NEAR(ge[i].offset, g[i].offset, 1e-12 * scale) << i;
    EXPECT_NEAR(ge[i].sigma, g[i].sigma, 1e-12 * scale) << i;
    EXPECT_NEAR(ge[i].weight, g[i].weight, 1e-12 * scale) << i;
  }
}

// N = 0: the best kernel by a brute-force search over (sigma, weight) is the closed form,
// and its error is (r - 1) / (r + 1) by quadrature. The equal-area kernel of Sec. 3.5 has
// the same sigma and unit weight, and the error sqrt(2 - 4 sqrt(r) / (1 + r)).
TEST(KernelFit, SingleKernelClosedForms) {
  for (double r : {1.5, 3.0, 9.0}) {
    // Brent on sigma, with the weight minimised by Brent inside.
    auto best_for_sigma = [r](double s) {
      return boost::math::tools::brent_find_minima(
          [&](double w) {
            return mixture_error(std::vector{CircularKernel{0, s, w}}, 1, r);
          },
          0.0, 2.0, 40);
    };
    const auto sigma = boost::math::tools::brent_find_minima(
        [&](double s) { return best_for_sigma(s).second; }, 0.3, 3 * std::sqrt(r), 40);
    const CircularKernel opt = single_kernel_l2_optimum(r);
    // Brent to 40 bits on a minimum: the argument is found to about sqrt(2^-40) ~ 1e-6.
    EXPECT_NEAR(sigma.first, opt.sigma, 1e-5 * opt.sigma) << r;
    EXPECT_NEAR(best_for_sigma(opt.sigma).first, opt.weight, 1e-5) << r;
    const std::vector<CircularKernel> k{opt};
    EXPECT_NEAR(std::sqrt(quadrature_error(k, 1, r) / ellipse_norm_sq(1, r)), (r - 1) / (r + 1),
                1e-8)
        << r;
    const std::vector<CircularKernel> ea{equal_area_kernel(r)};
    EXPECT_DOUBLE_EQ(ea[0].sigma, opt.sigma);
    EXPECT_EQ(ea[0].weight, 1.0);
    EXPECT_NEAR(std::sqrt(quadrature_error(ea, 1, r) / ellipse_norm_sq(1, r)),
                std::sqrt(2 - 4 * std::sqrt(r) / (1 + r)), 1e-8)
        << r;
  }
}

// ---------------------------------------------------------------------------- the table

// Rows: ratio column on the grid, unit mass, positive weights and stds, strictly ordered
// offsets, and interpolation that passes through the solved rows.
TEST(KernelTable, RowsAreValid) {
  for (int count : {3, 5, 9}) {
    const KernelTable& t = compiled_kernel_table(count);
    EXPECT_EQ(t.pairs, (count - 1) / 2);
    ASSERT_EQ(t.values.size(), static_cast<size_t>((t.intervals + 1) * t.columns()));
    EXPECT_EQ(t.max_ratio, kernel_table_max_ratio());
    for (int j = 0; j <= t.intervals; ++j) {
      const double ratio = t.values[j * t.columns()];
      EXPECT_NEAR(ratio, table_ratio(t.max_ratio, t.intervals, j), 1e-15 * ratio) << j;
      const SymmetricKernels row = interpolate(t, ratio);
      const std::vector<CircularKernel> k = expand(row);
      // Sums of a handful of doubles near 1: a few ulps.
      EXPECT_NEAR(total_weight(k), 1.0, 1e-15) << count << " row " << j;
      // Rows below first_solved are scale_to_ratio of that row, stored for reading: the
      // interpolation reproduces every row to rounding.
      const std::vector<double> at = flatten(row);
      for (int c = 1; c < t.columns(); ++c) {
        const double stored = t.values[j * t.columns() + c];
        EXPECT_NEAR(at[c], stored, 1e-14 * std::max(1.0, std::abs(stored))) << count << " " << j;
      }
      double prev = 0;
      for (const CircularKernel& c : k) {
        EXPECT_GE(c.weight, 0) << count << " row " << j;
        EXPECT_GT(c.sigma, 0) << count << " row " << j;
      }
      for (const KernelPair& q : row.pairs) {
        if (j > 0) {
          EXPECT_GT(q.distance, prev) << count << " row " << j;
        }
        prev = q.distance;
      }
    }
  }
}

// Interpolated anywhere: unit mass, non-negative weights, ordered offsets.
TEST(KernelTable, InterpolationKeepsMassAndOrder) {
  for (int count : {3, 5, 9}) {
    for (int i = 1; i <= 3000; ++i) {
      const double ratio = 1 + 15.0 * i / 3000 - 1e-3;
      const SymmetricKernels p = tabulated_kernels(count, ratio);
      const std::vector<CircularKernel> k = expand(p);
      EXPECT_NEAR(total_weight(k), 1.0, 1e-14) << count << " at " << ratio;
      double prev = 0;
      for (const KernelPair& q : p.pairs) {
        EXPECT_GE(q.weight, 0) << count << " at " << ratio;
        EXPECT_GT(q.distance, prev) << count << " at " << ratio;
        prev = q.distance;
      }
    }
  }
}

// Below 1e-7 a relative L2 error is at the rounding of the closed form in double (epsilon
// is a difference of terms of size ||G||^2, known to ~1e-16 of it; sqrt(1e-15) ~ 3e-8).
constexpr double kErrorFloor = 1e-7;

// More kernels, smaller error: at every tabulated ratio > 1 and at 2000 ratios between.
TEST(KernelTable, ErrorFallsWithKernelCount) {
  const KernelTable& t = compiled_kernel_table(3);
  std::vector<double> ratios;
  for (int j = 1; j <= t.intervals; ++j)
    ratios.push_back(table_ratio(t.max_ratio, t.intervals, j));
  for (int i = 0; i < 2000; ++i)
    ratios.push_back(1.001 + (t.max_ratio - 1.001) * i / 1999.0);
  for (double r : ratios) {
    double prev = rel_error(1, r);
    for (int count : {3, 5, 9}) {
      const double e = rel_error(count, r);
      if (prev > kErrorFloor) {
        EXPECT_LT(e, prev) << count << " kernels at ratio " << r;
      } else {
        EXPECT_LT(e, kErrorFloor) << count << " kernels at ratio " << r;
      }
      prev = e;
    }
  }
  // At ratio 1 every count is exact, up to that rounding.
  for (int count : kKernelCounts)
    EXPECT_LT(rel_error(count, 1.0), kErrorFloor) << count;
}

// The interpolated mixture against the ellipse by quadrature, at the ratios of
// docs/kernel-fits.md. `bound` is the measured error rounded up in its third digit.
struct ErrorCase {
  int count;
  double ratio;
  double bound;
};
const ErrorCase kErrors[] = {
    {1, 1.5, 0.2011}, {1, 3, 0.5177},   {1, 9, 0.8945},  {3, 1.5, 1.411e-2}, {3, 2, 5.959e-2},
    {3, 3, 0.1737},   {3, 9, 0.5655},   {3, 16, 0.7298}, {5, 1.5, 6.536e-4}, {5, 2, 7.937e-3},
    {5, 3, 5.292e-2}, {5, 5, 0.1843},   {5, 16, 0.5869}, {9, 1.5, 1.201e-6}, {9, 2, 1.155e-4},
    {9, 3, 4.058e-3}, {9, 5, 4.551e-2}, {9, 9, 0.1877},  {9, 16, 0.3862},
};

TEST(KernelTable, InterpolatedErrorAgainstEllipseByQuadrature) {
  for (const ErrorCase& c : kErrors) {
    const std::vector<CircularKernel> k = expand(tabulated_kernels(c.count, c.ratio));
    const double quad = std::sqrt(quadrature_error(k, 1.0, c.ratio) / ellipse_norm_sq(1, c.ratio));
    // The quadrature of epsilon is good to its 1e-12 relative tolerance; the closed form to
    // ~1e-16 ||G||^2 absolute, which is 4e-11 of relative L2 error at the smallest case.
    EXPECT_NEAR(quad, rel_error(c.count, c.ratio), 1e-6 * quad + 1e-10)
        << c.count << " at " << c.ratio;
    EXPECT_LE(quad, c.bound) << c.count << " at " << c.ratio;
    EXPECT_GE(quad, 0.99 * c.bound) << c.count << " at " << c.ratio << ": better; update";
  }
}

// Up to the paper's threshold (ratio = count, Sec. 3.6) the error stays below about 19%
// for every count: the threshold keeps a roughly constant quality.
TEST(KernelTable, ErrorUpToThreshold) {
  for (int count : {3, 5, 9}) {
    double worst = 0;
    for (int i = 0; i <= 400; ++i)
      worst = std::max(worst, rel_error(count, 1 + (count - 1) * i / 400.0));
    EXPECT_LT(worst, 0.19) << count;
    EXPECT_NEAR(worst, rel_error(count, count), 1e-12) << count << ": largest at the threshold";
  }
}

// ---------------------------------------------------------------------------- runtime

TEST(EllipticalKernels, ScalesTheUnitFit) {
  for (int count : kKernelCounts) {
    for (double ratio : {1.0, 1.7, 4.0, 8.5}) {
      const double s = 0.013;
      const KernelSet set = elliptical_kernels(count, s, s * ratio);
      const std::vector<CircularKernel> unit = expand(tabulated_kernels(count, ratio));
      ASSERT_EQ(set.kernels.size(), static_cast<size_t>(count));
      EXPECT_NEAR(set.ratio, ratio, 1e-14 * ratio);
      EXPECT_EQ(set.past_threshold, ratio > count);
      EXPECT_FALSE(set.beyond_table);
      for (size_t i = 0; i < unit.size(); ++i) {
        EXPECT_NEAR(set.kernels[i].offset, s * unit[i].offset, 1e-13 * s * (1 + ratio));
        EXPECT_NEAR(set.kernels[i].sigma, s * unit[i].sigma, 1e-13 * s * (1 + ratio));
        EXPECT_NEAR(set.kernels[i].weight, unit[i].weight, 1e-13);
      }
      EXPECT_NEAR(total_weight(set.kernels), 1.0, 1e-14);
      // The relative error does not depend on the scale.
      EXPECT_NEAR(relative_l2_error(set.kernels, s, s * ratio), rel_error(count, ratio), 1e-7);
    }
  }
}

TEST(EllipticalKernels, OneKernelIsTheEqualAreaCircle) {
  const KernelSet set = elliptical_kernels(1, 0.5, 2.0);
  ASSERT_EQ(set.kernels.size(), 1u);
  EXPECT_DOUBLE_EQ(set.kernels[0].sigma, 1.0);  // sqrt(0.5 * 2)
  EXPECT_EQ(set.kernels[0].weight, 1.0);
  EXPECT_EQ(set.kernels[0].offset, 0.0);
  EXPECT_TRUE(set.past_threshold);
  EXPECT_FALSE(elliptical_kernels(1, 0.5, 0.5).past_threshold);
}

TEST(EllipticalKernels, BeyondTheTable) {
  const double max = kernel_table_max_ratio(), s = 2.0, ratio = 1.5 * max;
  const KernelSet set = elliptical_kernels(9, s, s * ratio);
  EXPECT_TRUE(set.beyond_table);
  EXPECT_TRUE(set.past_threshold);
  const std::vector<CircularKernel> last = expand(tabulated_kernels(9, max));
  for (size_t i = 0; i < last.size(); ++i) {
    EXPECT_NEAR(set.kernels[i].offset, last[i].offset * s * ratio / max, 1e-12);
    EXPECT_NEAR(set.kernels[i].sigma, last[i].sigma * s * ratio / max, 1e-12);
    EXPECT_EQ(set.kernels[i].weight, last[i].weight);
  }
  // It matches the ellipse (s ratio / max, s ratio) as the table's last row matches (1, max).
  EXPECT_NEAR(relative_l2_error(set.kernels, s * ratio / max, s * ratio), rel_error(9, max), 1e-9);
}

TEST(EllipticalKernels, RejectsInvalidInput) {
  EXPECT_THROW(elliptical_kernels(2, 1, 2), Error);
  EXPECT_THROW(elliptical_kernels(7, 1, 2), Error);
  EXPECT_THROW(elliptical_kernels(3, 0, 2), Error);
  EXPECT_THROW(elliptical_kernels(3, 1, -2), Error);
  EXPECT_THROW(elliptical_kernels(3, std::numeric_limits<double>::quiet_NaN(), 2), Error);
  EXPECT_THROW(elliptical_kernels(3, 1, std::numeric_limits<double>::infinity()), Error);
  EXPECT_THROW(elliptical_kernels(3, 2, 1), Error);  // swapped axes
  // Equal axes computed a few ulps apart are one circle.
  const KernelSet set = elliptical_kernels(5, 1.0, 1.0 - 1e-15);
  EXPECT_EQ(set.ratio, 1.0);
  EXPECT_LT(relative_l2_error(set.kernels, 1.0, 1.0), kErrorFloor);
}

}  // namespace
}  // namespace sg
