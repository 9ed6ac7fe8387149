// `sunglint render SCENE --method M --out FILE [--frame F | --frames A-B] ...`
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "base/error.h"
#include "cli/args.h"
#include "cli/commands.h"
#include "cli/method_flags.h"
#include "cli/progress.h"
#include "engine/render.h"
#include "image/image_io.h"
#include "image/sequence.h"
#include "methods/method.h"
#include "methods/reference.h"

namespace sg {
namespace {

struct RenderArgs {
  std::string scene_path, method = "", out, frames, variance_out;
  int frame = 0, width = 0, height = 0, threads = 0;
  double exposure = 0;
  bool quiet = false;
  MethodFlags flags;
};

void run_render(RenderArgs& a) {
  Scene scene = load_scene(a.scene_path);
  apply_image_size(scene, a.width, a.height);
  FrameRange range{a.frame, a.frame};
  const bool sequence = !a.frames.empty();
  if (sequence) range = parse_frame_range(a.frames, "--frames");
  check_frame(range.first, scene, sequence ? "--frames" : "--frame");
  check_frame(range.last, scene, sequence ? "--frames" : "--frame");
  // A pattern names each frame; a single frame may use one too.
  const bool pattern = sequence || is_frame_pattern(a.out);
  auto out_path = [&](int f) { return pattern ? format_frame_path(a.out, f, "--out") : a.out; };
  image_format_of(out_path(range.first));  // fails early on a bad pattern or extension
  if (!a.variance_out.empty()) {
    image_format_of(pattern ? format_frame_path(a.variance_out, range.first, "--variance-out")
                            : a.variance_out);
  }

  a.flags.finish();
  const MethodOptions& opt = a.flags.options;
  std::unique_ptr<Method> method = make_method(a.method, opt);
  SceneModel model(scene);

  ProgressBar bar(a.method, !a.quiet);
  RenderSettings rs;
  rs.threads = a.threads;
  rs.seed = opt.seed;
  // Frames rendered: the requested ones and a stateful method's warm-up frames before them.
  const int warmup = warmup_frame_count(*method);
  const long frames = range.count() + warmup;
  long frames_done = 0;
  rs.progress = [&](long done, long total) {
    bar.update(frames_done * total + done, frames * total);
    if (done == total) ++frames_done;  // calls are serialised; each frame ends once
  };
  WriteOptions wo;
  wo.exposure = a.exposure;
  auto t0 = std::chrono::steady_clock::now();
  // A method that measures its own noise (reference): the mean variance over the frames.
  double variance_sum = 0;
  int variance_frames = 0;
  render_frames(model, *method, range.first, range.last, rs, [&](int f, const Image& img) {
    write_image(out_path(f), img, wo);
    if (const Image* v = method->pixel_variance()) {
      variance_sum += sqr(image_standard_error(*v));
      ++variance_frames;
      if (!a.variance_out.empty()) {
        write_image(pattern ? format_frame_path(a.variance_out, f, "--variance-out") : a.variance_out,
                    *v, WriteOptions{});
      }
    }
  });
  bar.finish();
  double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("%s: %s, %dx%d, frames %d-%d%s, %.2f s (%.1f ms per frame) -> %s\n",
              scene.name.c_str(), method->name().c_str(), scene.width, scene.height, range.first,
              range.last,
              warmup > 0 ? (" after " + std::to_string(warmup) + " warm-up frames").c_str() : "",
              secs, 1000 * secs / frames, a.out.c_str());
  if (variance_frames > 0) {
    std::printf("%s: standard error %.3g (RMSE units, RMS over %d frame%s)\n",
                method->name().c_str(), std::sqrt(variance_sum / variance_frames), variance_frames,
                variance_frames > 1 ? "s" : "");
  }
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
                "--frames, a pattern such as out/frame_%04d.exr")
      ->required();
  auto* frame = c->add_option("--frame,-f", a->frame, "Frame to render (default 0)");
  c->add_option("--frames", a->frames, "Render a range of frames A-B (use a pattern in --out)")
      ->excludes(frame);
  c->add_option("--width", a->width,
                "Override the image width (height follows the aspect "
                "ratio unless given)")
      ->check(CLI::Range(1, 16384));
  c->add_option("--height", a->height, "Override the image height")->check(CLI::Range(1, 16384));
  c->add_option("--threads,-j", a->threads, "Worker threads (0: all cores)")
      ->check(CLI::Range(0, 1024));
  c->add_option("--variance-out", a->variance_out,
                "reference: also write each pixel's variance (of its estimate) to this file "
                "(.exr or .pfm; a pattern with --frames)");
  add_method_flags(*c, a->flags);
  c->add_option("--exposure", a->exposure, "Exposure in stops for .png output")
      ->capture_default_str();
  c->add_flag("--quiet,-q", a->quiet, "No progress bar");
  c->callback([a] { run_render(*a); });
}

}  // namespace sg
