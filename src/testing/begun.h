// A method with ctx's frame begun, for tests that shade single pixels: the engine calls
// begin_frame before a frame's tiles (engine/render.h), and the kernel methods refuse a
// frame whose inputs it did not build (methods/kernel_inputs.h). Works on temporaries:
// begun(StaaMethod(o), c).shade(c, i, j).
#pragma once

#include <type_traits>

#include "methods/method.h"

namespace sg::testing {

template <class M>
std::remove_reference_t<M>& begun(M&& method, const FrameContext& ctx) {
  method.begin_frame(ctx);
  return method;
}

}  // namespace sg::testing
