// `sunglint render SCENE --method M --out FILE [--frame F | --frames A-B] ...`, and
// `--frames A-B --video out.mp4` (with or without --out): the range rendered and encoded
// in one command. `--display` writes PNG pictures through the display pipeline of
// `compare` (exposure, glare, filmic curve; image/tonemap.h), as videos always are.
// `--engine gl` renders the kernel methods on the GPU (gl_engine/gl_engine.h).
// Everything the command line asks is checked before the first pixel.
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "base/atomic_file.h"
#include "base/error.h"
#include "base/output_path.h"
#include "cli/args.h"
#include "cli/commands.h"
#include "cli/method_flags.h"
#include "cli/progress.h"
#include "cli/slurm.h"
#include "engine/render.h"
#include "gl_engine/engines.h"
#include "image/image_io.h"
#include "image/sequence.h"
#include "image/tonemap.h"
#include "methods/fallback.h"
#include "methods/method.h"
#include "methods/reference.h"
#include "report/video.h"

namespace sg {
namespace {

struct RenderArgs {
  std::string scene_path, method = "", out, frames, video, variance_out;
  int frame = 0, width = 0, height = 0, threads = 0;
  double exposure = 0;
  bool quiet = false, mkdir = false, display = false, no_glare = false;
  MethodFlags flags;
  SlurmOptions slurm;  // --slurm: the frames as a job array (docs/cluster.md)
};

// `render --frames A-B --slurm`: the frames whose file is missing as one Slurm job array,
// element K rendering frame A + K (a stateful method: one element, the whole range, its
// history whole); prints the job id and returns.
void submit_frames(const RenderArgs& a, const FrameRange& range, bool stateful,
                   const std::function<std::string(int)>& out_path) {
  namespace fs = std::filesystem;
  const SlurmOptions& o = a.slurm;
  require_program("sbatch", "--slurm");
  const std::string exe = program_path();
  const std::string folder = fs::path(fs::absolute(out_path(range.first))).parent_path().string();
  const std::string shared =
      check_shared_folders({{"--out", folder},
                            {"the working folder", fs::current_path().string()},
                            {"the program", exe},
                            {"the scene", a.scene_path}},
                           o.partition, o.assume_shared);
  std::printf("shared folders: %s\n", shared.c_str());
  std::vector<int> missing;
  std::error_code ec;
  for (int f = range.first; f <= range.last; ++f) {
    if (!fs::exists(out_path(f), ec)) missing.push_back(f - range.first);
  }
  if (missing.empty()) {
    std::printf("every frame of %d-%d is there (%s ...): nothing to submit\n", range.first,
                range.last, out_path(range.first).c_str());
    return;
  }
  static const std::map<std::string, int> drop{
      {"--slurm", 0},         {"--partition", 1}, {"--max-parallel", 1},
      {"--time-per-task", 1}, {"--requeue", 0},   {"--assume-shared", 0},
      {"--frames", 1},        {"--threads", 1},   {"-j", 1},
      {"--quiet", 0},         {"-q", 0}};
  const std::vector<std::string> args = arguments_without(program_arguments(), drop);
  std::vector<std::string> base{exe};
  base.insert(base.end(), args.begin() + (args.empty() ? 0 : 1), args.end());
  const std::string frame =
      stateful ? "--frames " + std::to_string(range.first) + "-" + std::to_string(range.last)
               : "--frame \"$((" + std::to_string(range.first) + " + SLURM_ARRAY_TASK_ID))\"";
  if (stateful) missing = {0};
  const std::string dir = next_submission_dir((fs::path(folder) / "slurm").string());
  const int cpus = a.threads > 0 ? a.threads : 1;
  const std::map<std::string, std::string> v{
      {"KIND", "render"},
      {"WHAT", stateful ? "the whole range (a stateful method)"
                        : "frame " + std::to_string(range.first) + " + K of the range"},
      {"JOB_NAME", "sunglint-render"},
      {"ARRAY", array_spec(missing, o.max_parallel)},
      {"WORK_DIR", fs::current_path().string()},
      {"LOG_DIR", dir},
      {"TIME", o.time_per_task.empty() ? "1:00:00" : o.time_per_task},
      {"CPUS", std::to_string(cpus)},
      {"PARTITION", o.partition},
      {"REQUEUE", o.requeue ? "--requeue" : "--no-requeue"},
      {"RETRIES", std::to_string(o.requeue ? o.retries : 0)},
      {"TASK_COMMAND", shell_join(base) + " -q -j \"${SLURM_CPUS_PER_TASK:-1}\" " + frame}};
  const std::string script = (fs::path(dir) / "array.sh").string();
  write_file_atomic(script, fill_template(slurm_template("slurm-array.sh"), v, "slurm-array.sh"));
  const std::vector<std::string> sb{"sbatch", "--parsable", script};
  const std::string id = job_id(run_slurm(sb, "--slurm"), sb);
  std::printf(
      "submitted job array %s: %zu of frames %d-%d (%s each)\nfollow: squeue -j %s; "
      "sacct -j %s; logs and script in %s; run this command again to resubmit the "
      "frames still missing\n",
      id.c_str(), stateful ? size_t(range.count()) : missing.size(), range.first, range.last,
      v.at("TIME").c_str(), id.c_str(), id.c_str(), dir.c_str());
}

std::string lower_extension(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  for (char& c : e)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

// The combinations of outputs and display flags (usage errors).
void check_outputs(const RenderArgs& a, bool sequence, const std::string& first_out) {
  if (a.out.empty() && a.video.empty()) {
    throw Error("--out: required (or --video FILE.mp4 with --frames A-B)");
  }
  if (!a.video.empty()) {
    if (!sequence) throw Error("--video: needs --frames A-B (the frames of the video)");
    if (lower_extension(a.video) != ".mp4") {
      throw Error("--video: must be an .mp4 file (got '" + a.video + "')");
    }
  }
  if (!a.out.empty()) {
    const ImageFormat f = image_format_of(first_out);  // a bad pattern or extension
    if (a.display && f != ImageFormat::png) {
      throw Error("--display: applies to .png output (got '" + a.out +
                  "'; .exr and .pfm keep the linear values)");
    }
  }
  if (!a.variance_out.empty()) {
    const std::string first = is_frame_pattern(a.variance_out) || sequence
                                  ? format_frame_path(a.variance_out, 0, "--variance-out")
                                  : a.variance_out;
    if (image_format_of(first) == ImageFormat::png) {
      throw Error("--variance-out: must be .exr or .pfm (got '" + a.variance_out + "')");
    }
  }
  if (a.no_glare && !a.display && a.video.empty()) {
    throw Error("--no-glare: needs --display or --video");
  }
}

void run_render(RenderArgs& a) {
  // 1. The command line: every flag and value (exit code 2 on a mistake).
  std::unique_ptr<Method> method;
  FrameRange range{a.frame, a.frame};
  const bool sequence = !a.frames.empty();
  // A pattern names each frame; a single frame may use one too.
  const bool pattern = sequence || is_frame_pattern(a.out);
  auto out_path = [&](int f) { return pattern ? format_frame_path(a.out, f, "--out") : a.out; };
  auto variance_path = [&](int f) {
    return pattern ? format_frame_path(a.variance_out, f, "--variance-out") : a.variance_out;
  };
  check_usage([&] {
    if (sequence) range = parse_frame_range(a.frames, "--frames");
    check_outputs(a, sequence, a.out.empty() ? "" : out_path(range.first));
    if (a.slurm.submit) {
      if (!sequence || a.out.empty()) throw Error("--slurm: needs --frames A-B and --out PATTERN");
      if (!a.video.empty()) {
        throw Error("--slurm: not with --video (encode the frames once they are rendered)");
      }
    }
    a.flags.finish();
    make_method(a.method, a.flags.options);  // the name and options, before any GL
    a.flags.check_taken_by({a.method});
    check_engine_runs(a.flags.engine, a.method, a.flags.options);
  });
  const Engine engine = a.flags.engine;
  if (!a.video.empty()) {
    try {
      check_ffmpeg();
    } catch (const Error& e) {
      throw Error("--video: " + std::string(e.what()));
    }
  }
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
  auto check_file = [&](const std::string& p, const char* flag) {
    const std::string dir = std::filesystem::path(p).parent_path().string();
    if (!folders.insert(dir).second) return;
    try {
      if (check_output_file(p, a.mkdir, " (--mkdir creates it)")) {
        std::fprintf(stderr, "sunglint: created folder '%s' (--mkdir)\n", dir.c_str());
      }
    } catch (const Error& e) {
      throw Error(std::string(flag) + ": " + e.what());
    }
  };
  if (!a.out.empty()) {
    for (int f = range.first; f <= range.last; ++f)
      check_file(out_path(f), "--out");
  }
  if (!a.video.empty()) check_file(a.video, "--video");
  if (!a.variance_out.empty()) {
    for (int f = range.first; f <= range.last; ++f)
      check_file(variance_path(f), "--variance-out");
  }
  // 4. The method on its engine (the GL engine refuses what it lacks, or says why no
  // OpenGL 4.5 context can be made).
  check_usage([&] { method = make_method_on(engine, a.method, a.flags.options); });
  if (!a.variance_out.empty() && method->pixel_variance() == nullptr) {
    throw UsageError("--variance-out: method " + a.method + " on the " + engine_name(engine) +
                     " engine does not measure its noise (the CPU reference does)");
  }

  if (a.slurm.submit) return submit_frames(a, range, method->stateful(), out_path);

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
  DisplaySettings display;
  display.exposure = a.exposure;
  display.glare = !a.no_glare;
  WriteOptions wo;
  wo.exposure = a.exposure;
  if (a.display) wo.display = display;
  std::vector<std::vector<uint8_t>> video_frames;
  long fallbacks = 0;
  bool counted = false;
  // A method that measures its own noise (reference): the mean variance over the frames.
  double variance_sum = 0;
  int variance_frames = 0;
  auto t0 = std::chrono::steady_clock::now();
  render_frames(model, *method, range.first, range.last, rs, [&](int f, const Image& img) {
    if (!a.out.empty()) write_image(out_path(f), img, wo);
    if (!a.video.empty()) video_frames.push_back(display_srgb8(img, display));
    std::string what = "frame " + std::to_string(f);
    if (const long n = fallback_pixels(*method); n >= 0) {
      counted = true;
      fallbacks += n;
      what += ", " + std::to_string(n) + " fallback pixels";
    }
    if (const Image* v = method->pixel_variance()) {
      const double se = image_standard_error(*v);
      variance_sum += sqr(se);
      ++variance_frames;
      char buf[64];
      std::snprintf(buf, sizeof buf, ", standard error %.3g", se);
      what += buf;
      if (!a.variance_out.empty()) write_image(variance_path(f), *v, WriteOptions{});
    }
    bar.step(what, frames_done * tiles, frames * tiles);
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
  const std::string fb = counted ? ", " + std::to_string(fallbacks) + " fallback pixels" : "";
  std::printf("%s: %s (%s engine), %dx%d, frames %d-%d%s, %.2f s (%.1f ms per frame)%s -> %s\n",
              scene.name.c_str(), method->name().c_str(), engine_name(engine), scene.width,
              scene.height, range.first, range.last,
              warmup > 0 ? (" after " + std::to_string(warmup) + " warm-up frames").c_str() : "",
              secs, 1000 * secs / frames, fb.c_str(), written.c_str());
  if (variance_frames > 0) {
    // Batches that agree in every pixel measure no noise: either there is none, or a rare
    // bright sample (a glint) that no batch drew would not show in them.
    const char* unmeasured =
        variance_sum > 0 ? ""
                         : "; the batches agree in every pixel, so a rare bright sample that none "
                           "of them drew (a glint) would not show in it: more --samples or "
                           "--batches measure it";
    std::printf("%s: standard error %.3g (RMSE units, RMS over %d frame%s)%s\n",
                method->name().c_str(), std::sqrt(variance_sum / variance_frames), variance_frames,
                variance_frames > 1 ? "s" : "", unmeasured);
  }
}

}  // namespace

void add_render_command(CLI::App& app) {
  auto a = std::make_shared<RenderArgs>();
  std::string methods;
  for (const auto& m : method_catalog())
    methods += "\n  " + m.name + ": " + m.summary;
  CLI::App* c = app.add_subcommand("render", "Render a scene with one method");
  c->add_option("scene", a->scene_path, "Scene file (sunglint-scene/1, /2 or /3 JSON)")->required();
  c->add_option("--method,-m", a->method, "Rendering method:" + methods)->required();
  c->add_option("--out,-o", a->out,
                "Output file; the format follows the extension (.exr, .pfm, .png). With "
                "--frames, a pattern such as out/frame_%04d.exr. Its folder must exist, or "
                "give --mkdir. Required unless --video is given");
  c->add_flag("--mkdir", a->mkdir, "Create the output's (and the video's) folder when missing");
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
  c->add_option("--variance-out", a->variance_out,
                "reference: also write each pixel's variance (of its estimate) to this file "
                "(.exr or .pfm; a pattern with --frames)");
  add_method_flags(*c, a->flags);
  c->add_option("--exposure", a->exposure, "Exposure in stops for .png output and --video")
      ->capture_default_str()
      ->check(number_in(-64, 64));
  c->add_flag("--display", a->display,
              ".png output through the display pipeline of compare: exposure, glare, filmic "
              "tone curve (default: exposure and a clamp)");
  c->add_flag("--no-glare", a->no_glare, "--display and --video without glare");
  c->add_option("--video", a->video,
                "Also (or only) encode the --frames range as an H.264 .mp4 video through the "
                "display pipeline (needs ffmpeg)");
  c->add_flag("--quiet,-q", a->quiet,
              "No progress (default: a bar on a terminal, else a line per frame)");
  c->add_flag("--slurm", a->slurm.submit,
              "Submit the --frames range as a Slurm job array, one frame a task (the frames "
              "whose file is missing; docs/cluster.md); print the job id and return");
  c->add_option("--partition", a->slurm.partition, "--slurm: the partition");
  c->add_option("--max-parallel", a->slurm.max_parallel, "--slurm: at most N tasks at once")
      ->check(integer_in(0, 1000000));
  c->add_option("--time-per-task", a->slurm.time_per_task,
                "--slurm: each task's time limit in Slurm's format (default 1:00:00)")
      ->check([](const std::string& t) {
        try {
          check_slurm_time(t);
        } catch (const Error& e) {
          return std::string(e.what()).substr(std::string("--time-per-task: ").size());
        }
        return std::string();
      });
  c->add_flag("--requeue", a->slurm.requeue, "--slurm: requeue a task that fails (twice at most)");
  c->add_flag("--assume-shared", a->slurm.assume_shared,
              "--slurm: the folders are on a filesystem the nodes share, whatever its type");
  c->callback([a] { run_render(*a); });
}

}  // namespace sg
