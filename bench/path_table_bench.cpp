// Path-table figures for docs/path-tables.md: generation time and memory (Podee et al. 2021,
// Sec. 4 table sizes), cache load time, and the cost of one lookup.
//
//   build/bench/path_table_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <filesystem>
#include <string>

#include "base/atomic_file.h"
#include "math/rng.h"
#include "scene/light.h"
#include "shading/arc.h"
#include "shading/disk_gaussian.h"
#include "shading/path_table.h"

namespace sg {
namespace {

double peak_rss_mib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;  // kilobytes on Linux
}

// Full-size tables (512 x 512 x 64), on 1 thread and on every hardware thread.
void BM_Generate(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(0));
  size_t bytes = 0;
  for (auto _ : state) {
    PathTables t = PathTables::generate({}, threads);
    bytes = t.bytes();
    benchmark::DoNotOptimize(bytes);
  }
  state.counters["table_MiB"] = bytes / 1048576.0;
  state.counters["peak_rss_MiB"] = peak_rss_mib();
}
BENCHMARK(BM_Generate)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();

// Reading the cache file back: read, crc32, decode.
void BM_LoadCache(benchmark::State& state) {
  const std::string path =
      (std::filesystem::temp_directory_path() / "sunglint_bench_path_tables.bin").string();
  write_file_atomic(path, PathTables::generate().serialize());
  for (auto _ : state) {
    PathTableCacheResult r;
    PathTables t = PathTables::load_or_generate(path, {}, &r);
    if (!r.loaded) state.SkipWithError("cache not loaded");
    benchmark::DoNotOptimize(t.bytes());
  }
  std::filesystem::remove(path);
  state.counters["peak_rss_MiB"] = peak_rss_mib();
}
BENCHMARK(BM_LoadCache)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();

const PathTables& tables() {
  static const PathTables t = PathTables::generate();
  return t;
}

void BM_PathAverage(benchmark::State& state) {
  const PathTables& t = tables();
  Pcg32 rng(1, 2);
  double sum = 0;
  for (auto _ : state) {
    const vec2 p0(3 * rng.uniform() - 1.5, 3 * rng.uniform() - 1.5);
    const vec2 p1(3 * rng.uniform() - 1.5, 3 * rng.uniform() - 1.5);
    sum += t.path_average(p0, p1, 2 * rng.uniform(), 1.0);
  }
  benchmark::DoNotOptimize(sum);
}
BENCHMARK(BM_PathAverage);

void BM_DiskGaussianTable(benchmark::State& state) {
  const PathTables& t = tables();
  Pcg32 rng(3, 4);
  double sum = 0;
  for (auto _ : state)
    sum += t.disk_gaussian_table(3 * rng.uniform(), 2 * rng.uniform());
  benchmark::DoNotOptimize(sum);
}
BENCHMARK(BM_DiskGaussianTable);

void BM_DiskGaussianExact(benchmark::State& state) {
  Pcg32 rng(5, 6);
  double sum = 0;
  for (auto _ : state)
    sum += disk_gaussian(3 * rng.uniform(), 2 * rng.uniform());
  benchmark::DoNotOptimize(sum);
}
BENCHMARK(BM_DiskGaussianExact);

void BM_ArcFractions(benchmark::State& state) {
  LightDesc d;
  d.direction = vec3(0, 0.2, -1);
  d.angular_radius_deg = 0.27;
  const LightModel light(d);
  Pcg32 rng(7, 8);
  double sum = 0;
  for (auto _ : state) {
    const vec3 r0 = light.from_plane(vec2(rng.uniform() - 0.5, rng.uniform() - 0.5) * 0.02);
    const vec3 r1 = light.from_plane(vec2(rng.uniform() - 0.5, rng.uniform() - 0.5) * 0.02);
    sum += arc_fractions(r0, r1, light).in_light;
  }
  benchmark::DoNotOptimize(sum);
}
BENCHMARK(BM_ArcFractions);

}  // namespace
}  // namespace sg

BENCHMARK_MAIN();
