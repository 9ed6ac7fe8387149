// The CPU engine: renders a frame by splitting the image into tiles that oneTBB spreads
// over the threads. Each pixel's value depends only on the scene, the method, the frame,
// the seed and the pixel itself, so the output does not depend on the number of threads
// or on which thread ran which tile.
//
// Sequences render frames in order through the same method object, so stateful methods
// (history, as in TAA) see their previous frame. For a stateful method, frame F is defined
// as the method's output after it has rendered frames F - N .. F - 1 from an empty history,
// N = method.warmup_frames(): render_frames resets the method and renders those N warm-up
// frames (not passed to on_frame) before the first requested frame, so `--frame F` and
// the first frame of `--frames F-G` are the same image. Warm-up frames may have negative
// indices (times before t0: the waves are defined at every t). Later frames of a sequence
// carry history from further back; the difference from rendering them alone decays as
// the method's history weight after N frames ((1 - alpha)^N for TAA).
#pragma once

#include <functional>

#include "image/image.h"
#include "methods/method.h"

namespace sg {

// Progress of long work: `done` of `total` units (tiles) completed. Called from worker
// threads, serialised by the engine.
using ProgressFn = std::function<void(long done, long total)>;

struct RenderSettings {
  int threads = 0;  // 0: all hardware threads
  int tile = 16;    // tile side in pixels
  uint64_t seed = 0;
  ProgressFn progress;
};

// One step of the method at `frame`: begin_frame, the tiles, end_frame. No warm-up: a
// stateful method blends with whatever history it holds.
Image render_frame(const SceneModel& model, Method& method, int frame,
                   const RenderSettings& settings);

// The warm-up frames render_frames renders before a sequence: method.warmup_frames() for a
// stateful method, 0 otherwise.
int warmup_frame_count(const Method& method);

// Frames first..last in order, after the warm-up frames first - N .. first - 1 of a
// stateful method (reset first); `on_frame(frame, image)` receives each requested frame.
// settings.progress reports the tiles of every frame rendered, warm-up frames included.
void render_frames(const SceneModel& model, Method& method, int first, int last,
                   const RenderSettings& settings,
                   const std::function<void(int frame, const Image&)>& on_frame);

}  // namespace sg
