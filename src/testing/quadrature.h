// Adaptive quadrature for the tests' direct integrals: Boost's 61-point Gauss-Kronrod rule
// on [-1, 1] with our own interval bisection.
//
// Why not Boost's own adaptive gauss_kronrod::integrate: in Boost 1.74 it compares the
// error of the [-1, 1] rule, unscaled, with a tolerance that is scaled by the interval's
// half-width, so once the intervals are short enough (half-width < 2 eps / tol) no interval
// is ever accepted and it recurses to max_depth (seconds to minutes per integral).
#pragma once

#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <vector>

namespace sg::testing {

namespace detail {
template <class F>
double adaptive_gk(F& f, double a, double b, double tol, double abs_tol, int depth) {
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  auto g = [&](double x) { return f(mid + half * x) * half; };
  double err = 0;
  const double est =
      boost::math::quadrature::gauss_kronrod<double, 61>::integrate(g, -1.0, 1.0, 0, 0.0, &err);
  if (depth == 0 || err <= std::max(tol * std::abs(est), abs_tol)) return est;
  return adaptive_gk(f, a, mid, tol, abs_tol, depth - 1) +
         adaptive_gk(f, mid, b, tol, abs_tol, depth - 1);
}
}  // namespace detail

// The integral of f over [a, b], split first at the points of `breaks` inside it (where
// the caller knows f has narrow features). Each piece is bisected until the Gauss-Kronrod
// error estimate is below tol relative or abs_tol absolute, at most max_depth times. The
// absolute floor is per piece, not shared out: halving it at each bisection would chase
// relative accuracy in tails of 1e-300 through every level.
template <class F>
double integrate(F f, double a, double b, std::vector<double> breaks = {}, double tol = 1e-12,
                 double abs_tol = 1e-15, int max_depth = 30) {
  breaks.push_back(a);
  breaks.push_back(b);
  std::sort(breaks.begin(), breaks.end());
  double sum = 0;
  for (size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double lo = std::max(a, breaks[i]), hi = std::min(b, breaks[i + 1]);
    if (hi > lo) sum += detail::adaptive_gk(f, lo, hi, tol, abs_tol, max_depth);
  }
  return sum;
}

}  // namespace sg::testing
