// Everything a method needs to render one scene at one image size, derived once from the
// Scene: the wave field, the camera, the light, and the sky, sea and Fresnel settings.
// Built by value; immutable and shared by all threads while rendering.
#pragma once

#include "scene/camera.h"
#include "scene/light.h"
#include "scene/scene.h"
#include "scene/waves.h"

namespace sg {

struct SceneModel {
  Scene scene;
  WaveField waves;
  CameraModel camera;
  LightModel light;

  explicit SceneModel(const Scene& s)
      : scene(s), waves(s.surface.waves), camera(s.camera, s.width, s.height), light(s.light) {}

  int width() const { return scene.width; }
  int height() const { return scene.height; }
  bool displaced() const { return scene.surface.geometry == Geometry::displaced; }
};

// The time interval a frame integrates, [start, end] (end = the display time t_f).
struct FrameTime {
  int frame = 0;
  double start = 0, end = 0;
  double duration() const { return end - start; }
};

inline FrameTime frame_time(const Scene& s, int frame) {
  return FrameTime{frame, s.shutter_start(frame), s.frame_time(frame)};
}

}  // namespace sg
