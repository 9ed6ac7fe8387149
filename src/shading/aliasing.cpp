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
  alpha.resize(w.size());
  for (size_t i = 0; i < w.size(); ++i) {
    alpha[i] = alias_fraction(projected_frequency(vec2(w.a[i], w.b[i]), J, p.norm), p);
  }
}

}  // namespace sg
