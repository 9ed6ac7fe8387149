// The water surface: a sum of sine waves (Podee et al. 2021, Eq. 1, with the phase of
// the scene spec):
//     h(x, z, t) = sum_i A_i sin(a_i x + b_i z + c_i t + phi_i)
// and its analytic derivatives. The surface normal is normalize(-dh/dx, 1, -dh/dz)
// (scene spec). Waves are stored as structure-of-arrays so that sums over waves
// vectorise.
#pragma once

#include <span>
#include <vector>

#include "math/vec.h"
#include "scene/scene.h"

namespace sg {

// Second derivatives of h: (h_xx, h_xz, h_zz).
struct Hessian {
  double xx = 0, xz = 0, zz = 0;
};

// The sine and cosine of every wave's phase theta_i = a_i x + b_i z + c_i t + phi_i at one
// point and time: height, gradient and Hessian are weighted sums of them, so one
// (vectorised) evaluation serves all three, and the per-pixel NDF too (shading/ndf.h).
struct WavePhases {
  std::vector<double> s, c;  // sin(theta_i), cos(theta_i)
};

class WaveField {
 public:
  WaveField() = default;
  explicit WaveField(const std::vector<Wave>& waves);

  size_t size() const { return A.size(); }

  double height(double x, double z, double t) const;
  // (dh/dx, dh/dz)
  vec2 gradient(double x, double z, double t) const;
  Hessian hessian(double x, double z, double t) const;
  // Per-wave weights w_i scale the amplitudes (used to split waves into resolved and
  // aliasing sets, Podee et al. 2021 Sec. 3.7). weights.size() == size().
  vec2 gradient_weighted(double x, double z, double t, std::span<const double> weights) const;
  Hessian hessian_weighted(double x, double z, double t, std::span<const double> weights) const;
  // The field with amplitudes A_i w_i (bounds recomputed): a filtered surface to intersect.
  WaveField weighted(std::span<const double> weights) const;

  // The phases at (x, z, t), vectorised (math/simd_trig.h).
  void phases(double x, double z, double t, WavePhases& out) const;
  // The phases dt earlier, by angle subtraction: rot_c[i] = cos(c_i dt), rot_s[i] =
  // sin(c_i dt) (a table that depends on dt only; see rotation()).
  void shift_phases(const WavePhases& p, std::span<const double> rot_c,
                    std::span<const double> rot_s, WavePhases& out) const;
  void rotation(double dt, std::vector<double>& rot_c, std::vector<double>& rot_s) const;
  // Sums over precomputed phases; empty weights mean 1 for every wave.
  vec2 gradient(const WavePhases& p, std::span<const double> weights = {}) const;
  Hessian hessian(const WavePhases& p, std::span<const double> weights = {}) const;

  // Upper bounds over all x, z, t: |h| <= amplitude_bound, |grad h| <= slope_bound.
  double amplitude_bound() const { return amplitude_bound_; }
  double slope_bound() const { return slope_bound_; }

  // Per-wave parameters (structure of arrays): amplitude, wave vector (a, b), angular
  // frequency, phase.
  std::vector<double> A, a, b, c, phi;

 private:
  double amplitude_bound_ = 0, slope_bound_ = 0;
};

// The unit normal of the spec for a height gradient g = (dh/dx, dh/dz).
inline vec3 normal_from_gradient(vec2 g) {
  return normalize(vec3(-g.x, 1.0, -g.y));
}

}  // namespace sg
