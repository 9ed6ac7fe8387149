#include "shading/water_geometry.h"

#include <vector>

#include "base/error.h"
#include "kernel/cpu/wave_sums.h"
#include "kernel/kernel_double.h"
#include "shading/kernel_frame.h"

namespace sg {

struct WaterGeometry::Inputs {
  KernelInputsD in;
};

WaterGeometry::WaterGeometry() = default;
WaterGeometry::~WaterGeometry() = default;
WaterGeometry::WaterGeometry(WaterGeometry&&) noexcept = default;
WaterGeometry& WaterGeometry::operator=(WaterGeometry&&) noexcept = default;

WaterGeometry::WaterGeometry(const SceneModel& m, const FrameTime& ft)
    : model_(&m), model_id_(m.id), time_(ft), in_(std::make_unique<Inputs>()) {
  // One segment (no rotations are read: every time is a dt), seed 0 (no sampling), every
  // wave in the intersection, the cascades as their sines.
  build_kernel_inputs(m, ft, 1, 0, in_->in, 0.0, 1, false);
}

bool WaterGeometry::is_for(const SceneModel& m, const FrameTime& ft) const {
  return in_ && model_ == &m && model_id_ == m.id && time_.frame == ft.frame &&
         time_.start == ft.start && time_.end == ft.end;
}

namespace {

// `origin`: the world point at the camera-relative coordinates' origin.
RayHit to_world(const vec3& origin, const kd::RayHit& h) {
  RayHit r;
  r.hit = h.hit;
  r.s = h.s;
  r.point = h.hit ? vec3(h.point) + origin : vec3(0);
  return r;
}

PixelFootprint to_world(const vec3& origin, const kd::Footprint& k) {
  PixelFootprint f;
  if (!k.hit) return f;
  f.hit = true;
  f.point = vec3(k.point) + origin;
  f.view = k.view;
  f.dp_dpx = k.dp_dpx;
  f.dp_dpy = k.dp_dpy;
  f.distance = k.distance;
  f.at_camera = !(k.distance > 0);
  return f;
}

}  // namespace

RayHit WaterGeometry::intersect(const vec3& origin, const vec3& dir, double t) const {
  return model_->displaced() ? intersect_displaced(origin, dir, t) : intersect_flat(origin, dir);
}

RayHit WaterGeometry::intersect_displaced(const vec3& origin, const vec3& dir, double t) const {
  const double len = length(dir);
  const kd::WaveBuffer wb = wave_buffer(in_->in);
  kd::RayHit h =
      kd::intersect_displaced(wb, in_->in.frame, origin - in_->in.origin, dir / len, t - time_.end);
  h.s /= len;
  return to_world(in_->in.origin, h);
}

double WaterGeometry::height(double x, double z, double t) const {
  const vec3 p = vec3(x, 0, z) - in_->in.origin;
  return kd::water_height(wave_buffer(in_->in), in_->in.frame, p.x, p.z, t - time_.end);
}

vec2 WaterGeometry::gradient(double x, double z, double t) const {
  const vec3 p = vec3(x, 0, z) - in_->in.origin;
  return kd::water_gradient(wave_buffer(in_->in), in_->in.frame, p.x, p.z, t - time_.end);
}

Hessian WaterGeometry::hessian(double x, double z, double t) const {
  const vec3 p = vec3(x, 0, z) - in_->in.origin;
  const kd::vec3 h =
      kd::water_hessian(wave_buffer(in_->in), in_->in.frame, p.x, p.z, t - time_.end);
  return Hessian{h.x, h.y, h.z};
}

PixelFootprint WaterGeometry::footprint(double px, double py, double t) const {
  return to_world(in_->in.origin, kd::pixel_footprint(wave_buffer(in_->in), in_->in.frame, px, py,
                                                      t - time_.end, model_->displaced()));
}

PixelFootprint rest_plane_footprint(const SceneModel& m, double px, double py) {
  kd::Frame f{};
  f.camera = m.camera.kernel_camera();
  const kd::WaveBuffer none{nullptr, 0, {}};
  const vec3 origin(m.camera.position().x, 0.0, m.camera.position().z);
  return to_world(origin, kd::pixel_footprint(none, f, px, py, 0.0, false));
}

PixelFootprint pixel_footprint(const SceneModel& m, double px, double py, double t) {
  return WaterGeometry(m, FrameTime{0, t, t}).footprint(px, py, t);
}

vec3 water_normal(const vec2& g) {
  return normalize(vec3(kd::normal_direction(g)));
}

RayHit intersect_flat(const vec3& origin, const vec3& dir) {
  RayHit r;
  const kd::RayHit h = kd::intersect_flat(origin, dir);
  r.hit = h.hit;
  r.s = h.s;
  r.point = h.point;
  return r;
}

}  // namespace sg
