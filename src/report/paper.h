// Table 1 of Podee et al. (2021): RMSE of each method against the reference on their four
// scenes, measured on pictures after glare and tone mapping. Ours are measured on linear
// values (metrics/metrics.h) with our own reference, so absolute values do not compare;
// ratios within a column (a method's RMSE over No AA's) do.
//
// Each paper row is matched to one method variant of a study: by default the first of
// the row's candidate labels that the study renders; `compare --paper-row ROW=VARIANT`
// overrides it.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "report/results.h"

namespace sg {

struct PaperRow {
  std::string method;               // as the paper names it
  std::array<double, 4> rmse;       // simple, smooth, medium, high
  std::vector<std::string> labels;  // candidate variants, in order of preference
};

inline constexpr std::array<const char*, 4> kPaperScenes = {"simple", "smooth", "medium", "high"};

const std::vector<PaperRow>& paper_table1();

// For each paper row with a match, (row, label): `overrides` first (row -> label), then the
// row's candidates among `labels` (canonical). Throws sg::Error naming --paper-row for an
// unknown row or a label the study does not render.
std::vector<std::pair<std::string, std::string>> match_paper_rows(
    const std::vector<std::string>& labels,
    const std::vector<std::pair<std::string, std::string>>& overrides);

// Table 1 beside a study: per paper row, the paper's RMSE and ratio to No AA, and ours
// (nothing where the study lacks the variant or the scene).
struct PaperComparison {
  std::string method, label;  // label: "" when no variant matches
  std::array<double, 4> paper{}, paper_ratio{};
  std::array<std::optional<double>, 4> ours{}, ours_ratio{};
};
std::vector<PaperComparison> compare_with_paper(const StudyResults& r);

// Table 1 in words: where the paper's method (its rows "Ours (uniform)" and "Ours
// (per-pixel)", the better of the two per scene) has the lowest RMSE in the paper; where it
// wins and where it loses against the other rows in this study (with both RMSEs); and where
// the study's equal-cost target, when it is not one of the paper's rows (sunglint's `staa`,
// the paper's method with the footprint term), wins and loses against every row. Labels go
// through `code`. Empty when the study renders none of the paper's scenes.
std::vector<std::string> paper_table_verdict(
    const StudyResults& r, const std::function<std::string(const std::string&)>& code);

// Whether the study renders one of the paper's four scenes (kPaperScenes, by name): the
// report shows Table 1 beside it only then.
bool studies_a_paper_scene(const StudyResults& r);

}  // namespace sg
