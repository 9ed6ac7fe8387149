#include "shading/wave_lod.h"

#include <algorithm>

#include "shading/aliasing.h"

namespace sg {

double lod_weight(double a, double b, double x) {
  const double t = std::clamp((x - a) / (b - a), 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

void wave_lod_weights(const WaveField& waves, const mat2& J, double n_min, double n_max,
                      std::vector<double>& w) {
  w.resize(waves.size());
  for (size_t i = 0; i < waves.size(); ++i) {
    const double f = projected_frequency(vec2(waves.a[i], waves.b[i]), J, FrequencyNorm::max);
    w[i] = f > 0 ? lod_weight(n_min, n_max, 1.0 / f) : 1.0;
  }
}

}  // namespace sg
