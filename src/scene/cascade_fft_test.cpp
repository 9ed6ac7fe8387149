// The cascades' FFT (scene/cascade_fft.h) against an analytic impulse, a naive DFT and the
// direct sum of the lattice's sines at random grid points and times (the Nyquist rows
// included); a grid kept from call to call against a fresh one. (The moment chain built from
// the grid is tested where it is written: kernel/cascade_fields_test.cpp.)
#include "scene/cascade_fft.h"

#include <gtest/gtest.h>

#include <cmath>

#include "math/rng.h"
#include "scene/scene.h"
#include "testing/lattice.h"

namespace sg {
namespace {

using testing::full_cascade;

TEST(CascadeFft, InverseTransformIsTheNaiveDft) {
  const int n = 8;
  CascadeFft fft(n);
  Pcg32 rng(1, 1);
  std::vector<std::complex<double>> in(n * n);
  for (auto& v : in)
    v = {rng.uniform() - 0.5, rng.uniform() - 0.5};
  std::vector<std::complex<double>> out = in;
  fft.inverse_2d(out);
  for (int q = 0; q < n; ++q) {
    for (int p = 0; p < n; ++p) {
      std::complex<double> s = 0;
      for (int b = 0; b < n; ++b)
        for (int a = 0; a < n; ++a)
          s += in[b * n + a] * std::polar(1.0, kTwoPi * (a * p + b * q) / n);
      EXPECT_NEAR(std::abs(out[q * n + p] - s), 0, 1e-13);
    }
  }
}

TEST(CascadeFft, ImpulseIsOneSine) {
  // One lattice point (m, n) = (3, -2) of amplitude 0.5: h = 0.5 sin(k.x + omega t + phi)
  // exactly, slopes 0.5 k cos(...), at every grid point.
  const int n = 16;
  const double L = 40, t = 1.7, phi = 0.3;
  CascadeDesc c;
  c.patch_size = L;
  c.lattice = n;
  auto d = std::make_shared<LatticeData>();
  d->n = n;
  d->amplitude.assign(n * n, 0.0);
  d->phase.assign(n * n, 0.0);
  const int i = 3, j = n - 2;
  d->amplitude[j * n + i] = 0.5;
  d->phase[j * n + i] = phi;
  c.data = d;
  const Dispersion water{12};
  const CascadeGrid g = CascadeFft(n).evaluate(c, water, t);
  const vec2 k = lattice_wave_vector(L, n, i, j);
  const double w = water.omega(length(k));
  for (int q = 0; q < n; ++q) {
    for (int p = 0; p < n; ++p) {
      const double x = p * L / n, z = q * L / n, th = k.x * x + k.y * z + w * t + phi;
      EXPECT_NEAR(g.height[q * n + p], 0.5 * std::sin(th), 1e-14);
      EXPECT_NEAR(g.slope_x[q * n + p], 0.5 * k.x * std::cos(th), 1e-14);
      EXPECT_NEAR(g.slope_z[q * n + p], 0.5 * k.y * std::cos(th), 1e-14);
    }
  }
}

TEST(CascadeFft, GridIsTheDirectSumOfTheLatticesSines) {
  for (int n : {16, 64}) {
    const CascadeDesc c = full_cascade(n, 50, static_cast<uint64_t>(n));
    const Dispersion water{};
    std::vector<Wave> waves = cascade_waves(c, water);
    ASSERT_EQ(waves.size(), static_cast<size_t>(n * n - 1));
    double amp_sum = 0, slope_sum = 0;
    for (const Wave& w : waves) {
      amp_sum += w.amplitude;
      slope_sum += w.amplitude * length(w.wave_vector);
    }
    CascadeFft fft(n);
    Pcg32 rng(7, static_cast<uint64_t>(n));
    double worst_h = 0, worst_s = 0;
    for (int trial = 0; trial < 4; ++trial) {
      const double t = 100 * rng.uniform();
      const CascadeGrid g = fft.evaluate(c, water, t);
      for (int s = 0; s < 40; ++s) {
        const int p = static_cast<int>(rng.uniform() * n), q = static_cast<int>(rng.uniform() * n);
        const double x = p * c.patch_size / n, z = q * c.patch_size / n;
        double h = 0, sx = 0, sz = 0;
        for (const Wave& w : waves) {
          const double th =
              w.wave_vector.x * x + w.wave_vector.y * z + w.angular_frequency * t + w.phase;
          h += w.amplitude * std::sin(th);
          sx += w.amplitude * w.wave_vector.x * std::cos(th);
          sz += w.amplitude * w.wave_vector.y * std::cos(th);
        }
        worst_h = std::max(worst_h, std::fabs(g.height[q * n + p] - h));
        worst_s = std::max(worst_s, std::max(std::fabs(g.slope_x[q * n + p] - sx),
                                             std::fabs(g.slope_z[q * n + p] - sz)));
      }
    }
    // Double rounding: the phases' (omega t ~ 1e3 rad) dominate.
    EXPECT_LT(worst_h, 1e-11 * amp_sum) << n;
    EXPECT_LT(worst_s, 1e-11 * slope_sum) << n;
    std::printf("lattice %d: max |FFT - direct| height %.3g (sum A %.3g), slope %.3g\n", n, worst_h,
                amp_sum, worst_s);
  }
}

// The curvatures (the third transform) against the direct sum of -A k_i k_j sin: a full
// lattice, Nyquist rows included, where the mirror's factor k_m differs from -k; the
// slopes-only transform against the slopes of the two-transform evaluation.
TEST(CascadeFft, CurvaturesAreTheDirectSum) {
  for (int n : {8, 32}) {
    const CascadeDesc c = full_cascade(n, 30, static_cast<uint64_t>(n) + 11);
    const Dispersion water{};
    const std::vector<Wave> waves = cascade_waves(c, water);
    double bound = 0;
    for (const Wave& w : waves)
      bound += w.amplitude * dot(w.wave_vector, w.wave_vector);
    CascadeFft fft(n);
    const double t = 3.7;
    const CascadeGrid g = fft.evaluate(c, water, t);
    fft.set_lattice(c, water);
    const CascadeGrid gc = fft.evaluate(t, true);
    const CascadeGrid gs = fft.evaluate_slopes(t);
    ASSERT_EQ(gc.curv_xx.size(), static_cast<size_t>(n * n));
    EXPECT_TRUE(gs.height.empty());
    EXPECT_TRUE(g.curv_xx.empty());
    double worst = 0;
    for (int q = 0; q < n; ++q) {
      for (int p = 0; p < n; ++p) {
        const double x = p * c.patch_size / n, z = q * c.patch_size / n;
        double hxx = 0, hxz = 0, hzz = 0;
        for (const Wave& w : waves) {
          const vec2 k = w.wave_vector;
          const double s =
              w.amplitude * std::sin(k.x * x + k.y * z + w.angular_frequency * t + w.phase);
          hxx -= s * k.x * k.x;
          hxz -= s * k.x * k.y;
          hzz -= s * k.y * k.y;
        }
        const size_t e = static_cast<size_t>(q) * n + p;
        worst = std::max({worst, std::fabs(gc.curv_xx[e] - hxx), std::fabs(gc.curv_xz[e] - hxz),
                          std::fabs(gc.curv_zz[e] - hzz)});
        // The slopes are unchanged by the extra transform.
        EXPECT_NEAR(gc.slope_z[e], g.slope_z[e], 1e-13 * bound);
        EXPECT_NEAR(gc.slope_x[e], g.slope_x[e], 1e-13 * bound);
        // And the slopes-only transform gives them too.
        EXPECT_NEAR(gs.slope_x[e], g.slope_x[e], 1e-13 * bound);
        EXPECT_NEAR(gs.slope_z[e], g.slope_z[e], 1e-13 * bound);
      }
    }
    EXPECT_LT(worst, 1e-12 * bound) << n;
    std::printf("lattice %d: max |FFT - direct| curvature %.3g (sum A k^2 %.3g)\n", n, worst,
                bound);
  }
}

TEST(CascadeFft, ReusedGridIsTheFreshOne) {
  // A frame's fields evaluate into the same grid at every instant (the display time's with
  // curvatures, the others' slopes alone): whatever the grid held before, the result is the
  // fresh evaluation's, bit for bit, and a slopes-only grid holds no stale curvature.
  const int n = 16;
  const CascadeDesc c = full_cascade(n, 25, 9);
  CascadeFft fft(n);
  fft.set_lattice(c, Dispersion{});
  CascadeGrid grid;
  for (int round = 0; round < 2; ++round) {
    for (const bool curvatures : {true, false}) {
      const double t = 1.5 + round + (curvatures ? 0.0 : 0.25);
      if (curvatures) {
        fft.evaluate(t, true, grid);
      } else {
        fft.evaluate_slopes(t, grid);
      }
      const CascadeGrid fresh = curvatures ? fft.evaluate(t, true) : fft.evaluate_slopes(t);
      EXPECT_EQ(grid.slope_x, fresh.slope_x);
      EXPECT_EQ(grid.slope_z, fresh.slope_z);
      EXPECT_EQ(grid.height, fresh.height);
      EXPECT_EQ(grid.curv_xz, fresh.curv_xz);
      EXPECT_EQ(grid.curv_xx, fresh.curv_xx);
      EXPECT_EQ(grid.curv_zz, fresh.curv_zz);
      EXPECT_EQ(grid.curv_xx.empty(), !curvatures);
    }
  }
}

}  // namespace
}  // namespace sg
