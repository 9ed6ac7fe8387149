// `sunglint compare SCENES... -m VARIANT [-m VARIANT ...] --out DIR`: the study a user runs
// to see and trust the result (report/study.h; docs/report.md). This file only turns the
// command line into a StudyConfig and shows progress.
//
// Method variants are given one per -m/--method option, as "NAME [FLAGS]" with the
// flags of `render` ("supersample --samples 6x6x1"): each variant is one shell word, so
// no separator can collide with a flag's value.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

#include "base/error.h"
#include "base/output_path.h"
#include "cli/args.h"
#include "cli/commands.h"
#include "cli/method_flags.h"
#include "cli/progress.h"
#include "gl_engine/engines.h"
#include "methods/method.h"
#include "report/cache.h"
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
  bool no_video = false, no_glare = false, quiet = false, list_methods = false;
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
  StudyVariant s{canonical_label(v.label), v.name, v.options, {}};
  if (v.engine != Engine::cpu) {
    s.make = [e = v.engine, n = v.name, o = v.options] { return make_method_on(e, n, o); };
  }
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
  return c + " --out " + quote(a.out);
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
  c.command = command_line(a);

  // The live page of the study's scenes at its size (docs/web.md), which the report links.
  web::WebPageOptions live;
  live.out_dir = (std::filesystem::path(a.out) / "web").string();
  for (const auto& s : c.scenes)
    live.scenes.push_back({s.file, s.scene.width, s.scene.height});

  ProgressBar bar("compare", !a.quiet);
  std::string last;
  const StudyResults r = run_study(c, [&](double f, const std::string& what) {
    std::string label = what.size() > 36 ? what.substr(0, 35) + "~" : what;
    label.resize(36, ' ');
    bar.set_label("compare " + label);
    // In a log, one line as each piece of work starts (a method on a scene, the pictures).
    if (what != last) {
      bar.step("", static_cast<long>(f * 100000), 100000);
      last = what;
    } else {
      bar.update(static_cast<long>(f * 100000), 100000);
    }
  });
  bar.finish();
  web::write_web_page(live);

  std::printf("%-10s %-32s %9s %9s %9s %9s %10s\n", "scene", "variant", "rmse", "temporal", "near",
              "far", "ms/frame");
  for (const auto& s : r.scenes) {
    for (const auto& v : s.methods) {
      std::printf("%-10s %-32s %9.5f %9.5f %9.5f %9.5f %10.3g\n", s.name.c_str(), v.label.c_str(),
                  v.at(Region::image).rmse, v.at(Region::image).temporal_error,
                  v.at(Region::near).rmse, v.at(Region::far).rmse, v.ms_per_frame);
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
  std::printf("live page: %s/index.html\n", live.out_dir.c_str());
}

}  // namespace

void add_compare_command(CLI::App& app) {
  auto a = std::make_shared<CompareArgs>();
  CLI::App* c = app.add_subcommand(
      "compare",
      "Render methods on scenes against a cached reference and write a report (metrics, "
      "near/far water halves, equal-cost curve, pictures, videos, index.html)");
  c->add_option("scenes", a->scenes, "Scene files (sunglint-scene/1 or /2 JSON)");
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
  c->add_option("--threads,-j", a->threads, "Worker threads (0: all cores)")
      ->check(integer_in(0, 1024));
  c->add_flag("--quiet,-q", a->quiet, "No progress bar");
  c->add_flag("--list-methods", a->list_methods, "Print the catalogue's method names and exit");
  c->callback([a] { run_compare(*a); });
}

}  // namespace sg
