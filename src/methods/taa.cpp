#include "methods/taa.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>

#include "base/error.h"
#include "methods/taa_resolve.h"
#include "scene/camera_path.h"
#include "shading/radiance.h"
#include "shading/water_geometry.h"

namespace sg {

TaaMethod::TaaMethod(const TaaOptions& o) : options_(o) {
  if (o.jitter_count < 1 || o.jitter_count > 1024) {
    throw Error("--taa-jitter-count: must be in [1, 1024]");
  }
  if (!(o.alpha > 0 && o.alpha <= 1)) throw Error("--taa-alpha: must be in (0, 1]");
  if (!(o.gamma >= 0) || !std::isfinite(o.gamma)) throw Error("--taa-gamma: must be >= 0");
  if (o.warmup < 0 || o.warmup > 10000) throw Error("--taa-warmup: must be in [0, 10000]");
}

void TaaMethod::reset() {
  has_history_ = false;
  history_ = Image();
}

void TaaMethod::begin_frame(const FrameContext& ctx) {
  const SceneModel& m = ctx.model;
  if (has_history_ &&
      (ctx.time.frame != last_frame_ + 1 || history_.width != m.width() ||
       history_.height != m.height() || history_.channels != (m.scene.grey() ? 1 : 3))) {
    reset();  // a cut: the history belongs to another sequence
  }
  begin_host_frame(ctx);
  jitter_ = taa_jitter(ctx.time.frame, options_.jitter_count);
  t_prev_ = m.scene.frame_time(ctx.time.frame - 1);
  motion_.assign(static_cast<size_t>(m.width()) * m.height(), vec2(0));
  camera_moves_ = false;
  if (options_.motion == TaaMotion::full && m.scene.camera.moving()) {
    const CameraPoseAt prev = camera_pose(m.scene.camera, t_prev_);
    const CameraPoseAt now = camera_pose(m.scene.camera, ctx.time.end);
    if (prev.position != now.position || prev.look_at != now.look_at) {
      camera_moves_ = true;
      prev_camera_ = CameraModel(camera_at(m.scene.camera, t_prev_), m.width(), m.height());
    }
  }
}

RadianceWeights TaaMethod::sample(const FrameContext& ctx, int i, int j, vec2* motion) const {
  const SceneModel& m = ctx.model;
  const vec2 p = vec2(i + 0.5, j + 0.5) + jitter_;
  const vec3 origin = m.camera.position();
  if (motion && camera_moves_) return sample_moving(ctx, p, motion);
  if (!motion || !m.displaced()) {
    return weights_along_ray(water(ctx), origin, m.camera.direction(p.x, p.y), ctx.time.end);
  }
  RayHit hit;
  const RadianceWeights value =
      weights_along_ray(water(ctx), origin, m.camera.direction(p.x, p.y), ctx.time.end, &hit);
  if (hit.hit) {
    const vec3 before(hit.point.x, water(ctx).height(hit.point.x, hit.point.z, t_prev_),
                      hit.point.z);
    double px, py;
    if (m.camera.project(before - origin, px, py)) *motion = p - vec2(px, py);
  }
  return value;
}

RadianceWeights TaaMethod::sample_moving(const FrameContext& ctx, const vec2& p,
                                         vec2* motion) const {
  const SceneModel& m = ctx.model;
  const vec3 dir = m.camera.direction(p.x, p.y);
  RayHit hit;
  const WaterGeometry& g = water(ctx);
  const RadianceWeights value = weights_along_ray(g, m.camera.position(), dir, ctx.time.end, &hit);
  double px, py;
  bool seen;
  if (hit.hit) {
    const vec3 before =
        m.displaced() ? vec3(hit.point.x, g.height(hit.point.x, hit.point.z, t_prev_), hit.point.z)
                      : hit.point;
    seen = prev_camera_.project(before - prev_camera_.position(), px, py);
  } else {
    seen = prev_camera_.project(dir, px, py);  // the sky: a direction
  }
  // Behind the previous camera: a motion that puts the history off the image (rejected).
  *motion = seen ? p - vec2(px, py) : vec2(INFINITY);
  return value;
}

RadianceWeights TaaMethod::weights(const FrameContext& ctx, int i, int j) const {
  return sample(ctx, i, j, nullptr);
}

void TaaMethod::shade_tile(const FrameContext& ctx, int x0, int y0, int x1, int y1,
                           Image& out) const {
  const int w = ctx.model.width();
  for (int j = y0; j < y1; ++j) {
    for (int i = x0; i < x1; ++i) {
      store_pixel(ctx, out, i, j, sample(ctx, i, j, &motion_[static_cast<size_t>(j) * w + i]));
    }
  }
}

void TaaMethod::end_frame(const FrameContext& ctx, Image& img) {
  last_frame_ = ctx.time.frame;
  if (!has_history_) {
    history_ = img;
    has_history_ = true;
    return;
  }
  const Image current = img;
  const TaaOptions& o = options_;
  tbb::parallel_for(tbb::blocked_range<int>(0, img.height), [&](const tbb::blocked_range<int>& r) {
    for (int j = r.begin(); j < r.end(); ++j) {
      for (int i = 0; i < img.width; ++i) {
        const vec2 p = vec2(i + 0.5, j + 0.5) - motion_[static_cast<size_t>(j) * img.width + i];
        for (int ch = 0; ch < img.channels; ++ch) {  // each channel alone, clamp included
          const double c = current.at(i, j, ch);
          double h;
          if (!sample_history(history_, p, o.history, h, ch)) {
            img.at(i, j, ch) = static_cast<float>(c);
            continue;
          }
          if (o.clamp != TaaClamp::none) {
            h = clip_to_box(h, neighbourhood_box(current, i, j, o.clamp, o.gamma, ch));
          }
          const double blended = taa_blend(h, c, o.alpha);
          if (std::isfinite(blended)) {
            img.at(i, j, ch) = static_cast<float>(blended);
          } else {
            if (ch == 0) count_fallback();  // a pixel counts once
            img.at(i, j, ch) = static_cast<float>(c);
          }
        }
      }
    }
  });
  history_ = img;
}

}  // namespace sg
