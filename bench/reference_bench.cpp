// Micro-benchmarks of the reference renderer: one pixel of the estimator on each shared
// scene.
// Run: build/bench/reference_bench   (figures in docs/benchmarks.md)
#include <benchmark/benchmark.h>

#include "methods/stratified.h"
#include "scene/model.h"
#include "testing/paths.h"

namespace sg {
namespace {

void BM_ReferencePixel(benchmark::State& state, const char* scene_name) {
  Scene s = load_scene(sg::testing::source_dir() + "/scenes/" + scene_name + ".json");
  SceneModel m(s);
  FrameContext ctx{m, frame_time(s, 0), 0};
  StratifiedSettings st{{8, 8, 8}, false};
  int i = 300;
  for (auto _ : state) {
    benchmark::DoNotOptimize(stratified_pixel(ctx, i, 280, st));
    i = 300 + (i + 1) % 40;
  }
  state.SetItemsProcessed(state.iterations() * 512);  // samples
}
BENCHMARK_CAPTURE(BM_ReferencePixel, simple, "simple");
BENCHMARK_CAPTURE(BM_ReferencePixel, smooth, "smooth");
BENCHMARK_CAPTURE(BM_ReferencePixel, medium, "medium");
BENCHMARK_CAPTURE(BM_ReferencePixel, high, "high");

}  // namespace
}  // namespace sg

BENCHMARK_MAIN();
