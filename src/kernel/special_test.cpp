// The kernel's replacements for functions GLSL lacks (kernel/special.glsl) against the
// standard library, in both precisions, with the bounds the kernel states.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "kernel/kernel_double.h"
#include "kernel/kernel_float.h"

namespace sg {
namespace {

TEST(KernelSpecial, ErfcMatchesTheStandardLibraryInDouble) {
  // Relative error below 1e-13 on [-6, 26]: the Chebyshev expansion holds 1e-17, the rest
  // is the rounding of x^2 in exp(-x^2) (relative 2 x^2 eps).
  double worst = 0, at = 0;
  for (int k = 0; k <= 320000; ++k) {
    const double x = -6 + 32.0 * k / 320000;
    const double want = std::erfc(x);
    if (want < 1e-300) continue;
    const double err = std::fabs(kd::erfc(x) - want) / want;
    if (err > worst) worst = err, at = x;
  }
  std::printf("kernel erfc, double: max relative error %.3g at x = %.4f\n", worst, at);
  EXPECT_LT(worst, 1e-13);
  // Near 0, where erfc is about 1, the error is at rounding.
  for (double x : {-0.5, -1e-8, 0.0, 1e-8, 0.25, 0.5, 1.0})
    EXPECT_NEAR(kd::erfc(x), std::erfc(x), 4e-16) << x;
  EXPECT_EQ(kd::erfc(30.0), 0.0);
  EXPECT_EQ(kd::erfc(-30.0), 2.0);
}

TEST(KernelSpecial, ErfcMatchesTheStandardLibraryInFloat) {
  // In float: relative error below 2e-6 on [-6, 3] (beyond, float's exp(-x^2) carries
  // 2 x^2 2^-24 of rounding, 1e-5 at x = 9); absolute error below 5e-7 everywhere (about
  // 4 ulp of erfc near 1).
  double worst_rel = 0, worst_abs = 0;
  for (int k = 0; k <= 40000; ++k) {
    const float x = static_cast<float>(-6 + 16.0 * k / 40000);
    const double want = std::erfc(double(x));
    const double got = kf::float_erfc(x);
    worst_abs = std::max(worst_abs, std::fabs(got - want));
    if (want > 1e-30 && x < 3.0f) worst_rel = std::max(worst_rel, std::fabs(got - want) / want);
  }
  std::printf("kernel erfc, float: max relative error %.3g on [-6, 3], absolute %.3g\n", worst_rel,
              worst_abs);
  EXPECT_LT(worst_rel, 2e-6);
  EXPECT_LT(worst_abs, 5e-7);
}

TEST(KernelSpecial, NormalMassAndIntervalAgreeWithTheStandardLibrary) {
  auto phi = [](double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); };
  for (double a : {-12.0, -9.5, -3.0, -0.5, 0.0, 0.7, 4.0, 8.9})
    for (double b : {-8.0, -1.0, 0.0, 0.3, 2.5, 9.5, 20.0}) {
      if (b < a) continue;
      // The tails beyond 9 standard deviations are dropped (below 1.2e-19).
      EXPECT_NEAR(kd::normal_mass(a, b), phi(b) - phi(a), 2e-16 + 2e-19) << a << " " << b;
    }
  EXPECT_DOUBLE_EQ(kd::normal_interval(-1.0, 1.0, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(kd::normal_interval(0.5, 1.0, 0.0), 0.0);
  EXPECT_NEAR(kd::normal_interval(-2.0, 1.0, 2.0), phi(0.5) - phi(-1.0), 1e-15);
}

TEST(KernelSpecial, WrapAngleReducesToPlusMinusPi) {
  for (double x : {0.0, 1.0, -3.0, 3.2, 100.0, -1234.5, 39000.0, 1e6}) {
    const double r = kd::wrap_angle(x);
    EXPECT_LE(std::fabs(r), kd::kPi + 1e-12) << x;
    EXPECT_NEAR(std::sin(r), std::sin(x), 1e-15 * std::max(1.0, std::fabs(x))) << x;
    EXPECT_NEAR(std::cos(r), std::cos(x), 1e-15 * std::max(1.0, std::fabs(x))) << x;
  }
}

TEST(KernelSpecial, SincIsAccurateNearZero) {
  for (double x : {0.0, 1e-8, 1e-5, 9.9e-5, 1e-4, 0.3, 2.0}) {
    const double want = x == 0 ? 1.0 : std::sin(x) / x;
    EXPECT_NEAR(kd::sinc(x), want, 1e-15) << x;
  }
}

TEST(KernelSpecial, NormalQuantileInvertsTheCdf) {
  // Round trip through the standard library's CDF, from the far lower tail to the upper.
  double worst = 0;
  for (double x = -12.0; x <= 5.0; x += 0.01) {
    const double p = 0.5 * std::erfc(-x / std::sqrt(2.0));
    const double got = kd::normal_quantile(p);
    worst = std::max(worst, std::fabs(got - x) / std::max(1.0, std::fabs(x)));
  }
  std::printf("normal_quantile: worst relative error %.2e on [-12, 5]\n", worst);
  EXPECT_LT(worst, 2e-9);
  // Float: the lower tail keeps its digits (log p, not log of a difference).
  for (double x : {-9.0, -4.0, -1.0, 0.0, 1.5}) {
    const float p = static_cast<float>(0.5 * std::erfc(-x / std::sqrt(2.0)));
    EXPECT_NEAR(kf::float_normal_quantile(p), x, 2e-5 * std::max(1.0, std::fabs(x))) << x;
  }
}

TEST(KernelSpecial, ExpMinusOneKeepsItsDigitsNearZero) {
  // Against std::expm1 over |u| in [1e-12, 40], both signs: double to 2 ulp of e^u - 1
  // everywhere; float to 4 ulp (exp(u) - 1 would lose 2^-24 / |u| of it near 0: 0.6 for
  // u = 1e-7).
  double worst_d = 0, worst_f = 0;
  for (int k = 0; k <= 20000; ++k) {
    for (double sign : {-1.0, 1.0}) {
      const double u = sign * std::pow(10.0, -12 + 13.6 * k / 20000);
      const double want = std::expm1(u);
      worst_d = std::max(worst_d, std::fabs(kd::exp_minus_one(u) - want) / std::fabs(want));
      const float uf = static_cast<float>(u);
      const double want_f = std::expm1(double(uf));
      worst_f = std::max(
          worst_f, std::fabs(double(kf::float_exp_minus_one(uf)) - want_f) / std::fabs(want_f));
    }
  }
  std::printf("exp_minus_one: max relative error %.3g (double), %.3g (float)\n", worst_d, worst_f);
  EXPECT_LT(worst_d, 4.5e-16);
  EXPECT_LT(worst_f, 4.8e-7);
  EXPECT_EQ(kd::exp_minus_one(0.0), 0.0);
}

TEST(KernelSpecial, SkySharesKeepTheirDigitsEachWay) {
  // The sky's zenith share y^e and horizon share 1 - y^e, each to a few ulp of itself in
  // float against double's log1p/expm1, for flat exponents (the horizon's share tiny) and
  // steep ones (the zenith's tiny). 1 - pow(y, e) in float errs by 2^-24 / (e |ln y|) of
  // the horizon's share: 8e-4 for e = 0.004, y = 0.98.
  double worst_z = 0, worst_h = 0;
  for (double e : {0.004, 0.05, 0.5, 2.0, 8.0}) {
    kd::Frame fd{};
    fd.sky_gradient = true;
    fd.sky_exponent = e;
    kf::Frame ff{};
    ff.sky_gradient = true;
    ff.sky_exponent = static_cast<float>(e);
    for (double y : {1e-6, 0.01, 0.2, 0.7, 0.98, 0.9999}) {
      const float yf = static_cast<float>(y);
      const double u = double(ff.sky_exponent) * std::log(double(yf));
      const double z = std::exp(u), h = -std::expm1(u);
      const kd::vec2 d = kd::sky_shares(fd, y);
      const kf::vec2 g = kf::float_sky_shares(ff, yf);
      EXPECT_NEAR(d.x + d.y, 1.0, 1e-15);
      if (z < 1e-30) {  // float underflows there (y^8 for y = 1e-6)
        EXPECT_LT(g.x, 1e-30);
        continue;
      }
      worst_z = std::max(worst_z, std::fabs(g.x - z) / z);
      worst_h = std::max(worst_h, std::fabs(g.y - h) / h);
    }
  }
  std::printf("sky shares in float: max relative error zenith %.3g, horizon %.3g\n", worst_z,
              worst_h);
  EXPECT_LT(worst_z, 1e-6);
  EXPECT_LT(worst_h, 1e-6);
}

}  // namespace
}  // namespace sg
