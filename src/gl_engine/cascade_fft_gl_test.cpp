// The GL engine's cascade FFT (gl_engine/cascade_fft_gl.h) against the CPU's in double
// (scene/cascade_fft.h): the height and slopes of random full lattices (the Nyquist rows
// included) at a time far from the origin, a single lattice point against its sine, and the
// fields' texels in the wave buffer (gl_engine/cascade_fields_gl.h) against the host's. The bounds
// are float's: a few 1e-7 of the sums of the amplitudes (height) and of the steepnesses (slopes)
// per FFT stage (1e-7: llvmpipe measured 1.5e-8 to 3e-8 of the sums, and a GPU's sine and cosine
// are less exact than its).
#include "gl_engine/cascade_fft_gl.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "gl_engine/cascade_fields_gl.h"
#include "shading/kernel_frame.h"
#include "testing/lattice.h"
#include "testing/testing.h"

#include "gl/dispatch.h"
#include "kernel/kernel_double.h"
#include "math/rng.h"
#include "testing/gl_context.h"

namespace sg::gl_engine {
namespace {

using testing::full_cascade;

using CascadeFftGlTest = sg::testing::GlTest;

double max_abs_diff(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0;
  for (size_t e = 0; e < a.size(); ++e)
    m = std::max(m, std::fabs(a[e] - b[e]));
  return m;
}

TEST_F(CascadeFftGlTest, FieldIsTheCpusWithinFloat) {
  // Every lattice the GL transform takes, 4 to 1024: radix 4 alone where log2 N is even,
  // with the one radix-2 pass where it is odd.
  for (int n : {4, 8, 16, 32, 64, 128, 256, 512, 1024}) {
    const CascadeDesc c = full_cascade(n, 37.0, static_cast<uint64_t>(n));
    const Dispersion water{25};
    // A time 10^4 s from zero, 0.7 s after the GL's origin.
    const double t0 = 1.0e4, t = t0 + 0.7;
    CascadeFftGl gl(n);
    gl.set_lattice(c, water, t0);
    gl.evaluate(t);
    const CascadeGrid g = gl.read_field();
    const CascadeGrid want = CascadeFft(n).evaluate(c, water, t);
    double amp_sum = 0, slope_sum = 0;
    for (size_t e = 0; e < c.data->amplitude.size(); ++e) {
      amp_sum += c.data->amplitude[e];
      slope_sum += c.data->amplitude[e] *
                   length(lattice_wave_vector(c.patch_size, n, static_cast<int>(e % n),
                                              static_cast<int>(e / n)));
    }
    const double stages = std::log2(n);
    const double dh = max_abs_diff(g.height, want.height);
    const double ds =
        std::max(max_abs_diff(g.slope_x, want.slope_x), max_abs_diff(g.slope_z, want.slope_z));
    std::printf(
        "lattice %d: max |GL - CPU| height %.3g (%.3g of sum A), slopes %.3g (%.3g of "
        "the steepnesses' sum)\n",
        n, dh, dh / amp_sum, ds, ds / slope_sum);
    EXPECT_LT(dh, 1e-7 * stages * amp_sum) << n;
    EXPECT_LT(ds, 1e-7 * stages * slope_sum) << n;
    // Not vacuous: the field is far from zero.
    EXPECT_GT(max_abs_diff(want.height, std::vector<double>(want.height.size(), 0.0)),
              1e-3 * amp_sum / n);
  }
}

TEST_F(CascadeFftGlTest, OneLatticePointIsItsSine) {
  const int n = 32;
  const double L = 20, t = 3.3;
  CascadeDesc c;
  c.patch_size = L;
  c.lattice = n;
  auto d = std::make_shared<LatticeData>();
  d->n = n;
  d->amplitude.assign(n * n, 0.0);
  d->phase.assign(n * n, 0.0);
  const int i = n / 2, j = 5;  // the Nyquist column: m = -16
  d->amplitude[j * n + i] = 0.25;
  d->phase[j * n + i] = 1.1;
  c.data = d;
  CascadeFftGl gl(n);
  gl.set_lattice(c, Dispersion{}, 0.0);
  gl.evaluate(t);
  const CascadeGrid g = gl.read_field();
  const vec2 k = lattice_wave_vector(L, n, i, j);
  const double w = Dispersion{}.omega(length(k));
  for (int q = 0; q < n; ++q) {
    for (int p = 0; p < n; ++p) {
      const double th = k.x * p * L / n + k.y * q * L / n + w * t + 1.1;
      ASSERT_NEAR(g.height[q * n + p], 0.25 * std::sin(th), 2e-6) << p << "," << q;
      ASSERT_NEAR(g.slope_x[q * n + p], 0.25 * k.x * std::cos(th), 2e-5) << p << "," << q;
      ASSERT_NEAR(g.slope_z[q * n + p], 0.25 * k.y * std::cos(th), 2e-5) << p << "," << q;
    }
  }
}

TEST_F(CascadeFftGlTest, FieldsAreTheHostsTexels) {
  // Two random full cascades (lattices 16 and 8, on grids of 128 and 64) under the smooth
  // scene's camera, at a time 10^4 s + 3.3 s (the GPU's time origin 10^4 + 0), with K = 1,
  // 2, 3 and 4 path instants (the display time's two transforms, the slopes paired or
  // alone) and a zero shutter (the display time's chain copied to every instant), for each
  // method's reads (shading/cascade_fields.h, CascadeReads: the whole fields, level 0 of
  // every instant, level 0 of the display time): every texel built that the GL engine's
  // transforms write into the wave buffer against the host's
  // (shading/cascade_fields.h, double rounded to float), component by component, within
  // float's error relative to the largest value of that component; the headers, the
  // bounds' texels and the frame's bounds against the host's. Displaced water (whose path
  // instants hold their heights), then flat.
  Scene s = testing::project_scene("smooth");
  s.surface.waves.clear();
  s.surface.cascades = {full_cascade(16, 30.0, 1), full_cascade(8, 7.0, 2)};
  s.surface.geometry = Geometry::displaced;
  const SceneModel m(s);
  CascadeFieldsGl gl;
  auto check = [&](const SceneModel& m, CascadeReads reads, int segments, double shutter) {
    const FrameTime ft{0, 1.0e4 + 3.3 - shutter, 1.0e4 + 3.3};
    KernelInputsF host, gpu;
    build_kernel_inputs(m, ft, segments, 0, host, 0.25, 1, true, CascadeData::host, reads);
    build_kernel_inputs(m, ft, segments, 0, gpu, 0.25, 1, true, CascadeData::layout, reads);
    const CascadeLayout& layout = gpu.cascades->layout();
    ASSERT_EQ(layout.end, host.texels.size());
    ASSERT_EQ(gpu.frame.cascade_base, host.frame.cascade_base);
    gl::Buffer waves(layout.end * 16);
    waves.fill(0x7fc00000u);  // NaN: a texel left unwritten fails
    const std::vector<glm::dvec3> bounds = gl.fill(m, ft, segments, layout, waves, reads);
    set_cascade_bounds(m, bounds, gpu);
    std::vector<float> got = waves.read<float>();
    for (size_t i = 0; i < gpu.texels.size(); ++i)
      for (int c = 0; c < 4; ++c)
        got[4 * i + c] = gpu.texels[i][c];
    // The texels the reads build: all of them, or level 0 of the instants read.
    auto built = [&](size_t i) {
      if (reads == CascadeReads::all || i < layout.data[0]) return true;
      for (size_t c = 0; c < layout.data.size(); ++c) {
        const size_t n = static_cast<size_t>(layout.grid[c]);
        const size_t per = static_cast<size_t>(kd::cascade_instant_texels(int(n)));
        for (int k = 0; k <= segments; ++k) {
          if (k < segments && reads == CascadeReads::display_level0) continue;
          const size_t at = layout.data[c] + static_cast<size_t>(k) * per;
          if (i >= at && i < at + 2 * n * n) return true;
        }
      }
      return false;
    };
    // The largest value of each of the eight components of a data texel pair.
    std::array<double, 8> scale{};
    for (size_t i = layout.data[0]; i < layout.end; ++i)
      for (int c = 0; c < 4; ++c)
        scale[4 * ((i - layout.data[0]) % 2) + c] = std::max(
            scale[4 * ((i - layout.data[0]) % 2) + c], double(std::fabs(host.texels[i][c])));
    double worst = 0;
    size_t compared = 0;
    for (size_t i = size_t(host.frame.cascade_base); i < layout.end; ++i) {
      if (!built(i)) continue;
      ++compared;
      for (int c = 0; c < 4; ++c) {
        const double want = host.texels[i][c], have = got[4 * i + c];
        ASSERT_TRUE(std::isfinite(have)) << "texel " << i << "." << c;
        if (i < layout.data[0]) {
          EXPECT_NEAR(have, want, 1e-5 * std::fabs(want) + 1e-12) << "header " << i << "." << c;
          continue;
        }
        const double sc = scale[4 * ((i - layout.data[0]) % 2) + c];
        worst = std::max(worst, sc > 0 ? std::fabs(have - want) / sc : std::fabs(have - want));
      }
    }
    std::printf(
        "reads %d, K = %d, shutter %.2f: %zu texels, largest |GL - host| over the component's "
        "largest %.3g\n",
        int(reads), segments, shutter, compared, worst);
    EXPECT_LT(worst, 2e-5) << segments << " " << shutter;
    EXPECT_NEAR(gpu.frame.amplitude_bound, host.frame.amplitude_bound,
                1e-5 * host.frame.amplitude_bound);
    EXPECT_NEAR(gpu.frame.slope_bound, host.frame.slope_bound, 1e-5 * host.frame.slope_bound);
  };
  for (const CascadeReads reads :
       {CascadeReads::all, CascadeReads::instants_level0, CascadeReads::display_level0}) {
    for (const int segments : {1, 2, 3, 4})
      for (const double shutter : {0.0, 0.04})
        check(m, reads, segments, shutter);
  }
  // Another sea of the same sizes through the same transforms (the viewer's wind
  // regenerates the lattices so): its own lattices, not the last model's.
  s.surface.cascades = {full_cascade(16, 30.0, 7), full_cascade(8, 7.0, 8)};
  check(SceneModel(s), CascadeReads::all, 2, 0.04);
  // Flat water, whose other instants hold their slopes alone (two to a transform; on
  // displaced water each instant's height too, one transform an instant).
  s.surface.geometry = Geometry::flat;
  const SceneModel flat(s);
  for (const CascadeReads reads : {CascadeReads::all, CascadeReads::instants_level0})
    for (const int segments : {1, 2, 3})
      check(flat, reads, segments, 0.04);
}

}  // namespace
}  // namespace sg::gl_engine
