#include "methods/kernel_counts.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <iterator>
#include <memory>
#include <vector>

#include "base/error.h"
#include "kernel/kernel_counting.h"
#include "methods/bruneton.h"
#include "methods/kernel_inputs.h"
#include "methods/lean.h"
#include "methods/microspec.h"
#include "methods/specaa.h"
#include "methods/staa.h"
#include "methods/stratified.h"
#include "methods/supersample.h"
#include "methods/taa.h"
#include "shading/kernel_table.h"
#include "shading/path_table.h"

namespace sg {

namespace {

// The double kernel's structs as the counting kernel's: the same text in the same
// precision, so the same layout.
template <class To, class From>
To same_struct(const From& f) {
  static_assert(sizeof(To) == sizeof(From));
  return std::bit_cast<To>(f);
}

// The counters, one by one (the same order as KernelWork's statistics).
constexpr uint64_t KernelCounters::*kCounters[] = {
    &KernelCounters::waves, &KernelCounters::buffer_fetches,  &KernelCounters::table_fetches,
    &KernelCounters::nodes, &KernelCounters::transcendentals, &KernelCounters::march_steps};
KernelWork::Stat KernelWork::*const kStats[] = {
    &KernelWork::waves, &KernelWork::buffer_fetches,  &KernelWork::table_fetches,
    &KernelWork::nodes, &KernelWork::transcendentals, &KernelWork::march_steps};

// Sums and maxima over a set of pixels.
struct Sums {
  KernelCounters total{}, max{};
  long pixels = 0, host_finished = 0;
  void add_pixel(const KernelCounters& d) {
    for (auto c : kCounters) {
      total.*c += d.*c;
      max.*c = std::max(max.*c, d.*c);
    }
    ++pixels;
  }
  void add(const Sums& o) {
    for (auto c : kCounters) {
      total.*c += o.total.*c;
      max.*c = std::max(max.*c, o.max.*c);
    }
    pixels += o.pixels;
    host_finished += o.host_finished;
  }
};

}  // namespace

bool kernel_work_counted(const std::string& method) {
  return method == "point" || method == "supersample" || method == "staa-temporal" ||
         method == "staa" || method == "specaa" || method == "microspec" || method == "bruneton" ||
         method == "lean" || method == "taa";
}

KernelWork count_kernel_work(const SceneModel& m, const std::string& method, const MethodOptions& o,
                             int frame) {
  if (!kernel_work_counted(method)) {
    throw Error("--counters: no counting render for method '" + method +
                "' (point, supersample, staa-temporal, staa, specaa, microspec, bruneton, lean and "
                "taa have one)");
  }
  validate(o);
  const bool super = method == "supersample";
  const int segments = method == "staa" || method == "staa-temporal" ? o.staa.segments : 1;
  // bruneton and lean: the cascades' fields on flat water only (shading/cascade_fields.h).
  const bool filtered = method == "bruneton" || method == "lean";
  const bool fields =
      o.cascade_fields && (!super || o.samples.st == 1) && (!filtered || !m.displaced());
  KernelFrameInputs inputs(
      segments, Precision::float64,
      super ? stratified_intersect_tolerance(o) : intersect_tolerance_for(o, method), 1, fields);
  const FrameContext ctx{m, frame_time(m.scene, frame), o.seed};
  inputs.build(ctx);
  const KernelInputsD& in = inputs.d();
  // The kernel's own loops over the waves (no arrays: no vectorised sums).
  const kc::WaveBuffer waves{in.texels.data(), static_cast<int>(in.texels.size()), {}};
  const kc::Frame f = same_struct<kc::Frame>(in.frame);
  kc::SampleCounts counts{};
  if (super) {
    counts = same_struct<kc::SampleCounts>(
        kernel_sample_counts(StratifiedSettings{o.samples, o.samples.st == 1}));
  }
  // The path tables: staa's alone (the caller's, MethodOptions::path_tables).
  const PathTables* tables = method == "staa" ? &required_path_tables(o, method) : nullptr;
  const KernelFitTexture& fits = kernel_fit_texture();
  const kc::StaaParams params =
      same_struct<kc::StaaParams>(staa_kernel_params<kd::StaaParams>(o.staa));
  const kc::PathTableInfo tinfo =
      tables ? same_struct<kc::PathTableInfo>(tables->kernel_info()) : kc::PathTableInfo{};
  const kc::KernelFitInfo finfo = same_struct<kc::KernelFitInfo>(fits.info);
  const kc::MicrospecParams mparams =
      same_struct<kc::MicrospecParams>(microspec_kernel_params<kd::MicrospecParams>(o.microspec));
  const kc::BrunetonParams bparams =
      same_struct<kc::BrunetonParams>(bruneton_kernel_params<kd::BrunetonParams>(o.bruneton));
  const kc::SpecaaParams sparams =
      same_struct<kc::SpecaaParams>(specaa_kernel_params<kd::SpecaaParams>(o.specaa));

  // lean: the frame's map, built by the method (its texels per frame, not per pixel, are
  // not counted); the pixels read it.
  std::unique_ptr<LeanMethod> lean;
  kc::LeanParams lparams{};
  if (method == "lean") {
    lean = std::make_unique<LeanMethod>(o.lean, Precision::float64, o.cascade_fields);
    lean->begin_frame(ctx);
    lparams = same_struct<kc::LeanParams>(lean->params());
  }
  const int w = m.scene.width, h = m.scene.height;
  // taa: its sample, then its resolve against a history (images of zeros: what it reads,
  // not their values, is counted).
  const int channels = m.scene.grey() ? 1 : 3;
  const kc::TaaParams tparams = same_struct<kc::TaaParams>(
      method == "taa" ? taa_frame_params(m, ctx.time, o.taa, in.origin) : kd::TaaParams{});
  const kc::TaaResolveParams rparams =
      same_struct<kc::TaaResolveParams>(taa_resolve_params(o.taa, w, h, channels));
  const std::vector<float> zeros(method == "taa" ? size_t(w) * size_t(h) * size_t(channels) : 0);
  const kc::ImagePlanes planes{zeros.data(), w, channels};
  std::vector<Sums> rows(static_cast<size_t>(h));
  tbb::parallel_for(0, h, [&](int j) {
    Sums& s = rows[static_cast<size_t>(j)];
    for (int i = 0; i < w; ++i) {
      KernelCounters& c = kernel_counters();
      c = KernelCounters{};
      if (method == "point") {
        kc::point_pixel(waves, f, i, j);
      } else if (super) {
        kc::stratified_pixel(waves, f, counts, i, j);
      } else if (method == "staa-temporal") {
        kc::staa_temporal_pixel(waves, f, i, j);
      } else if (method == "specaa") {
        // An invocation samples its own pixel and shades it; its quad neighbours' samples
        // are the other invocations' (shared, not counted here).
        const kc::SpecaaSample own = kc::specaa_sample(waves, f, i + 0.5, j + 0.5);
        const KernelCounters mine = c;
        const kc::SpecaaSample nx = kc::specaa_sample(waves, f, (i ^ 1) + 0.5, j + 0.5);
        const kc::SpecaaSample ny = kc::specaa_sample(waves, f, i + 0.5, (j ^ 1) + 0.5);
        c = mine;
        kc::specaa_shade(waves, f, sparams, own, nx, ny, i, j);
      } else if (method == "microspec") {
        // An invocation traces its own corner (i, j) and shades; the other three are its
        // neighbours' (the workgroup's last row and column trace 17 more corners per 64
        // pixels, not counted here).
        kc::PixelCorners corners;
        corners.c[0] = kc::microspec_corner(waves, f, i, j);
        const KernelCounters mine = c;
        corners.c[1] = kc::microspec_corner(waves, f, i + 1, j);
        corners.c[2] = kc::microspec_corner(waves, f, i + 1, j + 1);
        corners.c[3] = kc::microspec_corner(waves, f, i, j + 1);
        c = mine;
        kc::microspec_shade(waves, f, mparams, corners, i, j);
      } else if (method == "bruneton") {
        kc::bruneton_pixel(waves, f, bparams, i, j);
      } else if (method == "lean") {
        kc::lean_pixel(waves, f, lean->map().texels(), lparams, i, j);
      } else if (method == "taa") {
        const kc::TaaSample smp = kc::taa_sample(waves, f, tparams, i, j);
        kc::taa_resolve_pixel(planes, planes, rparams, true, smp.motion, i, j);
      } else {
        kc::StaaPath path;
        const kc::StaaResult r = kc::staa_pixel(waves, tables->f_texture(), tables->s_texture(),
                                                tinfo, fits.view(), finfo, f, params, i, j, path);
        if (r.exact_pending) ++s.host_finished;
      }
      s.add_pixel(c);
    }
  });
  Sums all;
  for (const Sums& s : rows)
    all.add(s);
  KernelWork r;
  r.pixels = all.pixels;
  r.host_finished = all.host_finished;
  const double n = double(std::max<long>(1, all.pixels));
  for (size_t q = 0; q < std::size(kCounters); ++q) {
    r.*kStats[q] = KernelWork::Stat{double(all.total.*kCounters[q]) / n, all.max.*kCounters[q]};
  }
  return r;
}

double predicted_frame_ms(const KernelWork& k, long pixels, const GpuPeakRates& gpu,
                          bool from_max) {
  const double trans = from_max ? double(k.transcendentals.max) : k.transcendentals.mean;
  const double fetches = from_max ? double(k.buffer_fetches.max + k.table_fetches.max)
                                  : k.buffer_fetches.mean + k.table_fetches.mean;
  const double sfu = gpu.sms * gpu.clock_hz * gpu.sfu_per_sm_clock;
  const double tex = gpu.sms * gpu.clock_hz * gpu.texel_per_sm_clock;
  return 1000.0 * double(pixels) * std::max(trans / sfu, fetches / tex);
}

}  // namespace sg
