#include "report/summary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sg {
namespace {

std::string num(const char* f, double v) {
  return format_number(f, v);
}

// The best and the next best of the scene's methods by `value` (lower is better).
template <class F>
void rank(const SceneResult& sc, F value, Ranked& best, Ranked& next) {
  std::vector<Ranked> all;
  for (const VariantResult& v : sc.methods) {
    const double x = value(v);
    if (std::isfinite(x)) all.push_back({v.label, x});
  }
  std::stable_sort(all.begin(), all.end(),
                   [](const Ranked& a, const Ranked& b) { return a.value < b.value; });
  if (!all.empty()) best = all[0];
  if (all.size() > 1) next = all[1];
}

const VariantResult* find_label(const SceneResult& sc, const std::string& label) {
  for (const VariantResult& v : sc.methods) {
    if (v.label == label) return &v;
  }
  return nullptr;
}

// `point` as the study names it: the variant labelled "point", else the first of that name.
const VariantResult* find_point(const SceneResult& sc) {
  if (const VariantResult* v = find_label(sc, "point")) return v;
  for (const VariantResult& v : sc.methods) {
    if (v.name == "point") return &v;
  }
  return nullptr;
}

// "a, b and c"
std::string listed(const std::vector<std::string>& items) {
  std::string t;
  for (size_t k = 0; k < items.size(); ++k)
    t += (k == 0 ? "" : k + 1 == items.size() ? " and " : ", ") + items[k];
  return t;
}

// "0.3" or "0.3 to 0.45" over the values.
std::string span(std::vector<double> v, const char* f) {
  std::sort(v.begin(), v.end());
  const std::string lo = num(f, v.front()), hi = num(f, v.back());
  return lo == hi ? lo : lo + " to " + hi;
}

}  // namespace

StudySummary summarise(const StudyResults& r) {
  StudySummary s;
  s.target = r.settings.equal_cost_target;
  for (const SceneResult& sc : r.scenes) {
    SceneSummary m;
    m.scene = sc.name;
    rank(
        sc, [](const VariantResult& v) { return v.at(Region::image).rmse; }, m.best_rmse,
        m.next_rmse);
    rank(
        sc, [](const VariantResult& v) { return v.at(Region::image).temporal_error; },
        m.best_temporal, m.next_temporal);
    m.reference_se = sc.reference.at(Region::image).reference_se;
    m.rmse_within_noise = !m.next_rmse.label.empty() && m.reference_se > 0 &&
                          m.next_rmse.value - m.best_rmse.value < m.reference_se;
    const VariantResult* target = s.target.empty() ? nullptr : find_label(sc, s.target);
    if (target != nullptr) {
      m.target = target->label;
      m.target_rmse = target->at(Region::image).rmse;
      m.target_temporal = target->at(Region::image).temporal_error;
      m.target_ms = target->ms_per_frame;
      if (sc.equal_cost) {
        const EqualCost& e = *sc.equal_cost;
        m.cost_status = e.cost.status;
        if (e.cost.status == CurveStatus::interpolated) {
          m.same_cost_spp = e.cost.spp;
          m.supersampling_rmse = e.cost.rmse;
        } else if (!sc.budgets.empty()) {
          const VariantResult& b =
              e.cost.status == CurveStatus::below ? sc.budgets.front() : sc.budgets.back();
          m.bound_budget = b.label;
          m.bound_ms = b.ms_per_frame;
          m.supersampling_rmse = b.at(Region::image).rmse;
        }
        if (m.supersampling_rmse > 0)
          m.rmse_vs_supersampling = m.target_rmse / m.supersampling_rmse;
      }
      if (const VariantResult* p = find_point(sc); p != nullptr && p != target) {
        m.point_ms = p->ms_per_frame;
        if (p->ms_per_frame > 0) m.cost_vs_point = m.target_ms / p->ms_per_frame;
        const double pt = p->at(Region::image).temporal_error;
        if (pt > 0) m.temporal_vs_point = m.target_temporal / pt;
      }
    }
    s.scenes.push_back(m);
  }
  return s;
}

SummaryText summary_text(const StudySummary& s,
                         const std::function<std::string(const std::string&)>& code) {
  SummaryText out;
  std::vector<std::string> best_rmse_scenes, best_temporal_scenes;
  std::vector<double> ratios, costs, temporals;
  int with_target = 0;
  for (const SceneSummary& m : s.scenes) {
    std::string t = m.scene + ": ";
    if (m.best_rmse.label.empty()) {
      out.scenes.push_back(t + "no method was measured.");
      continue;
    }
    t += "the lowest RMSE is " + code(m.best_rmse.label) + "'s (" + num("%.3g", m.best_rmse.value);
    if (!m.next_rmse.label.empty()) {
      t += m.rmse_within_noise ? "; within the reference's noise, " + num("%.2g", m.reference_se) +
                                     ", of " + code(m.next_rmse.label) + "'s "
                               : "; next " + code(m.next_rmse.label) + ", ";
      t += num("%.3g", m.next_rmse.value);
    }
    t += "), the lowest temporal error " + code(m.best_temporal.label) + "'s (" +
         num("%.3g", m.best_temporal.value);
    if (!m.next_temporal.label.empty()) {
      t += "; next " + code(m.next_temporal.label) + ", " + num("%.3g", m.next_temporal.value);
    }
    t += ").";
    if (!m.target.empty()) {
      ++with_target;
      if (m.best_rmse.label == m.target) best_rmse_scenes.push_back(m.scene);
      if (m.best_temporal.label == m.target) best_temporal_scenes.push_back(m.scene);
      t += ' ';  // (not " " + ...: GCC 12 warns falsely of an overlapping copy there)
      t += code(m.target) + " takes " + num("%.3g", m.target_ms) + " ms a frame";
      if (m.cost_vs_point) {
        costs.push_back(*m.cost_vs_point);
        t += ", " + num("%.3g", *m.cost_vs_point) + " times " + code("point") + "'s " +
             num("%.3g", m.point_ms) + " ms";
      }
      if (m.temporal_vs_point) {
        temporals.push_back(*m.temporal_vs_point);
        t += ", with " + num("%.2g", *m.temporal_vs_point) + " of its temporal error";
      }
      t += ".";
      if (m.rmse_vs_supersampling) {
        ratios.push_back(*m.rmse_vs_supersampling);
        const std::string ratio = num("%.2g", *m.rmse_vs_supersampling);
        if (m.cost_status == CurveStatus::interpolated) {
          t += " Supersampling at that cost (" + num("%.3g", m.same_cost_spp) +
               " samples per pixel) reaches RMSE " + num("%.3g", m.supersampling_rmse) + ": " +
               code(m.target) + "'s is " + ratio + " of it.";
        } else {
          t += std::string(" It costs ") +
               (m.cost_status == CurveStatus::below ? "less than the cheapest"
                                                    : "more than the largest") +
               " supersampling budget (" + code(m.bound_budget) + ", " + num("%.3g", m.bound_ms) +
               " ms, RMSE " + num("%.3g", m.supersampling_rmse) + "); its RMSE is " + ratio +
               " of that budget's.";
        }
      }
    }
    out.scenes.push_back(t);
  }
  if (s.scenes.size() > 1 && with_target > 0) {
    const size_t n = s.scenes.size();
    std::string t = "Over the " + std::to_string(n) + " scenes, " + code(s.target) +
                    " has the lowest RMSE on " + std::to_string(best_rmse_scenes.size()) +
                    (best_rmse_scenes.empty() ? "" : " (" + listed(best_rmse_scenes) + ")") +
                    " and the lowest temporal error on " +
                    std::to_string(best_temporal_scenes.size()) +
                    (best_temporal_scenes.empty() ? "" : " (" + listed(best_temporal_scenes) + ")");
    if (!ratios.empty()) {
      t += "; at equal cost its RMSE is " + span(ratios, "%.2g") + " of supersampling's";
    }
    if (!costs.empty()) {
      t += "; it costs " + span(costs, "%.3g") + " times " + code("point") +
           (temporals.empty() ? "" : " for " + span(temporals, "%.2g") + " of its temporal error");
    }
    out.overall = t + ".";
  }
  return out;
}

}  // namespace sg
