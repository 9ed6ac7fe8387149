// The CPU engine's sums over the waves in SIMD lanes: the kernel's own per-wave terms
// (kernel/wave_terms.glsl, path_terms.glsl, staa_waves.glsl), compiled over Highway's
// vectors (kernel/cpu/lane_types.h) in kernel/cpu/lane_passes.inc, once per precision and
// instruction set, and dispatched at run time to the host's widest. The kernel's loops are
// the definition; kernel_wave_sums_test holds the lanes equal to them (they differ only in
// rounding: the order of the sums and the sine's last bits).
//
// The arrays the lanes read (sg::wave_simd::Arrays, kernel/cpp_prelude.h) are padded to a
// multiple of kLanePadding with waves of amplitude 0 (shading/kernel_frame.h), so the
// vectors need no tail; a sum over some of the waves sets the amplitude of the lanes
// outside them to 0, so that it equals the loop's.
#pragma once

namespace sg::wave_simd {

inline constexpr int kLanePadding = 16;

// The instruction set the sums run on, as Highway names it ("AVX3", "AVX2", ...).
const char* target();

}  // namespace sg::wave_simd
