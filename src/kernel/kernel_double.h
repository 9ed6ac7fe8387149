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

namespace sg::kd {
// The LEAN map's level-0 slopes of a block of texels, lean_waves.glsl's lean_wave_slope over
// the CPU's SIMD lanes (kernel/cpu/lane_passes.inc, LeanBlockPass, says the layout; width a
// multiple of sg::wave_simd::kLanePadding).
void lean_block_slopes(const double* amplitude, int nk, const double* rows, int row_count,
                       const double* column_cos, const double* column_sin, int width, double* out);
}  // namespace sg::kd
