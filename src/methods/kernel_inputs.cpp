#include "methods/kernel_inputs.h"

namespace sg {

void KernelFrameInputs::build(const FrameContext& ctx) {
  if (precision_ == Precision::float64) {
    build_kernel_inputs(ctx.model, ctx.time, segments_, ctx.seed, d_, intersect_tolerance_,
                        windows_);
  } else {
    build_kernel_inputs(ctx.model, ctx.time, segments_, ctx.seed, f_, intersect_tolerance_,
                        windows_);
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
  std::lock_guard<std::mutex> lock(lazy_);
  if (!current(ctx)) const_cast<KernelFrameInputs*>(this)->build(ctx);
}

}  // namespace sg
