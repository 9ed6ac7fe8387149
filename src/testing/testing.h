// Helpers shared by the unit tests: the project's scenes, and small scenes built in code.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <string>

#include "scene/scene.h"
#include "testing/paths.h"

namespace sg::testing {

// A scene shipped with the project (scenes/NAME.json).
inline Scene project_scene(const std::string& name) {
  return load_scene(source_dir() + "/scenes/" + name + ".json");
}

// The camera and light of the project's scenes, with the given waves, at a small size.
inline Scene small_scene(std::vector<Wave> waves, int width = 64, int height = 36) {
  Scene s;
  s.name = "test";
  s.width = width;
  s.height = height;
  s.camera = CameraDesc{{0, 2.5, 0}, {0, 0, -60}, {0, 1, 0}, 40, {}};
  s.light = LightDesc{{0, 0.207912, -0.978148}, 0.27, Rgb(1.0), false};
  s.sky = SkyDesc::constant(Rgb(0));
  s.surface.waves = std::move(waves);
  s.animation = AnimationDesc{0, 30, 60, 1.0};
  return s;
}

// A displaced, Schlick, sky-and-sea variant of a scene: the spec's other options at once,
// with a bright light (radiance 20) so the sun term stands out of sky and sea.
inline Scene displaced_variant(Scene s, double sea_radiance = 0.05) {
  s.surface.geometry = Geometry::displaced;
  s.surface.fresnel = FresnelMode::schlick;
  s.sky = SkyDesc::constant(Rgb(0.3));
  s.surface.sea_radiance = Rgb(sea_radiance);
  s.light.radiance = Rgb(20);
  return s;
}

}  // namespace sg::testing
