// The viewer's camera in motion, as scene files can say it (format /3, docs/scene-format.md):
//  - A frame of the view whose camera moved since the previous frame (fly, orbit, look,
//    dolly) is rendered with the camera keyed over its shutter, from the previous frame's
//    camera at the shutter's opening to the current one at its end, so that the methods
//    that sample time see the motion (motion blur) exactly as a `/3` scene shows them.
//  - `view --record PATH.json` writes the path the view's camera took: the scene as
//    loaded (with the view's edits) and the camera's pose at each rendered frame as
//    keyframes, on the recording's clock (viewer/viewer.h says which), with an animation
//    that covers the keys; `render` and `compare` read it as any `/3` scene.
#pragma once

#include <string>
#include <vector>

#include "scene/model.h"
#include "scene/scene.h"

namespace sg::viewer {

// The scene a frame of the view renders. `scene` itself when its camera is keyed (its own
// keys move it), when the shutter is empty, or when `previous` (the camera of the frame
// rendered before) has the same position and look_at; otherwise `scene` with keyframes
// (ft.start, previous's pose) and (ft.end, scene's camera). A motion the scene's rules
// refuse between the two poses (the view passing within the loader's limits of `up`)
// gives `scene` unchanged: that frame is still.
Scene moving_view_scene(const Scene& scene, const CameraDesc& previous, const FrameTime& ft);

// The keys of a flown path. Keys are at least `min_gap` seconds apart (the last one
// excepted), so a frame's shutter holds few of them however fast the view renders.
class CameraRecorder {
 public:
  explicit CameraRecorder(double min_gap) : min_gap_(min_gap) {}

  // The camera's pose at time t (a keyed camera's pose at t). A time at or before the last
  // key's (the clock stood: moves while paused) replaces the last key's pose; a time
  // within min_gap of the key before the last replaces the last key.
  void add(double t, const CameraDesc& camera);

  const std::vector<CameraKey>& keys() const { return keys_; }

  // `base` with the recorded camera: keyframes (format /3) when there are two keys or
  // more, else the one pose as a fixed camera; the animation starts at the first key
  // (t0) and has the frames, at base's fps and shutter, up to the last key. Checked by the
  // scene loader's rules (sg::Error naming the key otherwise). Throws sg::Error when no
  // key was recorded.
  Scene scene(const Scene& base) const;

 private:
  double min_gap_;
  std::vector<CameraKey> keys_;
};

// `scene` written as a scene file at `path`, whole (a temporary file and a rename).
void write_recording(const std::string& path, const Scene& scene);

}  // namespace sg::viewer
