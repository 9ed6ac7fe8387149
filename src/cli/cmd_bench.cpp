// `sunglint bench [SCENES...] --methods LIST`: time per frame of each method on each scene,
// with the sampling methods' throughput (samples per second; wave evaluations per second
// for supersample) and each method's cost as a ratio to `point` on the same engine,
// measured in the same run (docs/benchmarks.md). On the CPU engine a frame's time is the
// wall time of the frame (the fastest of --repeat); on the GL engine (`--engine gl`) it is
// the GPU time of the frame's dispatch from timer queries, with the wall time of the whole
// frame around it (upload, dispatch, read-back) beside it, both the medians of the same
// repeats after one warm-up, so the GPU time never exceeds the frame's. The GL program's
// compilation happens before the warm-up and is not timed (gl_engine/program_notice.h).
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
#include "methods/kernel_counts.h"
#include "methods/method.h"
#include "methods/reference.h"
#include "methods/stratified.h"

namespace sg {
namespace {

struct BenchArgs {
  std::vector<std::string> scenes;
  std::string methods = "point,reference";
  int width = 640, height = 360, frame = 0, threads = 0, repeat = 1;
  bool counters = false;
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

// The samples a method takes in a frame (point: one per pixel; supersample: its
// positions and times; reference without --adaptive: every batch's) and, for supersample,
// the wave evaluations; 0 where it is not a sampling method or the count varies per pixel
// (the adaptive reference).
struct Throughput {
  double samples = 0, wave_evaluations = 0;
};
Throughput throughput(const FrameContext& ctx, const std::string& name, const MethodOptions& o) {
  const double pixels = double(ctx.model.width()) * ctx.model.height();
  Throughput t;
  if (name == "point") {
    t.samples = pixels;
  } else if (name == "supersample") {
    const StratifiedSettings st{o.samples, o.samples.st == 1};
    t.samples = pixels * o.samples.sx * o.samples.sy * (st.time_at_frame ? 1 : o.samples.st);
    for (int j = 0; j < ctx.model.height(); ++j) {
      for (int i = 0; i < ctx.model.width(); ++i)
        t.wave_evaluations += double(stratified_pixel_wave_evaluations(ctx, i, j, st));
    }
  } else if (name == "reference") {
    const ReferenceSettings rs = reference_settings(o);
    if (!rs.adaptive) t.samples = pixels * rs.batches * double(rs.samples.total());
  }
  return t;
}

// --counters: per scene and method, the kernel's work per pixel (mean / max, counted by
// the counting build of the kernel: methods/kernel_counts.h) and the predicted time of a
// 1920x1080 frame on an H200 from those counts and its peak rates (a lower bound).
void print_counters(const std::vector<Scene>& scenes, const std::vector<MethodVariant>& variants,
                    int frame) {
  std::printf(
      "| scene | method | waves | buffer fetches | table fetches | quadrature nodes | "
      "transcendentals | march steps | predicted 1920x1080 on %s, ms (means / maxima) |\n",
      kH200.name);
  std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const Scene& s : scenes) {
    const SceneModel model(s);
    for (const MethodVariant& v : variants) {
      const KernelWork k = count_kernel_work(model, v.name, v.options, frame);
      auto cell = [](const KernelWork::Stat& st) {
        char b[64];
        std::snprintf(b, sizeof b, "%.1f / %llu", st.mean, static_cast<unsigned long long>(st.max));
        return std::string(b);
      };
      const long hd = 1920L * 1080L;
      std::printf("| %s | %s | %s | %s | %s | %s | %s | %s | %.3g / %.3g |\n", s.name.c_str(),
                  v.label.c_str(), cell(k.waves).c_str(), cell(k.buffer_fetches).c_str(),
                  cell(k.table_fetches).c_str(), cell(k.nodes).c_str(),
                  cell(k.transcendentals).c_str(), cell(k.march_steps).c_str(),
                  predicted_frame_ms(k, hd, kH200, false), predicted_frame_ms(k, hd, kH200, true));
      if (k.host_finished > 0) {
        std::printf(
            "|  | (%ld pixels left to the host's exact finish, not counted) | | | | | | | |\n",
            k.host_finished);
      }
      std::fflush(stdout);
    }
  }
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
    // The command's method flags configure the plain names of --methods (a variant with
    // flags of its own takes only those): each flag must configure one of them.
    std::vector<std::string> plain;
    for (const auto& item : split(a.methods)) {
      if (item.find(' ') == std::string::npos) plain.push_back(item);
    }
    a.flags.check_taken_by(plain);
  });
  std::vector<Scene> scenes;
  for (const auto& path : a.scenes) {
    scenes.push_back(load_scene(path));
    check_usage([&] {
      set_image_size(scenes.back(), a.width, a.height);
      check_frame(a.frame, scenes.back(), "--frame");
    });
  }
  if (a.counters) {
    check_usage([&] {
      for (const MethodVariant& v : variants) {
        if (!kernel_work_counted(v.name)) {
          throw Error(
              "--counters: no counting render for '" + v.label +
              "' (point, supersample, staa-temporal, staa, specaa, microspec, bruneton, lean and "
              "taa have one)");
        }
      }
    });
    print_counters(scenes, variants, a.frame);
    return;
  }
  RenderSettings rs;
  rs.threads = a.threads;
  std::printf("| scene | method | engine | ms/frame | x point | samples/s | wave evals/s |\n");
  std::printf("|---|---|---|---:|---:|---:|---:|\n");
  for (const Scene& s : scenes) {
    SceneModel model(s);
    const FrameContext ctx{model, frame_time(s, a.frame), 0};
    double point_ms[2] = {0, 0};  // per engine
    for (const MethodVariant& v : variants) {
      const std::string& n = v.name;
      const MethodOptions& vo = v.options;
      std::unique_ptr<Method> m;
      check_usage([&] { m = make_method_on(v.engine, n, vo); });
      double best = 1e300;
      std::string engine = "cpu";
      if (auto* g = dynamic_cast<gl_engine::GlMethod*>(m.get())) {
        // Per frame the GPU time of its dispatch and the wall time of the whole frame
        // around it (upload, dispatch, read-back); the medians after one warm-up.
        const gl_engine::GlEngine::FrameTimes t =
            g->engine().time_frames(ctx, 1, std::max(3, a.repeat));
        best = t.gpu_ms;
        char buf[64];
        std::snprintf(buf, sizeof buf, "gl (GPU timer; frame %.1f ms)", t.frame_ms);
        engine = buf;
      } else {
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
      }
      const int e = v.engine == Engine::gl ? 1 : 0;
      if (n == "point" && point_ms[e] == 0) point_ms[e] = best;
      const Throughput tp = throughput(ctx, n, vo);
      char ratio[32] = "-", sps[32] = "-", wps[32] = "-";
      if (point_ms[e] > 0) std::snprintf(ratio, sizeof ratio, "%.2f", best / point_ms[e]);
      if (tp.samples > 0) std::snprintf(sps, sizeof sps, "%.3g", tp.samples / (best / 1000));
      if (tp.wave_evaluations > 0) {
        std::snprintf(wps, sizeof wps, "%.3g", tp.wave_evaluations / (best / 1000));
      }
      std::printf("| %s | %s | %s | %.2f | %s | %s | %s |\n", s.name.c_str(), v.label.c_str(),
                  engine.c_str(), best, ratio, sps, wps);
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
  c->add_flag("--counters", a->counters,
              "Count the kernel's work per pixel instead of timing (waves visited, texel "
              "fetches, quadrature nodes, transcendentals, march steps; point, supersample, "
              "staa-temporal, staa, specaa, microspec, bruneton, lean, taa) with a predicted "
              "1920x1080 time on an "
              "H200");
  add_method_flags(*c, a->flags);
  c->callback([a] { run_bench(*a); });
}

}  // namespace sg
