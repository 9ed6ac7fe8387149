#include "methods/taa.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>

#include "base/error.h"
#include "kernel/kernel_double.h"
#include "kernel/kernel_float.h"
#include "scene/camera_path.h"

namespace sg {

void validate_taa_options(const TaaOptions& o) {
  if (o.jitter_count < 1 || o.jitter_count > 1024) {
    throw Error("--taa-jitter-count: must be in [1, 1024]");
  }
  if (!(o.alpha > 0 && o.alpha <= 1)) throw Error("--taa-alpha: must be in (0, 1]");
  if (!(o.gamma >= 0) || !std::isfinite(o.gamma)) throw Error("--taa-gamma: must be >= 0");
  if (o.warmup < 0 || o.warmup > 10000) throw Error("--taa-warmup: must be in [0, 10000]");
}

kd::TaaParams taa_frame_params(const SceneModel& m, const FrameTime& ft, const TaaOptions& o,
                               const glm::dvec3& origin) {
  kd::TaaParams p{};
  p.jitter = kd::taa_jitter(ft.frame, o.jitter_count);
  const double t_prev = m.scene.frame_time(ft.frame - 1);
  p.dt_prev = t_prev - ft.end;
  p.prev_camera_differs = false;
  p.prev_camera = m.camera.kernel_camera();
  if (o.motion == TaaMotion::full && m.scene.camera.moving()) {
    const CameraPoseAt prev = camera_pose(m.scene.camera, t_prev);
    const CameraPoseAt now = camera_pose(m.scene.camera, ft.end);
    if (prev.position != now.position || prev.look_at != now.look_at) {
      const CameraModel c(camera_at(m.scene.camera, t_prev), m.width(), m.height());
      p.prev_camera_differs = true;
      p.prev_camera = c.kernel_camera();
      p.prev_camera.position = c.position() - vec3(origin);
    }
  }
  return p;
}

kf::TaaParams taa_params_float(const kd::TaaParams& p) {
  kf::TaaParams f{};
  f.jitter = kf::vec2(p.jitter);
  f.dt_prev = static_cast<float>(p.dt_prev);
  f.prev_camera_differs = p.prev_camera_differs;
  const kd::Camera& c = p.prev_camera;
  f.prev_camera.position = kf::vec3(c.position);
  f.prev_camera.forward = kf::vec3(c.forward);
  f.prev_camera.right = kf::vec3(c.right);
  f.prev_camera.up = kf::vec3(c.up);
  f.prev_camera.half_w = static_cast<float>(c.half_w);
  f.prev_camera.half_h = static_cast<float>(c.half_h);
  f.prev_camera.width = static_cast<float>(c.width);
  f.prev_camera.height = static_cast<float>(c.height);
  return f;
}

kd::TaaResolveParams taa_resolve_params(const TaaOptions& o, int width, int height, int channels) {
  kd::TaaResolveParams p{};
  p.size = kd::ivec2(width, height);
  p.channels = channels;
  p.alpha = o.alpha;
  p.gamma = o.gamma;
  p.clamp = o.clamp == TaaClamp::none     ? kd::kTaaClampNone
            : o.clamp == TaaClamp::minmax ? kd::kTaaClampMinmax
                                          : kd::kTaaClampVariance;
  p.catmull_rom = o.history == TaaHistoryFilter::catmull_rom;
  return p;
}

kf::TaaResolveParams taa_resolve_params_float(const kd::TaaResolveParams& p) {
  kf::TaaResolveParams f{};
  f.size = kf::ivec2(p.size);
  f.channels = p.channels;
  f.alpha = static_cast<float>(p.alpha);
  f.gamma = static_cast<float>(p.gamma);
  f.clamp = p.clamp;
  f.catmull_rom = p.catmull_rom;
  return f;
}

TaaMethod::TaaMethod(const TaaOptions& o, Precision precision, double intersect_tolerance)
    : options_(o), inputs_(1, precision, intersect_tolerance, 1, false) {
  validate_taa_options(o);
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
  inputs_.build(ctx);
  reset_fallbacks();
  const glm::dvec3 origin =
      inputs_.precision() == Precision::float64 ? inputs_.d().origin : inputs_.f().origin;
  params_ = taa_frame_params(m, ctx.time, options_, origin);
  params_f_ = taa_params_float(params_);
  motion_.assign(static_cast<size_t>(m.width()) * m.height(), vec2(0));
}

RadianceWeights TaaMethod::weights(const FrameContext& ctx, int i, int j) const {
  inputs_.check(ctx);
  if (inputs_.precision() == Precision::float32) {
    const KernelInputsF& in = inputs_.f();
    return to_weights(kf::float_taa_sample(wave_buffer(in), in.frame, params_f_, i, j).weights);
  }
  const KernelInputsD& in = inputs_.d();
  return to_weights(kd::taa_sample(wave_buffer(in), in.frame, params_, i, j).weights);
}

void TaaMethod::shade_tile(const FrameContext& ctx, int x0, int y0, int x1, int y1,
                           Image& out) const {
  inputs_.check(ctx);
  const int w = ctx.model.width();
  const bool single = inputs_.precision() == Precision::float32;
  for (int j = y0; j < y1; ++j) {
    for (int i = x0; i < x1; ++i) {
      vec2& motion = motion_[static_cast<size_t>(j) * w + i];
      if (single) {
        const KernelInputsF& in = inputs_.f();
        const kf::TaaSample s = kf::float_taa_sample(wave_buffer(in), in.frame, params_f_, i, j);
        motion = vec2(s.motion);
        store_pixel(ctx, out, i, j, to_weights(s.weights));
      } else {
        const KernelInputsD& in = inputs_.d();
        const kd::TaaSample s = kd::taa_sample(wave_buffer(in), in.frame, params_, i, j);
        motion = s.motion;
        store_pixel(ctx, out, i, j, to_weights(s.weights));
      }
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
  const kd::ImagePlanes now{current.data.data(), current.width, current.channels};
  const kd::ImagePlanes before{history_.data.data(), history_.width, history_.channels};
  const kd::TaaResolveParams p = taa_resolve_params(options_, img.width, img.height, img.channels);
  const kf::TaaResolveParams pf = taa_resolve_params_float(p);
  const bool single = inputs_.precision() == Precision::float32;
  tbb::parallel_for(tbb::blocked_range<int>(0, img.height), [&](const tbb::blocked_range<int>& r) {
    for (int j = r.begin(); j < r.end(); ++j) {
      for (int i = 0; i < img.width; ++i) {
        const vec2 motion = motion_[static_cast<size_t>(j) * img.width + i];
        kd::vec4 value;
        bool fallback;
        if (single) {
          const kf::TaaResolved o =
              kf::float_taa_resolve_pixel(now, before, pf, true, kf::vec2(motion), i, j);
          value = kd::vec4(o.value);
          fallback = o.fallback;
        } else {
          const kd::TaaResolved o = kd::taa_resolve_pixel(now, before, p, true, motion, i, j);
          value = o.value;
          fallback = o.fallback;
        }
        if (fallback) count_fallback();
        for (int c = 0; c < img.channels; ++c)
          img.at(i, j, c) = static_cast<float>(value[c]);
      }
    }
  });
  history_ = img;
}

}  // namespace sg
