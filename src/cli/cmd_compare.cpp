// `sunglint compare SCENES... -m VARIANT [-m VARIANT ...] --out DIR`: the study a user runs
// to see and trust the result (report/study.h; docs/report.md). This file only turns the
// command line into a StudyConfig and shows progress.
//
// Method variants are given one per -m/--method option, as "NAME [FLAGS]" with the
// flags of `render` ("supersample --samples 6x6x1"): each variant is one shell word, so
// no separator can collide with a flag's value.
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "base/atomic_file.h"
#include "base/error.h"
#include "base/output_path.h"
#include "cli/args.h"
#include "cli/commands.h"
#include "cli/method_flags.h"
#include "cli/path_tables.h"
#include "cli/progress.h"
#include "cli/slurm.h"
#include "gl_engine/engines.h"
#include "methods/method.h"
#include "report/cache.h"
#include "report/plan.h"
#include "report/study.h"
#include "web/web_page.h"

namespace sg {
namespace {

struct CompareArgs {
  std::vector<std::string> scenes, methods, paper_rows;
  std::string out, cache, frames = "0-9", reference = "24x24x1";
  std::string budgets = "1x1x1,2x2x1,2x2x2,3x3x2,4x4x2,4x4x4,6x6x4,8x8x4";
  std::string target = "auto", engine = "cpu";
  int width = 0, height = 0, threads = 0;
  double exposure = 3.0;
  bool no_video = false, no_glare = false, quiet = false, list_methods = false, split = false;
  // The study as tasks (report/plan.h) and on Slurm (cli/slurm.h).
  bool plan = false, merge = false;
  int task = -1;
  std::string plan_file;
  double task_seconds = 0;
  SlurmOptions slurm;
};

// A variant on its engine. One whose text names no --engine runs on the study's (`engine`):
// with gl it gets " --engine gl" in its label, so that its tables, files and cache keys
// tell it from the CPU's.
StudyVariant to_study(MethodVariant v, Engine engine, const std::string& flag) {
  if (v.label.find("--engine") == std::string::npos && engine != Engine::cpu) {
    v.engine = engine;
    v.label += std::string(" --engine ") + engine_name(engine);
    check_engine_runs(v.engine, v.name, v.options, flag + ": '" + v.label + "': ");
  }
  StudyVariant s{canonical_label(v.label), v.name, v.options, v.engine, {}};
  return s;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  for (std::string item; std::getline(ss, item, sep);) {
    item = canonical_label(item);
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

// A shell-safe rendering of the command, for the record.
std::string quote(const std::string& s) {
  if (!s.empty() && s.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                        "0123456789-_./=,:+") == std::string::npos) {
    return s;
  }
  std::string q = "'";
  for (char c : s)
    q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string command_line(const CompareArgs& a) {
  std::string c = "sunglint compare";
  for (const auto& s : a.scenes)
    c += " " + quote(s);
  for (const auto& m : a.methods)
    c += " -m " + quote(canonical_label(m));
  c += " --frames " + a.frames + " --reference " + a.reference;
  if (a.engine != "cpu") c += " --engine " + a.engine;
  if (a.width > 0) c += " --width " + std::to_string(a.width);
  if (a.height > 0) c += " --height " + std::to_string(a.height);
  c += " --budgets " + quote(a.budgets) + " --equal-cost-target " + quote(a.target);
  for (const auto& p : a.paper_rows)
    c += " --paper-row " + quote(p);
  char e[32];
  std::snprintf(e, sizeof e, "%g", a.exposure);
  c += std::string(" --exposure ") + e;
  if (a.no_glare) c += " --no-glare";
  if (a.no_video) c += " --no-video";
  if (a.split) c += " --split";
  return c + " --out " + quote(a.out);
}

// The progress of a study on `bar`: in a log, one line as each piece of work starts (a
// variant on a scene, the pictures), with the time left from the pilot's estimates.
StudyProgress progress_of(ProgressBar& bar) {
  return [&bar, last = std::string()](const StudyStatus& st) mutable {
    std::string piece = st.what.substr(0, st.what.find(", frame"));
    std::string label = piece.size() > 36 ? piece.substr(0, 35) + "~" : piece;
    label.resize(36, ' ');
    bar.set_label("compare " + label);
    bar.set_seconds_left(st.seconds_left);
    if (piece != last) {
      bar.step("", static_cast<long>(st.fraction * 100000), 100000);
      last = piece;
    } else {
      bar.update(static_cast<long>(st.fraction * 100000), 100000);
    }
  };
}

namespace fs = std::filesystem;

std::string default_plan_file(const CompareArgs& a) {
  return (fs::path(a.out) / "plan.json").string();
}

// The plan of the units missing from the cache, their costs from the pilot.
StudyPlan make_plan(const CompareArgs& a, const StudyConfig& c, bool quiet) {
  std::vector<StudyUnit> all = study_units(c, false);
  std::vector<StudyUnit> todo = study_units(c, true);
  StudyPlan p;
  p.command = c.command;
  std::vector<std::string> files;
  for (const auto& u : all)
    files.push_back(u.file);
  p.study = study_fingerprint(files);
  p.units_total = static_cast<int>(all.size());
  p.units_cached = p.units_total - static_cast<int>(todo.size());
  ProgressBar bar("compare pilot", !quiet);
  p.pilot_seconds = estimate_unit_costs(c, todo, progress_of(bar));
  bar.finish();
  std::vector<PlannedUnit> units;
  for (const auto& u : todo)
    units.push_back({u.id, u.file, u.seconds});
  p.tasks = group_into_tasks(units, a.task_seconds);
  return p;
}

void run_plan(const CompareArgs& a, const StudyConfig& c) {
  const StudyPlan p = make_plan(a, c, a.quiet);
  const std::string file = a.plan_file.empty() ? default_plan_file(a) : a.plan_file;
  write_file_atomic(file, plan_to_json(p));
  std::printf("%s", plan_table(p).c_str());
  std::printf("plan: %s (run task K with the same command and --task K%s; --slurm submits them)\n",
              file.c_str(), a.plan_file.empty() ? "" : (" --plan-file " + file).c_str());
}

// `--task K`: the units of task K of the plan, into the cache; units already there are
// skipped. SUNGLINT_TEST_KILL_TASKS=K,L (the tests' fault injection) kills task K once
// (a file beside the plan remembers it) in the middle of its last unit, as the OOM killer
// or a node's failure would.
void run_task(const CompareArgs& a, const StudyConfig& c) {
  const std::string file = a.plan_file.empty() ? default_plan_file(a) : a.plan_file;
  std::error_code ec;
  if (!fs::exists(file, ec)) {
    throw Error("--task: no plan '" + file +
                "' (write one with --plan; on a cluster, is the study's folder on a filesystem "
                "this node shares?)");
  }
  const StudyPlan p = plan_from_json(read_file(file, 256u << 20), file);
  if (a.task >= static_cast<int>(p.tasks.size())) {
    throw UsageError("--task: " + std::to_string(a.task) + " is not a task of " + file + " (0 to " +
                     std::to_string(int(p.tasks.size()) - 1) + ")");
  }
  const std::vector<StudyUnit> all = study_units(c, false);
  std::vector<std::string> files;
  std::map<std::string, const StudyUnit*> by_file;
  for (const auto& u : all) {
    files.push_back(u.file);
    by_file[u.file] = &u;
  }
  if (study_fingerprint(files) != p.study) {
    throw Error("--task: " + file + " is the plan of another study (" + p.command +
                "); run the task with the command that wrote it");
  }
  std::vector<StudyUnit> units;
  for (const auto& pu : p.tasks[a.task].units) {
    auto it = by_file.find(pu.file);
    if (it == by_file.end())
      throw Error("--task: " + file + ": unit " + pu.id + " is not in the study");
    units.push_back(*it->second);
    units.back().seconds = pu.seconds;
  }
  bool kill = false;
  const std::string marker =
      (fs::path(file).parent_path() / ("killed-task-" + std::to_string(a.task))).string();
  if (const char* k = std::getenv("SUNGLINT_TEST_KILL_TASKS")) {
    std::stringstream ss(k);
    for (std::string t; std::getline(ss, t, ',');)
      kill = kill || t == std::to_string(a.task);
    kill = kill && !fs::exists(marker, ec);
  }
  size_t done = 0;
  const auto t0 = std::chrono::steady_clock::now();
  ProgressBar bar("compare task " + std::to_string(a.task), !a.quiet);
  StudyProgress show = progress_of(bar);
  const int rendered = render_units(
      c, units,
      [&](const StudyStatus& st) {
        if (kill && done + 1 == units.size()) {
          write_file_atomic(marker, "killed on purpose (SUNGLINT_TEST_KILL_TASKS)\n");
          std::fprintf(stderr, "sunglint: task %d killed on purpose (SUNGLINT_TEST_KILL_TASKS)\n",
                       a.task);
          std::fflush(stderr);
          std::raise(SIGKILL);
        }
        show(st);
      },
      [&](size_t, double) { ++done; });
  bar.finish();
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf(
      "task %d: %d units rendered, %d already in the cache, %.2f s (estimated %.3g core-s)\n",
      a.task, rendered, int(units.size()) - rendered, secs, p.tasks[a.task].seconds());
}

// The largest array index the cluster takes (MaxArraySize - 1; Slurm's default 1001).
int max_array_index() {
  const CommandOutput r = run_program({"scontrol", "show", "config"});
  std::stringstream ss(r.out);
  for (std::string line; std::getline(ss, line);) {
    if (line.rfind("MaxArraySize", 0) == 0) {
      const size_t eq = line.find('=');
      if (eq != std::string::npos) return std::atoi(line.c_str() + eq + 1) - 1;
    }
  }
  return 1000;
}

// The options a batch script's command does not repeat (the submission's own, the plan's,
// the threads and the progress).
const std::map<std::string, int> kSubmissionFlags{{"--slurm", 0},
                                                  {"--partition", 1},
                                                  {"--max-parallel", 1},
                                                  {"--time-per-task", 1},
                                                  {"--requeue", 0},
                                                  {"--assume-shared", 0},
                                                  {"--task-seconds", 1},
                                                  {"--plan", 0},
                                                  {"--plan-file", 1},
                                                  {"--threads", 1},
                                                  {"-j", 1},
                                                  {"--quiet", 0},
                                                  {"-q", 0},
                                                  {"--task", 1},
                                                  {"--merge", 0}};

void submit_study(const CompareArgs& a, const StudyConfig& c) {
  const SlurmOptions& o = a.slurm;
  // Slurm is there, and the nodes see the study's folders, the scenes and the program.
  require_program("sbatch", "--slurm");
  const std::string exe = program_path();
  std::vector<std::pair<std::string, std::string>> paths{
      {"--out", a.out},
      {"--cache", a.cache.empty() ? (fs::path(a.out) / "cache").string() : a.cache},
      {"the working folder", fs::current_path().string()},
      {"the program", exe}};
  for (const auto& s : a.scenes)
    paths.push_back({"the scene", s});
  const std::string shared = check_shared_folders(paths, o.partition, o.assume_shared);
  // A previous submission of this study: still running, or its merge left waiting on
  // tasks that failed.
  const fs::path last = fs::path(a.out) / "slurm" / "last.json";
  std::string note;
  std::error_code ec;
  if (fs::exists(last, ec)) {
    const auto j = nlohmann::json::parse(read_file(last.string()), nullptr, false);
    const std::string array = j.is_object() ? j.value("array", "") : "";
    const std::string merge = j.is_object() ? j.value("merge", "") : "";
    std::vector<std::string> ids;
    if (!array.empty()) ids.push_back(array);
    if (!merge.empty()) ids.push_back(merge);
    const std::vector<std::string> queued =
        ids.empty() ? std::vector<std::string>{} : queued_jobs(ids);
    bool tasks_queued = false;
    for (const auto& q : queued) {
      std::stringstream f(q);
      std::string job, arr;
      f >> job >> arr;
      tasks_queued = tasks_queued || (!array.empty() && (arr == array || job == array));
    }
    if (tasks_queued) {
      throw Error("--slurm: the previous submission's tasks (job " + array +
                  ") are still queued or running (squeue -j " + array +
                  "); wait for them to end, or cancel them (scancel " + array +
                  "), then run this command again");
    }
    if (!queued.empty() && !merge.empty()) {
      run_slurm({"scancel", merge}, "--slurm");
      note = "cancelled merge job " + merge +
             " of the previous submission (it waited on tasks that did not all succeed)\n";
    }
  }
  std::printf("%s", note.c_str());
  std::printf("shared folders: %s\n", shared.c_str());

  const StudyPlan p = make_plan(a, c, a.quiet);
  const int cpus = a.threads > 0 ? a.threads : 1;
  if (!p.tasks.empty() && int(p.tasks.size()) - 1 > max_array_index()) {
    throw Error("--slurm: " + std::to_string(p.tasks.size()) +
                " tasks are more than the cluster's job arrays take (MaxArraySize " +
                std::to_string(max_array_index() + 1) +
                "); group units into fewer tasks with --task-seconds S (e.g. --task-seconds " +
                std::to_string(int(std::ceil(p.core_seconds() / max_array_index()))) + ")");
  }
  const std::string dir = next_submission_dir((fs::path(a.out) / "slurm").string());
  const std::string plan_file = (fs::path(dir) / "plan.json").string();
  write_file_atomic(plan_file, plan_to_json(p));
  const std::string time =
      o.time_per_task.empty() ? slurm_time(2 * p.longest_task() / cpus + 300) : o.time_per_task;
  const std::string name = "sunglint-" + fs::path(fs::absolute(a.out)).filename().string();
  std::vector<std::string> base{exe};
  const std::vector<std::string> args = arguments_without(program_arguments(), kSubmissionFlags);
  base.insert(base.end(), args.begin() + (args.empty() ? 0 : 1), args.end());
  std::vector<int> indices(p.tasks.size());
  for (size_t k = 0; k < indices.size(); ++k)
    indices[k] = static_cast<int>(k);
  std::map<std::string, std::string> v{
      {"KIND", "compare"},
      {"WHAT", "its units of the study, rendered into the frame cache"},
      {"JOB_NAME", name},
      {"ARRAY", array_spec(indices, o.max_parallel)},
      {"WORK_DIR", fs::current_path().string()},
      {"LOG_DIR", dir},
      {"TIME", time},
      {"CPUS", std::to_string(cpus)},
      {"PARTITION", o.partition},
      {"REQUEUE", o.requeue ? "--requeue" : "--no-requeue"},
      {"RETRIES", std::to_string(o.requeue ? o.retries : 0)},
      {"TASK_COMMAND", shell_join(base) + " -q -j \"${SLURM_CPUS_PER_TASK:-1}\" --plan-file " +
                           shell_quote(plan_file) + " --task \"$SLURM_ARRAY_TASK_ID\""},
      {"ARRAY_JOB", "@ARRAY_JOB@"},
      {"OUT_DIR", fs::absolute(a.out).string()},
      {"MERGE_COMMAND", shell_join(base) + " -q -j \"${SLURM_CPUS_PER_TASK:-1}\" --merge"}};
  const std::string array_script = (fs::path(dir) / "array.sh").string();
  const std::string merge_script = (fs::path(dir) / "merge.sh").string();
  std::string array_id;
  if (!p.tasks.empty()) {
    write_file_atomic(array_script,
                      fill_template(slurm_template("slurm-array.sh"), v, "slurm-array.sh"));
    const std::vector<std::string> sb{"sbatch", "--parsable", array_script};
    array_id = job_id(run_slurm(sb, "--slurm"), sb);
  }
  v["ARRAY_JOB"] = array_id.empty() ? "(none: every unit was in the cache)" : array_id;
  v["TIME"] = o.time_per_task.empty()
                  ? slurm_time(std::max(1800.0, 2 * p.longest_task() / cpus + 300))
                  : o.time_per_task;
  write_file_atomic(merge_script,
                    fill_template(slurm_template("slurm-merge.sh"), v, "slurm-merge.sh"));
  std::vector<std::string> sb{"sbatch", "--parsable"};
  if (!array_id.empty()) sb.push_back("--dependency=afterok:" + array_id);
  sb.push_back(merge_script);
  const std::string merge_id = job_id(run_slurm(sb, "--slurm"), sb);
  write_file_atomic(
      last.string(),
      nlohmann::json{
          {"array", array_id}, {"merge", merge_id}, {"dir", dir}, {"tasks", p.tasks.size()}}
              .dump(1) +
          "\n");
  std::printf(
      "%d units, %d in the cache: %zu tasks (estimated %s, the longest %.3g core-s; %s each)\n",
      p.units_total, p.units_cached, p.tasks.size(), format_core_hours(p.core_seconds()).c_str(),
      p.longest_task(), time.c_str());
  if (!array_id.empty()) {
    std::printf(
        "submitted job array %s (%zu tasks%s) and merge job %s (after every task succeeds)\n",
        array_id.c_str(), p.tasks.size(),
        o.max_parallel > 0 ? (", at most " + std::to_string(o.max_parallel) + " at once").c_str()
                           : "",
        merge_id.c_str());
  } else {
    std::printf("every unit is in the cache: submitted merge job %s\n", merge_id.c_str());
  }
  std::printf("follow: squeue -j %s%s; sacct -j %s%s; logs and scripts in %s\n",
              array_id.empty() ? "" : (array_id + ",").c_str(), merge_id.c_str(),
              array_id.empty() ? "" : (array_id + ",").c_str(), merge_id.c_str(), dir.c_str());
  std::printf(
      "report: %s/index.html when merge job %s ends; if a task fails, run this command "
      "again: it resubmits only what is missing\n",
      a.out.c_str(), merge_id.c_str());
}

void run_compare(const CompareArgs& a) {
  if (a.list_methods) {
    for (const auto& m : method_catalog())
      std::printf("%s\n", m.name.c_str());
    return;
  }
  // The command line (exit code 2 on a mistake), then the scenes, then the folders the
  // study writes, before its first pixel.
  StudyConfig c;
  FrameRange range;
  check_usage([&] {
    if (a.scenes.empty()) throw Error("compare: give at least one scene file");
    if (a.methods.empty()) throw Error("--method: give at least one method variant");
    if (a.out.empty()) throw Error("--out: give the study's folder");
    range = parse_frame_range(a.frames, "--frames");
    const Engine engine = parse_engine(a.engine);
    c.first_frame = range.first;
    c.last_frame = range.last;
    for (const auto& m : a.methods)
      c.methods.push_back(to_study(parse_method_variant(m, "--method"), engine, "--method"));
    parse_sample_counts(a.reference, "--reference");
    c.reference =
        to_study(parse_method_variant("reference --samples " + a.reference, "--reference"), engine,
                 "--reference");
    if (a.budgets != "none") {
      for (const auto& b : split(a.budgets, ',')) {
        parse_sample_counts(b, "--budgets");
        c.budgets.push_back(to_study(
            parse_method_variant("supersample --samples " + b, "--budgets"), engine, "--budgets"));
      }
    }
    if (a.target == "auto") {
      c.equal_cost_target = c.budgets.empty() ? "" : default_equal_cost_target(c.methods);
    } else if (a.target != "none") {
      if (c.budgets.empty()) throw Error("--equal-cost-target: needs --budgets");
      c.equal_cost_target = canonical_label(a.target);
    }
    for (const auto& p : a.paper_rows) {
      const size_t eq = p.find('=');
      if (eq == std::string::npos) {
        throw Error("--paper-row: expected ROW=VARIANT (got '" + p + "')");
      }
      c.paper_rows.emplace_back(canonical_label(p.substr(0, eq)),
                                canonical_label(p.substr(eq + 1)));
    }
  });
  for (const auto& path : a.scenes) {
    Scene s = load_scene(path);
    check_usage([&] {
      apply_image_size(s, a.width, a.height);
      check_frame(range.first, s, "--frames");
      check_frame(range.last, s, "--frames");
    });
    c.scenes.push_back({path, s});
  }
  // The study creates them once it has checked its configuration.
  check_output_folder(a.out, "--out");
  if (!a.cache.empty()) check_output_folder(a.cache, "--cache");
  c.out_dir = a.out;
  c.cache_dir = a.cache;
  c.threads = a.threads;
  c.display.exposure = a.exposure;
  c.display.glare = !a.no_glare;
  c.video = !a.no_video;
  c.split = a.split;
  c.command = command_line(a);

  const int modes = a.plan + (a.task >= 0) + a.merge + a.slurm.submit;
  if (modes > 1) throw UsageError("--plan, --task, --merge and --slurm: give one of them");
  if (a.task >= 0) return run_task(a, c);
  if (a.plan) return run_plan(a, c);
  if (a.slurm.submit) return submit_study(a, c);

  // The live page of the study's scenes at its size (docs/web.md), which the report links:
  // the scenes with a fixed camera and explicit waves (the page renders no other); none,
  // no page.
  web::WebPageOptions live;
  live.out_dir = (std::filesystem::path(a.out) / "web").string();
  for (const auto& s : c.scenes) {
    if (!s.scene.camera.moving() && s.scene.surface.cascades.empty())
      live.scenes.push_back({s.file, s.scene.width, s.scene.height});
  }

  ProgressBar bar("compare", !a.quiet);
  const StudyResults r =
      a.merge ? merge_study(c, progress_of(bar)) : run_study(c, progress_of(bar));
  bar.finish();
  if (!live.scenes.empty()) web::write_web_page(live, cli_path_tables().tables());

  std::printf("%-10s %-32s %9s %9s %9s %9s %10s\n", "scene", "variant", "rmse", "temporal", "near",
              "far", "ms/frame");
  for (const auto& s : r.scenes) {
    for (const auto& v : s.methods) {
      std::printf("%-10s %-32s %9.5f %9.5f %9.5f %9.5f %10.3g\n", s.name.c_str(), v.label.c_str(),
                  v.at(Region::image).rmse, v.at(Region::image).temporal_error,
                  v.at(Region::near).rmse, v.at(Region::far).rmse, v.ms_per_frame);
      for (const ClassFigures& x : v.classes) {  // --split: what the pixel sees
        if (!(x.pixel_share > 0)) continue;
        std::printf(
            "%-10s   %-30s %5.1f%% of pixels, RMSE %.3g (%.3g corrected), %4.1f%% of the "
            "squared error, temporal %.3g (%.3g corrected)\n",
            "", x.name.c_str(), 100 * x.pixel_share, x.rmse, x.rmse_corrected, 100 * x.error_share,
            x.temporal_error, x.temporal_corrected);
      }
      const auto& ch = v.at(Region::image).channels;
      if (ch.size() == 3) {  // colour: each channel's RMSE and temporal error
        std::printf("%-10s %-32s %9s R %.5f G %.5f B %.5f, temporal R %.5f G %.5f B %.5f\n", "", "",
                    "", ch[0].rmse, ch[1].rmse, ch[2].rmse, ch[0].temporal_error,
                    ch[1].temporal_error, ch[2].temporal_error);
      }
    }
  }
  std::printf("report: %s/index.html (results.json, results.csv, results.md beside it)\n",
              a.out.c_str());
  if (!live.scenes.empty()) std::printf("live page: %s/index.html\n", live.out_dir.c_str());
}

}  // namespace

void add_compare_command(CLI::App& app) {
  auto a = std::make_shared<CompareArgs>();
  CLI::App* c = app.add_subcommand(
      "compare",
      "Render methods on scenes against a cached reference and write a report (metrics, "
      "near/far water halves, equal-cost curve, pictures, videos, index.html)");
  c->add_option("scenes", a->scenes, "Scene files (sunglint-scene/1, /2 or /3 JSON)");
  c->add_option("--method,-m", a->methods,
                "A method variant 'NAME [FLAGS]' with the flags of render, e.g. -m point -m "
                "'supersample --samples 6x6x1'; repeat for each variant")
      ->take_all();
  c->add_option("--out,-o", a->out, "The study's folder (created; reused to resume)");
  c->add_option("--frames", a->frames, "Frame range A-B")->capture_default_str();
  c->add_option("--reference", a->reference,
                "Reference samples SxSxT per batch (docs/reference-renderer.md)")
      ->capture_default_str();
  c->add_option("--engine", a->engine,
                "The engine of every variant that names none: cpu, or gl (the GL engine; "
                "its variants are labelled '... --engine gl')")
      ->capture_default_str();
  c->add_option("--width", a->width, "Override the image width (height follows the aspect ratio)")
      ->check(integer_in(1, 16384));
  c->add_option("--height", a->height, "Override the image height")->check(integer_in(1, 16384));
  c->add_option("--cache", a->cache,
                "Frame cache folder (default: OUT/cache); share it between "
                "studies to reuse references");
  c->add_option("--budgets", a->budgets,
                "Supersampling budgets SxSxT of the quality-cost curve, comma-separated, in "
                "increasing cost; 'none' for no curve")
      ->capture_default_str();
  c->add_option("--equal-cost-target", a->target,
                "Method variant placed on the curve: 'auto' (staa if given, else the first "
                "method that is not reference, supersample or point, else the first that is "
                "not reference or supersample) or 'none'")
      ->capture_default_str();
  c->add_option("--paper-row", a->paper_rows,
                "Match a row of the paper's Table 1 to a variant, e.g. 'LEAN=lean --foo 2' "
                "(repeatable; default: point, supersample --samples 6x6x1, lean, staa ...)");
  c->add_option("--exposure", a->exposure, "Exposure of pictures and videos, in stops")
      ->capture_default_str()
      ->check(number_in(-64, 64));
  c->add_flag("--no-glare", a->no_glare, "Pictures and videos without glare");
  c->add_flag("--no-video", a->no_video, "No MP4 videos (they need ffmpeg)");
  c->add_flag("--split", a->split,
              "Split each method's error by what the pixel sees, frame by frame (sky, horizon, a "
              "nearer crest, over a crest, left-out waves, a tilted face, plain; docs/report.md) "
              "into results.md and results.json");
  c->add_option("--threads,-j", a->threads, "Worker threads (0: all cores)")
      ->check(integer_in(0, 1024));
  c->add_flag("--quiet,-q", a->quiet, "No progress bar");
  c->add_flag("--list-methods", a->list_methods, "Print the catalogue's method names and exit");
  // The study as tasks and on Slurm (docs/cluster.md).
  c->add_flag("--plan", a->plan,
              "Print and write (OUT/plan.json, or --plan-file) the tasks of the units not in the "
              "cache, each with its cost estimated by a pilot, and the estimated core-hours; "
              "render nothing");
  c->add_option("--task", a->task,
                "Render task K of the plan (OUT/plan.json, or --plan-file) into the cache")
      ->check(integer_in(0, 100000000));
  c->add_option("--plan-file", a->plan_file, "The plan --plan writes and --task reads");
  c->add_flag("--merge", a->merge,
              "Write the report from the cache alone (every unit rendered); render nothing");
  c->add_option("--task-seconds", a->task_seconds,
                "Group units into tasks of at least this estimated cost, core-seconds "
                "(0: one unit per task)")
      ->capture_default_str()
      ->check(number_in(0, 1e9));
  c->add_flag("--slurm", a->slurm.submit,
              "Submit the units not in the cache as one Slurm job array and a merge job that "
              "writes the report after it (afterok); print the job ids and return. Running the "
              "same command again resubmits only what is missing");
  c->add_option("--partition", a->slurm.partition,
                "--slurm: the partition (default: the cluster's)");
  c->add_option("--max-parallel", a->slurm.max_parallel,
                "--slurm: at most N tasks at once (sbatch --array=...%N; 0: no cap)")
      ->check(integer_in(0, 1000000));
  c->add_option("--time-per-task", a->slurm.time_per_task,
                "--slurm: each task's time limit in Slurm's format (default: twice the costliest "
                "task's estimate, plus 5 minutes)")
      ->check([](const std::string& t) {
        try {
          check_slurm_time(t);
        } catch (const Error& e) {
          return std::string(e.what()).substr(std::string("--time-per-task: ").size());
        }
        return std::string();
      });
  c->add_flag("--requeue", a->slurm.requeue,
              "--slurm: requeue a task that fails or is killed (twice at most)");
  c->add_flag(
      "--assume-shared", a->slurm.assume_shared,
      "--slurm: the study's folders are on a filesystem the nodes share, whatever its type");
  c->callback([a] { run_compare(*a); });
}

}  // namespace sg
