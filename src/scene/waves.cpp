#include "scene/waves.h"

#include <cassert>
#include <cmath>
#include <vector>

#include "math/simd_trig.h"

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

void WaveField::phases(double x, double z, double t, WavePhases& out) const {
  thread_local std::vector<double> theta;
  const size_t n = size();
  theta.resize(n);
  out.s.resize(n);
  out.c.resize(n);
  for (size_t i = 0; i < n; ++i)
    theta[i] = a[i] * x + b[i] * z + c[i] * t + phi[i];
  sincos_array(theta.data(), out.s.data(), out.c.data(), n);
}

void WaveField::rotation(double dt, std::vector<double>& rot_c, std::vector<double>& rot_s) const {
  thread_local std::vector<double> arg;
  arg.resize(size());
  rot_c.resize(size());
  rot_s.resize(size());
  for (size_t i = 0; i < size(); ++i)
    arg[i] = c[i] * dt;
  sincos_array(arg.data(), rot_s.data(), rot_c.data(), size());
}

void WaveField::shift_phases(const WavePhases& p, std::span<const double> rot_c,
                             std::span<const double> rot_s, WavePhases& out) const {
  // sin(theta - d) = sin(theta) cos(d) - cos(theta) sin(d); cos(theta - d) = cos cos + sin sin
  const size_t n = size();
  out.s.resize(n);
  out.c.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const double s = p.s[i], co = p.c[i];
    out.s[i] = s * rot_c[i] - co * rot_s[i];
    out.c[i] = co * rot_c[i] + s * rot_s[i];
  }
}

vec2 WaveField::gradient(const WavePhases& p, std::span<const double> w) const {
  assert(w.empty() || w.size() == size());
  double gx = 0, gz = 0;
  // The sums may be vectorised (reassociated): deterministic for a given build.
  const double* wi = w.empty() ? nullptr : w.data();
  if (wi) {
#pragma omp simd reduction(+ : gx, gz)
    for (size_t i = 0; i < size(); ++i) {
      const double k = wi[i] * A[i] * p.c[i];
      gx += a[i] * k;
      gz += b[i] * k;
    }
  } else {
#pragma omp simd reduction(+ : gx, gz)
    for (size_t i = 0; i < size(); ++i) {
      const double k = A[i] * p.c[i];
      gx += a[i] * k;
      gz += b[i] * k;
    }
  }
  return {gx, gz};
}

Hessian WaveField::hessian(const WavePhases& p, std::span<const double> w) const {
  assert(w.empty() || w.size() == size());
  double xx = 0, xz = 0, zz = 0;
#pragma omp simd reduction(+ : xx, xz, zz)
  for (size_t i = 0; i < size(); ++i) {
    const double s = -(w.empty() ? 1.0 : w[i]) * A[i] * p.s[i];
    xx += a[i] * a[i] * s;
    xz += a[i] * b[i] * s;
    zz += b[i] * b[i] * s;
  }
  return Hessian{xx, xz, zz};
}

namespace {

const WavePhases& phases_at(const WaveField& w, double x, double z, double t) {
  thread_local WavePhases p;
  w.phases(x, z, t, p);
  return p;
}

}  // namespace

double WaveField::height(double x, double z, double t) const {
  const WavePhases& p = phases_at(*this, x, z, t);
  double h = 0;
  for (size_t i = 0; i < size(); ++i)
    h += A[i] * p.s[i];
  return h;
}

vec2 WaveField::gradient(double x, double z, double t) const {
  return gradient(phases_at(*this, x, z, t));
}

Hessian WaveField::hessian(double x, double z, double t) const {
  return hessian(phases_at(*this, x, z, t));
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
  return gradient(phases_at(*this, x, z, t), w);
}

Hessian WaveField::hessian_weighted(double x, double z, double t, std::span<const double> w) const {
  return hessian(phases_at(*this, x, z, t), w);
}

}  // namespace sg
