// The shading kernel compiled as C++ in double precision with its work counted, in
// namespace sg::kc: every wave visited, wave-buffer and table texel read, quadrature node,
// transcendental call and march step adds to the calling thread's sg::KernelCounters
// (kernel/cpp_prelude.h; the kernel text marks them with SG_COUNT, the C++ prelude counts
// the texel reads and the built-ins). The kernel's own loops run (no vectorised wave
// sums): the work a GPU invocation of the same text does, per pixel, for
// `sunglint bench --counters` (methods/kernel_counts.h). Include it in one translation
// unit: it is the whole kernel a third time.
#pragma once

#include "kernel/cpp_prelude.h"

#define SG_KERNEL_REAL double
#define SG_KERNEL_COUNTING
namespace sg::kc {
#include "kernel/cpp_types.h"
#include "kernel/interface.glsl"
#include "kernel/kernel.glsl"
}  // namespace sg::kc
#undef SG_KERNEL_COUNTING
#undef SG_KERNEL_REAL
