// What colour costs: every method of the catalogue renders a frame of a shared scene
// (scenes/medium.json, 160x90, one thread) twice, as the grey scene and as a colour
// version that differs only in its radiances (light [1, 0.7, 0.4], sky [0.02, 0.04, 0.08],
// sea [0.002, 0.01, 0.014]; the grey version has the same values in every channel: 1,
// 0.02 and 0.002, so both shade the same sky, sea and Fresnel). Methods compute weights
// of the radiances (methods/method.h); colour adds the RGB image (three values per pixel
// stored instead of one) and, for TAA, the resolve of three channels. The ratio
// colour/grey of each method, within one run, is in docs/benchmarks.md.
// Run: build/bench/colour_bench --benchmark_min_time=0.5
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <string>

#include "engine/render.h"
#include "methods/method.h"
#include "testing/path_tables.h"
#include "testing/paths.h"

namespace sg {
namespace {

Scene bench_scene(bool colour) {
  Scene s = load_scene(sg::testing::source_dir() + "/scenes/medium.json");
  set_image_size(s, 160, 90);
  s.surface.fresnel = FresnelMode::schlick;
  s.light.radiance = colour ? Rgb(1, 0.7, 0.4) : Rgb(1);
  s.sky = SkyDesc::constant(colour ? Rgb(0.02, 0.04, 0.08) : Rgb(0.02));
  s.surface.sea_radiance = colour ? Rgb(0.002, 0.01, 0.014) : Rgb(0.002);
  return s;
}

void BM_Frame(benchmark::State& state, const std::string& method, bool colour) {
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  const Scene s = bench_scene(colour);
  const SceneModel model(s);
  MethodOptions o;
  o.samples = SampleCounts{4, 4, 2};  // reference, supersample: 32 samples per pixel
  auto m = make_method(method, testing::with_tables(o));
  int frame = 1;
  render_frame(model, *m, 0, RenderSettings{});  // tables, maps, a TAA history
  for (auto _ : state) {
    const Image img = render_frame(model, *m, frame++ % 60, RenderSettings{});
    benchmark::DoNotOptimize(img.data.data());
  }
  state.SetItemsProcessed(state.iterations() * int64_t(s.width) * s.height);
}

// Grey and colour of each method next to each other.
const bool registered = [] {
  for (const MethodInfo& info : method_catalog()) {
    for (bool colour : {false, true}) {
      benchmark::RegisterBenchmark(
          ("BM_Frame/" + info.name + (colour ? "/colour" : "/grey")).c_str(), BM_Frame, info.name,
          colour)
          ->Unit(benchmark::kMillisecond);
    }
  }
  return true;
}();

}  // namespace
}  // namespace sg

BENCHMARK_MAIN();
