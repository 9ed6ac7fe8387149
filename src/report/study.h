// The study behind `sunglint compare`: every method variant on every scene and frame,
// measured against a cached reference, with the near and far halves of the water apart,
// a quality-cost curve of supersampling budgets and the equal-cost comparison, pictures,
// videos and the report (results.json/.csv/.md, index.html). docs/report.md describes
// it for users.
//
// Frames are rendered one after another, each by the engine on all threads
// (engine/render.h), so the time per frame is the wall time of one frame. A stateless
// variant renders only its frames that are not in the cache (report/cache.h). A stateful
// variant (Method::stateful) renders its whole frame range in order through one method
// object (render_frames) whenever one of its frames is missing, because each frame
// depends on the ones before; its cache keys hold the range's first frame.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "image/tonemap.h"
#include "methods/method.h"
#include "report/results.h"
#include "scene/scene.h"

namespace sg {

struct StudyVariant {
  std::string label;  // as given; canonicalised for tables and cache keys
  std::string name;   // catalogue name
  MethodOptions options;
  // Builds the method; empty: make_method(name, options). Tests inject their own.
  std::function<std::unique_ptr<Method>()> make;
};

struct StudyScene {
  std::string file;  // as given (for the record)
  Scene scene;       // at the study's image size
};

struct StudyConfig {
  std::vector<StudyScene> scenes;
  std::vector<StudyVariant> methods;
  StudyVariant reference;
  std::vector<StudyVariant> budgets;  // the supersampling curve, increasing samples
  std::string equal_cost_target;      // a method label; "" = no equal-cost comparison
  std::vector<std::pair<std::string, std::string>> paper_rows;  // Table 1 row -> label overrides
  int first_frame = 0, last_frame = 9;
  std::string out_dir;
  std::string cache_dir;  // "" = out_dir/cache
  int threads = 0;        // 0: all hardware threads
  DisplaySettings display;
  int zoom = 4;          // crops: 1/zoom of the image, enlarged zoom times
  bool pictures = true;  // grid, per-variant pictures and error maps
  bool video = true;     // side-by-side MP4 (needs ffmpeg)
  bool html = true;      // index.html and its assets
  std::string command;   // recorded in results.json
};

// The default target of the equal-cost comparison among `labels`: `staa` when present,
// else the first variant that is not a baseline (reference, supersample, point), else
// the first that is not a supersampling estimator (reference, supersample), else "".
std::string default_equal_cost_target(const std::vector<StudyVariant>& methods);

// Progress of the whole study: fraction in [0, 1] of the estimated work, and what runs.
using StudyProgress = std::function<void(double fraction, const std::string& what)>;

// Runs the study and writes its outputs into config.out_dir. Throws sg::Error on bad
// configuration (naming the option) or failed writes.
StudyResults run_study(const StudyConfig& config, const StudyProgress& progress = {});

// results.json, results.csv, results.md and (with html) index.html and its assets.
void write_study_outputs(const StudyResults& results, const std::string& out_dir, bool html);

}  // namespace sg
