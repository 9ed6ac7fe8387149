// fit_kernels: fits the circular-kernel approximations of an elliptical Gaussian RDF
// (Podee et al. 2021, Appendix C, Eqs. 25-27) for 3, 5 and 9 kernels over a grid of
// ratios, writes them as src/shading/kernel_table.inc, and measures them.
//
//   fit_kernels [--out FILE] [--report] [--max-ratio R] [--intervals M]
//
// --out writes the table (deterministic: same bytes every run). --report prints the
// figures of docs/kernel-fits.md, all measured on the fits of this run with the same
// interpolation the renderer uses: the relative L2 error sqrt(eps) / ||G|| per kernel
// count at chosen ratios (the table interpolated, a fresh fit there, a fit with free
// mass, the single-kernel closed forms), the interpolation error at every midpoint of the
// grid, and a global search against the continuation. The fit alone takes about a
// second; the report, with its global searches, about half a minute (docs/kernel-fits.md).
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <map>
#include <string>
#include <vector>

#include "base/atomic_file.h"
#include "base/error.h"
#include "kernel_fitter.h"
#include "math/vec.h"
#include "shading/kernel_fit.h"
#include "shading/kernel_table.h"

namespace sg::fit {
namespace {

constexpr int kPairs[] = {1, 2, 4};

struct Args {
  std::string out;
  bool report = false;
  double max_ratio = 16;
  int intervals = 128;
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double total_mass(const SymmetricKernels& p) {
  double m = p.center_weight;
  for (const KernelPair& q : p.pairs)
    m += 2 * q.weight;
  return m;
}

// ||C_a - C_b|| / ||G|| for the ellipse (1, ratio).
double relative_distance(const SymmetricKernels& a, const SymmetricKernels& b, double ratio) {
  const std::vector<CircularKernel> ka = expand(a), kb = expand(b);
  const double d2 = mixture_inner_product(ka, ka) - 2 * mixture_inner_product(ka, kb) +
                    mixture_inner_product(kb, kb);
  return std::sqrt(std::max(0.0, d2) / ellipse_norm_sq(1.0, ratio));
}

double rel_error(const SymmetricKernels& p, double ratio) {
  return relative_l2_error(expand(p), 1.0, ratio);
}

void report(const Args& a, const std::vector<Family>& families, double fit_seconds) {
  std::printf("fit_kernels report: max ratio %g, %d intervals in t = sqrt(r^2 - 1)\n", a.max_ratio,
              a.intervals);
  std::printf("fit time (3 families, continuation): %.3f s\n\n", fit_seconds);

  // Table views of this run's fits, interpolated exactly as the renderer does.
  std::vector<std::vector<double>> values;
  std::vector<KernelTable> tables;
  for (size_t f = 0; f < families.size(); ++f)
    values.push_back(table_values(families[f]));
  for (size_t f = 0; f < families.size(); ++f)
    tables.push_back({kPairs[f], a.intervals, a.max_ratio, families[f].first_solved, values[f]});

  // 1. The fitted rows: error decreasing with the count, ordering, weights, mass.
  std::printf("== fitted rows\n");
  for (size_t f = 0; f < families.size(); ++f) {
    double worst_mass = 0, min_weight = 1, min_step = 1e300, max_err = 0;
    const int first_solved = families[f].first_solved;
    std::map<int, int> statuses;  // NLopt result code -> solves
    for (size_t j = 1; j < families[f].rows.size(); ++j) {
      const FitResult& r = families[f].rows[j];
      worst_mass = std::max(worst_mass, std::abs(total_mass(r.params) - 1));
      min_weight = std::min(min_weight, r.params.center_weight);
      double prev = 0;
      for (const KernelPair& q : r.params.pairs) {
        min_weight = std::min(min_weight, q.weight);
        if (static_cast<int>(j) >= first_solved)
          min_step = std::min(min_step, (q.distance - prev) / ratio_to_t(r.ratio));
        prev = q.distance;
      }
      max_err = std::max(max_err, r.error);
      if (static_cast<int>(j) >= first_solved) ++statuses[r.status];
    }
    const FitResult& first = families[f].rows[families[f].first_solved];
    std::printf(
        "%d kernels: rows solved from %d (ratio %.4f, error %.3e); max |sum w - 1| %.2e, min "
        "weight %.3e, min (d_i - d_(i-1)) / t %.4f, max error %.4f; NLopt results",
        2 * kPairs[f] + 1, families[f].first_solved, first.ratio, first.error, worst_mass,
        min_weight, min_step, max_err);
    for (const auto& [code, n] : statuses)
      std::printf(" %d: %d", code, n);
    std::printf("\n");
  }
  int violations = 0;
  for (int j = 1; j <= a.intervals; ++j) {
    const double r = families[0].rows[j].ratio;
    double prev = relative_l2_error(std::vector{equal_area_kernel(r)}, 1.0, r);
    for (const Family& fam : families) {
      // Below 1e-7 the errors are at the rounding of the closed form (see the tests).
      if (!(fam.rows[j].error < prev) && prev > 1e-7) ++violations;
      prev = fam.rows[j].error;
    }
  }
  std::printf("rows where the error does not fall from 1 to 3 to 5 to 9 kernels: %d\n\n",
              violations);

  // 2. Errors at chosen ratios.
  std::vector<double> ratios{1, 1.5, 2, 3, 5, 9};
  if (a.max_ratio > 9) ratios.push_back(a.max_ratio);
  std::printf("== relative L2 error sqrt(eps) / ||G|| at chosen ratios\n");
  std::printf(
      "1 kernel: sigma^2 = r in all three; weight 1 (equal area, Sec. 3.5, the runtime),\n");
  std::printf("          2 sqrt(r) / (1 + r) (free-weight L2 optimum, closed form), and the\n");
  std::printf("          unit-mass L2 optimum (fitted; its sigma^2 / r given)\n");
  std::printf("%8s %12s %12s %8s %12s %10s\n", "ratio", "equal-area", "L2 opt", "mass", "unit-mass",
              "sigma^2/r");
  for (double r : ratios) {
    const CircularKernel opt = single_kernel_l2_optimum(r);
    const FitResult unit = refine(r, {1.0, std::sqrt(r), {}});
    std::printf("%8.3f %12.4e %12.4e %8.5f %12.4e %10.5f\n", r,
                relative_l2_error(std::vector{equal_area_kernel(r)}, 1.0, r),
                relative_l2_error(std::vector{opt}, 1.0, r), opt.weight, unit.error,
                sqr(unit.params.center_sigma) / r);
  }
  for (size_t f = 0; f < families.size(); ++f) {
    std::printf("%d kernels: the table interpolated (the runtime), a fresh fit from it, and a\n",
                2 * kPairs[f] + 1);
    std::printf("          fit with free mass (Eq. 25 alone) from the fresh fit, with its mass\n");
    std::printf("%8s %12s %12s %12s %8s\n", "ratio", "table", "fresh fit", "free mass", "mass");
    for (double r : ratios) {
      const SymmetricKernels interp = interpolate(tables[f], r);
      const FitResult fresh = refine(r, interp);
      const FitResult free_mass = refine(r, fresh.params, Mass::free);
      std::printf("%8.3f %12.4e %12.4e %12.4e %8.5f\n", r, rel_error(interp, r), fresh.error,
                  free_mass.error, total_mass(free_mass.params));
    }
  }
  std::printf("\n");

  // 3. Interpolation error at every midpoint (in t) of the grid, against a fresh fit there
  // (a local solve started from the interpolated parameters), by bands of ratios.
  std::printf("== interpolation error at the %d midpoints in t, against fresh fits there\n",
              a.intervals);
  std::printf("   distance = ||C_table - C_fresh|| / ||G||; rise = err_table - err_fresh\n");
  const double bands[] = {1, 1.5, 2, 3, 5, 9, a.max_ratio};
  std::printf("%9s %15s %11s %11s %11s %11s %11s\n", "kernels", "ratios", "midpoints", "max dist",
              "max rise", "max rise /", "fresh err");
  std::printf("%9s %15s %11s %11s %11s %11s %11s\n", "", "", "", "", "", "err_fresh", "at that");
  for (size_t f = 0; f < families.size(); ++f) {
    const double t_max = ratio_to_t(a.max_ratio);
    for (size_t b = 0; b + 1 < std::size(bands); ++b) {
      double worst_d = 0, worst_rise = 0, worst_rel = 0, err_at_rel = 0;
      int count = 0;
      for (int j = 0; j < a.intervals; ++j) {
        const double t = t_max * (j + 0.5) / a.intervals, r = std::sqrt(1 + t * t);
        if (r < bands[b] || r >= bands[b + 1]) continue;
        ++count;
        const SymmetricKernels interp = interpolate(tables[f], r);
        const FitResult fresh = refine(r, interp);
        const double rise = rel_error(interp, r) - fresh.error;
        worst_d = std::max(worst_d, relative_distance(interp, fresh.params, r));
        worst_rise = std::max(worst_rise, rise);
        if (fresh.error > 0 && rise / fresh.error > worst_rel) {
          worst_rel = rise / fresh.error;
          err_at_rel = fresh.error;
        }
      }
      std::printf("%9d %7.2f-%-7.2f %11d %11.3e %11.3e %11.3e %11.3e\n", 2 * kPairs[f] + 1,
                  bands[b], bands[b + 1], count, worst_d, worst_rise, worst_rel, err_at_rel);
    }
  }
  std::printf("\n");

  // 4. The continuation against a global search (G_MLSL_LDS) every 8th row.
  std::printf("== continuation against a global search (G_MLSL_LDS, 20000 evaluations)\n");
  std::printf("%8s %9s %12s %12s %12s\n", "ratio", "kernels", "continued", "global", "global/cont");
  const auto t0 = std::chrono::steady_clock::now();
  for (int j = 8; j <= a.intervals; j += 8) {
    for (size_t f = 0; f < families.size(); ++f) {
      const FitResult& c = families[f].rows[j];
      const FitResult g = global_fit(kPairs[f], c.ratio);
      std::printf("%8.4f %9d %12.4e %12.4e %12.6f%s\n", c.ratio, 2 * kPairs[f] + 1, c.error,
                  g.error, c.error > 0 ? g.error / c.error : 1.0,
                  g.error < c.error * (1 - 1e-6) ? "  global lower" : "");
    }
  }
  std::printf("global searches: %.1f s\n", seconds_since(t0));
}

int run(const Args& a) {
  if (!(a.max_ratio > 1)) throw Error("--max-ratio: must be > 1");
  if (a.intervals < 2) throw Error("--intervals: must be >= 2");
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<Family> families;
  for (int pairs : kPairs)
    families.push_back(fit_family(pairs, a.max_ratio, a.intervals));
  const double fit_seconds = seconds_since(t0);
  if (!a.out.empty()) {
    write_file_atomic(a.out, table_source(a.max_ratio, a.intervals, families));
    std::fprintf(stderr, "fit_kernels: wrote %s (fit in %.3f s)\n", a.out.c_str(), fit_seconds);
  }
  if (a.report) report(a, families, fit_seconds);
  return 0;
}

}  // namespace
}  // namespace sg::fit

int main(int argc, char** argv) {
  CLI::App app{
      "fit_kernels: fits circular Gaussian kernels to elliptical Gaussians "
      "(Podee et al. 2021, Appendix C) and writes src/shading/kernel_table.inc"};
  sg::fit::Args a;
  app.add_option("--out", a.out, "write the table here (e.g. src/shading/kernel_table.inc)");
  app.add_flag("--report", a.report, "print the measured figures of docs/kernel-fits.md");
  app.add_option("--max-ratio", a.max_ratio, "largest ratio sigma_major / sigma_minor")
      ->capture_default_str();
  app.add_option("--intervals", a.intervals, "grid intervals in t = sqrt(ratio^2 - 1)")
      ->capture_default_str();
  try {
    app.parse(argc, argv);
    return sg::fit::run(a);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fit_kernels: %s\n", e.what());
    return 1;
  }
}
