// The estimator of the scene spec's pixel value, the mean over the pixel square and the
// shutter interval, by stratified jittered sampling: the ground truth of every comparison
// (`--method reference`) and the `supersample` baseline. The estimator is the kernel's
// (kernel/sampling.glsl, stratified_pixel: S_x x S_y jittered positions times T jittered
// times, random numbers from the stream of (seed, frame, pixel) in a fixed order); the
// CPU engine runs it as written there, or, on flat water in double precision, by its
// vectorised product form (kernel/cpu/), which evaluates each wave's phase once per
// position and reaches the other times by angle addition (tested equal to the kernel's).
#pragma once

#include "methods/kernel_inputs.h"
#include "methods/method.h"

namespace sg {

struct StratifiedSettings {
  SampleCounts samples;
  bool time_at_frame = false;
};

inline kd::SampleCounts kernel_sample_counts(const StratifiedSettings& s) {
  kd::SampleCounts n;
  n.sx = s.samples.sx;
  n.sy = s.samples.sy;
  n.nt = s.samples.st;
  n.time_at_frame = s.time_at_frame;
  return n;
}

// Pixel (i, j) of the frame whose inputs are `in`.
RadianceWeights stratified_pixel(const KernelFrameInputs& in, int i, int j,
                                 const StratifiedSettings& s);
// The same, building the frame's inputs for this one call (tests).
RadianceWeights stratified_pixel(const FrameContext& ctx, int i, int j,
                                 const StratifiedSettings& s);

// Wave evaluations (one wave's sine/cosine pair or its update) that the product form
// performs for one pixel, for the throughput figures of `sunglint bench`.
long stratified_pixel_wave_evaluations(const FrameContext& ctx, int i, int j,
                                       const StratifiedSettings& s);

}  // namespace sg
