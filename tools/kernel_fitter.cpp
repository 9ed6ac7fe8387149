#include "kernel_fitter.h"

#include <nlopt.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "base/error.h"
#include "math/vec.h"
#include "shading/kernel_table.h"

namespace sg::fit {
namespace {

int dimension(int pairs, Mass mass) {
  return 1 + 3 * pairs + (mass == Mass::free ? 1 : 0);
}

struct Problem {
  double ratio;
  int pairs;
  Mass mass;
  int evaluations = 0;
  double unit = 1;  // the objective's unit
};

// epsilon / ||G||^2 (Eq. 25 relative to the ellipse's squared norm) in units of `unit`,
// and its gradient in x.
double objective(const std::vector<double>& x, std::vector<double>& grad, void* data) {
  auto* prob = static_cast<Problem*>(data);
  ++prob->evaluations;
  const int pairs = prob->pairs;
  const SymmetricKernels p = unpack(x, pairs, prob->mass);
  const std::vector<CircularKernel> k = expand(p);
  std::vector<CircularKernel> g(grad.empty() ? 0 : k.size());
  const double scale = 1 / (ellipse_norm_sq(1.0, prob->ratio) * prob->unit);
  const double eps = mixture_error_extended(k, 1.0, prob->ratio, g);
  if (!grad.empty()) {
    // The kernels are (centre, +d_1, -d_1, +d_2, ...); a pair's parameters act on both.
    // With g_a = dE/dw_a, g_i = dE/dw_i (both kernels) and W = w_a g_a + sum_i w_i g_i,
    // the chain rule through w_a = m / Z, w_i = m u_i / Z gives
    //   dE/du_j = w_a (g_j - 2 W / m),   dE/dm = W / m.
    double m = p.center_weight;
    for (const KernelPair& q : p.pairs)
      m += 2 * q.weight;
    double W = p.center_weight * g[0].weight;
    for (int i = 0; i < pairs; ++i)
      W += p.pairs[i].weight * (g[1 + 2 * i].weight + g[2 + 2 * i].weight);
    grad[0] = g[0].sigma * scale;
    // d_i = sum_{j <= i} x[1 + 3j]: dE/dx[1 + 3j] = sum_{i >= j} dE/dd_i.
    double tail = 0;
    for (int i = pairs - 1; i >= 0; --i) {
      tail += g[1 + 2 * i].offset - g[2 + 2 * i].offset;
      grad[1 + 3 * i] = tail * scale;
      grad[2 + 3 * i] = (g[1 + 2 * i].sigma + g[2 + 2 * i].sigma) * scale;
      const double gi = g[1 + 2 * i].weight + g[2 + 2 * i].weight;
      grad[3 + 3 * i] = (gi - 2 * W / m) * p.center_weight * scale;
    }
    if (prob->mass == Mass::free) grad[1 + 3 * pairs] = W / m * scale;
  }
  return eps * scale;
}

// The fitted error below which fit_family stops solving rows (kernel_table.h). Below it the
// optimum is so flat that several configurations lie within rounding of each other and a
// change in the last bit of the objective can pick another; rows solved there made the
// interpolation error jump by 1e-5. 1e-6 is far below anything visible.
constexpr double kResolvedError = 1e-6;

// The smallest increment d_i - d_(i-1), in units of t = sqrt(ratio^2 - 1): keeps the
// offsets strictly ordered, so that no two pairs merge into one (a local optimum that
// wastes a pair, which a continuation without it fell into near ratio 1.3). The tabulated
// fits never reach it (fit_kernels --report prints their smallest increment over t).
constexpr double kMinStep = 0.2;

// Bounds of the local solve: wide, only to keep the stds positive (>= 0.2 of the minor std),
// the offsets ordered and the weights non-negative.
void local_bounds(int pairs, Mass mass, double ratio, std::vector<double>& lb,
                  std::vector<double>& ub) {
  const int n = dimension(pairs, mass);
  lb.assign(n, 0.0);
  ub.assign(n, 0.0);
  lb[0] = 0.2;
  ub[0] = 2 * ratio + 2;
  for (int i = 0; i < pairs; ++i) {
    lb[1 + 3 * i] = kMinStep * ratio_to_t(ratio);
    ub[1 + 3 * i] = 3 * ratio + 3;
    lb[2 + 3 * i] = 0.2;
    ub[2 + 3 * i] = 2 * ratio + 2;
    ub[3 + 3 * i] = 100;
  }
  if (mass == Mass::free) ub[1 + 3 * pairs] = 2;
}

// opt.optimize, returning NLopt's result code rather than throwing for a stop on rounding
// or a failed line search: x then holds the best point found, which the callers check.
int run(nlopt::opt& opt, std::vector<double>& x) {
  double f = 0;
  try {
    return opt.optimize(x, f);
  } catch (const nlopt::roundoff_limited&) {
    return NLOPT_ROUNDOFF_LIMITED;
  } catch (const std::invalid_argument&) {
    throw;
  } catch (const std::runtime_error&) {
    return NLOPT_FAILURE;
  }
}

}  // namespace

// With the bounds d_i - d_(i-1) >= 0 and u_i >= 0, every x inside them has ordered offsets
// and non-negative weights summing to m.
SymmetricKernels unpack(const std::vector<double>& x, int pairs, Mass mass) {
  double z = 1;
  for (int i = 0; i < pairs; ++i)
    z += 2 * x[3 + 3 * i];
  const double m = mass == Mass::free ? x[1 + 3 * pairs] : 1.0;
  SymmetricKernels p;
  p.center_weight = m / z;
  p.center_sigma = x[0];
  double d = 0;
  for (int i = 0; i < pairs; ++i) {
    d += x[1 + 3 * i];
    p.pairs.push_back({d, x[2 + 3 * i], m * x[3 + 3 * i] / z});
  }
  return p;
}

std::vector<double> pack(const SymmetricKernels& p, Mass mass) {
  std::vector<double> x;
  x.push_back(p.center_sigma);
  double prev = 0, m = p.center_weight;
  for (const KernelPair& q : p.pairs) {
    x.push_back(q.distance - prev);
    x.push_back(q.sigma);
    x.push_back(q.weight / p.center_weight);
    prev = q.distance;
    m += 2 * q.weight;
  }
  if (mass == Mass::free) x.push_back(m);
  return x;
}

double relative_error_sq(const std::vector<double>& x, std::vector<double>& grad, double ratio,
                         int pairs, Mass mass) {
  Problem prob{ratio, pairs, mass};
  return objective(x, grad, &prob);
}

FitResult refine(double ratio, const SymmetricKernels& start, Mass mass) {
  const int pairs = static_cast<int>(start.pairs.size());
  std::vector<double> lb, ub;
  local_bounds(pairs, mass, ratio, lb, ub);
  std::vector<double> x = pack(start, mass);
  for (size_t j = 0; j < x.size(); ++j)
    x[j] = std::clamp(x[j], lb[j], ub[j]);
  Problem prob{ratio, pairs, mass};
  nlopt::opt opt(nlopt::LD_SLSQP, dimension(pairs, mass));
  opt.set_lower_bounds(lb);
  opt.set_upper_bounds(ub);
  std::vector<double> no_grad, x0_copy = x;
  prob.unit = std::max(objective(x0_copy, no_grad, &prob), 1e-300);
  opt.set_min_objective(objective, &prob);
  // Tolerances near rounding: the solve runs until SLSQP cannot improve (`status` says
  // which criterion stopped it), or until the relative L2 error is 1e-9 (epsilon / ||G||^2
  // = 1e-18, a few times the rounding of long double).
  opt.set_ftol_rel(1e-15);
  opt.set_xtol_rel(1e-12);
  opt.set_maxeval(5000);
  opt.set_stopval(1e-18 / prob.unit);
  const std::vector<double> x0 = x;
  const int status = run(opt, x);
  x0_copy = x0;
  const double f = objective(x, no_grad, &prob);
  const double f0 = objective(x0_copy, no_grad, &prob);
  if (!(f <= f0)) x = x0;  // never worse than the start
  const SymmetricKernels p = unpack(x, pairs, mass);
  const double eps =
      mixture_error_extended(expand(p), 1.0, ratio, {}) / ellipse_norm_sq(1.0, ratio);
  return {ratio, p, std::sqrt(std::max(0.0, eps)), prob.evaluations, status};
}

FitResult global_fit(int pairs, double ratio, Mass mass) {
  const int n = dimension(pairs, mass);
  // The search box, narrower than the local bounds: stds up to half the major std plus
  // one, offset steps up to 2.5 ratio / N + 1, pair weights up to three times the central
  // one, mass in [0.5, 1.5]. The polish by `refine` may leave the box.
  std::vector<double> lb(n, 0.0), ub(n, 0.0);
  lb[0] = 0.5;
  ub[0] = 0.5 * ratio + 1;
  for (int i = 0; i < pairs; ++i) {
    ub[1 + 3 * i] = 2.5 * ratio / pairs + 1;
    lb[2 + 3 * i] = 0.5;
    ub[2 + 3 * i] = 0.5 * ratio + 1;
    ub[3 + 3 * i] = 3;
  }
  if (mass == Mass::free) {
    lb[1 + 3 * pairs] = 0.5;
    ub[1 + 3 * pairs] = 1.5;
  }
  Problem prob{ratio, pairs, mass};
  nlopt::srand(20210601);  // MLSL's own random choices: fixed, so runs repeat
  nlopt::opt local(nlopt::LD_SLSQP, n);
  local.set_ftol_rel(1e-10);
  local.set_xtol_rel(1e-8);
  local.set_maxeval(5000);
  nlopt::opt opt(nlopt::G_MLSL_LDS, n);
  opt.set_local_optimizer(local);
  opt.set_lower_bounds(lb);
  opt.set_upper_bounds(ub);
  opt.set_min_objective(objective, &prob);
  // MLSL's bookkeeping grows with the square of its samples; 20000 evaluations take under
  // a second, and at ratio 16 find the optimum that 150 random local starts find
  // (kernel_fitter_test).
  opt.set_maxeval(20000);
  std::vector<double> x(n);
  for (int j = 0; j < n; ++j)
    x[j] = 0.5 * (lb[j] + ub[j]);
  run(opt, x);
  FitResult r = refine(ratio, unpack(x, pairs, mass), mass);
  r.evaluations += prob.evaluations;
  return r;
}

Family fit_family(int pairs, double max_ratio, int intervals, Mass mass) {
  Family fam;
  std::vector<FitResult>& out = fam.rows;
  out.resize(intervals + 1);
  out[intervals] = global_fit(pairs, max_ratio, mass);
  int last = intervals;  // the last row solved on the way down
  for (int j = intervals - 1; j >= 1; --j) {
    // Start from the row above, extrapolated linearly in t (the grid is uniform in t) from
    // the two rows above where there are two; `refine` clamps the start into its bounds.
    SymmetricKernels start = out[j + 1].params;
    if (j + 2 <= intervals) {
      const std::vector<double> a = pack(out[j + 2].params, mass);
      const std::vector<double> b = pack(out[j + 1].params, mass);
      std::vector<double> x(b.size());
      for (size_t k = 0; k < x.size(); ++k)
        x[k] = 2 * b[k] - a[k];
      for (int i = 0; i < pairs; ++i)
        x[3 + 3 * i] = std::max(0.0, x[3 + 3 * i]);  // u_i >= 0
      start = unpack(x, pairs, mass);
    }
    const FitResult r = refine(table_ratio(max_ratio, intervals, j), start, mass);
    if (r.error < kResolvedError) break;  // ill-determined from here down
    out[j] = r;
    last = j;
  }
  fam.first_solved = last;
  // Below: the last solved row scaled to each ratio, as the renderer does (kernel_table.h).
  for (int j = last - 1; j >= 0; --j) {
    const double ratio = table_ratio(max_ratio, intervals, j);
    const SymmetricKernels p = scale_to_ratio(out[last].params, out[last].ratio, ratio);
    out[j] = {ratio, p, relative_l2_error(expand(p), 1.0, ratio), 0, 0};
  }
  return fam;
}

std::vector<double> table_values(const Family& family) {
  std::vector<double> v;
  for (const FitResult& r : family.rows) {
    v.push_back(r.ratio);
    v.push_back(r.params.center_weight);
    v.push_back(r.params.center_sigma);
    for (const KernelPair& q : r.params.pairs) {
      v.push_back(q.distance);
      v.push_back(q.sigma);
      v.push_back(q.weight);
    }
  }
  return v;
}

std::string table_source(double max_ratio, int intervals, const std::vector<Family>& families) {
  std::string out;
  auto line = [&out](const std::string& s) { out += s + "\n"; };
  auto num = [](double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return std::string(buf);
  };
  line(
      "// Fitted circular-kernel parameters for elliptical Gaussians (Podee et al. 2021, App. C).");
  line("// Generated by tools/fit_kernels; do not edit. Regenerate from the repository root with");
  line("//   cmake --build build --target fit_kernels && build/tools/fit_kernels --out " +
       std::string(kTableFile));
  line("// docs/kernel-fits.md says what is fitted, how, and how well.");
  line("//");
  line("// Row j of each table is the optimum at the ratio r_j, where t_j = sqrt(r_j^2 - 1) =");
  line(
      "// t_max j / intervals and t_max = sqrt(max_ratio^2 - 1). Columns: r_j, w_a, sigma_a, then");
  line("// d_i, sigma_i, w_i for each pair i (unit minor std; weights are masses, summing to 1).");
  line("// Rows below kKernelTableFirstSolvedN are not fitted but scaled from that row (see");
  line("// kernel_table.h); they are here for reading only.");
  line("// clang-format off");
  line("inline constexpr double kKernelTableMaxRatio = " + num(max_ratio) + ";");
  line("inline constexpr int kKernelTableIntervals = " + std::to_string(intervals) + ";");
  for (const Family& family : families) {
    if (static_cast<int>(family.rows.size()) != intervals + 1)
      throw Error("table_source: a family has " + std::to_string(family.rows.size()) +
                  " rows, not " + std::to_string(intervals + 1));
    const int pairs = static_cast<int>(family.rows.front().params.pairs.size());
    const int columns = 3 + 3 * pairs;
    const std::string count = std::to_string(2 * pairs + 1);
    line("inline constexpr int kKernelTableFirstSolved" + count + " = " +
         std::to_string(family.first_solved) + ";");
    line("inline constexpr double kKernelTable" + count + "[" + std::to_string(intervals + 1) +
         "][" + std::to_string(columns) + "] = {");
    const std::vector<double> v = table_values(family);
    for (int j = 0; j <= intervals; ++j) {
      std::string row = "    {";
      for (int k = 0; k < columns; ++k)
        row += (k ? ", " : "") + num(v[j * columns + k]);
      line(row + "},");
    }
    line("};");
  }
  line("// clang-format on");
  return out;
}

}  // namespace sg::fit
