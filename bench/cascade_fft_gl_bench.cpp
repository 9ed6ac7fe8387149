// The GL engine's per-frame cascade FFT (gl_engine/cascade_fft_gl.h): one cascade's
// spectra and inverse 2-D FFT at lattices of 64 to 512; and a frame's fields of the
// default four-cascade ocean (gl_engine/cascade_fields_gl.h: the transforms at the display
// time and the shutter's start, the chains, the bounds) at lattices of 64 and 256; timed on
// the GPU by timestamp queries (gl/timer.h), on whatever context EGL gives (llvmpipe here,
// a GPU on a GPU machine). docs/benchmarks.md.
#include <benchmark/benchmark.h>

#include <memory>

#include "gl/context.h"
#include "gl/timer.h"
#include "gl_engine/cascade_fft_gl.h"
#include "gl_engine/cascade_fields_gl.h"
#include "ocean/lattice_ocean.h"
#include "shading/kernel_frame.h"

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
  sg::gl::GpuTimer timer;
  double t = 0;
  for (auto _ : state) {
    const double ms = timer.time([&] { fft.evaluate(t += 1.0 / 30); });
    state.SetIterationTime(ms / 1000);
  }
  state.SetLabel(context().info().gl_renderer);
}
BENCHMARK(BM_CascadeFftGl)
    ->Arg(64)
    ->Arg(256)
    ->Arg(512)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

void BM_CascadeFieldsGl(benchmark::State& state) {
  context();
  sg::ocean::OceanParams p;
  sg::ocean::CascadeParams c;
  c.lattice = static_cast<int>(state.range(0));
  const sg::ocean::LatticeOcean o = sg::ocean::generate_lattice(p, c);
  sg::Scene s;
  s.surface.waves.clear();
  s.surface.cascades = o.cascades;
  s.surface.depth = o.depth;
  const sg::SceneModel m(s);
  sg::KernelInputsF in;
  sg::gl_engine::CascadeFieldsGl fields;
  double t = 0;
  auto frame = [&] {
    const sg::FrameTime ft{0, t, t + 1.0 / 60};
    t += 1.0 / 30;
    sg::build_kernel_inputs(m, ft, 1, 0, in, 0.25, 1, true, sg::CascadeData::layout);
    return ft;
  };
  sg::FrameTime ft = frame();
  sg::gl::Buffer waves(in.cascades->layout().end * 16);
  fields.fill(m, ft, 1, in.cascades->layout(), waves);  // warm up
  sg::gl::GpuTimer timer;
  for (auto _ : state) {
    ft = frame();
    const double ms = timer.time([&] { fields.fill(m, ft, 1, in.cascades->layout(), waves); });
    state.SetIterationTime(ms / 1000);
  }
  state.SetLabel("4 cascades, K = 1, " + context().info().gl_renderer);
}
BENCHMARK(BM_CascadeFieldsGl)->Arg(64)->Arg(256)->UseManualTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
