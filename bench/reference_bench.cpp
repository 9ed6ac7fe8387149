// Micro-benchmarks of the reference renderer's inner parts: the batched sine/cosine, the
// wave gradient by angle addition, and one pixel of the estimator on each shared scene.
// Run: build/bench/reference_bench   (figures in docs/benchmarks.md)
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "math/rng.h"
#include "math/simd_trig.h"
#include "methods/stratified.h"
#include "scene/model.h"
#include "testing/paths.h"

namespace sg {
namespace {

// n angles in [0, 2000) rad, the same for both sine benchmarks.
std::vector<double> random_angles(size_t n) {
  std::vector<double> x(n);
  Pcg32 rng(1, 1);
  for (auto& v : x)
    v = 2000 * rng.uniform();
  return x;
}

void BM_SincosArray(benchmark::State& state) {
  const size_t n = 4096;
  const std::vector<double> x = random_angles(n);
  std::vector<double> s(n), c(n);
  for (auto _ : state) {
    sincos_array(x.data(), s.data(), c.data(), n);
    benchmark::DoNotOptimize(s.data());
  }
  state.SetItemsProcessed(state.iterations() * n);
}
BENCHMARK(BM_SincosArray);

void BM_LibmSincos(benchmark::State& state) {
  const size_t n = 4096;
  const std::vector<double> x = random_angles(n);
  std::vector<double> s(n), c(n);
  for (auto _ : state) {
    for (size_t k = 0; k < n; ++k) {
      s[k] = std::sin(x[k]);
      c[k] = std::cos(x[k]);
    }
    benchmark::DoNotOptimize(s.data());
  }
  state.SetItemsProcessed(state.iterations() * n);
}
BENCHMARK(BM_LibmSincos);

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
