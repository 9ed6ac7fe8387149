// The water's geometry for host code: where a ray meets the water, a pixel's footprint,
// the height and the slope, in world coordinates and absolute times, from the kernel
// (kernel/intersect.glsl, kernel/footprint.glsl, kernel/waves.glsl), so that the report's
// regions and the tests meet the same water as the methods through the same code.
//
// A WaterGeometry holds the kernel's inputs of one frame (shading/kernel_frame.h) in
// double, with every wave in the intersection (tolerance 0: the march of intersect.glsl
// exactly) and the lattice cascades as their sines (the surface of the scene spec); a
// time t other than the frame's display time is the kernel's dt = t - t_f.
//
// The kernel works in camera-relative coordinates (the camera at (0, y, 0)); the
// conversions to the world's are made here, once.
#pragma once

#include <cstdint>
#include <memory>
#include <span>

#include "math/vec.h"
#include "scene/footprint.h"
#include "scene/model.h"

namespace sg {

// Where a ray meets the water.
struct RayHit {
  bool hit = false;
  double s = 0;   // ray parameter: point = origin + s * dir, for the direction given
  vec3 point{0};  // world coordinates
};

class WaterGeometry {
 public:
  WaterGeometry();
  ~WaterGeometry();
  WaterGeometry(WaterGeometry&&) noexcept;
  WaterGeometry& operator=(WaterGeometry&&) noexcept;

  // The geometry of model m at frame time ft (display time ft.end).
  WaterGeometry(const SceneModel& m, const FrameTime& ft);

  // Whether this is the geometry of ctx's model and frame time.
  bool is_for(const SceneModel& m, const FrameTime& ft) const;

  // The first hit of the ray from `origin` along `dir` (any length) at time t: the plane
  // y = 0 on flat water, the height field on displaced water.
  RayHit intersect(const vec3& origin, const vec3& dir, double t) const;
  // The same on displaced water whatever the scene's geometry.
  RayHit intersect_displaced(const vec3& origin, const vec3& dir, double t) const;

  double height(double x, double z, double t) const;
  // (dh/dx, dh/dz)
  vec2 gradient(double x, double z, double t) const;
  // (h_xx, h_xz, h_zz)
  Hessian hessian(double x, double z, double t) const;

  // The footprint of image-plane point (px, py) at time t (scene/footprint.h).
  PixelFootprint footprint(double px, double py, double t) const;

  const SceneModel& model() const { return *model_; }

 private:
  struct Inputs;
  const SceneModel* model_ = nullptr;
  uint64_t model_id_ = 0;
  FrameTime time_{};
  std::unique_ptr<Inputs> in_;
};

// The footprint on the water at rest (the plane y = 0) whatever the geometry: where a
// projected grid (Bruneton et al. 2010, Sec. 3.2) places the pixel before displacing it.
// Needs only the camera (kernel/footprint.glsl on flat water).
PixelFootprint rest_plane_footprint(const SceneModel& m, double px, double py);

// The footprint of (px, py) at time t on m's water, with a geometry built for this one
// call (display time t): for tests and single queries; a loop over pixels builds one
// WaterGeometry and asks it.
PixelFootprint pixel_footprint(const SceneModel& m, double px, double py, double t);

// The unit normal of the scene spec for a height gradient g = (dh/dx, dh/dz):
// normalize(-dh/dx, 1, -dh/dz) (kernel/waves.glsl, normal_direction).
vec3 water_normal(const vec2& g);

// The plane y = 0 (kernel/intersect.glsl); `dir` need not be unit length.
RayHit intersect_flat(const vec3& origin, const vec3& dir);

}  // namespace sg
