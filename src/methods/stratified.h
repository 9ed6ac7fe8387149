// The estimator of the scene spec's pixel value: the mean over the pixel square and the
// shutter interval, by stratified jittered sampling (the ground truth of every
// comparison, `--method reference`, and the `supersample` baseline).
//
// Samples form a product grid: S_x x S_y jittered positions, one per cell of the pixel
// square, times T jittered times, one per stratum of the shutter [t_f - shutter/fps, t_f];
// every position is paired with every time (S_x S_y T samples). Each stratum is sampled
// uniformly, so the estimate is unbiased; its error falls as the samples grow (tested).
// The product design lets flat water evaluate each wave's sine once per position and once
// per time instead of once per sample, using
//     cos(theta + c t) = cos(theta) cos(c t) - sin(theta) sin(c t).
//
// Random numbers come from the stream of (seed, frame, pixel) (math/rng.h), drawn in a
// fixed order: the T time jitters, then for each cell in row-major order its x and y
// jitter. Same inputs, same bytes, whatever the threads.
//
// `time_at_frame` replaces the T times by the single display time t_f (used by
// `supersample` with T = 1: spatial-only supersampling, as MSAA would).
#pragma once

#include <vector>

#include "math/rng.h"
#include "methods/method.h"

namespace sg {

struct StratifiedSettings {
  SampleCounts samples;
  bool time_at_frame = false;
};

RadianceWeights stratified_pixel(const FrameContext& ctx, int i, int j,
                                 const StratifiedSettings& s);

// The sample times: the first T numbers of the pixel's stream, one uniform time in each
// of the T equal strata of [start, end] (or the single time t_f with time_at_frame).
void draw_sample_times(Pcg32& rng, const FrameTime& ft, const StratifiedSettings& s,
                       std::vector<double>& times);

// Wave evaluations (one wave's sine/cosine pair or its update) that stratified_pixel
// performs for one pixel, for the throughput figures of `sunglint bench`.
long stratified_pixel_wave_evaluations(const FrameContext& ctx, int i, int j,
                                       const StratifiedSettings& s);

}  // namespace sg
