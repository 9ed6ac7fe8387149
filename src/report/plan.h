// The study as tasks (`sunglint compare --plan`, `--task K`, `--slurm`; docs/cluster.md).
//
// A study's work is cut into units, each a piece of the frame cache that one process
// renders and stores whole (report/study.h, study_units): one frame of a stateless variant,
// one batch of one frame of the reference, or the whole frame range of a stateful variant
// (whose frames need their history). A plan groups the units that are not in the cache yet
// into tasks, in the order a local run renders them, each with the cost a pilot estimated
// (core-seconds: one thread); a task is what one element of a Slurm job array runs. The
// plan is written as JSON, so that every task of an array reads the same list however the
// cache changes while they run; a unit is named by its cache file, which holds the hash of
// everything its pixels depend on, so a task run by another command's study is refused.
//
// TimeEstimate turns the pilot's estimates into `compare`'s time left: the estimated cost
// of the work not done yet, scaled by the ratio of the measured to the estimated time of
// the work done (a prior ratio until enough is done), plus the report's own estimate.
// This file holds no rendering: its tests use hand-made cost tables.
#pragma once

#include <string>
#include <vector>

namespace sg {

// A unit as a plan holds it.
struct PlannedUnit {
  std::string id;      // what it is: "simple: reference --samples 2x2x1, frame 0, batch 1/2"
  std::string file;    // its cache file's name (the unit's identity)
  double seconds = 0;  // estimated cost, core-seconds
};

struct PlanTask {
  std::vector<PlannedUnit> units;
  double seconds() const;  // the units' estimated cost
};

struct StudyPlan {
  std::string command;       // the study's command, for the record
  std::string study;         // fingerprint of every unit of the study (cached or not)
  int units_total = 0;       // every unit of the study
  int units_cached = 0;      // of which in the cache when planned
  double pilot_seconds = 0;  // the pilot's own time
  std::vector<PlanTask> tasks;
  double core_seconds() const;  // the tasks' estimated cost
  double longest_task() const;  // the costliest task's estimated cost, core-seconds
  int units_planned() const;
};

// Units in order into tasks: each task takes units until their estimated cost reaches
// `task_seconds` (0: one unit per task). Every unit lands in exactly one task, in order.
std::vector<PlanTask> group_into_tasks(const std::vector<PlannedUnit>& units, double task_seconds);

// JSON (`sunglint-plan/1`) and back; plan_from_json throws sg::Error naming `origin`.
std::string plan_to_json(const StudyPlan& plan);
StudyPlan plan_from_json(const std::string& text, const std::string& origin);

// The table `--plan` prints: one line per task (its number, cost, units), then the totals.
std::string plan_table(const StudyPlan& plan);

// The fingerprint of a study: FNV-1a 64 of its units' cache file names, in order (hex).
std::string study_fingerprint(const std::vector<std::string>& unit_files);

// "0.0123 core-hours (44.3 core-s)".
std::string format_core_hours(double core_seconds);

// The time left of a run, from estimated costs and the measured time of what is done.
class TimeEstimate {
 public:
  // `total`: the estimated cost of the work to do (core-seconds); `prior_rate`: the wall
  // seconds a core-second is expected to take before any work is measured (1 / threads);
  // `fixed_seconds`: work outside the estimate's scale (the report), in wall seconds.
  TimeEstimate(double total, double prior_rate, double fixed_seconds = 0);
  // A piece of estimated cost `estimated` took `wall` seconds.
  void done(double estimated, double wall);
  // Within the current piece: `estimated` of its cost is done (not yet measured).
  void partial(double estimated) { partial_ = estimated; }
  // Part of the fixed work is done (wall seconds of its estimate).
  void fixed_done(double seconds) { fixed_done_ += seconds; }
  // Measured wall seconds per estimated core-second: the prior, weighted as `prior_weight`
  // of estimated cost (2 % of the total), blended with what was measured.
  double rate() const;
  double seconds_left() const;
  // Estimated share of the work done, in [0, 1].
  double fraction() const;

 private:
  double total_, prior_rate_, fixed_, prior_weight_;
  double done_est_ = 0, done_wall_ = 0, partial_ = 0, fixed_done_ = 0;
};

}  // namespace sg
