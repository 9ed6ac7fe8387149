// The GL engine's per-frame cascade FFT (gl_engine/cascade_fft_gl.h): one cascade's
// spectra, inverse 2-D FFT and moment chain at lattices of 64 to 512, timed on the GPU by
// timestamp queries (gl/timer.h), on whatever context EGL gives (llvmpipe here, a GPU on a
// GPU machine). docs/benchmarks.md.
#include <benchmark/benchmark.h>

#include <memory>

#include "gl/context.h"
#include "gl/timer.h"
#include "gl_engine/cascade_fft_gl.h"
#include "ocean/lattice_ocean.h"

namespace {

sg::gl::HeadlessContext& context() {
  static sg::gl::HeadlessContext ctx;
  return ctx;
}

void BM_CascadeFftGl(benchmark::State& state) {
  context();
  sg::ocean::OceanParams p;
  sg::ocean::CascadeParams c;
  c.lattice = static_cast<int>(state.range(0));
  const sg::ocean::LatticeOcean o = sg::ocean::generate_lattice(p, c);
  sg::gl_engine::CascadeFftGl fft(c.lattice);
  fft.set_lattice(o.cascades[1], sg::Dispersion{o.depth}, 0.0);
  fft.evaluate(0.0);  // warm up
  fft.build_moments();
  sg::gl::GpuTimer timer;
  double t = 0;
  for (auto _ : state) {
    const double ms = timer.time([&] {
      fft.evaluate(t += 1.0 / 30);
      if (state.range(1)) fft.build_moments();
    });
    state.SetIterationTime(ms / 1000);
  }
  state.SetLabel(std::string(state.range(1) ? "fft + moment chain" : "fft") + ", " +
                 context().info().gl_renderer);
}
BENCHMARK(BM_CascadeFftGl)
    ->ArgsProduct({{64, 256, 512}, {0, 1}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
