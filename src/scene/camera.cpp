#include "scene/camera.h"

#include <cmath>

#include "kernel/kernel_double.h"

namespace sg {

CameraModel::CameraModel(const CameraDesc& desc, int width, int height)
    : position_(desc.position), width_(width), height_(height) {
  // The basis of the kernel (kernel/camera.glsl), which builds a moving camera's too.
  const kd::mat3 b = kd::camera_basis(desc.position, desc.look_at, normalize(desc.up));
  forward_ = b[0];
  right_ = b[1];
  up_ = b[2];
  half_h_ = std::tan(radians(desc.vfov_deg) / 2);
  half_w_ = half_h_ * width / height;
}

kd::Camera CameraModel::kernel_camera() const {
  kd::Camera k;
  k.position = vec3(0, position().y, 0);
  k.forward = forward_;
  k.right = right_;
  k.up = up_;
  k.half_w = half_w_;
  k.half_h = half_h_;
  k.width = width_;
  k.height = height_;
  return k;
}

vec3 CameraModel::direction(double px, double py) const {
  return kd::camera_direction(kernel_camera(), px, py);
}
vec3 CameraModel::ddir_dpx() const {
  return kd::camera_ddir_dpx(kernel_camera());
}
vec3 CameraModel::ddir_dpy() const {
  return kd::camera_ddir_dpy(kernel_camera());
}

vec3 transfer_differential(const vec3& d, double s, const vec3& dd, const vec3& m) {
  return kd::transfer_differential(d, s, dd, m);
}

bool CameraModel::project(const vec3& dir, double& px, double& py) const {
  const kd::ImagePoint q = kd::camera_project(kernel_camera(), dir);
  if (!q.seen) return false;
  px = q.p.x;
  py = q.p.y;
  return true;
}

}  // namespace sg
