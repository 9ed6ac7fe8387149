// The results of a study (`sunglint compare`) and their files: results.json (the
// record; every other output can be regenerated from it), results.csv (one row per
// scene, variant and region, for spreadsheets) and Markdown tables (results.md,
// docs/results.md). The schema is described in docs/report.md ("results.json").
//
// All metrics are on the linear pixel values (metrics/metrics.h), never on pictures.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "report/equal_cost.h"

namespace sg {

// The pixel sets metrics are measured on: the whole image, the pixels that see water,
// and its near and far halves (report/regions.h).
enum class Region { image = 0, water = 1, near = 2, far = 3 };
inline constexpr std::array<const char*, 4> kRegionNames = {"image", "water", "near", "far"};

// One channel's figures of a colour study (R, G or B).
struct ChannelFigures {
  double rmse = 0, temporal_error = 0, flicker = 0;
};
inline constexpr std::array<const char*, 3> kChannelNames = {"R", "G", "B"};

struct RegionMetrics {
  double rmse = 0;               // over all values (pixels x channels) of the region, all frames
  double psnr = 0;               // 20 log10(1 / rmse); +inf when rmse = 0
  double temporal_error = 0;     // metrics.h: frame-to-frame change the reference lacks
  double flicker = 0;            // mean |I_f - I_{f-1}| of the variant
  double flicker_reference = 0;  // the same of the reference
  long pixels = 0;               // per frame
  // The reference's standard error over the same values (NaN when the reference does not
  // measure its noise) and the RMSE with it taken out, sqrt(max(0, rmse^2 - se^2)).
  double reference_se = 0;
  double rmse_corrected = 0;
  std::vector<ChannelFigures> channels;  // R, G, B of a colour scene; empty for a grey one
};

// A variant's figures over the pixels of one class of what the pixel sees
// (report/pixel_classes.h; `compare --split`), each frame's own pixels of the class.
struct ClassFigures {
  std::string name;        // kPixelClassNames
  double pixel_share = 0;  // of the image's pixels, over the frames
  double error_share = 0;  // of the variant's squared error over the image
  double rmse = 0, temporal_error = 0;
  // The reference's standard error there (NaN: unknown) and the figures with its noise
  // taken out: sqrt(max(0, rmse^2 - se^2)) and, for the frame-to-frame change (two
  // frames' independent noise), sqrt(max(0, temporal^2 - 2 se^2)).
  double reference_se = 0, rmse_corrected = 0, temporal_corrected = 0;
};

struct VariantResult {
  std::string label;  // canonical: "supersample --samples 6x6x1"
  std::string name;   // catalogue name: "supersample"
  bool stateful = false;
  double spp = 0;  // samples per pixel for reference/supersample, 0 otherwise
  double ms_per_frame = 0;
  int frames_rendered = 0, frames_cached = 0;       // in this run
  std::array<RegionMetrics, 4> regions{};           // indexed by Region
  std::string picture, error_map;                   // figure files relative to the study folder
  std::string near_crop_picture, far_crop_picture;  // the crops at kCropScale:1 pixels
  // The flicker pixel's value (mean over the channels) in each frame, when the study has one.
  std::vector<double> trace;
  std::vector<ClassFigures> classes;  // with `compare --split`, else empty

  const RegionMetrics& at(Region r) const { return regions[static_cast<int>(r)]; }
  RegionMetrics& at(Region r) { return regions[static_cast<int>(r)]; }
};

struct EqualCost {
  std::string target;  // label of the target method
  double target_ms = 0, target_rmse = 0;
  SameCost cost;  // the supersampling budget that costs what the target costs
  SameRmse rmse;  // the budget that reaches the target's RMSE
};

struct CropBox {
  int x = 0, y = 0, width = 0, height = 0;
};

// Screen pixels per image pixel of the report's crops: glints are a pixel or two wide, so
// the crops are shown enlarged, never shrunk.
inline constexpr int kCropScale = 2;

// The pixel whose value over time the report plots: where the variant `chosen_by` (point
// sampling when the study has it) has its largest temporal error against the reference.
struct FlickerPixel {
  int x = -1, y = -1;  // -1: none (a study of one frame)
  std::string chosen_by;
};

struct SceneResult {
  std::string name, file;
  int shown_frame = 0;  // the frame of the pictures
  long water_pixels = 0, near_pixels = 0, far_pixels = 0;
  double split_distance = 0;
  int channels = 1;  // of the scene's images: 1 grey, 3 colour
  // A moving camera (format /3) over the studied frames, from the first frame's shutter
  // opening to the last frame: the fastest speed (m/s) and turn rate (degrees/s) of the
  // keyframe segments in that interval (scene/camera_path.h, camera_motion); the water
  // regions are those of the first frame's camera.
  bool moving_camera = false;
  double camera_speed = 0, camera_turn_deg = 0;
  // The surface holds lattice cascades (format /3): the live page, which reads explicit
  // waves only, does not show the scene.
  bool cascades = false;
  CropBox near_crop, far_crop;
  double error_range = 0;  // |difference| at the ends of the error maps' colour scale
  VariantResult reference;
  std::vector<VariantResult> methods;
  std::vector<VariantResult> budgets;  // the supersampling curve, increasing spp
  std::optional<EqualCost> equal_cost;
  FlickerPixel flicker_pixel;
  std::string grid, video;  // figure files relative to the study folder ("" if none)
  std::string crops;        // every column's near and far crops at kCropScale:1, one picture
};

struct StudySettings {
  int width = 0, height = 0, first_frame = 0, last_frame = 0;
  double fps = 0;                             // of the first scene (videos)
  std::string reference;                      // label
  std::vector<std::string> methods, budgets;  // labels
  std::string equal_cost_target;              // "" when none
  double exposure = 0;
  std::vector<std::pair<std::string, std::string>> paper_rows;  // Table 1 row -> label
  std::string command;                                          // the command line
};

struct StudyResults {
  StudySettings settings;
  std::vector<SceneResult> scenes;
};

std::string results_to_json(const StudyResults& r);
// Throws sg::Error naming the key on a malformed file.
StudyResults results_from_json(const std::string& text, const std::string& name_for_errors);

// CSV (RFC 4180 quoting): header, then one row per scene x variant (reference, method,
// budget) x region. Numbers round-trip (17 significant digits).
std::string results_to_csv(const StudyResults& r);
// The per-channel columns (rmse_r ... temporal_error_b) are empty for a grey scene.
inline constexpr std::array<const char*, 21> kCsvColumns = {"scene",
                                                            "kind",
                                                            "variant",
                                                            "region",
                                                            "rmse",
                                                            "psnr",
                                                            "temporal_error",
                                                            "flicker",
                                                            "flicker_reference",
                                                            "ms_per_frame",
                                                            "spp",
                                                            "pixels",
                                                            "frames_rendered",
                                                            "frames_cached",
                                                            "stateful",
                                                            "rmse_r",
                                                            "rmse_g",
                                                            "rmse_b",
                                                            "temporal_error_r",
                                                            "temporal_error_g",
                                                            "temporal_error_b"};
// Parses CSV text into rows of fields (quotes resolved); throws sg::Error on bad quoting.
std::vector<std::vector<std::string>> parse_csv(const std::string& text);

// The Markdown of the study: settings, Table 1 beside ours, one table per scene and the
// equal-cost comparison. `image_prefix` is prepended to figure paths ("" inside the
// study folder).
std::string results_to_markdown(const StudyResults& r, const std::string& image_prefix = "");

// printf-style `format` of one number for the documents; infinities as `inf_text` with a
// minus for -inf ("inf" in Markdown, "&infin;" in HTML).
std::string format_number(const char* format, double v, const std::string& inf_text = "inf");

// The equal-cost comparison in words; `target_markup` is the target's label as the
// document writes it (Markdown code, escaped HTML).
std::string equal_cost_sentence(const EqualCost& e, const std::string& target_markup);

// A short summary for the README: one picture, the RMSE and temporal error of each
// method on each scene, the equal-cost line of each scene.
std::string results_summary_markdown(const StudyResults& r, const std::string& picture);

// `text` with what lies between the lines `begin` and `end` replaced by `content`
// (the markers kept). Throws sg::Error naming `name_for_errors` when a marker is missing.
std::string replace_marked_section(const std::string& text, const std::string& begin,
                                   const std::string& end, const std::string& content,
                                   const std::string& name_for_errors);

// The sentence on a scene's reference noise: its standard error (whole image, near, far),
// which figures are corrected for it, and the methods whose RMSEs differ by less than it
// (labels quoted with `quote`).
std::string reference_noise_text(const SceneResult& sc, const std::string& quote);

// The sentence on a moving camera's speed and turn rate; "" for a fixed camera.
std::string camera_motion_sentence(const SceneResult& sc);

}  // namespace sg
