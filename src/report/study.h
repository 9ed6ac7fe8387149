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

#include "gl_engine/engines.h"
#include "image/tonemap.h"
#include "methods/method.h"
#include "report/results.h"
#include "scene/scene.h"

namespace sg {

struct StudyVariant {
  std::string label;  // as given; canonicalised for tables and cache keys
  std::string name;   // catalogue name
  MethodOptions options;
  Engine engine = Engine::cpu;
  // Builds the method; empty: make_method_on(engine, name, options). Tests inject their own.
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
  // Each method's error split by what the pixel sees (report/pixel_classes.h), per frame,
  // into results.json and results.md.
  bool split = false;
  std::string command;  // recorded in results.json
};

// The default target of the equal-cost comparison among `labels`: `staa` when present,
// else the first variant that is not a baseline (reference, supersample, point), else
// the first that is not a supersampling estimator (reference, supersample), else "".
std::string default_equal_cost_target(const std::vector<StudyVariant>& methods);

// Progress of the whole study: the estimated share of the work done, the time left (from
// the pilot's costs and the measured time of the work done; < 0 while unknown) and what
// runs.
struct StudyStatus {
  double fraction = 0;
  double seconds_left = -1;
  std::string what;
};
using StudyProgress = std::function<void(const StudyStatus&)>;

// One unit of the study's work (report/plan.h): a frame of a stateless variant, a batch of
// a frame of the reference, or the whole range of a stateful variant, rendered by one
// process and stored whole in the frame cache.
struct StudyUnit {
  int scene = 0;            // index into StudyConfig::scenes
  std::string variant;      // canonical label
  int first = 0, last = 0;  // frames (one, except a stateful variant's range)
  int batch = -1;           // the reference's batch, or -1
  std::string id;           // "simple: point, frame 3"
  std::string file;         // its (first) cache file's name: the unit's identity
  double seconds = 0;       // estimated cost, core-seconds (estimate_unit_costs)
};

// Every unit of the study in the order a local run renders them (per scene: the reference's
// batches frame by frame, each method, each budget not already a method); with
// `missing_only`, those not complete in the cache. Checks the configuration first (throws
// sg::Error naming the option).
std::vector<StudyUnit> study_units(const StudyConfig& config, bool missing_only);

// The pilot: each (scene, variant) with a unit in `units` renders a sample of the tiles of
// one of its frames on one thread (its per-frame setup whole); the time, extrapolated to
// the frame, is the estimated cost of each of its units. Returns the pilot's wall seconds.
double estimate_unit_costs(const StudyConfig& config, std::vector<StudyUnit>& units,
                           const StudyProgress& progress = {});

// Renders `units` (from study_units of the same configuration) into the frame cache; a unit
// already complete there is skipped. `on_unit(k, seconds)` follows each unit rendered.
// Returns the number of units rendered.
int render_units(const StudyConfig& config, const std::vector<StudyUnit>& units,
                 const StudyProgress& progress = {},
                 const std::function<void(size_t unit, double seconds)>& on_unit = {});

// Runs the study and writes its outputs into config.out_dir: the pilot on the missing
// units, those units, then the measures, pictures and report from the cache. Throws
// sg::Error on bad configuration (naming the option) or failed writes.
StudyResults run_study(const StudyConfig& config, const StudyProgress& progress = {});

// The merge: the outputs from a complete cache, rendering nothing; throws sg::Error naming
// the missing units (and how many) when the cache is not complete.
StudyResults merge_study(const StudyConfig& config, const StudyProgress& progress = {});

// results.json, results.csv, results.md and (with html) index.html and its assets.
void write_study_outputs(const StudyResults& results, const std::string& out_dir, bool html);

}  // namespace sg
