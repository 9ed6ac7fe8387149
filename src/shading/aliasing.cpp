// Host wrappers of the kernel's aliasing classification (kernel/aliasing.glsl).
#include "shading/aliasing.h"

#include "kernel/kernel_double.h"

namespace sg {

double projected_frequency(const vec2& k, const mat2& J, FrequencyNorm norm) {
  return kd::projected_frequency(k, J, norm == FrequencyNorm::max);
}

double alias_fraction(double f, const AliasingParams& p) {
  return kd::alias_fraction(f, p.start, p.end);
}

void alias_fractions(const WaveField& w, const mat2& J, const AliasingParams& p,
                     std::vector<double>& alpha) {
  alpha.resize(w.size());
  for (size_t i = 0; i < w.size(); ++i)
    alpha[i] = alias_fraction(projected_frequency(vec2(w.a[i], w.b[i]), J, p.norm), p);
}

}  // namespace sg
