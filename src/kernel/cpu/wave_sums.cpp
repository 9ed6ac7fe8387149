// The instruction set the kernel's SIMD lanes run on (kernel/cpu/wave_sums.h).
#include "kernel/cpu/wave_sums.h"

#include <hwy/targets.h>
#include <cstdint>

namespace sg::wave_simd {

const char* target() {
  const int64_t targets = hwy::SupportedTargets() & HWY_TARGETS;
  return targets ? hwy::TargetName(targets & -targets) : "none";
}

}  // namespace sg::wave_simd
