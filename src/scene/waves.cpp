#include "scene/waves.h"

#include <cassert>
#include <cmath>

namespace sg {

WaveField::WaveField(const std::vector<Wave>& waves) {
  for (const Wave& w : waves) {
    A.push_back(w.amplitude);
    a.push_back(w.wave_vector.x);
    b.push_back(w.wave_vector.y);
    c.push_back(w.angular_frequency);
    phi.push_back(w.phase);
    amplitude_bound_ += std::fabs(w.amplitude);
    slope_bound_ += std::fabs(w.amplitude) * length(w.wave_vector);
  }
}

double WaveField::height(double x, double z, double t) const {
  double h = 0;
  for (size_t i = 0; i < size(); ++i)
    h += A[i] * std::sin(a[i] * x + b[i] * z + c[i] * t + phi[i]);
  return h;
}

vec2 WaveField::gradient(double x, double z, double t) const {
  double gx = 0, gz = 0;
  for (size_t i = 0; i < size(); ++i) {
    double k = A[i] * std::cos(a[i] * x + b[i] * z + c[i] * t + phi[i]);
    gx += a[i] * k;
    gz += b[i] * k;
  }
  return {gx, gz};
}

Hessian WaveField::hessian(double x, double z, double t) const {
  Hessian H;
  for (size_t i = 0; i < size(); ++i) {
    double s = -A[i] * std::sin(a[i] * x + b[i] * z + c[i] * t + phi[i]);
    H.xx += a[i] * a[i] * s;
    H.xz += a[i] * b[i] * s;
    H.zz += b[i] * b[i] * s;
  }
  return H;
}

WaveField WaveField::weighted(std::span<const double> w) const {
  assert(w.size() == size());
  WaveField f = *this;
  f.amplitude_bound_ = f.slope_bound_ = 0;
  for (size_t i = 0; i < size(); ++i) {
    f.A[i] = w[i] * A[i];
    f.amplitude_bound_ += std::fabs(f.A[i]);
    f.slope_bound_ += std::fabs(f.A[i]) * std::hypot(a[i], b[i]);
  }
  return f;
}

vec2 WaveField::gradient_weighted(double x, double z, double t, std::span<const double> w) const {
  assert(w.size() == size());
  double gx = 0, gz = 0;
  for (size_t i = 0; i < size(); ++i) {
    if (w[i] == 0) continue;
    double k = w[i] * A[i] * std::cos(a[i] * x + b[i] * z + c[i] * t + phi[i]);
    gx += a[i] * k;
    gz += b[i] * k;
  }
  return {gx, gz};
}

Hessian WaveField::hessian_weighted(double x, double z, double t, std::span<const double> w) const {
  assert(w.size() == size());
  Hessian H;
  for (size_t i = 0; i < size(); ++i) {
    if (w[i] == 0) continue;
    double s = -w[i] * A[i] * std::sin(a[i] * x + b[i] * z + c[i] * t + phi[i]);
    H.xx += a[i] * a[i] * s;
    H.xz += a[i] * b[i] * s;
    H.zz += b[i] * b[i] * s;
  }
  return H;
}

}  // namespace sg
