#include "scene/camera.h"

#include <cmath>

#include "kernel/kernel_double.h"

namespace sg {

CameraModel::CameraModel(const CameraDesc& desc, int width, int height)
    : position_(desc.position), width_(width), height_(height) {
  // The basis of the kernel (kernel/camera.glsl), which builds a moving camera's too.
  const kd::mat3 b = kd::camera_basis(desc.position, desc.look_at, normalize(desc.up));
  k_.position = desc.position;
  k_.forward = b[0];
  k_.right = b[1];
  k_.up = b[2];
  k_.half_h = std::tan(radians(desc.vfov_deg) / 2);
  k_.half_w = k_.half_h * width / height;
  k_.width = width;
  k_.height = height;
}

bool CameraModel::project(const vec3& dir, double& px, double& py) const {
  double f = dot(dir, k_.forward);
  if (f <= 0) return false;
  double x = dot(dir, k_.right) / f / k_.half_w;  // -1..1 across the image
  double y = dot(dir, k_.up) / f / k_.half_h;
  px = (x + 1.0) * 0.5 * width_;
  py = (1.0 - y) * 0.5 * height_;
  return true;
}

}  // namespace sg
