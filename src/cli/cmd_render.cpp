// `sunglint render SCENE --method M --out FILE [--frame F | --frames A-B] ...`
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "base/error.h"
#include "base/output_path.h"
#include "cli/args.h"
#include "cli/commands.h"
#include "cli/method_flags.h"
#include "cli/progress.h"
#include "engine/render.h"
#include "image/image_io.h"
#include "image/sequence.h"
#include "methods/fallback.h"
#include "methods/method.h"

namespace sg {
namespace {

struct RenderArgs {
  std::string scene_path, method = "", out, frames;
  int frame = 0, width = 0, height = 0, threads = 0;
  double exposure = 0;
  bool quiet = false, mkdir = false;
  MethodFlags flags;
};

void run_render(RenderArgs& a) {
  // 1. The command line: every flag and value (exit code 2 on a mistake).
  std::unique_ptr<Method> method;
  FrameRange range{a.frame, a.frame};
  const bool sequence = !a.frames.empty();
  // A pattern names each frame; a single frame may use one too.
  const bool pattern = sequence || is_frame_pattern(a.out);
  auto out_path = [&](int f) { return pattern ? format_frame_path(a.out, f, "--out") : a.out; };
  check_usage([&] {
    if (sequence) range = parse_frame_range(a.frames, "--frames");
    image_format_of(out_path(range.first));  // a bad pattern or extension
    a.flags.finish();
    method = make_method(a.method, a.flags.options);
  });
  // 2. The scene (exit code 1 when it cannot be read or is invalid), then what the command
  // line asks of it.
  Scene scene = load_scene(a.scene_path);
  check_usage([&] {
    apply_image_size(scene, a.width, a.height);
    check_frame(range.first, scene, sequence ? "--frames" : "--frame");
    check_frame(range.last, scene, sequence ? "--frames" : "--frame");
  });
  // 3. Every output file can be written, before the first pixel.
  std::set<std::string> folders;
  for (int f = range.first; f <= range.last; ++f) {
    const std::string p = out_path(f);
    const std::string dir = std::filesystem::path(p).parent_path().string();
    if (!folders.insert(dir).second) continue;
    if (check_output_file(p, a.mkdir, " (--mkdir creates it)")) {
      std::fprintf(stderr, "sunglint: created folder '%s' (--mkdir)\n", dir.c_str());
    }
  }

  const MethodOptions& opt = a.flags.options;
  SceneModel model(scene);
  ProgressBar bar(a.method, !a.quiet);
  RenderSettings rs;
  rs.threads = a.threads;
  rs.seed = opt.seed;
  // Frames rendered: the requested ones and a stateful method's warm-up frames before them.
  const int warmup = warmup_frame_count(*method);
  const long frames = range.count() + warmup;
  long frames_done = 0, tiles = 1;
  rs.progress = [&](long done, long total) {
    tiles = total;
    bar.update(frames_done * total + done, frames * total);
    if (done == total) ++frames_done;  // calls are serialised; each frame ends once
  };
  WriteOptions wo;
  wo.exposure = a.exposure;
  long fallbacks = 0;
  bool counted = false;
  auto t0 = std::chrono::steady_clock::now();
  render_frames(model, *method, range.first, range.last, rs, [&](int f, const Image& img) {
    write_image(out_path(f), img, wo);
    std::string what = "frame " + std::to_string(f);
    if (const long n = fallback_pixels(*method); n >= 0) {
      counted = true;
      fallbacks += n;
      what += ", " + std::to_string(n) + " fallback pixels";
    }
    bar.step(what, frames_done * tiles, frames * tiles);
  });
  bar.finish();
  double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::string fb = counted ? ", " + std::to_string(fallbacks) + " fallback pixels" : "";
  std::printf("%s: %s, %dx%d, frames %d-%d%s, %.2f s (%.1f ms per frame)%s -> %s\n",
              scene.name.c_str(), method->name().c_str(), scene.width, scene.height, range.first,
              range.last,
              warmup > 0 ? (" after " + std::to_string(warmup) + " warm-up frames").c_str() : "",
              secs, 1000 * secs / frames, fb.c_str(), a.out.c_str());
}

}  // namespace

void add_render_command(CLI::App& app) {
  auto a = std::make_shared<RenderArgs>();
  std::string methods;
  for (const auto& m : method_catalog())
    methods += "\n  " + m.name + ": " + m.summary;
  CLI::App* c = app.add_subcommand("render", "Render a scene with one method");
  c->add_option("scene", a->scene_path, "Scene file (sunglint-scene/1 JSON)")->required();
  c->add_option("--method,-m", a->method, "Rendering method:" + methods)->required();
  c->add_option("--out,-o", a->out,
                "Output file; the format follows the extension (.exr, .pfm, .png). With "
                "--frames, a pattern such as out/frame_%04d.exr. Its folder must exist, or "
                "give --mkdir")
      ->required();
  c->add_flag("--mkdir", a->mkdir, "Create the output's folder when it is missing");
  auto* frame = c->add_option("--frame,-f", a->frame, "Frame to render (default 0)")
                    ->check(integer_in(0, 2000000000));
  c->add_option("--frames", a->frames, "Render a range of frames A-B (use a pattern in --out)")
      ->excludes(frame);
  c->add_option("--width", a->width,
                "Override the image width (height follows the aspect "
                "ratio unless given)")
      ->check(integer_in(1, 16384));
  c->add_option("--height", a->height, "Override the image height")->check(integer_in(1, 16384));
  c->add_option("--threads,-j", a->threads, "Worker threads (0: all cores)")
      ->check(integer_in(0, 1024));
  add_method_flags(*c, a->flags);
  c->add_option("--exposure", a->exposure, "Exposure in stops for .png output")
      ->capture_default_str()
      ->check(number_in(-64, 64));
  c->add_flag("--quiet,-q", a->quiet,
              "No progress (default: a bar on a terminal, else a line per frame)");
  c->callback([a] { run_render(*a); });
}

}  // namespace sg
