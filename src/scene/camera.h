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

#include "math/vec.h"
#include "scene/scene.h"

namespace sg {

namespace kd {
struct Camera;  // kernel/interface.glsl, in double (kernel/kernel_double.h)
}

class CameraModel {
 public:
  CameraModel() = default;
  CameraModel(const CameraDesc& desc, int width, int height);

  const vec3& position() const { return position_; }
  int width() const { return width_; }
  int height() const { return height_; }

  // The (unnormalised) direction through image-plane point (px, py), pixel units, and
  // d direction / d px and d direction / d py: the kernel's (kernel/camera.glsl).
  vec3 direction(double px, double py) const;
  // The kernel's camera with this basis, half-extents and size, camera-relative (its
  // position (0, y, 0), as in the kernel's frames).
  kd::Camera kernel_camera() const;
  vec3 ddir_dpx() const;
  vec3 ddir_dpy() const;

  // The image-plane point (px, py) that direction `dir` passes through; false when the
  // direction points away from the image plane: the kernel's (camera.glsl, camera_project).
  bool project(const vec3& dir, double& px, double& py) const;

  // tan(hfov / 2) and tan(vfov / 2).
  double half_w() const { return half_w_; }
  double half_h() const { return half_h_; }
  const vec3& forward() const { return forward_; }
  const vec3& right() const { return right_; }
  const vec3& up() const { return up_; }

 private:
  vec3 position_{0}, forward_{0, 0, -1}, right_{1, 0, 0}, up_{0, 1, 0};
  double half_w_ = 1, half_h_ = 1;
  int width_ = 1, height_ = 1;
};

// Transfer of a ray differential onto a surface (Igehy 1999, Eq. 10 for a plane): the
// kernel's (kernel/camera.glsl, transfer_differential).
vec3 transfer_differential(const vec3& d, double s, const vec3& dd, const vec3& m);

}  // namespace sg
