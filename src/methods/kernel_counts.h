// The shading kernel's work per pixel, counted (`sunglint bench --counters`): a frame of a
// kernel method rendered through the counting build of the kernel (kernel/kernel_counting.h),
// which runs the kernel's own loops, as a GPU invocation runs the same text, and counts the
// explicit waves it visits, the wave-buffer and table texels it reads, its quadrature nodes,
// its transcendental calls and its march steps. Per counter, the mean and the maximum over
// the frame's pixels: the mean is the work, the maximum what the slowest lane of a GPU warp
// waits for. The images are not kept (the counting kernel is the kernel; its output is the
// double kernel's, without the CPU's vectorised sums).
#pragma once

#include <cstdint>
#include <string>

#include "methods/options.h"
#include "scene/model.h"

namespace sg {

struct KernelWork {
  struct Stat {
    double mean = 0;
    uint64_t max = 0;
  };
  Stat waves, buffer_fetches, table_fetches, nodes, transcendentals, march_steps;
  long pixels = 0;
  // staa: pixels the kernel left to the host's exact finish (--footprint exact), not counted
  long host_finished = 0;
};

// Whether `method` has a counting render: the kernel methods with a per-pixel entry point of
// their own (point, supersample, staa-temporal, staa, specaa, microspec).
bool kernel_work_counted(const std::string& method);

// Frame `frame` of m with `method` and its options, every pixel (oneTBB's threads, each
// counting its own pixels). sg::Error for a method without a counting render.
KernelWork count_kernel_work(const SceneModel& m, const std::string& method, const MethodOptions& o,
                             int frame);

// A prediction, not a measurement: a frame's time on a GPU from the counts and the
// GPU's published peak rates, as if the frame were bound by its transcendentals (the
// special-function units) or by its texel reads (the texture pipes), whichever takes
// longer, at full occupancy; ALU work, latency and the host's share are left out, so it is
// a lower bound. `from_max`: every pixel at the frame's largest counts (a warp waits for
// its slowest lane: the bound with the worst divergence), else at their means.
struct GpuPeakRates {
  const char* name;
  double sms, clock_hz;
  double sfu_per_sm_clock;    // transcendental results per SM per clock
  double texel_per_sm_clock;  // texel fetches per SM per clock
};
// NVIDIA H200 SXM (Hopper, as H100 SXM5): 132 SMs at 1.98 GHz (the H100 architecture
// whitepaper, 2022); 16 results of the special functions (sin, cos, exp2, log2, rcp, rsqrt)
// per SM per clock for compute capability 9.0 (CUDA C++ Programming Guide, "Arithmetic
// Instructions" throughput table); 4 texture units per SM (the whitepaper's SM diagram),
// taken as 4 texel fetches per clock.
inline constexpr GpuPeakRates kH200{"H200 SXM", 132, 1.98e9, 16, 4};
double predicted_frame_ms(const KernelWork& k, long pixels, const GpuPeakRates& gpu, bool from_max);

}  // namespace sg
