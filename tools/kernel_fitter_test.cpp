// The kernel fitter (tools/kernel_fitter.h): its objective's gradient, its answer where the
// answer is known in closed form, the optimality of its fits against many random starts,
// its determinism, and that the compiled-in table (src/shading/kernel_table.inc) is what it
// produces now, so that a stale table fails here.
#include "kernel_fitter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "math/rng.h"
#include "math/vec.h"
#include "shading/kernel_fit.h"
#include "shading/kernel_table.h"

namespace sg::fit {
namespace {

constexpr int kPairs[] = {1, 2, 4};

// The objective's gradient (through the weight and offset parameterisation) against central
// differences with step 1e-6: agreement to 1e-6 of the largest component (the truncation
// error is ~1e-12, the rounding ~1e-16 / 1e-6).
TEST(KernelFitter, ObjectiveGradientMatchesFiniteDifferences) {
  Pcg32 rng(11, 5);
  for (Mass mass : {Mass::unit, Mass::free}) {
    for (int pairs : {0, 1, 4}) {
      const double ratio = 1.5 + 6 * rng.uniform();
      std::vector<double> x{0.8 + rng.uniform()};
      for (int i = 0; i < pairs; ++i)
        x.insert(x.end(), {0.3 + 2 * rng.uniform(), 0.8 + rng.uniform(), 0.1 + rng.uniform()});
      if (mass == Mass::free) x.push_back(0.7 + 0.5 * rng.uniform());
      std::vector<double> grad(x.size()), none;
      relative_error_sq(x, grad, ratio, pairs, mass);
      double scale = 0;
      for (double g : grad)
        scale = std::max(scale, std::abs(g));
      for (size_t k = 0; k < x.size(); ++k) {
        std::vector<double> up = x, down = x;
        up[k] += 1e-6;
        down[k] -= 1e-6;
        const double fd = (relative_error_sq(up, none, ratio, pairs, mass) -
                           relative_error_sq(down, none, ratio, pairs, mass)) /
                          2e-6;
        EXPECT_NEAR(grad[k], fd, 1e-6 * scale) << pairs << " pairs, x[" << k << "]";
      }
      // pack inverts unpack.
      const std::vector<double> back = pack(unpack(x, pairs, mass), mass);
      ASSERT_EQ(back.size(), x.size());
      for (size_t k = 0; k < x.size(); ++k)
        EXPECT_NEAR(back[k], x[k], 1e-14 * (1 + x[k]));
    }
  }
}

// With one kernel and a free weight the fitter finds the closed form sigma^2 = r,
// w = 2 sqrt(r) / (1 + r) (kernel_fit.h), from a poor start. SLSQP stops at a relative
// tolerance of 1e-12 in x and 1e-15 in the objective: sigma is found to ~1e-7 or better.
TEST(KernelFitter, FindsTheSingleKernelClosedForm) {
  for (double r : {1.5, 4.0, 12.0}) {
    const FitResult fit = refine(r, {0.5, 1.0, {}}, Mass::free);
    const CircularKernel opt = single_kernel_l2_optimum(r);
    EXPECT_NEAR(fit.params.center_sigma, opt.sigma, 1e-6 * opt.sigma) << r;
    EXPECT_NEAR(fit.params.center_weight, opt.weight, 1e-6) << r;
    EXPECT_NEAR(fit.error, (r - 1) / (r + 1), 1e-9) << r;
  }
}

// The table follows the global optimum: no local solve from 150 random starts (fixed seed)
// beats the table's own optimum (a local solve from the interpolated table) by more than
// 1e-6 of its error, at ratios from 2 to the end of the table. (Below ratio ~1.5 the
// 9-kernel optimum is flat, with several configurations within 1e-7 of each other;
// docs/kernel-fits.md.)
TEST(KernelFitter, TableFollowsTheGlobalOptimum) {
  Pcg32 rng(2021, 9);
  for (int pairs : kPairs) {
    const int count = 2 * pairs + 1;
    for (double ratio : {2.0, double(count), 16.0}) {
      const double table = refine(ratio, tabulated_kernels(count, ratio)).error;
      double best = 1e300;
      for (int s = 0; s < 150; ++s) {
        SymmetricKernels p;
        p.center_weight = 1;
        p.center_sigma = 0.5 + 0.5 * ratio * rng.uniform();
        double d = 0;
        for (int i = 0; i < pairs; ++i) {
          d += (0.2 + 2.5 * rng.uniform()) * ratio / pairs;
          p.pairs.push_back({d, 0.5 + 0.5 * ratio * rng.uniform(), 2 * rng.uniform()});
        }
        best = std::min(best, refine(ratio, p).error);
      }
      EXPECT_GE(best, table * (1 - 1e-6)) << count << " kernels at ratio " << ratio;
    }
  }
}

// The checked-in table is what the fitter produces now. Where the optimum is well
// determined (fitted error >= 1e-5) every parameter agrees to 1e-6 relative; everywhere,
// the table's error agrees to 1e-7 (the rounding floor of the error in double). On the
// machine that wrote the table they are bit-identical; another libm or compiler may move
// the last digits, which the nearly flat optimum near ratio 1 amplifies, hence the
// tolerances. Any change to the fit itself (objective, constraints, grid) moves the well
// determined rows by far more. Then determinism: the same bytes twice.
TEST(KernelFitter, TableIsNotStale) {
  std::vector<Family> families;
  for (int pairs : kPairs) {
    const KernelTable& t = compiled_kernel_table(2 * pairs + 1);
    const Family fam = fit_family(pairs, t.max_ratio, t.intervals);
    EXPECT_EQ(fam.first_solved, t.first_solved) << pairs << " pairs";
    const std::vector<double> fresh = table_values(fam);
    ASSERT_EQ(fresh.size(), t.values.size());
    for (int j = 0; j <= t.intervals; ++j) {
      const double ratio = t.values[j * t.columns()];
      const SymmetricKernels stored = interpolate(t, ratio);
      EXPECT_NEAR(relative_l2_error(expand(stored), 1, ratio),
                  relative_l2_error(expand(fam.rows[j].params), 1, ratio), 1e-7)
          << pairs << " pairs, row " << j;
      if (fam.rows[j].error < 1e-5) continue;
      for (int c = 0; c < t.columns(); ++c) {
        const double v = t.values[j * t.columns() + c], w = fresh[j * t.columns() + c];
        EXPECT_NEAR(v, w, 1e-6 * std::max(1.0, std::abs(v)))
            << pairs << " pairs, row " << j << ", column " << c;
      }
    }
    families.push_back(fam);
  }
  const KernelTable& t = compiled_kernel_table(3);
  const std::string text = table_source(t.max_ratio, t.intervals, families);
  std::vector<Family> again;
  for (int pairs : kPairs)
    again.push_back(fit_family(pairs, t.max_ratio, t.intervals));
  EXPECT_EQ(table_source(t.max_ratio, t.intervals, again), text);
}

}  // namespace
}  // namespace sg::fit
