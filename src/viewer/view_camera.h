// The viewer's camera moves: orbit about a point on the water, fly (move along the view,
// look around), dolly towards the orbit's point; the scene's camera is home. Every move
// maps a CameraDesc to a CameraDesc, so the moved camera is an ordinary scene camera: the
// view renders it on both sides of the split, and "save scene" writes it.
//
// A move is a rigid motion (or, the dolly, a scaling about the target) of both the
// position and the look_at point, so the view direction turns exactly as the motion does
// and a view never jumps when a drag starts. `up` is left as it is. A move that would leave
// the scene's ranges (the camera under 1 cm above the water at rest, the view within 5
// degrees of straight up or down, where `up` stops defining the image's roll) is refused:
// the camera stays where it was.
#pragma once

#include "math/vec.h"
#include "scene/scene.h"

namespace sg::viewer {

// The point an orbit turns about and a dolly moves towards: where the camera's view ray
// (position towards look_at) meets the water at rest, y = 0, within 10 km; otherwise, a
// ray at or above the horizon, the point on the ray at the look_at's distance (clamped to
// [1 m, 1 km]).
vec3 orbit_target(const CameraDesc& c);

// The camera turned about `target`: by `yaw` (radians) about the vertical through it, then
// by `pitch` (radians, positive raises the camera) about the horizontal axis through it
// that is perpendicular to the view. Keeps the distance of position and look_at to target.
CameraDesc orbit(const CameraDesc& c, const vec3& target, double yaw, double pitch);

// The view turned about the camera's position: `yaw` (radians, positive turns left) about
// the vertical, then `pitch` (radians, positive looks up) about the camera's right axis.
CameraDesc look(const CameraDesc& c, double yaw, double pitch);

// The camera moved by `right` metres along its horizontal right axis, `up` metres
// vertically and `forward` metres along its view direction; position and look_at move
// alike, so the view direction stays.
CameraDesc fly(const CameraDesc& c, double right, double up, double forward);

// position and look_at scaled about `target` by `factor` (< 1 moves closer): the view
// direction stays. Refused (c returned) when the camera would come within 1 cm of target.
CameraDesc dolly(const CameraDesc& c, const vec3& target, double factor);

}  // namespace sg::viewer
