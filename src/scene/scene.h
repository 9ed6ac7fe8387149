// A scene as the file format defines it (docs/scene-format.md, `sunglint-scene/1`, `/2`
// and `/3`): the water waves, the camera, the light, sky and sea radiances, and the
// animation's timing. Values are stored as given (directions not yet normalised); the
// models built from a scene (waves.h, camera.h, light.h) derive what rendering needs.
//
// Radiances are linear RGB triples (Rec. 709 primaries). Format /1 has grey radiances
// only (three equal channels) and a constant sky; format /2 adds colour and a sky
// gradient; format /3 a moving camera (keyframes of position and look-at) and lattice
// cascades (scene/lattice.h). Every method computes a
// pixel as weights of the four radiances (light, zenith, horizon, sea; shading/radiance.h), so
// colour costs nothing in the methods.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "math/vec.h"
#include "scene/lattice.h"

namespace sg {

struct Wave {
  double amplitude = 0;          // A_i, metres
  vec2 wave_vector{0, 0};        // (a_i, b_i), rad/m
  double angular_frequency = 0;  // c_i, rad/s
  double phase = 0;              // phi_i, rad
};

enum class Geometry { flat, displaced };
enum class FresnelMode { none, schlick };

// A key of a moving camera (format /3): its position and look-at point at `time` (s, on
// the scene's clock).
struct CameraKey {
  double time = 0;
  vec3 position{0, 3, 0};
  vec3 look_at{0, 0, -100};
};

// A fixed camera (position, look_at), or a moving one: `keyframes` (at least two, times
// strictly increasing; format /3), between which position and look-at are interpolated
// linearly (scene/camera_path.h). A moving camera's position and look_at hold its pose at
// one time: the first key's as loaded, the shutter end's in a frame's model (model.h).
struct CameraDesc {
  vec3 position{0, 3, 0};
  vec3 look_at{0, 0, -100};
  vec3 up{0, 1, 0};
  double vfov_deg = 40;
  std::vector<CameraKey> keyframes;
  bool moving() const { return !keyframes.empty(); }
};

// A linear RGB radiance; a grey one has three equal channels.
using Rgb = vec3;

struct LightDesc {
  vec3 direction{0, 0.17, -1};  // towards the light, any length > 0
  double angular_radius_deg = 0.27;
  Rgb radiance{1.0};
  bool visible = false;
};

// The sky's radiance in unit direction d: horizon + (zenith - horizon) max(d.y, 0)^exponent.
// A constant sky (format /1's `sky.radiance`) has zenith == horizon.
struct SkyDesc {
  Rgb zenith{0.0}, horizon{0.0};
  double exponent = 0.5;
  bool gradient = false;  // written as zenith/horizon (format /2), else as `radiance`
  static SkyDesc constant(const Rgb& radiance) { return SkyDesc{radiance, radiance, 0.5, false}; }
};

struct SurfaceDesc {
  Geometry geometry = Geometry::flat;
  FresnelMode fresnel = FresnelMode::none;
  Rgb sea_radiance{0.0};
  std::vector<Wave> waves;
  // Format /3: lattice cascades (scene/lattice.h) and the water depth their waves'
  // frequencies follow (infinite: deep water; the explicit waves give theirs).
  double depth = std::numeric_limits<double>::infinity();
  std::vector<CascadeDesc> cascades;
};

struct AnimationDesc {
  double t0 = 0;
  double fps = 30;
  int frames = 60;
  double shutter = 1.0;
};

struct Scene {
  std::string name;
  // The folder the scene was read from: where its cascades' relative sidecar files are
  // (empty: the working directory). Not part of the scene's JSON.
  std::string source_dir;
  int width = 640;
  int height = 360;
  CameraDesc camera;
  LightDesc light;
  SkyDesc sky;
  SurfaceDesc surface;
  AnimationDesc animation;

  // True when every radiance has three equal channels (a grey image renders the scene).
  bool grey() const;
  // The format the scene needs: 3 with camera keyframes, cascades or a depth, else 2 with colour or
  // a gradient sky, else 1 (scene_to_json).
  int format_version() const;

  // Frame f is displayed at t_f = t0 + f / fps and integrates [t_f - shutter/fps, t_f].
  double frame_time(int frame) const { return animation.t0 + frame / animation.fps; }
  double shutter_start(int frame) const {
    return frame_time(frame) - animation.shutter / animation.fps;
  }
};

// Loading and checking. Every error names the key path and the rule, for example
// "surface.waves[3].amplitude: must be >= 0"; file errors are prefixed by the file name.
Scene load_scene(const std::string& path);
// Cascade files named by a relative path are read from `source_dir` (scene/lattice.h).
Scene parse_scene(const std::string& json_text, const std::string& name_for_errors,
                  const std::string& source_dir = "");

// The scene as canonical JSON (every key written, defaults included): what `info`
// prints and what cache keys hash.
std::string scene_to_json(const Scene& scene);

// Writes `scene` to `path` whole (temp file and rename), each cascade's lattice beside it
// as `<stem>.cascade<c>.npy` (scene/lattice.h, write_lattice) and named so in the file:
// what `sunglint ocean --cascades` writes, and a scene whose cascades were generated in
// memory or loaded from another folder saved so that it renders as it is.
void write_scene(const std::string& path, const Scene& scene);

// Command-line overrides, checked by the same rules as the file ("--width: must be >= 1").
void set_image_size(Scene& scene, int width, int height);

}  // namespace sg
