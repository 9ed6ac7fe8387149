// `sunglint view SCENE [--method M] [--split M2]`: the interactive viewer (viewer/viewer.h)
// on the GL engine; with `--frames N` a scripted run of frames 0 .. N-1 that writes the
// last one's displayed image (`--screenshot OUT.png`) and exits; `--record PATH.json` writes
// the camera's path as a `/3` scene at the end (viewer/camera_record.h). Everything the
// command line asks is checked before the window opens; no file is written when it cannot
// open.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "base/error.h"
#include "base/output_path.h"
#include "cli/args.h"
#include "cli/commands.h"
#include "cli/method_flags.h"
#include "gl_engine/gl_engine.h"
#include "image/image_io.h"
#include "methods/method.h"
#include "scene/scene.h"
#include "viewer/view_camera.h"
#include "viewer/viewer.h"

namespace sg {
namespace {

struct ViewArgs {
  std::string scene_path, method = "staa", split, screenshot, save_scene, record,
                          display_on = "auto";
  int frames = 0, width = 0, height = 0, reference_batches = 0;
  double exposure = 0, reference_difference = 0;
  bool no_glare = false, show_controls = false;
  // Edits of the scene (NaN: as the scene has it).
  double sun_elevation = std::nan(""), sun_azimuth = std::nan(""), sun_radius = std::nan("");
  double amplitude_scale = 1;
  double orbit_yaw = 0, orbit_pitch = 0;  // degrees: the view's camera orbited at the start
  double orbit_rate = 0;                  // degrees per second: a scripted orbit
  MethodFlags flags;
};

// Whether the viewer can show `method` with `o`: the GL engine's options only (it runs
// every method). The GL engine's own message advises --engine cpu, which the viewer lacks:
// this one points to `render` instead.
void check_viewer_runs(const std::string& method, const MethodOptions& o) {
  make_method(method, o);  // an unknown name or a bad option, named as render names it
  if (method == "staa" && o.staa.footprint == FootprintMode::exact) {
    throw Error(
        "--footprint exact: not in the viewer (the GL engine lacks it: the swept parallelogram "
        "is integrated on the host); use --footprint gaussian or none, or render it on the CPU "
        "with: sunglint render SCENE -m staa --footprint exact -o FILE");
  }
  gl_engine::gl_variant(method, o);
}

void run_view(ViewArgs& a) {
  check_usage([&] {
    a.flags.finish();
    if (a.flags.engine != Engine::gl) {
      throw Error("--engine " + a.flags.engine_name + ": the viewer runs on the GL engine only");
    }
    check_viewer_runs(a.method, a.flags.options);
    if (!a.split.empty()) check_viewer_runs(a.split, a.flags.options);
    std::vector<std::string> shown = {a.method};
    if (!a.split.empty()) shown.push_back(a.split);
    if (a.reference_batches > 0) shown.push_back("reference");
    a.flags.check_taken_by(shown);
    if (a.frames == 0 &&
        (!a.screenshot.empty() || !a.save_scene.empty() || a.show_controls ||
         a.reference_batches > 0 || a.reference_difference > 0 || a.orbit_rate != 0)) {
      throw Error(
          "--screenshot, --save-scene, --show-controls, --reference-batches, "
          "--reference-difference, --orbit-rate: need --frames N (a scripted run)");
    }
    if (!a.record.empty() && !a.record.ends_with(".json"))
      throw Error("--record: must be a .json file (got '" + a.record + "')");
    if (a.reference_difference > 0 && a.reference_batches == 0)
      throw Error("--reference-difference: needs --reference-batches N");
    if (a.reference_batches > 0) {
      try {
        gl_engine::gl_variant("reference", a.flags.options);
      } catch (const Error& e) {
        throw Error("--reference-batches: " + std::string(e.what()));
      }
    }
    if (!a.screenshot.empty() && image_format_of(a.screenshot) != ImageFormat::png)
      throw Error("--screenshot: must be a .png file (got '" + a.screenshot + "')");
  });
  Scene scene = load_scene(a.scene_path);
  viewer::ViewerOptions o;
  check_usage([&] {
    apply_image_size(scene, a.width, a.height);
    if (a.frames > 0) check_frame(a.frames - 1, scene, "--frames");
    viewer::ViewEdits e = viewer::edits_of(scene);
    if (!std::isnan(a.sun_elevation)) e.sun_elevation_deg = a.sun_elevation;
    if (!std::isnan(a.sun_azimuth)) e.sun_azimuth_deg = a.sun_azimuth;
    if (!std::isnan(a.sun_radius)) e.sun_radius_deg = a.sun_radius;
    e.amplitude_scale = a.amplitude_scale;
    if (scene.camera.moving() && (a.orbit_yaw != 0 || a.orbit_pitch != 0 || a.orbit_rate != 0)) {
      throw Error(
          "--orbit-yaw, --orbit-pitch, --orbit-rate: the scene's camera is keyed (format /3); "
          "they move a fixed camera");
    }
    if (a.orbit_yaw != 0 || a.orbit_pitch != 0) {
      constexpr double kDeg = 3.14159265358979323846 / 180;
      const CameraDesc c = viewer::orbit(e.camera, viewer::orbit_target(e.camera),
                                         a.orbit_yaw * kDeg, a.orbit_pitch * kDeg);
      if (c.position == e.camera.position) {
        throw Error(
            "--orbit-yaw, --orbit-pitch: the orbit would take the camera under 1 cm above the "
            "water or its view within 5 degrees of the vertical");
      }
      e.camera = c;
    }
    try {
      viewer::edited_scene(scene, e);
    } catch (const Error& err) {
      throw Error("--sun-elevation, --sun-azimuth, --sun-radius, --amplitude-scale: " +
                  std::string(err.what()));
    }
    o.edits = e;
  });
  auto check_file = [](const std::string& p, const char* flag) {
    if (p.empty()) return;
    try {
      check_output_file(p, false);
    } catch (const Error& e) {
      throw Error(std::string(flag) + ": " + e.what());
    }
  };
  check_file(a.screenshot, "--screenshot");
  check_file(a.save_scene, "--save-scene");
  check_file(a.record, "--record");
  o.scene = scene;
  o.method = a.method;
  o.options = a.flags.options;
  o.split = a.split;
  o.exposure = a.exposure;
  o.glare = !a.no_glare;
  o.frames = a.frames;
  o.screenshot = a.screenshot;
  o.save_scene = a.save_scene;
  o.record = a.record;
  o.orbit_rate_deg = a.orbit_rate;
  o.show_controls = a.show_controls;
  o.reference_batches = a.reference_batches;
  o.reference_difference = a.reference_difference;
  o.display_on = a.display_on;
  viewer::run_viewer(o);
}

}  // namespace

void add_view_command(CLI::App& app) {
  auto a = std::make_shared<ViewArgs>();
  CLI::App* c = app.add_subcommand(
      "view", "Watch a scene in a window, rendered on the GPU every frame (docs/viewer.md)");
  c->add_option("scene", a->scene_path, "Scene file (sunglint-scene/1, /2 or /3 JSON)")->required();
  c->add_option("--method,-m", a->method,
                std::string("Method (the GL engine's: ") + gl_engine::gl_methods() + ")")
      ->capture_default_str();
  c->add_option("--split", a->split,
                "A second method: the view split in two at a movable divider, --method on the "
                "left");
  c->add_option("--frames", a->frames,
                "A scripted run: render frames 0 to N-1, write --screenshot and --save-scene, "
                "exit")
      ->check(integer_in(1, 2000000000));
  c->add_option("--screenshot", a->screenshot,
                "Scripted run: the last frame's displayed image (.png; RGB)");
  c->add_option("--save-scene", a->save_scene, "Scripted run: the view's scene file (.json)");
  c->add_flag("--show-controls", a->show_controls,
              "Scripted run: draw the controls (and the split's divider) in the screenshot too");
  c->add_option("--reference-batches", a->reference_batches,
                "Scripted run: show the still-frame reference of the last frame after N batches "
                "(seeds --seed, --seed + 1, ...) instead of the method")
      ->check(integer_in(1, 65536));
  c->add_option("--reference-difference", a->reference_difference,
                "Scripted run: show |reference - method| times this scale instead")
      ->check(number_in(0.001, 1e6));
  c->add_option("--width", a->width,
                "Override the image (and window) width (height follows the aspect ratio unless "
                "given)")
      ->check(integer_in(1, 16384));
  c->add_option("--height", a->height, "Override the image height")->check(integer_in(1, 16384));
  c->add_option("--exposure", a->exposure, "Exposure in stops")
      ->capture_default_str()
      ->check(number_in(-64, 64));
  c->add_flag("--no-glare", a->no_glare, "The display pipeline without glare");
  c->add_option("--display-on", a->display_on,
                "Where the display pipeline runs: gpu, cpu, or auto (the GPU unless the "
                "renderer is Mesa's llvmpipe or softpipe)")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "gpu", "cpu"}));
  c->add_option("--sun-elevation", a->sun_elevation,
                "The light's elevation above the horizon, degrees (default: the scene's)")
      ->check(number_in(-90, 90));
  c->add_option("--sun-azimuth", a->sun_azimuth,
                "The light's azimuth from -z towards +x, degrees (default: the scene's)")
      ->check(number_in(-360, 360));
  c->add_option("--sun-radius", a->sun_radius,
                "The light's angular radius, degrees (default: the scene's)")
      ->check(number_in(0, 89));
  c->add_option("--orbit-yaw", a->orbit_yaw,
                "Start with the camera orbited this many degrees about the vertical through the "
                "point its view meets the water (as a left drag does)")
      ->check(number_in(-3600, 3600));
  c->add_option("--orbit-pitch", a->orbit_pitch,
                "... and raised by this many degrees about that point (negative: lowered)")
      ->check(number_in(-90, 90));
  c->add_option("--orbit-rate", a->orbit_rate,
                "Scripted run: the camera orbits about the vertical through the point its view "
                "meets the water at this many degrees per second of the scene's clock (each "
                "frame's shutter sees the motion)")
      ->check(number_in(-3600, 3600));
  c->add_option("--record", a->record,
                "Write the camera's path (each frame's pose as a keyframe) as a sunglint-scene/3 "
                "file when the view ends (.json; render and compare read it)");
  c->add_option("--amplitude-scale", a->amplitude_scale, "A scale on every wave's amplitude")
      ->capture_default_str()
      ->check(number_in(0, 100));
  a->flags.engine_name = "gl";  // the viewer's only engine
  add_method_flags(*c, a->flags);
  c->callback([a] { run_view(*a); });
}

}  // namespace sg
