// Everything a method needs to render one scene at one image size, derived once from the
// Scene: the wave field, the camera, the light, and the sky, sea and Fresnel settings.
// Built by value; immutable and shared by all threads while rendering.
#pragma once

#include <atomic>
#include <cstdint>

#include "scene/camera.h"
#include "scene/light.h"
#include "scene/scene.h"
#include "scene/waves.h"

namespace sg {

// The weights of the scene's four radiances in a value (shading/radiance.h): x light,
// y sky zenith, z sky horizon, w sea. Every method computes a pixel as such weights.
using RadianceWeights = vec4;

// The scene's radiances per channel, applied to a pixel's weights once, at the end.
struct Radiances {
  Rgb light{1.0}, zenith{0.0}, horizon{0.0}, sea{0.0};
  Radiances() = default;
  explicit Radiances(const Scene& s)
      : light(s.light.radiance),
        zenith(s.sky.zenith),
        horizon(s.sky.horizon),
        sea(s.surface.sea_radiance) {}
  // The four radiances' channel c (0, 1, 2): (light, zenith, horizon, sea).
  vec4 channel(int c) const { return vec4(light[c], zenith[c], horizon[c], sea[c]); }
  // Channel c (0, 1, 2) of the value with weights w: the kernel's (kernel/radiance.glsl,
  // weights_radiance).
  double apply(const RadianceWeights& w, int c) const;
  Rgb apply(const RadianceWeights& w) const { return Rgb(apply(w, 0), apply(w, 1), apply(w, 2)); }
};

struct SceneModel {
  Scene scene;
  WaveField waves;
  CameraModel camera;
  LightModel light;
  Radiances radiances;
  // Unique per constructed model in this process: what per-frame data built from a model
  // is keyed by (an address can be reused by a later model).
  uint64_t id;

  explicit SceneModel(const Scene& s)
      : scene(s),
        waves(surface_waves(s.surface)),
        camera(s.camera, s.width, s.height),
        light(s.light),
        radiances(s),
        id(next_id()) {}

 private:
  static uint64_t next_id() {
    static std::atomic<uint64_t> counter{0};
    return ++counter;
  }

 public:
  int width() const { return scene.width; }
  int height() const { return scene.height; }
  bool displaced() const { return scene.surface.geometry == Geometry::displaced; }
};

// Channel 0 of weights applied to the scene's radiances: a grey scene's value.
inline double grey_value(const SceneModel& m, const RadianceWeights& w) {
  return m.radiances.apply(w, 0);
}

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
