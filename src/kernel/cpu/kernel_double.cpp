// The double kernel's SG_CPU_WAVE_SUMS hooks (kernel/kernel_double.h declares them), and
// its passes over the waves in SIMD lanes (kernel/cpu/lane_passes.inc), compiled for each
// instruction set Highway targets and dispatched at run time to the host's widest.
#ifndef SG_KERNEL_DOUBLE_CPP_ONCE
#define SG_KERNEL_DOUBLE_CPP_ONCE
#include "kernel/kernel_double.h"
#include "kernel/cpu/wave_sums.h"
#endif

// Highway's per-target compilation (kernel/cpu/lane_targets.inc): this file is included
// again once per instruction set.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "kernel/cpu/kernel_double.cpp"
#define SG_LANE_KERNEL kd
#define SG_LANE_REAL double
#include "kernel/cpu/lane_targets.inc"
