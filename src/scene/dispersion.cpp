#include "scene/dispersion.h"

#include <cmath>

namespace sg {

double Dispersion::omega(double k) const {
  if (deep()) return std::sqrt(kGravity * k);
  return std::sqrt(kGravity * k * std::tanh(k * depth));
}

double Dispersion::group_speed(double k) const {
  if (k <= 0) return deep() ? std::numeric_limits<double>::infinity() : std::sqrt(kGravity * depth);
  const double w = omega(k);
  if (deep()) return 0.5 * w / k;
  // d/dk of sqrt(g k tanh(kh)): (omega / 2k) (1 + 2kh / sinh(2kh)); for large kh the
  // ratio underflows to 0 (deep water), for small kh it tends to 1 (c_g -> sqrt(g h)).
  const double kh2 = 2 * k * depth;
  const double ratio = kh2 > 700 ? 0.0 : kh2 / std::sinh(kh2);
  return 0.5 * w / k * (1 + ratio);
}

double Dispersion::wavenumber(double w) const {
  if (w <= 0) return 0;
  const double k_deep = w * w / kGravity;
  if (deep()) return k_deep;
  // Eckart 1952: k h ~ (omega^2 h / g) / sqrt(tanh(omega^2 h / g)), within 5% everywhere,
  // then Newton on f(k) = g k tanh(k h) - omega^2 (convex increasing: converges
  // monotonically after the first step).
  const double x = k_deep * depth;
  double k = x / std::sqrt(std::tanh(x)) / depth;
  for (int it = 0; it < 50; ++it) {
    const double t = std::tanh(k * depth);
    const double f = kGravity * k * t - w * w;
    const double df = kGravity * (t + k * depth * (1 - t * t));
    const double step = f / df;
    k -= step;
    if (std::fabs(step) <= 1e-15 * k) break;
  }
  return k;
}

}  // namespace sg
