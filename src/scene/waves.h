// The water surface's waves: a sum of sine waves (Podee et al. 2021, Eq. 1, with the
// phase of the scene spec):
//     h(x, z, t) = sum_i A_i sin(a_i x + b_i z + c_i t + phi_i)
// held as structure-of-arrays, with the bounds of the height and slope that the displaced
// intersection relies on. The sums themselves are the kernel's alone (kernel/waves.glsl;
// host code reaches them through shading/water_geometry.h), so that every method and
// every host query meets one surface.
#pragma once

#include <vector>

#include "math/vec.h"
#include "scene/scene.h"

namespace sg {

// Second derivatives of h: (h_xx, h_xz, h_zz).
struct Hessian {
  double xx = 0, xz = 0, zz = 0;
};

class WaveField {
 public:
  WaveField() = default;
  explicit WaveField(const std::vector<Wave>& waves);

  size_t size() const { return A.size(); }

  // Upper bounds over all x, z, t: |h| <= amplitude_bound, |grad h| <= slope_bound.
  double amplitude_bound() const { return amplitude_bound_; }
  double slope_bound() const { return slope_bound_; }

  // Per-wave parameters (structure of arrays): amplitude, wave vector (a, b), angular
  // frequency, phase.
  std::vector<double> A, a, b, c, phi;

 private:
  double amplitude_bound_ = 0, slope_bound_ = 0;
};

}  // namespace sg
