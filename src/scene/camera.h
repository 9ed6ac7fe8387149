// The pinhole camera of the scene spec and its ray differentials.
//
// Pixel (i, j), i to the right and j downwards, covers the square [i, i+1] x [j, j+1] of
// the image plane; a point (px, py) of that plane (in pixel units) maps to the ray
//     d(px, py) = w + (2 px / W - 1) tan(hfov/2) u + (1 - 2 py / H) tan(vfov/2) v
// from the camera position, with w the viewing direction, u (right) = normalize(w x up),
// v = u x w, and tan(hfov/2) = tan(vfov/2) W / H (square pixels). d is not normalised:
// it is linear in (px, py), so its derivatives are constant (Igehy 1999, "Tracing ray
// differentials": the ray differentials of a pinhole camera).
#pragma once

#include "kernel/kernel_double.h"
#include "math/vec.h"
#include "scene/scene.h"

namespace sg {

class CameraModel {
 public:
  CameraModel() = default;
  CameraModel(const CameraDesc& desc, int width, int height);

  const vec3& position() const { return position_; }
  int width() const { return width_; }
  int height() const { return height_; }

  // The (unnormalised) direction through image-plane point (px, py), pixel units, and
  // d direction / d px and d direction / d py: the kernel's (kernel/camera.glsl).
  vec3 direction(double px, double py) const { return kd::camera_direction(k_, px, py); }
  vec3 ddir_dpx() const { return kd::camera_ddir_dpx(k_); }
  vec3 ddir_dpy() const { return kd::camera_ddir_dpy(k_); }

  // The image-plane point (px, py) that direction `dir` passes through; false when the
  // direction points away from the image plane.
  bool project(const vec3& dir, double& px, double& py) const;

  // tan(hfov / 2) and tan(vfov / 2).
  double half_w() const { return k_.half_w; }
  double half_h() const { return k_.half_h; }
  const vec3& forward() const { return k_.forward; }
  const vec3& right() const { return k_.right; }
  const vec3& up() const { return k_.up; }

 private:
  vec3 position_{0};
  int width_ = 1, height_ = 1;
  // The kernel's camera (kernel/interface.glsl): the basis, the half-extents and the size;
  // its position is not used here (the kernel's is camera-relative).
  kd::Camera k_{vec3(0), vec3(0, 0, -1), vec3(1, 0, 0), vec3(0, 1, 0), 1, 1, 1, 1};
};

// Transfer of a ray differential onto a surface (Igehy 1999, Eq. 10 for a plane): the
// kernel's (kernel/camera.glsl, transfer_differential).
inline vec3 transfer_differential(const vec3& d, double s, const vec3& dd, const vec3& m) {
  return kd::transfer_differential(d, s, dd, m);
}

}  // namespace sg
