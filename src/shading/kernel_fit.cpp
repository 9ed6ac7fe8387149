#include "shading/kernel_fit.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "base/error.h"
#include "math/vec.h"
#include "shading/kernel_table.h"

namespace sg {

std::vector<CircularKernel> expand(const SymmetricKernels& p) {
  std::vector<CircularKernel> k;
  k.reserve(1 + 2 * p.pairs.size());
  k.push_back({0.0, p.center_sigma, p.center_weight});
  for (const KernelPair& q : p.pairs) {
    k.push_back({q.distance, q.sigma, q.weight});
    k.push_back({-q.distance, q.sigma, q.weight});
  }
  return k;
}

double ellipse_density(double x, double y, double sigma_minor, double sigma_major) {
  return std::exp(-0.5 * (sqr(x / sigma_minor) + sqr(y / sigma_major))) /
         (kTwoPi * sigma_minor * sigma_major);
}

double mixture_density(std::span<const CircularKernel> kernels, double x, double y) {
  double sum = 0;
  for (const CircularKernel& k : kernels) {
    const double s2 = k.sigma * k.sigma;
    sum += k.weight * std::exp(-0.5 * (x * x + sqr(y - k.offset)) / s2) / (kTwoPi * s2);
  }
  return sum;
}

double mixture_inner_product(std::span<const CircularKernel> a, std::span<const CircularKernel> b) {
  double sum = 0;
  for (const CircularKernel& p : a) {
    for (const CircularKernel& q : b) {
      const double S = p.sigma * p.sigma + q.sigma * q.sigma;
      sum += p.weight * q.weight * std::exp(-0.5 * sqr(p.offset - q.offset) / S) / (kTwoPi * S);
    }
  }
  return sum;
}

double ellipse_norm_sq(double sigma_minor, double sigma_major) {
  return 1.0 / (2.0 * kTwoPi * sigma_minor * sigma_major);
}

namespace {

// Eq. 25 expanded: eps = <G, G> - 2 sum_k w_k <G, N_k> + sum_kl w_k w_l <N_k, N_l>, where
// every inner product of two normal densities is a normal density of the difference of
// their means under the sum of their covariances:
//   <N(m1, S1), N(m2, S2)> = N(m1 - m2; 0, S1 + S2).
// With G = N(0, diag(a^2, b^2)) and N_k = N((0, m_k), s_k^2 I):
//   <G, G>     = 1 / (4 pi a b)
//   <G, N_k>   = exp(-m_k^2 / (2 (b^2 + s_k^2))) / (2 pi sqrt((a^2 + s_k^2)(b^2 + s_k^2)))
//   <N_k, N_l> = exp(-(m_k - m_l)^2 / (2 S)) / (2 pi S),  S = s_k^2 + s_l^2.
// The sum cancels down to eps, so its rounding is that of <G, G> in the type `Real`.
template <class Real>
double mixture_error_in(std::span<const CircularKernel> kernels, double sigma_minor,
                        double sigma_major, std::span<CircularKernel> gradient) {
  const bool want_gradient = !gradient.empty();
  if (want_gradient && gradient.size() != kernels.size())
    throw Error("mixture_error: gradient has " + std::to_string(gradient.size()) + " entries for " +
                std::to_string(kernels.size()) + " kernels");
  using std::exp;
  using std::sqrt;
  const Real two_pi = 2 * Real(3.141592653589793238462643383279502884L);
  const Real a = sigma_minor, b = sigma_major;
  const Real a2 = a * a, b2 = b * b;
  struct Grad {
    Real offset = 0, sigma = 0, weight = 0;
  };
  std::vector<Grad> g(want_gradient ? kernels.size() : 0);

  Real eps = 1 / (2 * two_pi * a * b);
  const size_t n = kernels.size();
  for (size_t k = 0; k < n; ++k) {
    const Real m = kernels[k].offset, s = kernels[k].sigma, w = kernels[k].weight;
    const Real s2 = s * s;
    // <G, N_k> and its derivatives (through u = s_k^2 for sigma).
    const Real ea = a2 + s2, eb = b2 + s2;
    const Real cross = exp(-m * m / (2 * eb)) / (two_pi * sqrt(ea * eb));
    eps -= 2 * w * cross;
    if (want_gradient) {
      const Real dlog_du = m * m / (2 * eb * eb) - 1 / (2 * ea) - 1 / (2 * eb);
      g[k].weight -= 2 * cross;
      g[k].offset += 2 * w * cross * m / eb;
      g[k].sigma -= 2 * w * cross * dlog_du * 2 * s;
    }
    // <N_k, N_k> = 1 / (4 pi s_k^2).
    const Real self = 1 / (2 * two_pi * s2);
    eps += w * w * self;
    if (want_gradient) {
      g[k].weight += 2 * w * self;
      g[k].sigma -= 2 * w * w * self / s;
    }
    // The pairs k < l, counted twice.
    for (size_t l = k + 1; l < n; ++l) {
      const Real mq = kernels[l].offset, sq = kernels[l].sigma, wq = kernels[l].weight;
      const Real S = s2 + sq * sq, D = m - mq;
      const Real A = exp(-D * D / (2 * S)) / (two_pi * S);
      eps += 2 * w * wq * A;
      if (want_gradient) {
        const Real c = 2 * w * wq * A;
        const Real dlog_dS = D * D / (2 * S * S) - 1 / S;
        g[k].weight += 2 * wq * A;
        g[l].weight += 2 * w * A;
        g[k].offset -= c * D / S;
        g[l].offset += c * D / S;
        g[k].sigma += c * dlog_dS * 2 * s;
        g[l].sigma += c * dlog_dS * 2 * sq;
      }
    }
  }
  for (size_t k = 0; k < g.size(); ++k)
    gradient[k] = {static_cast<double>(g[k].offset), static_cast<double>(g[k].sigma),
                   static_cast<double>(g[k].weight)};
  return static_cast<double>(eps);
}

}  // namespace

double mixture_error(std::span<const CircularKernel> kernels, double sigma_minor,
                     double sigma_major, std::span<CircularKernel> gradient) {
  return mixture_error_in<double>(kernels, sigma_minor, sigma_major, gradient);
}

double mixture_error(std::span<const CircularKernel> kernels, double sigma_minor,
                     double sigma_major) {
  return mixture_error_in<double>(kernels, sigma_minor, sigma_major, {});
}

double mixture_error_extended(std::span<const CircularKernel> kernels, double sigma_minor,
                              double sigma_major, std::span<CircularKernel> gradient) {
  return mixture_error_in<long double>(kernels, sigma_minor, sigma_major, gradient);
}

double relative_l2_error(std::span<const CircularKernel> kernels, double sigma_minor,
                         double sigma_major) {
  // eps can come out a few ulps of ||G||^2 below zero when the fit is near exact.
  const double eps = std::max(0.0, mixture_error(kernels, sigma_minor, sigma_major));
  return std::sqrt(eps / ellipse_norm_sq(sigma_minor, sigma_major));
}

// N = 0. With one kernel (0, s, w) and the ellipse (1, r), eps is quadratic in w with
// minimiser w* = <G, N> / <N, N> = 2 s^2 / sqrt((1 + s^2)(r^2 + s^2)), leaving
//   eps(s) = 1 / (4 pi r) - s^2 / (pi (1 + s^2)(r^2 + s^2)).
// With u = s^2, d/du [u / ((1 + u)(r^2 + u))] = (r^2 - u^2) / (...)^2 vanishes at u = r:
// the L2-optimal variance is sigma_x sigma_y, the equal-area variance of Sec. 3.5, and
// w* = 2 sqrt(r) / (1 + r), relative error sqrt(eps) / ||G|| = (r - 1) / (r + 1).
CircularKernel single_kernel_l2_optimum(double ratio) {
  return {0.0, std::sqrt(ratio), 2.0 * std::sqrt(ratio) / (1.0 + ratio)};
}

CircularKernel equal_area_kernel(double ratio) {
  return {0.0, std::sqrt(ratio), 1.0};
}

bool valid_kernel_count(int count) {
  return std::find(std::begin(kKernelCounts), std::end(kKernelCounts), count) !=
         std::end(kKernelCounts);
}

double kernel_table_max_ratio() {
  return compiled_kernel_table(3).max_ratio;
}

SymmetricKernels tabulated_kernels(int count, double ratio) {
  if (count == 1) {
    const CircularKernel k = equal_area_kernel(std::max(1.0, ratio));
    return {k.weight, k.sigma, {}};
  }
  return interpolate(compiled_kernel_table(count), ratio);
}

KernelSet elliptical_kernels(int count, double sigma_minor, double sigma_major) {
  if (!valid_kernel_count(count))
    throw Error("elliptical_kernels: kernel count must be 1, 3, 5 or 9 (got " +
                std::to_string(count) + ")");
  if (!(sigma_minor > 0) || !(sigma_major > 0) || !std::isfinite(sigma_minor) ||
      !std::isfinite(sigma_major))
    throw Error("elliptical_kernels: standard deviations must be finite and > 0 (got " +
                std::to_string(sigma_minor) + ", " + std::to_string(sigma_major) + ")");
  double ratio = sigma_major / sigma_minor;
  if (ratio < 1) {
    // Equal eigenvalues can come out a few ulps apart; a real swap is the caller's bug.
    if (ratio < 1 - 1e-9)
      throw Error("elliptical_kernels: sigma_major " + std::to_string(sigma_major) +
                  " is below sigma_minor " + std::to_string(sigma_minor));
    ratio = 1;
  }
  KernelSet set;
  set.ratio = ratio;
  set.past_threshold = ratio > count;
  // The unit-minor parameters, and the length that maps them to the RDF.
  SymmetricKernels p;
  double scale = sigma_minor;
  if (count == 1) {
    p = tabulated_kernels(1, ratio);
  } else {
    const double max_ratio = kernel_table_max_ratio();
    if (ratio > max_ratio) {
      // Past the table: the fit for max_ratio, scaled to match the major std; across the
      // major axis it is then ratio / max_ratio times too wide.
      set.beyond_table = true;
      scale = sigma_major / max_ratio;
      p = tabulated_kernels(count, max_ratio);
    } else {
      p = tabulated_kernels(count, ratio);
    }
  }
  set.kernels = expand(p);
  for (CircularKernel& k : set.kernels) {
    k.offset *= scale;
    k.sigma *= scale;
  }
  return set;
}

}  // namespace sg
