#include "viewer/camera_record.h"

#include <cmath>

#include "base/atomic_file.h"
#include "base/error.h"
#include "scene/camera_path.h"

namespace sg::viewer {

Scene moving_view_scene(const Scene& scene, const CameraDesc& previous, const FrameTime& ft) {
  const CameraDesc& now = scene.camera;
  if (now.moving() || !(ft.duration() > 0)) return scene;
  const CameraPoseAt before = camera_pose(previous, ft.start);
  if (before.position == now.position && before.look_at == now.look_at) return scene;
  Scene s = scene;
  s.camera.keyframes = {{ft.start, before.position, before.look_at},
                        {ft.end, now.position, now.look_at}};
  try {
    return parse_scene(scene_to_json(s), "the view's motion", s.source_dir);
  } catch (const Error&) {
    return scene;
  }
}

void CameraRecorder::add(double t, const CameraDesc& camera) {
  const CameraPoseAt p = camera_pose(camera, t);
  if (!keys_.empty() && !(t > keys_.back().time)) {
    keys_.back().position = p.position;
    keys_.back().look_at = p.look_at;
    return;
  }
  if (keys_.size() >= 2 && t - keys_[keys_.size() - 2].time < min_gap_) {
    keys_.back() = CameraKey{t, p.position, p.look_at};
    return;
  }
  keys_.push_back(CameraKey{t, p.position, p.look_at});
}

Scene CameraRecorder::scene(const Scene& base) const {
  if (keys_.empty()) throw Error("--record: no frame was rendered, so no camera was recorded");
  Scene s = base;
  s.camera.keyframes.clear();
  s.camera.position = keys_.front().position;
  s.camera.look_at = keys_.front().look_at;
  if (keys_.size() >= 2) s.camera.keyframes = keys_;
  AnimationDesc& a = s.animation;
  a.t0 = keys_.front().time;
  const double span = keys_.back().time - keys_.front().time;
  a.frames = 1 + static_cast<int>(std::floor(span * a.fps + 1e-9));
  return parse_scene(scene_to_json(s), "the recorded path", s.source_dir);
}

void write_recording(const std::string& path, const Scene& scene) {
  write_scene(path, scene);
}

}  // namespace sg::viewer
