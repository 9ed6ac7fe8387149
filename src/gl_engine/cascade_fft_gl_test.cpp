// The GL engine's cascade FFT (gl_engine/cascade_fft_gl.h) against the CPU's in double
// (scene/cascade_fft.h): the height and slopes of random full lattices (the Nyquist rows
// included) at a time far from the origin, a single lattice point against its sine, and the
// moment chain level by level. The bounds are float's: a few 1e-7 of the sums of the
// amplitudes (height) and of the steepnesses (slopes) per FFT stage (1e-7: llvmpipe measured
// 1.5e-8 to 3e-8 of the sums, and a GPU's sine and cosine are less exact than its).
#include "gl_engine/cascade_fft_gl.h"

#include <gtest/gtest.h>

#include "testing/lattice.h"

#include <cmath>

#include "gl/dispatch.h"
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
  for (int n : {16, 64, 256}) {
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

TEST_F(CascadeFftGlTest, MomentChainIsTheCpusOfTheSameField) {
  const int n = 64;
  const CascadeDesc c = full_cascade(n, 50.0, 3);
  CascadeFftGl gl(n);
  gl.set_lattice(c, Dispersion{}, 0.0);
  gl.evaluate(2.0);
  gl.build_moments();
  const std::vector<MomentLevel> got = gl.read_moments();
  const std::vector<MomentLevel> want = moment_chain(gl.read_field());
  ASSERT_EQ(got.size(), want.size());
  ASSERT_EQ(got.size(), 7u);
  for (size_t l = 0; l < got.size(); ++l) {
    ASSERT_EQ(got[l].n, want[l].n);
    double scale = 0;
    for (double v : want[0].mxx)
      scale = std::max(scale, v);
    for (auto [a, b] : {std::pair{&got[l].mx, &want[l].mx},
                        {&got[l].mz, &want[l].mz},
                        {&got[l].mxx, &want[l].mxx},
                        {&got[l].mxz, &want[l].mxz},
                        {&got[l].mzz, &want[l].mzz}}) {
      EXPECT_LT(max_abs_diff(*a, *b), 1e-6 * scale) << "level " << l;
    }
  }
}

}  // namespace
}  // namespace sg::gl_engine
