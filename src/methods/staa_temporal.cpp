#include "methods/staa_temporal.h"

#include "kernel/kernel_double.h"
#include "kernel/kernel_float.h"

namespace sg {

RadianceWeights StaaTemporalMethod::weights(const FrameContext& ctx, int i, int j) const {
  inputs_.check(ctx);
  if (inputs_.precision() == Precision::float32) {
    return to_weights(
        kf::float_staa_temporal_pixel(wave_buffer(inputs_.f()), inputs_.f().frame, i, j));
  }
  return kd::staa_temporal_pixel(wave_buffer(inputs_.d()), inputs_.d().frame, i, j);
}

}  // namespace sg
