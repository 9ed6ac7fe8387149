#include "viewer/view_camera.h"

#include <algorithm>
#include <cmath>

#include "scene/scene_limits.h"

namespace sg::viewer {
namespace {

constexpr double kMinHeight = 0.01;          // metres above the water at rest
constexpr double kMaxTargetDistance = 1e4;   // metres: farther hits are "the horizon"
constexpr double kMaxSinElevation = 0.9962;  // sin(85 degrees): the view's steepest
const vec3 kUp{0, 1, 0};

vec3 forward(const CameraDesc& c) {
  return glm::normalize(c.look_at - c.position);
}

// The horizontal unit vector to the right of the view (its direction is vertical: +x).
vec3 right_of(const vec3& fwd) {
  const vec3 r = glm::cross(fwd, kUp);
  const double n = glm::length(r);
  return n > 1e-12 ? r / n : vec3(1, 0, 0);
}

// v rotated by `angle` about the unit axis k (Rodrigues' rotation formula).
vec3 rotate(const vec3& v, const vec3& k, double angle) {
  const double cs = std::cos(angle), sn = std::sin(angle);
  return v * cs + glm::cross(k, v) * sn + k * (glm::dot(k, v) * (1 - cs));
}

// c when `moved` leaves the ranges the viewer keeps (see the header), else `moved`.
CameraDesc checked(const CameraDesc& c, const CameraDesc& moved) {
  const vec3 d = moved.look_at - moved.position;
  const double n = glm::length(d);
  const bool ok = moved.position.y >= kMinHeight && n > 1e-6 &&
                  std::abs(d.y / n) <= kMaxSinElevation &&
                  glm::length(moved.position) <= limits::kMaxCameraDistance &&
                  glm::length(moved.look_at) <= limits::kMaxLookAtDistance;
  return ok ? moved : c;
}

}  // namespace

vec3 orbit_target(const CameraDesc& c) {
  const vec3 fwd = forward(c);
  if (fwd.y < 0) {
    const double t = -c.position.y / fwd.y;
    if (t <= kMaxTargetDistance) return c.position + t * fwd;
  }
  const double d = std::clamp(glm::length(c.look_at - c.position), 1.0, 1000.0);
  return c.position + d * fwd;
}

CameraDesc orbit(const CameraDesc& c, const vec3& target, double yaw, double pitch) {
  // Pitch about right: +angle turns the offset -fwd towards -up, so the camera rises by
  // -pitch.
  const vec3 axis = right_of(forward(c));
  auto turn = [&](const vec3& p) {
    return target + rotate(rotate(p - target, axis, -pitch), kUp, yaw);
  };
  CameraDesc m = c;
  m.position = turn(c.position);
  m.look_at = turn(c.look_at);
  return checked(c, m);
}

CameraDesc look(const CameraDesc& c, double yaw, double pitch) {
  const vec3 axis = right_of(forward(c));
  CameraDesc m = c;
  m.look_at = c.position + rotate(rotate(c.look_at - c.position, axis, pitch), kUp, yaw);
  return checked(c, m);
}

CameraDesc fly(const CameraDesc& c, double right, double up, double forward_m) {
  const vec3 fwd = forward(c);
  const vec3 move = right * right_of(fwd) + up * kUp + forward_m * fwd;
  CameraDesc m = c;
  m.position = c.position + move;
  m.look_at = c.look_at + move;
  return checked(c, m);
}

CameraDesc dolly(const CameraDesc& c, const vec3& target, double factor) {
  if (!(factor > 0) || glm::length(c.position - target) * factor < 0.01) return c;
  CameraDesc m = c;
  m.position = target + factor * (c.position - target);
  m.look_at = target + factor * (c.look_at - target);
  return checked(c, m);
}

}  // namespace sg::viewer
