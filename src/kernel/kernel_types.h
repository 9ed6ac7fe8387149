// The kernel's interface types (kernel/interface.glsl) in both precisions, for host code
// that fills a frame or reads a result: sg::kd (double) and sg::kf (float). The float
// kernel's functions are compiled in their own translation unit (kernel/cpu/kernel_float.cpp,
// with -fsingle-precision-constant so that a literal is a float, as in GLSL) and reached
// through kernel/kernel_float.h.
#pragma once

#include "kernel/cpp_prelude.h"

#define SG_KERNEL_REAL float
namespace sg::kf {
#include "kernel/cpp_types.h"
#include "kernel/interface.glsl"
}  // namespace sg::kf
#undef SG_KERNEL_REAL
