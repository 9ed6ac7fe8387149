// The kernel's interface types (kernel/interface.glsl) in both precisions, for host code
// that fills a frame or reads a result: sg::kd (double) and sg::kf (float). Host code that
// only moves the kernel's inputs and results includes this alone, so that a change of the
// kernel's functions recompiles only the code that calls them. The double kernel's
// functions are reached through kernel/kernel_double.h (header-only); the float kernel's
// are compiled in their own translation unit (kernel/cpu/kernel_float.cpp, with
// -fsingle-precision-constant so that a literal is a float, as in GLSL) and reached
// through kernel/kernel_float.h.
#pragma once

#include "kernel/cpp_prelude.h"

#define SG_KERNEL_REAL double
namespace sg::kd {
#include "kernel/cpp_types.h"
#include "kernel/interface.glsl"
}  // namespace sg::kd
#undef SG_KERNEL_REAL

#define SG_KERNEL_REAL float
namespace sg::kf {
#include "kernel/cpp_types.h"
#include "kernel/interface.glsl"
}  // namespace sg::kf
#undef SG_KERNEL_REAL
