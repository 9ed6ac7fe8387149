#include "report/paper.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

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

namespace {

std::string g3(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}

// "a, b and c"
std::string listed(const std::vector<std::string>& items) {
  std::string t;
  for (size_t k = 0; k < items.size(); ++k)
    t += (k == 0 ? "" : k + 1 == items.size() ? " and " : ", ") + items[k];
  return t;
}

bool is_papers_method(const PaperComparison& c) {
  return c.method.rfind("Ours", 0) == 0;
}

}  // namespace

std::vector<std::string> paper_table_verdict(
    const StudyResults& r, const std::function<std::string(const std::string&)>& code) {
  std::vector<std::string> out;
  if (!studies_a_paper_scene(r)) return out;
  const std::vector<PaperComparison> rows = compare_with_paper(r);
  const size_t n = kPaperScenes.size();
  // The paper's method per scene: the better of its rows, in the paper and in this study.
  std::array<double, 4> paper_best{};
  std::array<std::optional<double>, 4> ours_best{};
  std::vector<std::string> ours_labels;
  for (size_t k = 0; k < n; ++k)
    paper_best[k] = INFINITY;
  for (const PaperComparison& c : rows) {
    if (!is_papers_method(c)) continue;
    if (!c.label.empty()) ours_labels.push_back(code(c.label));
    for (size_t k = 0; k < n; ++k) {
      paper_best[k] = std::min(paper_best[k], c.paper[k]);
      if (c.ours[k] && (!ours_best[k] || *c.ours[k] < *ours_best[k])) ours_best[k] = c.ours[k];
    }
  }
  // 1. In the paper.
  std::vector<std::string> lowest, beaten;
  for (size_t k = 0; k < n; ++k) {
    std::vector<std::string> by;
    for (const PaperComparison& c : rows) {
      if (!is_papers_method(c) && c.paper[k] <= paper_best[k]) by.push_back(c.method);
    }
    if (by.empty()) {
      lowest.push_back(kPaperScenes[k]);
    } else {
      beaten.push_back(std::string(kPaperScenes[k]) + " (by " + listed(by) + ")");
    }
  }
  std::string t = "In the paper, its method has the lowest RMSE on " +
                  (lowest.size() == n ? "all four scenes" : listed(lowest));
  if (!beaten.empty())
    t += (lowest.empty() ? "none; it is beaten on " : "; not on ") + listed(beaten);
  out.push_back(t + ".");
  // 2. In this study: the paper's method against the other rows.
  std::vector<std::string> studied;
  for (size_t k = 0; k < n; ++k) {
    if (ours_best[k]) studied.push_back(kPaperScenes[k]);
  }
  if (!studied.empty()) {
    std::vector<std::string> wins, losses;
    for (const PaperComparison& c : rows) {
      if (is_papers_method(c) || c.label.empty()) continue;
      std::vector<std::string> won, lost;
      for (size_t k = 0; k < n; ++k) {
        if (!ours_best[k] || !c.ours[k]) continue;
        if (*ours_best[k] < *c.ours[k]) {
          won.push_back(kPaperScenes[k]);
        } else {
          lost.push_back(std::string(kPaperScenes[k]) + " (" + g3(*ours_best[k]) + " against " +
                         g3(*c.ours[k]) + ")");
        }
      }
      const std::string row = c.method + " (" + code(c.label) + ")";
      if (!won.empty()) wins.push_back(row + " on " + listed(won));
      if (!lost.empty()) losses.push_back(row + " on " + listed(lost));
    }
    std::string u = "In this study (linear values against our reference, " + listed(studied) +
                    "), the paper's method (" + listed(ours_labels) +
                    (ours_labels.size() > 1 ? ", the better per scene" : "") + ")";
    auto joined = [](const std::vector<std::string>& v) {
      std::string j;
      for (const std::string& x : v)
        j += (j.empty() ? "" : ", ") + x;
      return j;
    };
    if (!wins.empty()) u += " beats " + joined(wins);
    if (!losses.empty())
      u += std::string(wins.empty() ? "" : "; it") + " loses to " + joined(losses);
    if (wins.empty() && losses.empty()) u += " has no other row to compare with";
    out.push_back(u + ".");
  }
  // 3. The study's target, when it is not one of the paper's rows.
  const std::string& target = r.settings.equal_cost_target;
  const bool paper_row = std::any_of(rows.begin(), rows.end(),
                                     [&](const PaperComparison& c) { return c.label == target; });
  if (!target.empty() && !paper_row) {
    std::vector<std::string> won, lost;
    for (size_t k = 0; k < n; ++k) {
      std::optional<double> mine;
      for (const SceneResult& sc : r.scenes) {
        if (sc.name != kPaperScenes[k]) continue;
        for (const VariantResult& v : sc.methods) {
          if (v.label == target) mine = v.at(Region::image).rmse;
        }
      }
      if (!mine) continue;
      std::vector<std::string> better;
      for (const PaperComparison& c : rows) {
        if (c.ours[k] && *c.ours[k] <= *mine)
          better.push_back(c.method + " (" + g3(*c.ours[k]) + ")");
      }
      if (better.empty()) {
        won.push_back(kPaperScenes[k]);
      } else {
        lost.push_back(std::string(kPaperScenes[k]) + " to " + listed(better) + " against its " +
                       g3(*mine));
      }
    }
    if (!won.empty() || !lost.empty()) {
      std::string v = code(target) + " has a lower RMSE than every row";
      v += won.empty() ? " on none of the scenes" : " on " + listed(won);
      if (!lost.empty()) v += "; it loses on " + listed(lost);
      out.push_back(v + ".");
    }
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
