// Micro-benchmarks of the two baselines' per-frame work (docs/baselines-lean-taa.md), on one
// thread so that the CPU time is the whole work and does not depend on the machine's load:
//  - LEAN's map build (LeanMethod::begin_frame: the region, the slopes of the waves at every
//    level-0 texel, the MIP chain) for map sizes 1024, 2048, 4096 on the shared scenes at
//    160x90 (automatic far distance), with the map's memory, its texel, its far distance
//    and the mapped waves as counters;
//  - the shading of all pixels once the map is built (trilinear, aniso), and TAA's resolve
//    (reprojection, clamp, blend) of a 160x90 frame.
// Run: build/bench/baselines_bench
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <string>

#include "engine/render.h"
#include "methods/lean.h"
#include "methods/taa.h"
#include "testing/paths.h"

namespace sg {
namespace {

Scene bench_scene(const char* name) {
  Scene s = load_scene(sg::testing::source_dir() + "/scenes/" + name + ".json");
  set_image_size(s, 160, 90);
  return s;
}

void BM_LeanMapBuild(benchmark::State& state, const char* name) {
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  Scene s = bench_scene(name);
  SceneModel m(s);
  LeanOptions o;
  o.size = static_cast<int>(state.range(0));
  LeanMethod lean(o);
  FrameContext ctx{m, frame_time(s, 0), 0};
  lean.begin_frame(ctx);  // the first call allocates
  for (auto _ : state) {
    lean.begin_frame(ctx);
    benchmark::DoNotOptimize(lean.map().texel(0, 0, 0));
  }
  const double mapped = lean.mapped_wave_count();
  state.counters["MiB"] = lean.map().bytes() / 1048576.0;
  state.counters["waves_mapped"] = mapped;
  state.counters["far_m"] = lean.region().far;
  state.counters["texel_mm"] = 1000 * lean.region().texel;
  state.SetItemsProcessed(state.iterations() * int64_t(o.size) * o.size);  // level-0 texels
  state.counters["wave_texels_per_s"] = benchmark::Counter(
      double(state.iterations()) * o.size * o.size * mapped, benchmark::Counter::kIsRate);
}
BENCHMARK_CAPTURE(BM_LeanMapBuild, simple, "simple")
    ->Arg(1024)
    ->Arg(2048)
    ->Arg(4096)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LeanMapBuild, smooth, "smooth")
    ->Arg(1024)
    ->Arg(2048)
    ->Arg(4096)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LeanMapBuild, medium, "medium")
    ->Arg(1024)
    ->Arg(2048)
    ->Arg(4096)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LeanMapBuild, high, "high")
    ->Arg(1024)
    ->Arg(2048)
    ->Arg(4096)
    ->Unit(benchmark::kMillisecond);

void BM_LeanShade(benchmark::State& state, const char* name, LeanFilter filter) {
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  Scene s = bench_scene(name);
  SceneModel m(s);
  LeanOptions o;
  o.size = 1024;
  o.filter = filter;
  LeanMethod lean(o);
  FrameContext ctx{m, frame_time(s, 0), 0};
  lean.begin_frame(ctx);
  Image img(m.width(), m.height());
  for (auto _ : state) {
    lean.shade_tile(ctx, 0, 0, m.width(), m.height(), img);
    benchmark::DoNotOptimize(img.data.data());
  }
  state.SetItemsProcessed(state.iterations() * int64_t(m.width()) * m.height());
}
BENCHMARK_CAPTURE(BM_LeanShade, medium_trilinear, "medium", LeanFilter::trilinear)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LeanShade, medium_aniso, "medium", LeanFilter::aniso)
    ->Unit(benchmark::kMillisecond);

void BM_TaaResolve(benchmark::State& state, const char* name) {
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  Scene s = bench_scene(name);
  SceneModel m(s);
  TaaMethod taa{TaaOptions{}};
  RenderSettings rs;
  rs.threads = 1;
  render_frame(m, taa, 0, rs);
  FrameContext ctx{m, frame_time(s, 1), 0};
  taa.begin_frame(ctx);
  Image current(m.width(), m.height());
  taa.shade_tile(ctx, 0, 0, m.width(), m.height(), current);
  int frame = 1;
  for (auto _ : state) {
    Image img = current;
    FrameContext c{m, frame_time(s, frame), 0};
    taa.end_frame(c, img);  // consecutive frames: the history is resolved each time
    benchmark::DoNotOptimize(img.data.data());
    ++frame;
  }
  state.SetItemsProcessed(state.iterations() * int64_t(m.width()) * m.height());
}
BENCHMARK_CAPTURE(BM_TaaResolve, medium, "medium")->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace sg

BENCHMARK_MAIN();
