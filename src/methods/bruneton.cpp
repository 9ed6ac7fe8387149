#include "methods/bruneton.h"

#include "kernel/kernel_double.h"
#include "kernel/kernel_float.h"

namespace sg {

RadianceWeights BrunetonMethod::weights(const FrameContext& ctx, int i, int j) const {
  inputs_->check(ctx);
  auto result = [&](const auto& r) {
    if (r.fallback) count_fallback();
    return to_weights(r.weights);
  };
  if (inputs_->precision() == Precision::float32) {
    const KernelInputsF& in = inputs_->f();
    return result(kf::float_bruneton_pixel(
        wave_buffer(in), in.frame, bruneton_kernel_params<kf::BrunetonParams>(options_), i, j));
  }
  const KernelInputsD& in = inputs_->d();
  return result(kd::bruneton_pixel(wave_buffer(in), in.frame,
                                   bruneton_kernel_params<kd::BrunetonParams>(options_), i, j));
}

}  // namespace sg
