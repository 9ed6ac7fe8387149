// A moving camera (format /3) on the host: the scene's keyframes evaluated at a time, the
// fixed camera a frame's methods see at its shutter's end, and the motion `sunglint info`
// reports. The interpolation is the kernel's (kernel/camera.glsl, camera_pose_between,
// compiled in double): the host only finds the keys around a time, so that the CPU's and
// the GPU's rays and these poses come from one formula.
#pragma once

#include <vector>

#include "scene/model.h"
#include "scene/scene.h"

namespace sg {

// The camera's position and look-at point at time t (s, the scene's clock): a fixed
// camera's own; a moving one's interpolated between the keys around t, held at the first
// and last key outside them.
struct CameraPoseAt {
  vec3 position, look_at;
};
CameraPoseAt camera_pose(const CameraDesc& c, double t);

// The fixed camera at time t: position and look_at at t, the keys kept (a frame's kernel
// inputs take the keys over its shutter from them).
CameraDesc camera_at(const CameraDesc& c, double t);

// The model a frame's methods see: for a moving camera, the scene with the camera at the
// shutter's end (ft.end), where the methods that do not sample time render it; a fixed
// camera's model is the same scene (a new model of it).
SceneModel frame_model(const Scene& s, const FrameTime& ft);

// One segment of a moving camera between two keys: the speed of its position (constant,
// m/s) and its mean turn rate (degrees/s: the angle of the rotation between the camera's
// bases at the two keys over the segment's duration).
struct CameraSegmentMotion {
  double t0 = 0, t1 = 0;
  double speed = 0;
  double turn_rate_deg = 0;
};
std::vector<CameraSegmentMotion> camera_motion(const CameraDesc& c);

}  // namespace sg
