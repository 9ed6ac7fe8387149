#include "shading/aliasing.h"

#include <algorithm>
#include <cmath>

namespace sg {

double projected_frequency(const vec2& k, const mat2& J, FrequencyNorm norm) {
  // Columns of J are dX/dpx and dX/dpy.
  const double fx = std::fabs(dot(k, J[0])), fy = std::fabs(dot(k, J[1]));
  const double rad = norm == FrequencyNorm::max ? std::max(fx, fy) : std::hypot(fx, fy);
  return rad / kTwoPi;
}

double alias_fraction(double f, const AliasingParams& p) {
  if (f <= p.start) return 0.0;
  if (f >= p.end) return 1.0;
  return (f - p.start) / (p.end - p.start);
}

void alias_fractions(const WaveField& w, const mat2& J, const AliasingParams& p,
                     std::vector<double>& alpha) {
  // projected_frequency and alias_fraction for every wave, written without branches so
  // that the loop vectorises (the same arithmetic; tested equal).
  const size_t n = w.size();
  alpha.resize(n);
  const double* a = w.a.data();
  const double* b = w.b.data();
  double* out = alpha.data();
  const double j00 = J[0][0], j01 = J[0][1], j10 = J[1][0], j11 = J[1][1];
  const double inv_width = 1.0 / (p.end - p.start), start = p.start;
  const bool max_norm = p.norm == FrequencyNorm::max;
  for (size_t i = 0; i < n; ++i) {
    const double fx = std::fabs(a[i] * j00 + b[i] * j01), fy = std::fabs(a[i] * j10 + b[i] * j11);
    const double rad = max_norm ? std::max(fx, fy) : std::sqrt(fx * fx + fy * fy);
    out[i] = std::clamp((rad / kTwoPi - start) * inv_width, 0.0, 1.0);
  }
}

}  // namespace sg
