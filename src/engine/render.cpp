#include "engine/render.h"

#include <tbb/blocked_range2d.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <mutex>
#include <optional>

#include "scene/camera_path.h"

namespace sg {

Image render_frame(const SceneModel& model, Method& method, int frame,
                   const RenderSettings& settings) {
  std::unique_ptr<tbb::global_control> limit;
  if (settings.threads > 0) {
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                  settings.threads);
  }
  const int w = model.width(), h = model.height(), t = std::max(1, settings.tile);
  // One channel for a grey scene (its files stay as they were), R, G, B for colour.
  Image img = Image::with_channels(w, h, model.scene.grey() ? 1 : 3);
  // A moving camera: the frame's model holds the camera at the shutter's end (what the
  // methods that do not sample time render; the kernel's take the keys over the shutter).
  const FrameTime ft = frame_time(model.scene, frame);
  std::optional<SceneModel> moved;
  if (model.scene.camera.moving()) moved.emplace(frame_model(model.scene, ft));
  FrameContext ctx{moved ? *moved : model, ft, settings.seed};
  method.begin_frame(ctx);

  const int tiles_x = (w + t - 1) / t, tiles_y = (h + t - 1) / t;
  const long total = static_cast<long>(tiles_x) * tiles_y;
  std::atomic<long> done{0};
  std::mutex progress_mutex;
  tbb::parallel_for(
      tbb::blocked_range2d<int>(0, tiles_y, 1, 0, tiles_x, 1),
      [&](const tbb::blocked_range2d<int>& r) {
        for (int ty = r.rows().begin(); ty < r.rows().end(); ++ty) {
          for (int tx = r.cols().begin(); tx < r.cols().end(); ++tx) {
            method.shade_tile(ctx, tx * t, ty * t, std::min(w, tx * t + t), std::min(h, ty * t + t),
                              img);
            long d = ++done;
            if (settings.progress) {
              std::lock_guard<std::mutex> lock(progress_mutex);
              settings.progress(d, total);
            }
          }
        }
      },
      tbb::simple_partitioner());
  method.end_frame(ctx, img);
  return img;
}

int warmup_frame_count(const Method& method) {
  return method.stateful() ? std::max(0, method.warmup_frames()) : 0;
}

void render_frames(const SceneModel& model, Method& method, int first, int last,
                   const RenderSettings& settings,
                   const std::function<void(int frame, const Image&)>& on_frame) {
  if (method.stateful()) {
    method.reset();
    for (int f = first - warmup_frame_count(method); f < first; ++f)
      render_frame(model, method, f, settings);
  }
  for (int f = first; f <= last; ++f)
    on_frame(f, render_frame(model, method, f, settings));
}

}  // namespace sg
