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
