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

namespace {

// The kernel's camera (kernel/interface.glsl) with this basis, half-extents and size; its
// position is not read by the functions below.
kd::Camera kernel_rays(const vec3& forward, const vec3& right, const vec3& up, double half_w,
                       double half_h, int width, int height) {
  kd::Camera k;
  k.position = vec3(0);
  k.forward = forward;
  k.right = right;
  k.up = up;
  k.half_w = half_w;
  k.half_h = half_h;
  k.width = width;
  k.height = height;
  return k;
}

}  // namespace

vec3 CameraModel::direction(double px, double py) const {
  return kd::camera_direction(kernel_rays(forward_, right_, up_, half_w_, half_h_, width_, height_),
                              px, py);
}
vec3 CameraModel::ddir_dpx() const {
  return kd::camera_ddir_dpx(kernel_rays(forward_, right_, up_, half_w_, half_h_, width_, height_));
}
vec3 CameraModel::ddir_dpy() const {
  return kd::camera_ddir_dpy(kernel_rays(forward_, right_, up_, half_w_, half_h_, width_, height_));
}

vec3 transfer_differential(const vec3& d, double s, const vec3& dd, const vec3& m) {
  return kd::transfer_differential(d, s, dd, m);
}

bool CameraModel::project(const vec3& dir, double& px, double& py) const {
  double f = dot(dir, forward_);
  if (f <= 0) return false;
  double x = dot(dir, right_) / f / half_w_;  // -1..1 across the image
  double y = dot(dir, up_) / f / half_h_;
  px = (x + 1.0) * 0.5 * width_;
  py = (1.0 - y) * 0.5 * height_;
  return true;
}

}  // namespace sg
