// `sunglint bench [SCENES...] --methods LIST`: time per frame of each method on each scene,
// with the reference's throughput (samples and wave evaluations per second) and each
// method's cost as a ratio to `point` on the same engine, measured in the same run
// (docs/benchmarks.md). On the CPU engine a frame's time is the wall time of the frame;
// on the GL engine (`--engine gl`) it is the GPU time of the frame's dispatch from timer
// queries (the median of the repeats after one warm-up; the upload and read-back are not
// included), with the wall time of a whole frame beside it.
#include <chrono>
#include <cstdio>
#include <memory>
#include <sstream>

#include "base/error.h"
#include "cli/args.h"
#include "cli/commands.h"
#include "cli/method_flags.h"
#include "engine/render.h"
#include "gl_engine/gl_engine.h"
#include "gl_engine/gl_method.h"
#include "methods/method.h"
#include "methods/stratified.h"

namespace sg {
namespace {

struct BenchArgs {
  std::vector<std::string> scenes;
  std::string methods = "point,reference";
  int width = 640, height = 360, frame = 0, threads = 0, repeat = 1;
  MethodFlags flags;
};

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) {
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

void run_bench(BenchArgs& a) {
  // The command line, then every scene, before the first frame is timed.
  std::vector<MethodVariant> variants;
  check_usage([&] {
    if (a.scenes.empty()) throw Error("bench: give at least one scene file");
    a.flags.finish();
    // Each item is a method name, run with the command's method flags, or a variant with
    // its own flags ("staa --footprint gaussian"), parsed as `compare` parses it.
    for (const auto& item : split(a.methods)) {
      if (item.find(' ') == std::string::npos) {
        make_method(item, a.flags.options);  // validate the name first
        check_engine_runs(a.flags.engine, item, a.flags.options, "--methods: '" + item + "': ");
        variants.push_back(MethodVariant{item, item, a.flags.options, a.flags.engine});
      } else {
        MethodVariant v = parse_method_variant(item, "--methods");
        // A variant without its own --engine runs on the command's.
        if (item.find("--engine") == std::string::npos) {
          v.engine = a.flags.engine;
          check_engine_runs(v.engine, v.name, v.options, "--methods: '" + item + "': ");
        }
        variants.push_back(v);
      }
    }
    if (variants.empty()) throw Error("--methods: give at least one method");
  });
  std::vector<Scene> scenes;
  for (const auto& path : a.scenes) {
    scenes.push_back(load_scene(path));
    check_usage([&] {
      set_image_size(scenes.back(), a.width, a.height);
      check_frame(a.frame, scenes.back(), "--frame");
    });
  }
  RenderSettings rs;
  rs.threads = a.threads;
  std::printf("| scene | method | engine | ms/frame | x point | samples/s | wave evals/s |\n");
  std::printf("|---|---|---|---:|---:|---:|---:|\n");
  for (const Scene& s : scenes) {
    SceneModel model(s);
    double point_ms[2] = {0, 0};  // per engine
    for (const MethodVariant& v : variants) {
      const std::string& n = v.name;
      const MethodOptions& vo = v.options;
      std::unique_ptr<Method> m;
      check_usage([&] { m = make_method_on(v.engine, n, vo); });
      double best = 1e300;
      if (auto* g = dynamic_cast<gl_engine::GlMethod*>(m.get())) {
        // GPU time of the dispatch; then one whole frame's wall time, for the record.
        const FrameContext ctx{model, frame_time(s, a.frame), 0};
        best = g->engine().time_dispatch(ctx, 1, std::max(3, a.repeat));
        auto t0 = std::chrono::steady_clock::now();
        render_frame(model, *m, a.frame, rs);
        const double wall =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count();
        if (n == "point" && point_ms[1] == 0) point_ms[1] = best;
        char ratio[32] = "";
        if (point_ms[1] > 0) std::snprintf(ratio, sizeof ratio, "%.2f", best / point_ms[1]);
        std::printf("| %s | %s | gl (GPU timer; frame %.1f ms) | %.2f | %s | | |\n", s.name.c_str(),
                    v.label.c_str(), wall, best, ratio);
        std::fflush(stdout);
        continue;
      }
      // A stateful method is timed on a frame that has history to resolve.
      if (m->stateful()) render_frame(model, *m, a.frame - 1, rs);
      for (int r = 0; r < std::max(1, a.repeat); ++r) {
        if (m->stateful() && r > 0) {
          m->reset();
          render_frame(model, *m, a.frame - 1, rs);
        }
        auto t0 = std::chrono::steady_clock::now();
        render_frame(model, *m, a.frame, rs);
        best = std::min(
            best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                      .count());
      }
      if (n == "point" && point_ms[0] == 0) point_ms[0] = best;
      std::string sps = "", wps = "";
      if (n == "supersample") {
        StratifiedSettings st{vo.samples, n == "supersample" && vo.samples.st == 1};
        FrameContext ctx{model, frame_time(s, a.frame), 0};
        long evals = 0;
        for (int j = 0; j < s.height; ++j) {
          for (int i = 0; i < s.width; ++i)
            evals += stratified_pixel_wave_evaluations(ctx, i, j, st);
        }
        const double samples = double(s.width) * s.height * vo.samples.sx * vo.samples.sy *
                               (st.time_at_frame ? 1 : vo.samples.st);
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.3g", samples / (best / 1000));
        sps = buf;
        std::snprintf(buf, sizeof buf, "%.3g", evals / (best / 1000));
        wps = buf;
      }
      char ratio[32] = "";
      if (point_ms[0] > 0) std::snprintf(ratio, sizeof ratio, "%.2f", best / point_ms[0]);
      std::printf("| %s | %s | cpu | %.1f | %s | %s | %s |\n", s.name.c_str(), v.label.c_str(),
                  best, ratio, sps.c_str(), wps.c_str());
      std::fflush(stdout);
    }
  }
}

}  // namespace

void add_bench_command(CLI::App& app) {
  auto a = std::make_shared<BenchArgs>();
  CLI::App* c = app.add_subcommand("bench", "Time methods on scenes (Markdown table)");
  c->add_option("scenes", a->scenes, "Scene files")->required();
  c->add_option("--methods", a->methods,
                "Comma-separated methods or variants with their own flags, e.g. "
                "\"point,staa,staa --footprint gaussian\" (put point first for ratios)")
      ->capture_default_str();
  c->add_option("--width", a->width, "Image width")
      ->capture_default_str()
      ->check(integer_in(1, 16384));
  c->add_option("--height", a->height, "Image height")
      ->capture_default_str()
      ->check(integer_in(1, 16384));
  c->add_option("--frame", a->frame, "Frame")
      ->capture_default_str()
      ->check(integer_in(0, 2000000000));
  c->add_option("--threads,-j", a->threads, "Threads (0: all)")
      ->capture_default_str()
      ->check(integer_in(0, 1024));
  c->add_option("--repeat", a->repeat, "Runs per method; the fastest counts")
      ->capture_default_str()
      ->check(integer_in(1, 1000));
  add_method_flags(*c, a->flags);
  c->callback([a] { run_bench(*a); });
}

}  // namespace sg
