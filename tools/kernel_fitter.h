// The fit behind kernel_table.inc: the parameters of Appendix C (Podee et al. 2021) that
// minimise the L2 error of Eq. 25 between the unit ellipse (1, ratio) and 2N + 1 circular
// Gaussian kernels, over the grid of ratios of a KernelTable.
//
// This lives beside tools/fit_kernels rather than in the shading layer because it needs
// NLopt, which the renderer does not; the unit tests link it to check that the table is not
// stale. docs/kernel-fits.md has the whole story; in short:
//   - objective: epsilon / ||G||^2, Eq. 25 in closed form (shading/kernel_fit.h) summed in
//     long double, with its analytic gradient;
//   - constraints, all as bounds: unit total mass (or a free mass, for comparison) and
//     non-negative weights, by the parameterisation w_a = m / Z, w_i = m u_i / Z with
//     Z = 1 + 2 sum u_i, u_i >= 0; stds >= 0.2; offsets ordered with increments
//     d_i - d_(i-1) >= 0.2 t (t = sqrt(ratio^2 - 1)), so that no two pairs merge;
//   - optimiser: a global search (NLopt's G_MLSL_LDS, a Sobol multistart of LD_SLSQP, fixed
//     seed) at the largest ratio, then continuation down the grid, each ratio a local
//     LD_SLSQP solve from the extrapolation of the two ratios above it, so that the
//     parameters vary smoothly and interpolate well.
#pragma once

#include <string>
#include <vector>

#include "shading/kernel_fit.h"

namespace sg::fit {

// Whether the weights are held to unit total mass (the tables) or left free (Eq. 25 alone).
enum class Mass { unit, free };

// One solved ratio.
struct FitResult {
  double ratio = 1;
  SymmetricKernels params;
  double error = 0;  // relative L2 error sqrt(epsilon) / ||G||
  int evaluations = 0;
  int status = 0;  // NLopt's result code of the local solve (nlopt_result)
};

// The optimiser's variables x for parameters p (and back), for N pairs:
//   x[0] = sigma_a;
//   x[1 + 3i] = d_i - d_(i-1) (d_0 = 0), x[2 + 3i] = sigma_i, x[3 + 3i] = u_i = w_i / w_a;
//   x[1 + 3N] = m, the total mass, with Mass::free only (else m = 1);
// the weights are w_a = m / Z and w_i = m u_i / Z with Z = 1 + 2 sum u_i.
std::vector<double> pack(const SymmetricKernels& p, Mass mass);
SymmetricKernels unpack(const std::vector<double>& x, int pairs, Mass mass);

// The objective: epsilon / ||G||^2 at x for the ellipse (1, ratio), and its gradient in x
// into `grad` unless empty.
double relative_error_sq(const std::vector<double>& x, std::vector<double>& grad, double ratio,
                         int pairs, Mass mass);

// A local solve (LD_LBFGS within the bounds) for `ratio` from `start`; never returns a
// point worse than the start.
FitResult refine(double ratio, const SymmetricKernels& start, Mass mass = Mass::unit);

// A global search for `pairs` pairs at `ratio` (G_MLSL_LDS with LD_LBFGS, 20000
// evaluations, fixed seed), polished by `refine`.
FitResult global_fit(int pairs, double ratio, Mass mass = Mass::unit);

// The rows of one table: the fits on the grid of a KernelTable (kernel_table.h), and the
// first row that was solved.
struct Family {
  std::vector<FitResult> rows;
  int first_solved = 0;
};

// The family for `pairs` pairs: a global search at max_ratio, then continuation down the
// grid, each row a local solve from the linear extrapolation in t of the two rows above,
// while the fitted error stays >= 1e-6; the rows below the last such row are that row
// scaled to their ratio (scale_to_ratio), as the renderer does.
Family fit_family(int pairs, double max_ratio, int intervals, Mass mass = Mass::unit);

// The rows of `family` in KernelTable layout.
std::vector<double> table_values(const Family& family);

// Where the table lives, relative to the repository root.
inline constexpr const char* kTableFile = "src/shading/kernel_table.inc";

// The text of kernel_table.inc for `families` (1, 2 and 4 pairs, each fit_family's rows
// for max_ratio and intervals). Same input, same bytes.
std::string table_source(double max_ratio, int intervals, const std::vector<Family>& families);

}  // namespace sg::fit
