#include "methods/kernel_inputs.h"

#include <string>

#include "base/error.h"

namespace sg {

void KernelFrameInputs::build(const FrameContext& ctx) {
  if (precision_ == Precision::float64) {
    build_kernel_inputs(ctx.model, ctx.time, segments_, ctx.seed, d_, intersect_tolerance_,
                        windows_, cascade_fields_, CascadeData::host, reads_);
  } else {
    build_kernel_inputs(ctx.model, ctx.time, segments_, ctx.seed, f_, intersect_tolerance_,
                        windows_, cascade_fields_, CascadeData::host, reads_);
  }
  model_ = ctx.model.id;
  frame_ = ctx.time.frame;
  start_ = ctx.time.start;
  end_ = ctx.time.end;
  seed_ = ctx.seed;
  built_ = true;
}

bool KernelFrameInputs::current(const FrameContext& ctx) const {
  return built_ && model_ == ctx.model.id && frame_ == ctx.time.frame && start_ == ctx.time.start &&
         end_ == ctx.time.end && seed_ == ctx.seed;
}

void KernelFrameInputs::check(const FrameContext& ctx) const {
  if (current(ctx)) return;
  throw Error(
      "kernel inputs: frame " + std::to_string(ctx.time.frame) +
      (built_ ? " differs from the frame they were built for" : " shaded before they were built") +
      " (the engine calls the method's begin_frame before its tiles: engine/render.h)");
}

}  // namespace sg
