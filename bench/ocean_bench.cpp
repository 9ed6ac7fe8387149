// The cost of `sunglint ocean`: sampling a sea (ocean/ocean.h) and writing it as a scene
// file's JSON, for 1024 to 65536 waves and each kind of spreading (docs/ocean.md); a
// lattice ocean's cascades (ocean/lattice_ocean.h) and one cascade's per-frame FFT
// (scene/cascade_fft.h) at lattices of 64 to 512. (The moment chain is built with a frame's
// fields, shading/cascade_fields.h, and timed with them: `sunglint bench`.)
#include <benchmark/benchmark.h>

#include "ocean/lattice_ocean.h"
#include "ocean/ocean.h"
#include "scene/cascade_fft.h"

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

void BM_GenerateLattice(benchmark::State& state) {
  OceanParams p;
  sg::ocean::CascadeParams c;
  c.lattice = static_cast<int>(state.range(0));
  for (auto _ : state)
    benchmark::DoNotOptimize(sg::ocean::generate_lattice(p, c));
  state.SetItemsProcessed(state.iterations() * c.cascades * c.lattice * c.lattice);
}
BENCHMARK(BM_GenerateLattice)->Arg(64)->Arg(256)->Unit(benchmark::kMillisecond);

// One cascade at one time: height and slopes (two inverse 2-D FFTs).
void BM_CascadeFft(benchmark::State& state) {
  OceanParams p;
  sg::ocean::CascadeParams c;
  c.lattice = static_cast<int>(state.range(0));
  const sg::ocean::LatticeOcean o = sg::ocean::generate_lattice(p, c);
  sg::CascadeFft fft(c.lattice);
  fft.set_lattice(o.cascades[1], sg::Dispersion{o.depth});
  double t = 0;
  for (auto _ : state) {
    const sg::CascadeGrid g = fft.evaluate(t += 1.0 / 30);
    benchmark::DoNotOptimize(g.height.data());
  }
  state.SetItemsProcessed(state.iterations() * c.lattice * c.lattice);
}
BENCHMARK(BM_CascadeFft)->Arg(64)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
