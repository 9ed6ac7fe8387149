// The cost of `sunglint ocean`: sampling a sea (ocean/ocean.h) and writing it as a scene
// file's JSON, for 1024 to 65536 waves and each kind of spreading (docs/ocean.md).
#include <benchmark/benchmark.h>

#include "ocean/ocean.h"

namespace {

using sg::ocean::OceanParams;
using sg::ocean::SpreadingKind;

void BM_Generate(benchmark::State& state) {
  OceanParams p;
  p.waves = static_cast<int>(state.range(0));
  p.spreading = static_cast<SpreadingKind>(state.range(1));
  for (auto _ : state)
    benchmark::DoNotOptimize(sg::ocean::generate(p));
  state.SetLabel(sg::ocean::to_string(p.spreading));
  state.SetItemsProcessed(state.iterations() * p.waves);
}
BENCHMARK(BM_Generate)
    ->ArgsProduct({{1024, 16384, 65536}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond);

void BM_SceneJson(benchmark::State& state) {
  OceanParams p;
  p.waves = static_cast<int>(state.range(0));
  const sg::Scene s =
      sg::ocean::ocean_scene(sg::ocean::plain_template(), sg::ocean::generate(p), "sea");
  for (auto _ : state)
    benchmark::DoNotOptimize(sg::scene_to_json(s));
  state.SetItemsProcessed(state.iterations() * p.waves);
}
BENCHMARK(BM_SceneJson)->Arg(1024)->Arg(65536)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
