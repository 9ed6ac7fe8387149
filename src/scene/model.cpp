// The scene model's radiances applied to a pixel's weights: the kernel's formula
// (kernel/radiance.glsl, weights_radiance), in double.
#include "scene/model.h"

#include "kernel/kernel_double.h"

namespace sg {

double Radiances::apply(const RadianceWeights& w, int c) const {
  return kd::weights_radiance(w, channel(c));
}

}  // namespace sg
