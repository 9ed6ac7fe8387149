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

namespace {

// The sines and cosines of every wave's phase a x + b z + c t + phi at one point and
// time, vectorised (math/simd_trig.h). Per-thread scratch: the wave field is shared by
// all threads.
struct PhaseScratch {
  std::vector<double> theta, s, c;
};

const PhaseScratch& phases(const WaveField& w, double x, double z, double t) {
  thread_local PhaseScratch p;
  const size_t n = w.size();
  p.theta.resize(n);
  p.s.resize(n);
  p.c.resize(n);
  for (size_t i = 0; i < n; ++i)
    p.theta[i] = w.a[i] * x + w.b[i] * z + w.c[i] * t + w.phi[i];
  sincos_array(p.theta.data(), p.s.data(), p.c.data(), n);
  return p;
}

}  // namespace

double WaveField::height(double x, double z, double t) const {
  const PhaseScratch& p = phases(*this, x, z, t);
  double h = 0;
  for (size_t i = 0; i < size(); ++i)
    h += A[i] * p.s[i];
  return h;
}

vec2 WaveField::gradient(double x, double z, double t) const {
  const PhaseScratch& p = phases(*this, x, z, t);
  double gx = 0, gz = 0;
  for (size_t i = 0; i < size(); ++i) {
    const double k = A[i] * p.c[i];
    gx += a[i] * k;
    gz += b[i] * k;
  }
  return {gx, gz};
}

Hessian WaveField::hessian(double x, double z, double t) const {
  const PhaseScratch& p = phases(*this, x, z, t);
  Hessian H;
  for (size_t i = 0; i < size(); ++i) {
    const double s = -A[i] * p.s[i];
    H.xx += a[i] * a[i] * s;
    H.xz += a[i] * b[i] * s;
    H.zz += b[i] * b[i] * s;
  }
  return H;
}

vec2 WaveField::gradient_weighted(double x, double z, double t, std::span<const double> w) const {
  assert(w.size() == size());
  const PhaseScratch& p = phases(*this, x, z, t);
  double gx = 0, gz = 0;
  for (size_t i = 0; i < size(); ++i) {
    const double k = w[i] * A[i] * p.c[i];
    gx += a[i] * k;
    gz += b[i] * k;
  }
  return {gx, gz};
}

Hessian WaveField::hessian_weighted(double x, double z, double t, std::span<const double> w) const {
  assert(w.size() == size());
  const PhaseScratch& p = phases(*this, x, z, t);
  Hessian H;
  for (size_t i = 0; i < size(); ++i) {
    const double s = -w[i] * A[i] * p.s[i];
    H.xx += a[i] * a[i] * s;
    H.xz += a[i] * b[i] * s;
    H.zz += b[i] * b[i] * s;
  }
  return H;
}

}  // namespace sg
