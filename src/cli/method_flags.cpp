#include "cli/method_flags.h"

#include <algorithm>
#include <limits>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

#include "base/error.h"
#include "cli/args.h"
#include "cli/path_tables.h"
#include "gl_engine/gl_engine.h"
#include "methods/method.h"

namespace sg {

void MethodFlags::finish(const std::string& context) {
  options.path_tables = &cli_path_tables();
  options.samples_given = !samples.empty();
  options.intersect_tolerance_given =
      intersect_tolerance_option != nullptr && intersect_tolerance_option->count() > 0;
  options.samples =
      samples.empty() ? SampleCounts{} : parse_sample_counts(samples, context + "--samples");
  engine = parse_engine(engine_name, context + "--engine");
  const AliasRange r = alias_range(options.staa);
  if (!(r.start >= 0 && r.end > r.start)) {
    throw Error(context + "--alias-start, --alias-end: need 0 <= start < end (got " +
                std::to_string(r.start) + ", " + std::to_string(r.end) + ")");
  }
}

void MethodFlags::check_taken_by(const std::vector<std::string>& methods,
                                 const std::string& context) const {
  for (const Scoped& s : scoped) {
    if (s.option->count() == 0) continue;
    bool taken = false;
    for (const std::string& m : methods) {
      for (const std::string& t : s.methods)
        taken = taken || m == t;
    }
    if (taken) continue;
    std::string names, takers;
    for (const std::string& m : methods)
      names += (names.empty() ? "" : ", ") + m;
    for (const std::string& t : s.methods)
      takers += (takers.empty() ? "" : ", ") + t;
    const std::string flag = s.option->get_name();
    const std::string whose = methods.empty()       ? "no method given here"
                              : methods.size() == 1 ? "method " + names
                                                    : "any of the methods " + names;
    throw Error(context + flag + ": not a flag of " + whose + " (it configures " + takers + ")");
  }
}

namespace {

// A flag that picks one of named values: CLI11 checks the name, the callback stores it.
template <class T>
CLI::Option* choice(CLI::App& app, const std::string& flag, T& field,
                    const std::map<std::string, T>& names, const std::string& help) {
  std::string current;
  std::vector<std::string> keys;
  for (const auto& [k, v] : names) {
    if (v == field) current = k;
    keys.push_back(k);
  }
  return app
      .add_option_function<std::string>(
          flag, [&field, names](const std::string& v) { field = names.at(v); }, help)
      ->check(CLI::IsMember(keys))
      ->default_str(current);
}

}  // namespace

static void add_baseline_flags(CLI::App& app, MethodOptions& o);

// Which methods each flag configures (MethodFlags::check_taken_by).
static void scope_method_flags(const std::vector<const CLI::Option*>& options, MethodFlags& f);

void check_engine_runs(Engine engine, const std::string& name, const MethodOptions& options,
                       const std::string& context) {
  if (engine != Engine::gl) return;
  try {
    gl_engine::gl_variant(name, options);
  } catch (const Error& e) {
    throw Error(context + e.what());
  }
}

void add_method_flags(CLI::App& app, MethodFlags& f) {
  const size_t before = std::as_const(app).get_options().size();
  MethodOptions& o = f.options;
  app.add_option("--engine", f.engine_name,
                 std::string("cpu (every method) or gl (OpenGL 4.5 compute shaders: ") +
                     gl_engine::gl_methods() + ")")
      ->capture_default_str();
  app.add_option("--samples", f.samples,
                 "Samples SxSxT. supersample: S x S positions times T times (default 8x8x8). "
                 "reference: per batch S x S strata of T samples each, time integrated exactly "
                 "on flat water (default 8x8x1)");
  app.add_option("--batches", o.batches,
                 "reference: independent batches per pixel, whose spread measures its noise")
      ->capture_default_str()
      ->check(integer_in(2, 8));
  choice(app, "--adaptive", o.adaptive, {{"on", true}, {"off", false}},
         "reference: a pilot at each pixel's centre and corners gives pixels far from the "
         "light and the horizon --quiet-samples instead of --samples (on), or not (off)");
  app.add_option("--quiet-samples", o.quiet_samples,
                 "reference: N x N strata per batch in the pixels the pilot finds quiet")
      ->capture_default_str()
      ->check(integer_in(1, 64));
  app.add_option("--seed", o.seed, "Seed of the sampling streams")
      ->capture_default_str()
      ->check(integer_in(0, std::numeric_limits<long long>::max()));
  choice(app, "--precision", o.precision,
         {{"double", Precision::float64}, {"float", Precision::float32}},
         "point, supersample, reference, staa-temporal, staa, specaa, microspec, bruneton, lean, "
         "taa: the shading kernel's precision on the CPU (float is what a GPU computes)");
  f.intersect_tolerance_option =
      app.add_option("--intersect-tolerance", o.intersect_tolerance,
                     "point, supersample, reference, staa-temporal, staa, specaa, microspec, taa "
                     "on displaced "
                     "water: "
                     "leave out of the intersection the shortest waves whose amplitudes sum to "
                     "at most this many pixels of the ray's footprint (0: every wave, the "
                     "default of all but staa, whose default is 0.25)")
          ->check(number_in(0, 16));
  choice(app, "--cascades", o.cascade_fields, {{"fields", true}, {"waves", false}},
         "point, supersample with T = 1, staa-temporal, staa, specaa (flat and displaced water), "
         "lean, bruneton (flat water): shade lattice cascades from their FFT fields (a cost "
         "fixed per cascade) or as their lattice's sines among the waves (exact, a cost that "
         "follows the waves)");
  choice(app, "--cascade-fft", o.cascade_fft_gpu, {{"gpu", true}, {"host", false}},
         "point, supersample, staa-temporal, staa, specaa on the GL engine with --cascades fields: "
         "transform the cascades each frame on the GPU, into the wave buffer, or on the host "
         "(uploaded); the CPU engine transforms on the host");

  // staa, staa-temporal (methods/staa.h)
  StaaOptions& s = o.staa;
  app.add_option("--segments", s.segments,
                 "staa, staa-temporal: sub-arcs of the shutter interval (Sec. 3.5)")
      ->capture_default_str()
      ->check(integer_in(1, 32));
  choice(app, "--ndf", s.ndf, {{"uniform", NdfMode::uniform}, {"per-pixel", NdfMode::per_pixel}},
         "staa: NDF of the aliasing waves: uniform (Eq. 3) or per-pixel (Eqs. 4-7); default: "
         "per-pixel with --footprint none (the paper's method), else uniform");
  choice(app, "--ndf-mean", s.ndf_mean_shift, {{"shift", true}, {"none", false}},
         "staa, per-pixel NDF: the aliasing waves' mean slope shifts the NDF centre (shift) or "
         "not (none)");
  app.add_option("--kernels", s.kernels,
                 "staa: circular Gaussians approximating the RDF: 1 (equal-area circle, Sec. "
                 "3.5), 3, 5 or 9 (Sec. 3.6); default: 3 with a footprint term, 9 (the "
                 "paper's) with --footprint none")
      ->check(CLI::IsMember({1, 3, 5, 9}));
  app.add_option("--elongation-threshold", s.elongation_threshold,
                 "staa: RDF axis ratio past which the fallback renders (0: the kernel count, "
                 "as the paper; none for --kernels 1)")
      ->capture_default_str()
      ->check(number_in(0, 1e6));
  choice(app, "--fallback", s.fallback,
         {{"quadrature", FallbackMode::quadrature}, {"riemann", FallbackMode::riemann}},
         "staa: the fallback's RDF-disk convolution: quadrature (accurate) or riemann (the "
         "paper's Riemann sum)");
  choice(app, "--fallback-time", s.fallback_along_path, {{"path", true}, {"current", false}},
         "staa: the fallback averaged along the reflection path (path) or at the display time "
         "only (current, the paper)");
  app.add_option("--riemann-cells", s.riemann_cells, "staa: cells across the disk for riemann")
      ->capture_default_str()
      ->check(integer_in(2, 1024));
  app.add_option("--alias-start", s.alias_start,
                 "staa: projected frequency (cycles/pixel) where aliasing begins (Eq. 20); "
                 "default 0.2 with --footprint none (the paper), else 0.3")
      ->check(number_in(0, 100));
  app.add_option("--alias-end", s.alias_end,
                 "staa: projected frequency (cycles/pixel) where a wave fully aliases (Eq. 20); "
                 "default 0.5 with --footprint none (the paper), else 0.8")
      ->check(number_in(0, 100));
  choice(app, "--nyquist", s.nyquist_max_axis, {{"max", true}, {"norm", false}},
         "staa: projected frequency as the larger axis frequency (max) or the norm");
  choice(app, "--footprint", s.footprint,
         {{"none", FootprintMode::none},
          {"gaussian", FootprintMode::gaussian},
          {"exact", FootprintMode::exact}},
         "staa: pixel-footprint term: none (the paper), gaussian (moment-matched, added to the "
         "RDF) or exact (swept parallelogram against the disk where nothing aliases)");
  app.add_option("--curvature-limit", s.curvature_limit,
                 "staa with a footprint: hand a resolved wave to the aliasing set when its "
                 "slope's departure from linear across the pixel exceeds this many disk radii "
                 "of reflection (0: never)")
      ->capture_default_str()
      ->check(number_in(0, 1e6));
  app.add_option("--fold-cells", s.fold_cells,
                 "staa with a footprint: shade a lit pixel as the mean of its four quarters where "
                 "a resolved wave's slope departs from linear across it by more than this many "
                 "disk radii of reflection (0: never)")
      ->capture_default_str()
      ->check(number_in(0, 1e6));
  choice(app, "--wave-remainder", s.wave_remainder, {{"sum", true}, {"each", false}},
         "staa: the waves that certainly alias fully in a pixel add their covariance from "
         "precomputed sums in O(1) (sum) or one by one (each)");
  choice(app, "--smooth-terms", s.smooth_over_normals, {{"ndf", true}, {"mean", false}},
         "staa: Fresnel times the sky, and the sea, integrated over the pixel's normals (ndf: "
         "the NDF, the footprint, the path) or taken at the centre normal (mean, the paper)");
  app.add_option("--smooth-cells", s.smooth_cells,
                 "staa, --smooth-terms ndf: the pixel cut into N x N cells, each with its own "
                 "Gaussian of normals")
      ->capture_default_str()
      ->check(integer_in(1, 3));
  choice(app, "--rdf-at", s.rdf_at, {{"light", RdfAnchor::light}, {"centre", RdfAnchor::centre}},
         "staa: the map from normals to the light plane linearised at the light (exact to "
         "first order in the disk's radius) or at the NDF's centre (the paper, Eqs. 11-16); "
         "default: centre with --footprint none (the paper's method), else light");

  // lean (methods/lean.h)
  app.add_option("--lean-size", o.lean.size,
                 "lean: texels per side of the slope-moment map (a power of two)")
      ->capture_default_str()
      ->check(integer_in(1, 1 << 30));
  app.add_option("--lean-far", o.lean.far,
                 "lean: distance (m) the map covers; beyond it the uniform NDF (Eq. 3). 0: "
                 "automatic (texel = the smallest pixel footprint)")
      ->capture_default_str()
      ->check(finite_number());
  choice(app, "--lean-filter", o.lean.filter,
         {{"trilinear", LeanFilter::trilinear}, {"aniso", LeanFilter::aniso}}, "lean: map filter");
  app.add_option("--lean-max-aniso", o.lean.max_aniso,
                 "lean: most trilinear probes per pixel with --lean-filter aniso")
      ->capture_default_str()
      ->check(integer_in(-1000000, 1000000));

  // taa (methods/taa.h)
  app.add_option("--taa-jitter-count", o.taa.jitter_count,
                 "taa: length of the Halton (2,3) jitter cycle")
      ->capture_default_str()
      ->check(integer_in(-1000000, 1000000));
  app.add_option("--taa-alpha", o.taa.alpha, "taa: weight of the current frame in the blend")
      ->capture_default_str()
      ->check(finite_number());
  app.add_option("--taa-gamma", o.taa.gamma,
                 "taa: width of the variance box, in standard deviations")
      ->capture_default_str()
      ->check(finite_number());
  choice(app, "--taa-clamp", o.taa.clamp,
         {{"none", TaaClamp::none}, {"minmax", TaaClamp::minmax}, {"variance", TaaClamp::variance}},
         "taa: history rectification");
  choice(app, "--taa-history", o.taa.history,
         {{"bilinear", TaaHistoryFilter::bilinear}, {"catmull-rom", TaaHistoryFilter::catmull_rom}},
         "taa: history resampling");
  choice(app, "--taa-motion", o.taa.motion,
         {{"full", TaaMotion::full}, {"surface", TaaMotion::surface}},
         "taa: motion vectors of a moving camera and the surface (full), or of the surface "
         "alone, as if the camera stood still (surface)");
  app.add_option("--taa-warmup", o.taa.warmup,
                 "taa: frames rendered (not written) before the first frame, to fill the history")
      ->capture_default_str()
      ->check(integer_in(-1000000, 1000000));
  add_baseline_flags(app, o);
  const std::vector<const CLI::Option*> all = std::as_const(app).get_options();
  scope_method_flags({all.begin() + static_cast<long>(before), all.end()}, f);
}

static void scope_method_flags(const std::vector<const CLI::Option*>& options, MethodFlags& f) {
  const std::vector<std::string> kernel = {"point", "supersample", "reference", "staa-temporal",
                                           "staa",  "specaa",      "microspec", "taa"};
  std::vector<std::string> with_baselines = kernel;
  with_baselines.push_back("bruneton");
  with_baselines.push_back("lean");
  const std::vector<std::string> sampling = {"supersample", "reference"};
  const std::vector<std::string> staa_both = {"staa", "staa-temporal"};
  const std::map<std::string, std::vector<std::string>> takers = {
      {"--samples", sampling},
      {"--seed", sampling},
      {"--batches", {"reference"}},
      {"--adaptive", {"reference"}},
      {"--quiet-samples", {"reference"}},
      {"--precision", with_baselines},
      {"--intersect-tolerance", kernel},
      {"--segments", staa_both},
      {"--cascades",
       {"point", "supersample", "staa-temporal", "staa", "lean", "specaa", "bruneton"}},
      {"--cascade-fft",
       {"point", "supersample", "staa-temporal", "staa", "specaa", "bruneton", "lean"}},
  };
  // staa's own (methods/staa.h).
  const std::vector<std::string> staa = {
      "--ndf",        "--ndf-mean",       "--kernels",       "--elongation-threshold",
      "--fallback",   "--fallback-time",  "--riemann-cells", "--alias-start",
      "--alias-end",  "--nyquist",        "--footprint",     "--curvature-limit",
      "--fold-cells", "--wave-remainder", "--smooth-terms",  "--smooth-cells",
      "--rdf-at"};
  // The baselines' flags name their method first: --lean-size (lean), --taa-alpha (taa), ...
  const std::vector<std::string> prefixed = {"lean", "taa", "microspec", "specaa", "bruneton"};
  for (const CLI::Option* opt : options) {
    const std::string name = opt->get_name();
    if (name == "--engine") continue;  // every method's
    std::vector<std::string> methods;
    if (auto t = takers.find(name); t != takers.end()) methods = t->second;
    if (std::find(staa.begin(), staa.end(), name) != staa.end()) methods = {"staa"};
    for (const std::string& p : prefixed) {
      if (name.rfind("--" + p + "-", 0) == 0) methods = {p};
    }
    if (methods.empty()) {
      f.unscoped.push_back(name);  // taken by every method (method_flags_test lists none)
    } else {
      f.scoped.push_back({opt, methods});
    }
  }
}

static void add_baseline_flags(CLI::App& app, MethodOptions& o) {
  // microspec (methods/microspec.h)
  choice(app, "--microspec-area", o.microspec.area,
         {{"exact", MicrospecArea::exact}, {"approx", MicrospecArea::approx}},
         "microspec: disk-quad area, exact (circle against polygon) or approx (each shape cut "
         "by one line where it meets the other)");
  // specaa (methods/specaa.h)
  app.add_option("--specaa-sigma2", o.specaa.sigma2,
                 "specaa: variance of the pixel filter kernel, pixels^2 (Tokuyoshi-Kaplanyan)")
      ->capture_default_str()
      ->check(finite_number());
  app.add_option("--specaa-kappa", o.specaa.kappa,
                 "specaa: clamp of the kernel roughness alpha^2 (Tokuyoshi-Kaplanyan)")
      ->capture_default_str()
      ->check(finite_number());
  choice(app, "--specaa-derivatives", o.specaa.derivatives,
         {{"quad", SpecaaDerivatives::quad}, {"analytic", SpecaaDerivatives::analytic}},
         "specaa: half-vector derivatives, quad (2x2 finite differences, as a GPU) or analytic "
         "(ray differentials and the wave Hessian)");
  choice(app, "--specaa-kernel", o.specaa.kernel,
         {{"rect", KernelShape::rect}, {"full", KernelShape::full}},
         "specaa: kernel shape, rect (per-axis bounding rectangle) or full (2x2 covariance)");
  // bruneton (methods/bruneton.h)
  app.add_option("--bruneton-nmin", o.bruneton.n_min,
                 "bruneton: wavelengths below N_min pixel sizes go fully into the BRDF")
      ->capture_default_str()
      ->check(finite_number());
  app.add_option("--bruneton-nmax", o.bruneton.n_max,
                 "bruneton: wavelengths above N_max pixel sizes stay fully in the geometry")
      ->capture_default_str()
      ->check(finite_number());
  app.add_option("--bruneton-min-variance", o.bruneton.min_variance,
                 "bruneton: minimum slope variance of the sun's lobe (Sec. 5.1 clamp)")
      ->capture_default_str()
      ->check(finite_number());
  choice(app, "--bruneton-fresnel", o.bruneton.fresnel,
         {{"fit", BrunetonFresnel::fit}, {"integral", BrunetonFresnel::integral}},
         "bruneton: effective Fresnel with fresnel schlick, fit (Eq. 26) or integral (Eq. 24)");
}

MethodVariant parse_method_variant(const std::string& text, const std::string& flag) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string w; in >> w;)
    words.push_back(w);
  if (words.empty()) throw Error(flag + ": empty method variant");
  MethodVariant v;
  v.label = text;
  v.name = words[0];
  CLI::App app{"method variant"};
  MethodFlags flags;
  add_method_flags(app, flags);
  std::vector<std::string> args(words.rbegin(), words.rend() - 1);  // CLI11 wants them reversed
  try {
    app.parse(args);
  } catch (const CLI::ExtrasError& e) {
    // A flag no method has: name it, and the one it may be a slip of.
    for (const std::string& w : app.remaining()) {
      if (w.size() < 2 || w[0] != '-') continue;
      const std::string near = closest_name(w, flag_names(&app));
      throw Error(flag + ": '" + text + "': unknown flag '" + w + "'" +
                  (near.empty() ? "" : " (did you mean " + near + "?)"));
    }
    throw Error(flag + ": '" + text + "': " + e.what());
  } catch (const CLI::ParseError& e) {
    throw Error(flag + ": '" + text + "': " + e.what());
  }
  flags.finish(flag + ": '" + text + "': ");
  flags.check_taken_by({v.name}, flag + ": '" + text + "': ");
  v.options = flags.options;
  v.engine = flags.engine;
  make_method(v.name, v.options);  // validates the name and the options
  check_engine_runs(v.engine, v.name, v.options, flag + ": '" + text + "': ");
  return v;
}

}  // namespace sg
