#include "shading/ndf.h"

#include <algorithm>
#include <cmath>

namespace sg {

mat2 uniform_ndf_covariance(const WaveField& w, std::span<const double> weights) {
  double xx = 0, xz = 0, zz = 0;
  for (size_t i = 0; i < w.size(); ++i) {
    const double e = sqr(weights[i] * w.A[i]) / 2;
    xx += e * w.a[i] * w.a[i];
    xz += e * w.a[i] * w.b[i];
    zz += e * w.b[i] * w.b[i];
  }
  return mat2(vec2(xx, xz), vec2(xz, zz));
}

namespace {

// sin(x) / x, accurate near 0.
double sinc(double x) {
  if (std::fabs(x) < 1e-4) return 1.0 - x * x / 6.0;
  return std::sin(x) / x;
}

}  // namespace

SlopeMoments wave_slope_moments(double A, const vec2& k, double p1, double p2) {
  const double theta = 0.5 * (p1 + p2), D = 0.5 * (p2 - p1);
  const double K = A * std::cos(theta) * sinc(D);                            // Eq. 23
  const double J = 0.5 * A * A * (1.0 + std::cos(2 * theta) * sinc(2 * D));  // Eq. 24
  SlopeMoments m;
  m.B = k * K;                                              // Eq. 21
  m.M = vec3(k.x * k.x * J, k.x * k.y * J, k.y * k.y * J);  // Eq. 22
  return m;
}

double footprint_phase_half_width(const vec2& k, const mat2& J) {
  const double kk = length(k);
  if (kk == 0) return 0.0;
  const double det = glm::determinant(J);
  if (std::fabs(det) < 1e-300) return 0.0;
  const vec2 uv = glm::inverse(J) * (k / kk);  // pixel offsets per metre along k
  const double m = std::max(std::fabs(uv.x), std::fabs(uv.y));
  return m > 0 ? 0.5 / m * kk : 0.0;
}

PlaneGaussian per_pixel_ndf(const WaveField& w, std::span<const double> weights, const vec2& xz,
                            const mat2& J, double t) {
  PlaneGaussian g;
  double xx = 0, xz_ = 0, zz = 0;
  for (size_t i = 0; i < w.size(); ++i) {
    if (weights[i] == 0 || w.A[i] == 0) continue;
    const vec2 k(w.a[i], w.b[i]);
    const double theta = dot(k, xz) + w.c[i] * t + w.phi[i];
    const double D = footprint_phase_half_width(k, J);
    SlopeMoments m = wave_slope_moments(weights[i] * w.A[i], k, theta - D, theta + D);
    g.mean -= m.B;  // NDF-plane coordinates are minus the slope
    xx += m.M.x - m.B.x * m.B.x;
    xz_ += m.M.y - m.B.x * m.B.y;
    zz += m.M.z - m.B.y * m.B.y;
  }
  g.cov = mat2(vec2(xx, xz_), vec2(xz_, zz));
  return g;
}

}  // namespace sg
