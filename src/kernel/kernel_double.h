// The shading kernel compiled as C++ in double precision, in namespace sg::kd: the CPU
// engine's default (`--precision double`), the tests' reference, and the host's own
// uses of the kernel's formulas; its types alone are kernel/kernel_types.h's. Header-only
// (every kernel function is inline); the CPU
// engine's vectorised passes over the waves are declared by the kernel itself
// (SG_CPU_WAVE_SUMS, waves.glsl) and defined in kernel/cpu/.
#pragma once

#include "kernel/kernel_types.h"  // sg::kd's types: the prelude and interface.glsl

#define SG_CPU_WAVE_SUMS
namespace sg::kd {
#include "kernel/kernel.glsl"
}  // namespace sg::kd
#undef SG_CPU_WAVE_SUMS
