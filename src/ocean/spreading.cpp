#include "ocean/spreading.h"

#include <algorithm>
#include <cmath>

#include "math/vec.h"
#include "scene/dispersion.h"

namespace sg::ocean {
namespace {

// The continued fraction of the incomplete beta function by the modified Lentz method
// (Press, Teukolsky, Vetterling and Flannery 2007, "Numerical Recipes", 3rd ed., Sec. 6.4,
// Eqs. 6.4.5-6.4.6; it converges fast for x < (a + 1) / (a + b + 2), which is x < 1/2
// here).
double beta_continued_fraction(double a, double b, double x) {
  constexpr double kTiny = 1e-300, kEps = 1e-15;
  const double qab = a + b, qap = a + 1, qam = a - 1;
  double c = 1, d = 1 - qab * x / qap;
  if (std::fabs(d) < kTiny) d = kTiny;
  d = 1 / d;
  double h = d;
  for (int m = 1; m < 10000; ++m) {
    const int m2 = 2 * m;
    double aa = m * (b - m) * x / ((qam + m2) * (a + m2));
    d = 1 + aa * d;
    if (std::fabs(d) < kTiny) d = kTiny;
    c = 1 + aa / c;
    if (std::fabs(c) < kTiny) c = kTiny;
    d = 1 / d;
    h *= d * c;
    aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2));
    d = 1 + aa * d;
    if (std::fabs(d) < kTiny) d = kTiny;
    c = 1 + aa / c;
    if (std::fabs(c) < kTiny) c = kTiny;
    d = 1 / d;
    const double del = d * c;
    h *= del;
    if (std::fabs(del - 1) < kEps) break;
  }
  return h;
}

// The standard normal quantile by Acklam's rational approximation (relative error below
// 1.2e-9; P. J. Acklam 2003, "An algorithm for computing the inverse normal cumulative
// distribution function"): only the starting point of the Newton iteration below.
double normal_quantile(double p) {
  static constexpr double a[] = {-3.969683028665376e+01, 2.209460984245205e+02,
                                 -2.759285104469687e+02, 1.383577518672690e+02,
                                 -3.066479806614716e+01, 2.506628277459239e+00};
  static constexpr double b[] = {-5.447609879822406e+01, 1.615858368580409e+02,
                                 -1.556989798598866e+02, 6.680131188771972e+01,
                                 -1.328068155288572e+01};
  static constexpr double c[] = {-7.784894002430293e-03, -3.223964580411365e-01,
                                 -2.400758277161838e+00, -2.549732539343734e+00,
                                 4.374664141464968e+00,  2.938163982698783e+00};
  static constexpr double d[] = {7.784695709041462e-03, 3.224671290700398e-01,
                                 2.445134137142996e+00, 3.754408661907416e+00};
  if (p > 0.5) return -normal_quantile(1 - p);
  if (p < 0.02425) {
    const double q = std::sqrt(-2 * std::log(p));
    return (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
           ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1);
  }
  const double q = p - 0.5, r = q * q;
  return (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
         (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1);
}

}  // namespace

double symmetric_beta_quantile(double a, double u) {
  if (!(u > 0)) return 0;
  if (!(u < 1)) return 1;
  // By symmetry, solve I_x(a, a) = v <= 1/2 for x <= 1/2 and reflect.
  const bool upper = u > 0.5;
  const double v = upper ? 1 - u : u;
  const double ln_beta = 2 * std::lgamma(a) - std::lgamma(2 * a);
  // Newton on I_x(a, a) - v, kept inside the bracket [lo, hi] by bisection, from the
  // normal approximation of Beta(a, a) (mean 1/2, variance 1 / (4 (2a + 1))).
  double lo = 0, hi = 0.5;
  double x = std::clamp(0.5 + 0.5 * normal_quantile(v) / std::sqrt(2 * a + 1), 1e-300, 0.5);
  for (int it = 0; it < 200; ++it) {
    const double lx = std::log(x), l1x = std::log1p(-x);
    const double f = std::exp(a * (lx + l1x) - ln_beta) * beta_continued_fraction(a, a, x) / a - v;
    if (f < 0) {
      lo = x;
    } else {
      hi = x;
    }
    const double density = std::exp((a - 1) * (lx + l1x) - ln_beta);
    double next = x - f / density;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    const bool done = std::fabs(next - x) <= 1e-14 * x;
    x = next;
    if (done) break;
  }
  return upper ? 1 - x : x;
}

double cos2s_normalisation(double s) {
  return std::exp((2 * s - 1) * std::log(2.0) + 2 * std::lgamma(s + 1) - std::log(kPi) -
                  std::lgamma(2 * s + 1));
}

double Spreading::parameter(double omega) const {
  const double r = omega / omega_peak;
  switch (kind) {
    case SpreadingKind::cos2s: {
      const double sp =
          s_peak >= 0 ? s_peak : 11.5 * std::pow(omega_peak * wind_speed / kGravity, -2.5);
      return sp * std::pow(r, r < 1 ? 5.0 : -2.5);
    }
    case SpreadingKind::hasselmann: {
      const double mu = r < 1 ? 4.06 : -2.33 - 1.45 * (wind_speed / peak_speed - 1.17);
      return 6.97 * std::pow(r, mu);
    }
    case SpreadingKind::donelan_banner:
      if (r < 0.95) return 2.61 * std::pow(r, 1.3);
      if (r < 1.6) return 2.28 * std::pow(r, -1.3);
      return std::pow(10.0, -0.4 + 0.8393 * std::exp(-0.567 * std::log(r * r)));
  }
  return 0;
}

double Spreading::density(double theta, double omega) const {
  if (std::fabs(theta) > kPi) return 0;
  const double p = parameter(omega);
  if (kind == SpreadingKind::donelan_banner) {
    if (p < 1e-8) return 1 / kTwoPi;  // beta -> 0: uniform
    const double c = std::cosh(p * theta);
    return p / (2 * std::tanh(p * kPi)) / (c * c);
  }
  return cos2s_normalisation(p) * std::pow(std::cos(theta / 2), 2 * p);
}

double Spreading::sample(double u, double omega) const {
  u = std::clamp(u, 0.0, 1.0);
  const double p = parameter(omega);
  if (kind == SpreadingKind::donelan_banner) {
    if (p < 1e-8) return kPi * (2 * u - 1);
    return std::atanh((2 * u - 1) * std::tanh(p * kPi)) / p;
  }
  const double x = symmetric_beta_quantile(p + 0.5, u);
  return 2 * std::asin(std::clamp(2 * x - 1, -1.0, 1.0));
}

std::string to_string(SpreadingKind kind) {
  switch (kind) {
    case SpreadingKind::cos2s:
      return "cos2s";
    case SpreadingKind::hasselmann:
      return "hasselmann";
    case SpreadingKind::donelan_banner:
      return "donelan-banner";
  }
  return "";
}

}  // namespace sg::ocean
