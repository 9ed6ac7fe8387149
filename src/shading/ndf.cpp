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
  if (invertible(J)) {
    // half_width without its square root and branches, so that it vectorises: with
    // q = J^-1 k, D = |k| / (2 max(|q|) / |k|) = |k|^2 / (2 max(|q.x|, |q.y|)).
    const mat2 Ji = glm::inverse(J);
    const double i00 = Ji[0][0], i01 = Ji[1][0], i10 = Ji[0][1], i11 = Ji[1][1];
    const double* a = w.a.data();
    const double* b = w.b.data();
    double* d = D.data();
    for (size_t i = 0; i < n; ++i) {
      const double qx = std::fabs(i00 * a[i] + i01 * b[i]), qy = std::fabs(i10 * a[i] + i11 * b[i]);
      d[i] = 0.5 * (a[i] * a[i] + b[i] * b[i]) / std::max(std::max(qx, qy), 1e-300);
    }
  }
  sD.resize(n);
  cD.resize(n);
  sincos_array(D.data(), sD.data(), cD.data(), n);
  // A wave of weight or amplitude 0 has A = 0 and adds nothing, so the loop needs no
  // branch and its sums may be vectorised (reassociated; deterministic for a given build).
  double xx = 0, xz = 0, zz = 0, mx = 0, mz = 0;
#pragma omp simd reduction(+ : xx, xz, zz, mx, mz)
  for (size_t i = 0; i < n; ++i) {
    const double A = weights[i] * w.A[i], d = D[i];
    const double inv_d = 1.0 / std::max(d, 1e-4);  // one division per wave
    const double sinc1 = d < 1e-4 ? 1.0 - d * d / 6.0 : sD[i] * inv_d;
    const double sinc2 = d < 1e-4 ? 1.0 - 2.0 * d * d / 3.0 : sD[i] * cD[i] * inv_d;
    const double cos_t = ph.c[i], cos_2t = 2 * cos_t * cos_t - 1;
    const double K = A * cos_t * sinc1;
    const double JJ = 0.5 * A * A * (1.0 + cos_2t * sinc2);
    const double a = w.a[i], b = w.b[i];
    mx -= K * a;  // NDF-plane coordinates are minus the slope
    mz -= K * b;
    // M - B B^T (Eq. 4) for this wave: (JJ - K^2) times (a^2, ab, b^2).
    const double v = JJ - K * K;
    xx += v * a * a;
    xz += v * a * b;
    zz += v * b * b;
  }
  PlaneGaussian g;
  g.mean = vec2(mx, mz);
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
