#include "shading/ndf.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "math/simd_trig.h"

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

namespace {

// Half the phase range along unit direction k/|k| through the centre of the footprint
// whose inverse Jacobian is Jinv (Appendix A).
double half_width(const vec2& k, const mat2& Jinv) {
  const double kk = length(k);
  if (kk == 0) return 0.0;
  const vec2 uv = Jinv * (k / kk);  // pixel offsets per metre along k
  const double m = std::max(std::fabs(uv.x), std::fabs(uv.y));
  return m > 0 ? 0.5 / m * kk : 0.0;
}

bool invertible(const mat2& J) {
  return std::fabs(glm::determinant(J)) >= 1e-300;
}

}  // namespace

double footprint_phase_half_width(const vec2& k, const mat2& J) {
  return invertible(J) ? half_width(k, glm::inverse(J)) : 0.0;
}

PlaneGaussian per_pixel_ndf(const WaveField& w, std::span<const double> weights,
                            const WavePhases& ph, const mat2& J) {
  // Per wave: theta (phase at the centre), D (half-width), and
  //   K = A cos(theta) sin(D)/D,  J = A^2/2 (1 + cos(2 theta) sin(2D)/(2D))   (Eqs. 23-24)
  // with cos(2 theta) = 2 cos^2 - 1 and sin(2D)/(2D) = sin(D) cos(D) / D.
  thread_local std::vector<double> D, sD, cD;
  const size_t n = w.size();
  D.assign(n, 0.0);
  const bool inv = invertible(J);
  const mat2 Jinv = inv ? glm::inverse(J) : mat2(0.0);
  for (size_t i = 0; i < n; ++i) {
    if (inv && weights[i] != 0 && w.A[i] != 0) D[i] = half_width(vec2(w.a[i], w.b[i]), Jinv);
  }
  sD.resize(n);
  cD.resize(n);
  sincos_array(D.data(), sD.data(), cD.data(), n);
  PlaneGaussian g;
  double xx = 0, xz = 0, zz = 0;
  for (size_t i = 0; i < n; ++i) {
    if (weights[i] == 0 || w.A[i] == 0) continue;
    const double A = weights[i] * w.A[i], d = D[i];
    const double sinc1 = d < 1e-4 ? 1.0 - d * d / 6.0 : sD[i] / d;
    const double sinc2 = d < 1e-4 ? 1.0 - 2.0 * d * d / 3.0 : sD[i] * cD[i] / d;
    const double cos_t = ph.c[i], cos_2t = 2 * cos_t * cos_t - 1;
    const double K = A * cos_t * sinc1;
    const double JJ = 0.5 * A * A * (1.0 + cos_2t * sinc2);
    const double a = w.a[i], b = w.b[i];
    g.mean -= K * vec2(a, b);  // NDF-plane coordinates are minus the slope
    // M - B B^T (Eq. 4) for this wave: (JJ - K^2) times (a^2, ab, b^2).
    const double v = JJ - K * K;
    xx += v * a * a;
    xz += v * a * b;
    zz += v * b * b;
  }
  g.cov = mat2(vec2(xx, xz), vec2(xz, zz));
  return g;
}

PlaneGaussian per_pixel_ndf(const WaveField& w, std::span<const double> weights, const vec2& xz,
                            const mat2& J, double t) {
  thread_local WavePhases ph;
  w.phases(xz.x, xz.y, t, ph);
  return per_pixel_ndf(w, weights, ph, J);
}

}  // namespace sg
