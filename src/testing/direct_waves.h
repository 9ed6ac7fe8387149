// The scene spec's surface (Podee et al. 2021, Eq. 1) summed directly, wave by wave in
// file order, with the standard library's sine and cosine at the full phase
//     h(x, z, t) = sum_i w_i A_i sin(a_i x + b_i z + c_i t + phi_i)
// and its first and second derivatives: the brute-force truth that the kernel's sums
// (kernel/waves.glsl, through shading/water_geometry.h) and the terms built on them are
// tested against. Only tests include it; no method shades with it.
#pragma once

#include <cmath>
#include <span>

#include "scene/waves.h"

namespace sg::testing {

// Weights w_i scale the amplitudes (empty: 1 for every wave).
inline double direct_weight(std::span<const double> w, size_t i) {
  return w.empty() ? 1.0 : w[i];
}

// Wave i's phase a_i x + b_i z + c_i t + phi_i, unreduced.
inline double direct_phase(const WaveField& f, size_t i, double x, double z, double t) {
  return f.a[i] * x + f.b[i] * z + f.c[i] * t + f.phi[i];
}

inline double direct_height(const WaveField& f, double x, double z, double t,
                            std::span<const double> w = {}) {
  double h = 0;
  for (size_t i = 0; i < f.size(); ++i)
    h += direct_weight(w, i) * f.A[i] * std::sin(direct_phase(f, i, x, z, t));
  return h;
}

// (dh/dx, dh/dz)
inline vec2 direct_gradient(const WaveField& f, double x, double z, double t,
                            std::span<const double> w = {}) {
  vec2 g(0.0);
  for (size_t i = 0; i < f.size(); ++i) {
    const double k = direct_weight(w, i) * f.A[i] * std::cos(direct_phase(f, i, x, z, t));
    g += k * vec2(f.a[i], f.b[i]);
  }
  return g;
}

// (h_xx, h_xz, h_zz)
inline Hessian direct_hessian(const WaveField& f, double x, double z, double t,
                              std::span<const double> w = {}) {
  Hessian H;
  for (size_t i = 0; i < f.size(); ++i) {
    const double s = -direct_weight(w, i) * f.A[i] * std::sin(direct_phase(f, i, x, z, t));
    H.xx += s * f.a[i] * f.a[i];
    H.xz += s * f.a[i] * f.b[i];
    H.zz += s * f.b[i] * f.b[i];
  }
  return H;
}

}  // namespace sg::testing
