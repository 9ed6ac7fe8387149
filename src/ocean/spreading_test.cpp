// The spreading functions against their formulas: the parameters at hand-picked
// frequencies, the densities' normalisation, and the sampler as the inverse of the
// density's cumulative distribution (integrated numerically here).
#include "ocean/spreading.h"

#include <gtest/gtest.h>

#include <boost/math/special_functions/beta.hpp>

#include <cmath>

#include "math/vec.h"
#include "scene/dispersion.h"
#include "testing/quadrature.h"

namespace sg::ocean {
namespace {

// A JONSWAP sea of 10 m/s over 100 km: omega_p = 1.0391 rad/s, c_p = g / omega_p.
Spreading spreading(SpreadingKind kind) {
  Spreading d;
  d.kind = kind;
  d.omega_peak = 1.0391210620086602;
  d.wind_speed = 10;
  d.peak_speed = kGravity / d.omega_peak;
  return d;
}

TEST(Spreading, ParametersAtHandPickedFrequencies) {
  const double wp = 1.0391210620086602;
  // Mitsuyasu: s_p = 11.5 (omega_p U / g)^-2.5; exponents 5 below, -2.5 above.
  const Spreading c = spreading(SpreadingKind::cos2s);
  EXPECT_NEAR(c.parameter(wp), 9.958753657416288, 1e-12);
  EXPECT_NEAR(c.parameter(0.5 * wp), 0.311211051794259, 1e-12);
  EXPECT_NEAR(c.parameter(2 * wp), 1.7604755608313474, 1e-12);
  // Hasselmann et al. 1980: 6.97 (omega / omega_p)^4.06 below, mu = -2.33 - 1.45 (U / c_p
  // - 1.17) = -2.1694 above.
  const Spreading h = spreading(SpreadingKind::hasselmann);
  EXPECT_NEAR(h.parameter(wp), 6.97, 1e-12);
  EXPECT_NEAR(h.parameter(0.5 * wp), 0.4178794319810684, 1e-12);
  EXPECT_NEAR(h.parameter(2 * wp), 1.549444273035273, 1e-12);
  // Donelan et al. 1985 and Banner 1990.
  const Spreading d = spreading(SpreadingKind::donelan_banner);
  EXPECT_NEAR(d.parameter(0.8 * wp), 1.9527987590536333, 1e-12);
  EXPECT_NEAR(d.parameter(1.2 * wp), 1.7988677138982403, 1e-12);
  EXPECT_NEAR(d.parameter(2.0 * wp), 0.9603456696593401, 1e-12);
  // Banner's branch meets Donelan's at 1.6 omega_p (to the fits' three digits).
  EXPECT_NEAR(d.parameter(1.6 * wp * (1 - 1e-12)), d.parameter(1.6 * wp), 2e-3);
  // A given s_p (a swell's s_max) replaces Mitsuyasu's.
  Spreading sw = c;
  sw.s_peak = 75;
  EXPECT_DOUBLE_EQ(sw.parameter(wp), 75);
}

TEST(Spreading, Cos2sNormalisation) {
  EXPECT_NEAR(cos2s_normalisation(1), 1 / kPi, 1e-15);     // int cos^2(t/2) = pi
  EXPECT_NEAR(cos2s_normalisation(0), 1 / kTwoPi, 1e-15);  // uniform
  EXPECT_NEAR(cos2s_normalisation(10), 0.9032781268674752, 1e-13);
}

TEST(Spreading, SymmetricBetaQuantileIsBoosts) {
  for (double a : {0.5, 0.51, 0.8, 1.0, 2.3, 10.46, 75.5, 200.5}) {
    for (double u : {1e-9, 1e-4, 0.01, 0.1, 0.3, 0.5, 0.6, 0.97, 1 - 1e-7}) {
      const double ref = boost::math::ibeta_inv(a, a, u);
      EXPECT_NEAR(symmetric_beta_quantile(a, u), ref, 1e-13 + 1e-12 * ref) << a << " " << u;
    }
  }
  EXPECT_EQ(symmetric_beta_quantile(3, 0), 0);
  EXPECT_EQ(symmetric_beta_quantile(3, 1), 1);
}

TEST(Spreading, DensitiesIntegrateToOne) {
  for (SpreadingKind kind :
       {SpreadingKind::cos2s, SpreadingKind::hasselmann, SpreadingKind::donelan_banner}) {
    const Spreading d = spreading(kind);
    for (double r : {0.3, 0.7, 1.0, 1.3, 2.5, 8.0}) {
      const double w = r * d.omega_peak;
      const double total =
          testing::integrate([&](double t) { return d.density(t, w); }, -kPi, kPi, {0.0});
      EXPECT_NEAR(total, 1, 1e-10) << to_string(kind) << " " << r;
    }
  }
}

TEST(Spreading, SampleIsTheInverseCumulativeDistribution) {
  for (SpreadingKind kind :
       {SpreadingKind::cos2s, SpreadingKind::hasselmann, SpreadingKind::donelan_banner}) {
    const Spreading d = spreading(kind);
    for (double r : {0.6, 1.0, 1.4, 3.0}) {
      const double w = r * d.omega_peak;
      for (double u : {0.01, 0.2, 0.5, 0.77, 0.999}) {
        const double theta = d.sample(u, w);
        ASSERT_GE(theta, -kPi);
        ASSERT_LE(theta, kPi);
        const double cdf =
            testing::integrate([&](double t) { return d.density(t, w); }, -kPi, theta);
        EXPECT_NEAR(cdf, u, 1e-9) << to_string(kind) << " r " << r << " u " << u;
      }
      EXPECT_NEAR(d.sample(0.5, w), 0, 1e-12);
      EXPECT_NEAR(d.sample(0, w), -kPi, 1e-9);
      EXPECT_NEAR(d.sample(1, w), kPi, 1e-9);
    }
  }
}

}  // namespace
}  // namespace sg::ocean
