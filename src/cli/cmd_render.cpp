// `sunglint render SCENE --method M --out FILE [--frame F | --frames A-B] ...`
#include <chrono>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <memory>
#include <utility>

#include "base/error.h"
#include "cli/args.h"
#include "cli/commands.h"
#include "cli/progress.h"
#include "engine/render.h"
#include "image/image_io.h"
#include "image/sequence.h"
#include "methods/method.h"

namespace sg {
namespace {

struct RenderArgs {
  std::string scene_path, method = "", out, frames, samples = "8x8x8";
  int frame = 0, width = 0, height = 0, threads = 0;
  uint64_t seed = 0;
  double exposure = 0;
  bool quiet = false;
  MethodOptions options;  // the method flags below fill its numbers directly
  std::string microspec_area = "exact", specaa_derivatives = "quad", specaa_kernel = "rect",
              bruneton_fresnel = "fit";
};

// The value of an enumerated flag: `names[k]` maps to `values[k]`.
template <typename E>
E parse_choice(const std::string& text, const std::string& flag,
               std::initializer_list<std::pair<const char*, E>> choices) {
  std::string list;
  for (const auto& [name, value] : choices) {
    if (text == name) return value;
    list += (list.empty() ? "" : ", ") + std::string(name);
  }
  throw Error(flag + ": expected one of " + list + " (got '" + text + "')");
}

void run_render(const RenderArgs& a) {
  Scene scene = load_scene(a.scene_path);
  if (a.width > 0 || a.height > 0) {
    int w = a.width, h = a.height;
    if (w <= 0)
      w = std::max(1, static_cast<int>(std::lround(double(h) * scene.width / scene.height)));
    if (h <= 0)
      h = std::max(1, static_cast<int>(std::lround(double(w) * scene.height / scene.width)));
    set_image_size(scene, w, h);
  }
  FrameRange range{a.frame, a.frame};
  const bool sequence = !a.frames.empty();
  if (sequence) range = parse_frame_range(a.frames, "--frames");
  check_frame(range.first, scene, sequence ? "--frames" : "--frame");
  check_frame(range.last, scene, sequence ? "--frames" : "--frame");
  // A pattern names each frame; a single frame may use one too.
  const bool pattern = sequence || is_frame_pattern(a.out);
  auto out_path = [&](int f) { return pattern ? format_frame_path(a.out, f, "--out") : a.out; };
  image_format_of(out_path(range.first));  // fails early on a bad pattern or extension

  MethodOptions opt = a.options;
  opt.samples = parse_sample_counts(a.samples, "--samples");
  opt.seed = a.seed;
  opt.microspec.area = parse_choice<MicrospecArea>(
      a.microspec_area, "--microspec-area",
      {{"exact", MicrospecArea::exact}, {"approx", MicrospecArea::approx}});
  opt.specaa.derivatives = parse_choice<SpecaaDerivatives>(
      a.specaa_derivatives, "--specaa-derivatives",
      {{"quad", SpecaaDerivatives::quad}, {"analytic", SpecaaDerivatives::analytic}});
  opt.specaa.kernel =
      parse_choice<KernelShape>(a.specaa_kernel, "--specaa-kernel",
                                {{"rect", KernelShape::rect}, {"full", KernelShape::full}});
  opt.bruneton.fresnel = parse_choice<BrunetonFresnel>(
      a.bruneton_fresnel, "--bruneton-fresnel",
      {{"fit", BrunetonFresnel::fit}, {"integral", BrunetonFresnel::integral}});
  std::unique_ptr<Method> method = make_method(a.method, opt);
  SceneModel model(scene);

  ProgressBar bar(a.method, !a.quiet);
  RenderSettings rs;
  rs.threads = a.threads;
  rs.seed = a.seed;
  const long frames = range.count();
  long frames_done = 0;
  rs.progress = [&](long done, long total) {
    bar.update(frames_done * total + done, frames * total);
  };
  WriteOptions wo;
  wo.exposure = a.exposure;
  auto t0 = std::chrono::steady_clock::now();
  render_frames(model, *method, range.first, range.last, rs, [&](int f, const Image& img) {
    write_image(out_path(f), img, wo);
    ++frames_done;
  });
  bar.finish();
  double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("%s: %s, %dx%d, frames %d-%d, %.2f s (%.1f ms per frame) -> %s\n", scene.name.c_str(),
              method->name().c_str(), scene.width, scene.height, range.first, range.last, secs,
              1000 * secs / frames, a.out.c_str());
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
  c->add_option("--samples", a->samples, "Samples SxSxT for reference and supersample")
      ->capture_default_str();
  c->add_option("--width", a->width,
                "Override the image width (height follows the aspect "
                "ratio unless given)")
      ->check(CLI::Range(1, 16384));
  c->add_option("--height", a->height, "Override the image height")->check(CLI::Range(1, 16384));
  c->add_option("--threads,-j", a->threads, "Worker threads (0: all cores)")
      ->check(CLI::Range(0, 1024));
  c->add_option("--seed", a->seed, "Seed of the sampling streams")->capture_default_str();
  c->add_option("--exposure", a->exposure, "Exposure in stops for .png output")
      ->capture_default_str();
  c->add_flag("--quiet,-q", a->quiet, "No progress bar");
  // Method flags, --<method>-<option> (methods/options.h).
  c->add_option("--microspec-area", a->microspec_area,
                "microspec: disk-quad area, exact (circle against polygon) or approx (each "
                "shape cut by one line where it meets the other)")
      ->capture_default_str();
  c->add_option("--specaa-sigma2", a->options.specaa.sigma2,
                "specaa: variance of the pixel filter kernel, pixels^2 (Tokuyoshi-Kaplanyan)")
      ->capture_default_str();
  c->add_option("--specaa-kappa", a->options.specaa.kappa,
                "specaa: clamp of the kernel roughness alpha^2 (Tokuyoshi-Kaplanyan)")
      ->capture_default_str();
  c->add_option("--specaa-derivatives", a->specaa_derivatives,
                "specaa: half-vector derivatives, quad (2x2 finite differences, as a GPU) or "
                "analytic (ray differentials and the wave Hessian)")
      ->capture_default_str();
  c->add_option("--specaa-kernel", a->specaa_kernel,
                "specaa: kernel shape, rect (per-axis bounding rectangle) or full (2x2 "
                "covariance)")
      ->capture_default_str();
  c->add_option("--bruneton-nmin", a->options.bruneton.n_min,
                "bruneton: wavelengths below N_min pixel sizes go fully into the BRDF")
      ->capture_default_str();
  c->add_option("--bruneton-nmax", a->options.bruneton.n_max,
                "bruneton: wavelengths above N_max pixel sizes stay fully in the geometry")
      ->capture_default_str();
  c->add_option("--bruneton-min-variance", a->options.bruneton.min_variance,
                "bruneton: minimum slope variance of the sun's lobe (Sec. 5.1 clamp)")
      ->capture_default_str();
  c->add_option("--bruneton-fresnel", a->bruneton_fresnel,
                "bruneton: effective Fresnel with fresnel schlick, fit (Eq. 26) or integral "
                "(Eq. 24)")
      ->capture_default_str();
  c->callback([a] { run_render(*a); });
}

}  // namespace sg
