#include "scene/camera_path.h"

#include <algorithm>
#include <cmath>

#include "kernel/kernel_double.h"

namespace sg {

CameraPoseAt camera_pose(const CameraDesc& c, double t) {
  const std::vector<CameraKey>& k = c.keyframes;
  if (k.size() < 2) return {c.position, c.look_at};
  // The segment [k[i], k[i + 1]] around t (the first or last one outside the keys).
  const auto after = std::upper_bound(k.begin(), k.end(), t,
                                      [](double v, const CameraKey& key) { return v < key.time; });
  const size_t i = std::clamp<size_t>(static_cast<size_t>(after - k.begin()), 1, k.size() - 1) - 1;
  const kd::CameraPose p =
      kd::camera_pose_between(k[i].time, k[i].position, k[i].look_at, k[i + 1].time,
                              k[i + 1].position, k[i + 1].look_at, t);
  return {p.position, p.look_at};
}

CameraDesc camera_at(const CameraDesc& c, double t) {
  CameraDesc out = c;
  const CameraPoseAt p = camera_pose(c, t);
  out.position = p.position;
  out.look_at = p.look_at;
  return out;
}

SceneModel frame_model(const Scene& s, const FrameTime& ft) {
  Scene at = s;
  at.camera = camera_at(s.camera, ft.end);
  return SceneModel(at);
}

std::vector<CameraSegmentMotion> camera_motion(const CameraDesc& c) {
  std::vector<CameraSegmentMotion> out;
  const vec3 up = normalize(c.up);
  for (size_t i = 0; i + 1 < c.keyframes.size(); ++i) {
    const CameraKey &a = c.keyframes[i], &b = c.keyframes[i + 1];
    CameraSegmentMotion m;
    m.t0 = a.time;
    m.t1 = b.time;
    const double dt = b.time - a.time;
    m.speed = length(b.position - a.position) / dt;
    const kd::mat3 r0 = kd::camera_basis(a.position, a.look_at, up);
    const kd::mat3 r1 = kd::camera_basis(b.position, b.look_at, up);
    // The rotation r1 r0^T: its angle from its trace.
    const double tr = dot(r0[0], r1[0]) + dot(r0[1], r1[1]) + dot(r0[2], r1[2]);
    m.turn_rate_deg = degrees(std::acos(std::clamp((tr - 1) / 2, -1.0, 1.0))) / dt;
    out.push_back(m);
  }
  return out;
}

}  // namespace sg
