// The report's opening summary, written from a study's results alone (results.json), so
// that `compare`'s page, `report`'s Markdown and a test on a hand-made results file say
// the same: per scene, which method has the lowest RMSE and the lowest temporal error
// (whole image; with the next best, and whether the two differ by less than the
// reference's noise), and where the equal-cost target (`staa` by default) stands: its RMSE
// as a share of what supersampling reaches at the same cost (report/equal_cost.h; outside
// the curve, against its nearest end), its cost and its temporal error against `point`'s.
// Then the same over all scenes, in one sentence.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "report/results.h"

namespace sg {

struct Ranked {
  std::string label;  // "" when there is none (a study of one method)
  double value = 0;
};

struct SceneSummary {
  std::string scene;
  Ranked best_rmse, next_rmse;
  Ranked best_temporal, next_temporal;
  double reference_se = 0;         // whole image; NaN when the reference does not measure it
  bool rmse_within_noise = false;  // best and next RMSE closer than reference_se

  // The equal-cost target's standing ("" target: the study has none, or not in this scene).
  std::string target;
  double target_rmse = 0, target_temporal = 0, target_ms = 0;
  CurveStatus cost_status = CurveStatus::above;
  double same_cost_spp = 0;  // interpolated: supersampling's samples per pixel at that cost
  // The budget compared with outside the curve (below: the cheapest, above: the largest).
  std::string bound_budget;
  double bound_ms = 0;
  double supersampling_rmse = 0;                // at the same cost, or the bound budget's
  std::optional<double> rmse_vs_supersampling;  // target_rmse / supersampling_rmse
  std::optional<double> cost_vs_point;          // target_ms / point's
  std::optional<double> temporal_vs_point;      // target temporal error / point's
  double point_ms = 0;
};

struct StudySummary {
  std::string target;  // settings.equal_cost_target
  std::vector<SceneSummary> scenes;
};

StudySummary summarise(const StudyResults& r);

// In words: one sentence (or two) per scene and one over the study; labels go through
// `code` (HTML <code> with escaping, Markdown backticks), everything else is plain text.
struct SummaryText {
  std::vector<std::string> scenes;
  std::string overall;  // "" for a study of one scene
};
SummaryText summary_text(const StudySummary& s,
                         const std::function<std::string(const std::string&)>& code);

}  // namespace sg
