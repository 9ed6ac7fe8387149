// Host wrappers of the kernel's NDF terms (kernel/ndf.glsl), summed over a wave field.
#include "shading/ndf.h"

#include <cmath>

#include "kernel/kernel_double.h"

namespace sg {

mat2 uniform_ndf_covariance(const WaveField& w, std::span<const double> weights) {
  kd::NdfMoments m = kd::ndf_zero();
  for (size_t i = 0; i < w.size(); ++i)
    kd::ndf_add_uniform(m, weights[i] * w.A[i], vec2(w.a[i], w.b[i]));
  return kd::sym2(m.cov);
}

SlopeMoments wave_slope_moments(double A, const vec2& k, double p1, double p2) {
  const double theta = 0.5 * (p1 + p2), D = 0.5 * (p2 - p1);
  const vec2 KJ = kd::wave_moment_factors(A, std::cos(theta), D, std::sin(D), std::cos(D));
  SlopeMoments m;
  m.B = k * KJ.x;                                                    // Eq. 21
  m.M = vec3(k.x * k.x * KJ.y, k.x * k.y * KJ.y, k.y * k.y * KJ.y);  // Eq. 22
  return m;
}

double footprint_phase_half_width(const vec2& k, const mat2& J) {
  return glm::determinant(J) != 0 ? kd::footprint_half_width(k, glm::inverse(J)) : 0.0;
}

PlaneGaussian per_pixel_ndf(const WaveField& w, std::span<const double> weights, const vec2& xz,
                            const mat2& J, double t) {
  kd::NdfMoments m = kd::ndf_zero();
  const bool invertible = glm::determinant(J) != 0;
  const mat2 Jinv = invertible ? glm::inverse(J) : mat2(0.0);
  for (size_t i = 0; i < w.size(); ++i) {
    const vec2 k(w.a[i], w.b[i]);
    // The wave at the world's origin and time 0: its phase at (x, z) and t is the kernel's.
    kd::Wave kw{};
    kw.A = w.A[i];
    kw.a = w.a[i];
    kw.b = w.b[i];
    kw.theta0 = w.phi[i];
    kw.c = w.c[i];
    const double D = invertible ? kd::footprint_half_width(k, Jinv) : 0.0;
    kd::ndf_add_per_pixel(m, weights[i] * w.A[i], k, std::cos(kd::wave_phase(kw, xz.x, xz.y, t)), D,
                          std::sin(D), std::cos(D));
  }
  PlaneGaussian g;
  g.mean = m.mean;
  g.cov = kd::sym2(m.cov);
  return g;
}

}  // namespace sg
