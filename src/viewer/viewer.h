// `sunglint view`: the interactive viewer. A GLFW window (viewer/window.h) the size of the
// scene's image, the GL engine (gl_engine/) rendering the animation every frame, the
// display pipeline of `render --display` (viewer/view_image.h), and Dear ImGui controls:
// play, pause, step and scrub, playback speed, the method and a few of its options, a
// split view of two methods with a movable divider, a zoom lens under the cursor, the
// light's elevation, azimuth and radius, a wave-amplitude scale, the exposure and glare,
// saving the view as a scene file, EXR or PNG, the GPU time of each frame (timer
// queries), a fly/orbit camera with the scene's camera as home (viewer/view_camera.h), and,
// while paused, a progressive reference of the still frame (viewer/view_reference.h).
// docs/viewer.md lists the keys.
//
// A scripted run (`frames` > 0) needs no input: it renders frames 0 .. frames-1 of the
// animation in the window (without the controls unless `show_controls`), the camera orbiting
// at `orbit_rate_deg` if given, then writes the last frame's displayed image (`screenshot`, a
// PNG read back from the window) and the view's scene file (`save_scene`), prints the mean GPU
// time per frame and returns.
//
// A camera in motion (viewer/camera_record.h): a frame whose camera moved since the frame
// before is rendered with the camera keyed over its shutter (previous camera at the opening,
// current at the end), so the methods see the motion; `record` writes the path the camera
// took as a `/3` scene when the view ends. Its clock: a scripted run's frame times; an
// interactive view's clock starts at the animation's t0 and runs while the animation plays
// (at the playback speed, unwrapped past the last frame) or steps forward; it stands while
// paused or scrubbed, and moves made then replace the pose at that time.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "methods/options.h"
#include "scene/scene.h"
#include "viewer/view_edits.h"

namespace sg::viewer {

struct ViewerOptions {
  Scene scene;  // as loaded, with the command line's image size applied
  std::string method = "staa";
  MethodOptions options;
  std::string split;               // the second method of a split view; empty: none
  std::optional<ViewEdits> edits;  // none: the scene as loaded
  double exposure = 0;
  bool glare = true;
  int frames = 0;              // > 0: a scripted run of frames 0 .. frames-1
  std::string screenshot;      // scripted: the last frame's displayed image (.png)
  std::string save_scene;      // scripted: the view's scene (.json)
  std::string record;          // the camera's path as a /3 scene (.json), written at the end
  double orbit_rate_deg = 0;   // scripted: degrees per second of scene time about the vertical
  bool show_controls = false;  // scripted: the controls drawn too (pictures of the viewer)
  // Scripted: > 0 shows the still-frame reference (viewer/view_reference.h) of the last
  // frame after this many batches instead of the method; with reference_difference > 0,
  // its absolute difference to the method, times that scale.
  int reference_batches = 0;
  double reference_difference = 0;
  // Where the display pipeline runs: "gpu" (viewer/gpu_display.h), "cpu"
  // (image/tonemap.h), "auto": the GPU unless the renderer is Mesa's llvmpipe or softpipe
  // (a CPU, where the CPU path is faster).
  std::string display_on = "auto";
};

// The GL engine's methods, in the catalogue's order.
const std::vector<std::string>& gl_method_names();

// Opens the window and runs until it is closed (or, scripted, until the last frame).
// Throws gl::Unavailable without a display or OpenGL 4.5, sg::Error on a bad method,
// option or edit; writes no file then.
void run_viewer(const ViewerOptions& options);

}  // namespace sg::viewer
