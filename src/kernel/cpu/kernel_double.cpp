// The double kernel's SG_CPU_WAVE_SUMS hooks (kernel/kernel_double.h declares them).
#include "kernel/kernel_double.h"

#include "kernel/cpu/wave_sums.h"

namespace sg::kd {

#include "kernel/cpu/wave_sums_hooks.inc"

}  // namespace sg::kd
