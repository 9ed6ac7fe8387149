// F(d, sigma), the mass of a circular Gaussian inside the unit disk (Podee et al. 2021,
// inner integral of Eq. 17); the derivations are in disk_gaussian.h.
#include "shading/disk_gaussian.h"

#include <boost/math/distributions/non_central_chi_squared.hpp>
#include <boost/math/quadrature/trapezoidal.hpp>
#include <cmath>
#include <sstream>

#include "base/error.h"
#include "kernel/kernel_double.h"

namespace sg {
namespace {

constexpr double kCut = 40;           // |d - 1| / sigma beyond this: F is exactly 0 or 1
constexpr double kSmallSigma = 0.05;  // below: the exact 1D form
constexpr double kLargeSigma = 1e3;   // above: the wide-Gaussian expansion
constexpr double kZ2Max = 13;         // P(|Z| > 13) = 1.2e-38
constexpr double kInvSqrt2Pi = 0.39894228040143267794;

double small_sigma(double d, double sigma) {
  const double t = (d - 1) / sigma;
  auto integrand = [&](double z) {
    const double sz = sigma * z;
    const double s = std::sqrt(1 - sz * sz);
    // (s - d) / sigma = -t - (1 - s) / sigma, with 1 - s = sigma^2 z^2 / (1 + s).
    const double upper = -t - sigma * z * z / (1 + s);
    const double lower = (-s - d) / sigma;
    return kd::normal_mass(lower, upper) * kInvSqrt2Pi * std::exp(-0.5 * z * z);
  };
  // The integrand is even in z.
  return 2 * boost::math::quadrature::trapezoidal(integrand, 0.0, kZ2Max, 1e-15);
}

void check(double value, const char* name, const char* rule, bool ok) {
  if (!ok) {
    std::ostringstream msg;
    msg << "disk_gaussian: " << name << " must be " << rule << " (got " << value << ")";
    throw Error(msg.str());
  }
}

}  // namespace

double disk_gaussian_wide(double d, double sigma) {
  return kd::disk_gaussian_wide(d, sigma);
}

double disk_gaussian(double d, double sigma) {
  check(d, "d", "finite and >= 0", std::isfinite(d) && d >= 0);
  check(sigma, "sigma", "finite and >= 0", std::isfinite(sigma) && sigma >= 0);
  if (sigma == 0) return d < 1 ? 1.0 : (d == 1 ? 0.5 : 0.0);
  const double t = (d - 1) / sigma;
  if (t <= -kCut) return 1;
  if (t >= kCut) return 0;
  if (sigma < kSmallSigma) return small_sigma(d, sigma);
  if (sigma > kLargeSigma) return disk_gaussian_wide(d, sigma);
  const double x = 1 / (sigma * sigma);
  const double lambda = d * d * x;
  if (lambda == 0) return -std::expm1(-0.5 * x);  // central chi-squared, 2 dof
  return boost::math::cdf(boost::math::non_central_chi_squared_distribution<double>(2, lambda), x);
}

}  // namespace sg
