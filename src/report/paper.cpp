#include "report/paper.h"

#include <algorithm>

#include "base/error.h"
#include "report/cache.h"

namespace sg {

const std::vector<PaperRow>& paper_table1() {
  static const std::vector<PaperRow> rows = {
      {"No AA", {0.0797, 0.0299, 0.0315, 0.0778}, {"point"}},
      {"32x MSAA", {0.0795, 0.0287, 0.0282, 0.0676}, {"supersample --samples 6x6x1"}},
      {"LEAN", {0.0675, 0.0329, 0.0298, 0.0633}, {"lean"}},
      // The paper's method is `staa --footprint none` (sunglint's default adds the pixel
      // footprint term); the first variant the study renders is used.
      {"Ours (uniform)",
       {0.0384, 0.0200, 0.0278, 0.0611},
       {"staa --footprint none --ndf uniform", "staa --ndf uniform --footprint none"}},
      {"Ours (per-pixel)",
       {0.0384, 0.0192, 0.0229, 0.0610},
       {"staa --footprint none --ndf per-pixel", "staa --footprint none",
        "staa --ndf per-pixel --footprint none"}},
  };
  return rows;
}

std::vector<std::pair<std::string, std::string>> match_paper_rows(
    const std::vector<std::string>& labels,
    const std::vector<std::pair<std::string, std::string>>& overrides) {
  auto present = [&](const std::string& l) {
    return std::find(labels.begin(), labels.end(), canonical_label(l)) != labels.end();
  };
  for (const auto& [row, label] : overrides) {
    const auto& t = paper_table1();
    if (std::none_of(t.begin(), t.end(), [&](const PaperRow& p) { return p.method == row; })) {
      std::string names;
      for (const auto& p : t)
        names += (names.empty() ? "" : ", ") + p.method;
      throw Error("--paper-row: unknown row '" + row + "' (rows: " + names + ")");
    }
    if (!present(label)) {
      throw Error("--paper-row: '" + row + "=" + label + "': the study does not render '" + label +
                  "' (add it with --method)");
    }
  }
  std::vector<std::pair<std::string, std::string>> out;
  for (const PaperRow& p : paper_table1()) {
    auto o = std::find_if(overrides.begin(), overrides.end(),
                          [&](const auto& kv) { return kv.first == p.method; });
    if (o != overrides.end()) {
      out.emplace_back(p.method, canonical_label(o->second));
      continue;
    }
    for (const std::string& l : p.labels) {
      if (present(l)) {
        out.emplace_back(p.method, canonical_label(l));
        break;
      }
    }
  }
  return out;
}

std::vector<PaperComparison> compare_with_paper(const StudyResults& r) {
  auto label_of = [&](const std::string& row) -> std::string {
    for (const auto& [k, v] : r.settings.paper_rows) {
      if (k == row) return v;
    }
    return "";
  };
  auto rmse_of = [&](const std::string& label, const char* scene) -> std::optional<double> {
    if (label.empty()) return std::nullopt;
    for (const SceneResult& s : r.scenes) {
      if (s.name != scene) continue;
      for (const VariantResult& v : s.methods) {
        if (v.label == label) return v.at(Region::image).rmse;
      }
    }
    return std::nullopt;
  };
  const PaperRow& no_aa = paper_table1().front();
  const std::string no_aa_label = label_of(no_aa.method);
  std::vector<PaperComparison> out;
  for (const PaperRow& p : paper_table1()) {
    PaperComparison c;
    c.method = p.method;
    c.label = label_of(p.method);
    for (size_t k = 0; k < kPaperScenes.size(); ++k) {
      c.paper[k] = p.rmse[k];
      c.paper_ratio[k] = p.rmse[k] / no_aa.rmse[k];
      c.ours[k] = rmse_of(c.label, kPaperScenes[k]);
      const auto base = rmse_of(no_aa_label, kPaperScenes[k]);
      if (c.ours[k] && base && *base > 0) c.ours_ratio[k] = *c.ours[k] / *base;
    }
    out.push_back(c);
  }
  return out;
}

bool studies_a_paper_scene(const StudyResults& r) {
  for (const SceneResult& s : r.scenes)
    for (const char* name : kPaperScenes)
      if (s.name == name) return true;
  return false;
}

}  // namespace sg
