// `sunglint render SCENE --method M --out FILE [--frame F | --frames A-B] ...`, and
// `--frames A-B --video out.mp4` (with or without --out): the range rendered and encoded
// in one command. `--display` writes PNG pictures through the display pipeline of
// `compare` (exposure, glare, filmic curve; image/tonemap.h), as videos always are.
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
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
#include "image/tonemap.h"
#include "methods/method.h"
#include "report/video.h"

namespace sg {
namespace {

struct RenderArgs {
  std::string scene_path, method = "", out, frames, video;
  int frame = 0, width = 0, height = 0, threads = 0;
  double exposure = 0;
  bool quiet = false, display = false, no_glare = false;
  MethodFlags flags;
};

std::string lower_extension(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  for (char& c : e)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

// The combinations of outputs and display flags, checked before anything is rendered.
void check_outputs(const RenderArgs& a, bool sequence, const std::string& first_out) {
  if (a.out.empty() && a.video.empty()) {
    throw Error("--out: required (or --video FILE.mp4 with --frames A-B)");
  }
  if (!a.video.empty()) {
    if (!sequence) throw Error("--video: needs --frames A-B (the frames of the video)");
    if (lower_extension(a.video) != ".mp4") {
      throw Error("--video: must be an .mp4 file (got '" + a.video + "')");
    }
    const std::filesystem::path dir = std::filesystem::path(a.video).parent_path();
    if (!dir.empty() && !std::filesystem::is_directory(dir)) {
      throw Error("--video: folder '" + dir.string() + "' does not exist");
    }
  }
  if (!a.out.empty()) {
    const ImageFormat f = image_format_of(first_out);  // fails early on a bad extension
    if (a.display && f != ImageFormat::png) {
      throw Error("--display: applies to .png output (got '" + a.out +
                  "'; .exr and .pfm keep the linear values)");
    }
  }
  if (a.no_glare && !a.display && a.video.empty()) {
    throw Error("--no-glare: needs --display or --video");
  }
}

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
  check_outputs(a, sequence, a.out.empty() ? "" : out_path(range.first));
  if (!a.video.empty()) {
    try {
      check_ffmpeg();
    } catch (const Error& e) {
      throw Error("--video: " + std::string(e.what()));
    }
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
  DisplaySettings display;
  display.exposure = a.exposure;
  display.glare = !a.no_glare;
  WriteOptions wo;
  wo.exposure = a.exposure;
  if (a.display) wo.display = display;
  std::vector<std::vector<uint8_t>> video_frames;
  auto t0 = std::chrono::steady_clock::now();
  render_frames(model, *method, range.first, range.last, rs, [&](int f, const Image& img) {
    if (!a.out.empty()) write_image(out_path(f), img, wo);
    if (!a.video.empty()) video_frames.push_back(display_srgb8(img, display));
  });
  bar.finish();
  double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!a.video.empty()) {
    if (scene.grey()) {
      encode_h264(a.video, scene.width, scene.height, scene.animation.fps, video_frames);
    } else {
      encode_h264_rgb(a.video, scene.width, scene.height, scene.animation.fps, video_frames);
    }
  }
  const std::string written = a.out.empty()     ? a.video
                              : a.video.empty() ? a.out
                                                : a.out + " and " + a.video;
  std::printf("%s: %s, %dx%d, frames %d-%d%s, %.2f s (%.1f ms per frame) -> %s\n",
              scene.name.c_str(), method->name().c_str(), scene.width, scene.height, range.first,
              range.last,
              warmup > 0 ? (" after " + std::to_string(warmup) + " warm-up frames").c_str() : "",
              secs, 1000 * secs / frames, written.c_str());
}

}  // namespace

void add_render_command(CLI::App& app) {
  auto a = std::make_shared<RenderArgs>();
  std::string methods;
  for (const auto& m : method_catalog())
    methods += "\n  " + m.name + ": " + m.summary;
  CLI::App* c = app.add_subcommand("render", "Render a scene with one method");
  c->add_option("scene", a->scene_path, "Scene file (sunglint-scene/1 or /2 JSON)")->required();
  c->add_option("--method,-m", a->method, "Rendering method:" + methods)->required();
  c->add_option("--out,-o", a->out,
                "Output file; the format follows the extension (.exr, .pfm, .png). With "
                "--frames, a pattern such as out/frame_%04d.exr. Required unless --video is "
                "given");
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
  add_method_flags(*c, a->flags);
  c->add_option("--exposure", a->exposure, "Exposure in stops for .png output and --video")
      ->capture_default_str();
  c->add_flag("--display", a->display,
              ".png output through the display pipeline of compare: exposure, glare, filmic "
              "tone curve (default: exposure and a clamp)");
  c->add_flag("--no-glare", a->no_glare, "--display and --video without glare");
  c->add_option("--video", a->video,
                "Also (or only) encode the --frames range as an H.264 .mp4 video through the "
                "display pipeline (needs ffmpeg)");
  c->add_flag("--quiet,-q", a->quiet, "No progress bar");
  c->callback([a] { run_render(*a); });
}

}  // namespace sg
