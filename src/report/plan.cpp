#include "report/plan.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>

#include "base/error.h"
#include "base/fnv1a.h"

namespace sg {

double PlanTask::seconds() const {
  double s = 0;
  for (const auto& u : units)
    s += u.seconds;
  return s;
}

double StudyPlan::core_seconds() const {
  double s = 0;
  for (const auto& t : tasks)
    s += t.seconds();
  return s;
}

double StudyPlan::longest_task() const {
  double s = 0;
  for (const auto& t : tasks)
    s = std::max(s, t.seconds());
  return s;
}

int StudyPlan::units_planned() const {
  int n = 0;
  for (const auto& t : tasks)
    n += static_cast<int>(t.units.size());
  return n;
}

std::vector<PlanTask> group_into_tasks(const std::vector<PlannedUnit>& units, double task_seconds) {
  std::vector<PlanTask> tasks;
  double cost = 0;
  for (const auto& u : units) {
    if (tasks.empty() || cost >= task_seconds || !(task_seconds > 0)) {
      tasks.emplace_back();
      cost = 0;
    }
    tasks.back().units.push_back(u);
    cost += u.seconds;
  }
  return tasks;
}

std::string plan_to_json(const StudyPlan& p) {
  nlohmann::ordered_json j;
  j["schema"] = "sunglint-plan/1";
  j["command"] = p.command;
  j["study"] = p.study;
  j["units_total"] = p.units_total;
  j["units_cached"] = p.units_cached;
  j["pilot_seconds"] = p.pilot_seconds;
  j["core_seconds"] = p.core_seconds();
  auto& tasks = j["tasks"] = nlohmann::ordered_json::array();
  for (size_t k = 0; k < p.tasks.size(); ++k) {
    nlohmann::ordered_json t;
    t["task"] = k;
    t["seconds"] = p.tasks[k].seconds();
    auto& units = t["units"] = nlohmann::ordered_json::array();
    for (const auto& u : p.tasks[k].units)
      units.push_back({{"id", u.id}, {"file", u.file}, {"seconds", u.seconds}});
    tasks.push_back(t);
  }
  return j.dump(1) + "\n";
}

StudyPlan plan_from_json(const std::string& text, const std::string& origin) {
  try {
    const auto j = nlohmann::json::parse(text);
    if (j.at("schema").get<std::string>() != "sunglint-plan/1") {
      throw Error(origin + ": not a sunglint plan (schema '" + j.at("schema").get<std::string>() +
                  "')");
    }
    StudyPlan p;
    p.command = j.at("command").get<std::string>();
    p.study = j.at("study").get<std::string>();
    p.units_total = j.at("units_total").get<int>();
    p.units_cached = j.at("units_cached").get<int>();
    p.pilot_seconds = j.value("pilot_seconds", 0.0);
    for (const auto& t : j.at("tasks")) {
      PlanTask task;
      for (const auto& u : t.at("units")) {
        task.units.push_back({u.at("id").get<std::string>(), u.at("file").get<std::string>(),
                              u.at("seconds").get<double>()});
      }
      p.tasks.push_back(std::move(task));
    }
    return p;
  } catch (const nlohmann::json::exception& e) {
    throw Error(origin + ": not a readable sunglint plan (" + e.what() + ")");
  }
}

std::string format_core_hours(double s) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.3g core-hours (%.3g core-s)", s / 3600, s);
  return buf;
}

std::string plan_table(const StudyPlan& p) {
  std::string out;
  char line[256];
  std::snprintf(line, sizeof line, "%6s %10s  %s\n", "task", "core-s", "units");
  out += line;
  for (size_t k = 0; k < p.tasks.size(); ++k) {
    const PlanTask& t = p.tasks[k];
    for (size_t u = 0; u < t.units.size(); ++u) {
      if (u == 0) {
        std::snprintf(line, sizeof line, "%6zu %10.3g  %s\n", k, t.seconds(),
                      t.units[u].id.c_str());
      } else {
        std::snprintf(line, sizeof line, "%6s %10s  %s\n", "", "", t.units[u].id.c_str());
      }
      out += line;
    }
  }
  std::snprintf(line, sizeof line,
                "%d units, %d in the cache; %d to render in %zu tasks: estimated %s, the longest "
                "task %.3g core-s (pilot: %.1f s)\n",
                p.units_total, p.units_cached, p.units_planned(), p.tasks.size(),
                format_core_hours(p.core_seconds()).c_str(), p.longest_task(), p.pilot_seconds);
  return out + line;
}

std::string study_fingerprint(const std::vector<std::string>& files) {
  uint64_t h = kFnv1aBasis;
  for (const auto& f : files) {
    h = fnv1a64(f, h);
    h = fnv1a64(std::string_view("\n", 1), h);
  }
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

TimeEstimate::TimeEstimate(double total, double prior_rate, double fixed_seconds)
    : total_(std::max(0.0, total)),
      prior_rate_(prior_rate),
      fixed_(std::max(0.0, fixed_seconds)),
      prior_weight_(0.02 * std::max(0.0, total)) {}

void TimeEstimate::done(double estimated, double wall) {
  done_est_ += std::max(0.0, estimated);
  done_wall_ += std::max(0.0, wall);
  partial_ = 0;
}

double TimeEstimate::rate() const {
  const double w = prior_weight_ + done_est_;
  return w > 0 ? (prior_weight_ * prior_rate_ + done_wall_) / w : prior_rate_;
}

double TimeEstimate::seconds_left() const {
  const double left = std::max(0.0, total_ - done_est_ - partial_);
  return left * rate() + std::max(0.0, fixed_ - fixed_done_);
}

double TimeEstimate::fraction() const {
  const double r = rate();
  const double all = total_ * r + fixed_;
  if (!(all > 0)) return 1.0;
  const double done = std::min(total_, done_est_ + partial_) * r + std::min(fixed_, fixed_done_);
  return std::clamp(done / all, 0.0, 1.0);
}

}  // namespace sg
