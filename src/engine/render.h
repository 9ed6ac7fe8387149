// The CPU engine: renders a frame by splitting the image into tiles that oneTBB spreads
// over the threads. Each pixel's value depends only on the scene, the method, the frame,
// the seed and the pixel itself, so the output does not depend on the number of threads
// or on which thread ran which tile.
//
// Sequences render frames in order through the same method object, so stateful methods
// (history, as in TAA) see their previous frame.
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

Image render_frame(const SceneModel& model, Method& method, int frame,
                   const RenderSettings& settings);

// Frames first..last in order; `on_frame(frame, image)` receives each one.
void render_frames(const SceneModel& model, Method& method, int first, int last,
                   const RenderSettings& settings,
                   const std::function<void(int frame, const Image&)>& on_frame);

}  // namespace sg
