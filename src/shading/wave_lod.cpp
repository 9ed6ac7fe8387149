#include "shading/wave_lod.h"

#include "kernel/kernel_double.h"

namespace sg {

double lod_weight(double a, double b, double x) {
  return kd::lod_weight(a, b, x);
}

void wave_lod_weights(const WaveField& waves, const mat2& J, double n_min, double n_max,
                      std::vector<double>& w) {
  w.resize(waves.size());
  for (size_t i = 0; i < waves.size(); ++i)
    w[i] = kd::wave_lod_weight(vec2(waves.a[i], waves.b[i]), J, n_min, n_max);
}

double smallest_singular_value(const mat2& m) {
  return kd::smallest_singular_value(m);
}

}  // namespace sg
