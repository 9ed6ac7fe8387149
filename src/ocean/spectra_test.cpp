// The spectra against their formulas: values at hand-picked frequencies (computed from
// the published formulas with the constants written out, independently of this code),
// the depth function, and TMA's deep-water limit.
#include "ocean/spectra.h"

#include <gtest/gtest.h>

#include <cmath>

#include "math/vec.h"
#include "testing/quadrature.h"

namespace sg::ocean {
namespace {

TEST(Spectra, PiersonMoskowitzAtHandPickedFrequencies) {
  // S = 8.1e-3 g^2 w^-5 exp(-0.74 (g / (1.026 * 10 * w))^4), U_10 = 10 m/s.
  const Spectrum pm = pierson_moskowitz_spectrum(10);
  const struct {
    double w, s;
  } values[] = {{0.5, 0.0012572063520524773},
                {0.84, 0.5381880206364581},
                {1.5, 0.09084695233228075},
                {3.0, 0.003183469816606912}};
  for (const auto& v : values) {
    EXPECT_NEAR(pm(v.w), v.s, 1e-12 * v.s) << v.w;
    EXPECT_NEAR(pierson_moskowitz(v.w, 10.26), v.s, 1e-12 * v.s) << v.w;
  }
  // The peak, (4 beta / 5)^(1/4) g / U_19.5 = 0.8387 rad/s, i.e. 0.855 g / U_10.
  EXPECT_NEAR(pm.peak(), 0.8386911750788713, 1e-12);
  EXPECT_NEAR(pm.peak() * 10 / kGravity, 0.855, 5e-4);
}

TEST(Spectra, JonswapAtHandPickedFrequencies) {
  // U_10 = 10 m/s, F = 100 km: x = g F / U^2 = 9810, alpha = 0.076 x^-0.22,
  // omega_p = 2 pi 3.5 (g / U) x^-0.33, gamma = 3.3.
  const Spectrum js = jonswap_spectrum(10, 100e3, 3.3);
  EXPECT_NEAR(js.alpha, 0.010061121893912086, 1e-15);
  EXPECT_NEAR(js.omega_peak, 1.0391210620086602, 1e-13);
  const struct {
    double w, s;
  } values[] = {{0.8, 0.08464813468857348},
                {1.0391210620086602, 0.7556131800504435},
                {1.3, 0.1604180095019826},
                {2.5, 0.009551712750536403}};
  for (const auto& v : values)
    EXPECT_NEAR(js(v.w), v.s, 1e-12 * v.s) << v.w;
}

TEST(Spectra, FetchLawsCapAtAFullyDevelopedSea) {
  const FetchLaws short_fetch = jonswap_fetch_laws(10, 100e3);
  EXPECT_FALSE(short_fetch.capped);
  EXPECT_DOUBLE_EQ(short_fetch.dimensionless_fetch, 9810);
  // 10 m/s over 10000 km: x = 9.8e5, capped at 1.88e4, where the JONSWAP peak is
  // Pierson-Moskowitz's (0.855 g / U) and alpha is close to its 8.1e-3.
  const FetchLaws fd = jonswap_fetch_laws(10, 1e7);
  EXPECT_TRUE(fd.capped);
  EXPECT_NEAR(fd.omega_peak, pierson_moskowitz_spectrum(10).omega_peak, 1e-3 * fd.omega_peak);
  EXPECT_NEAR(fd.alpha, 8.7e-3, 1e-4);
}

TEST(Spectra, KitaigorodskiiDepthFunctionAtHandPickedValues) {
  // Phi = tanh^2(kh) / (1 + 2kh / sinh(2kh)), k from omega^2 = g k tanh(kh) (solved by
  // bisection outside this code).
  const struct {
    double w, h, phi;
  } values[] = {{0.5, 10, 0.12721357456603016},
                {1.0, 10, 0.49130424124086564},
                {0.3, 5, 0.022934683677195755},
                {2.0, 10, 0.9942168733044076}};
  for (const auto& v : values) {
    EXPECT_NEAR(kitaigorodskii_depth(v.w, v.h), v.phi, 1e-12) << v.w << " " << v.h;
    // Thompson and Vincent's approximation: within 0.02 everywhere (Thompson and Vincent
    // 1983 quote a few per cent).
    EXPECT_NEAR(thompson_vincent_depth(v.w, v.h), v.phi, 0.02) << v.w << " " << v.h;
  }
  // Limits: omega_h^2 / 2 in shallow water, 1 in deep water.
  const double wh = 0.05;
  EXPECT_NEAR(kitaigorodskii_depth(wh * std::sqrt(kGravity / 10), 10), wh * wh / 2, 1e-5);
  EXPECT_NEAR(kitaigorodskii_depth(10, 10), 1, 1e-15);
  EXPECT_EQ(kitaigorodskii_depth(1, std::numeric_limits<double>::infinity()), 1);
}

TEST(Spectra, TmaIsJonswapTimesTheDepthFunction) {
  const Spectrum js = jonswap_spectrum(12, 50e3, 3.3);
  const Spectrum tma = tma_spectrum(12, 50e3, 3.3, 15);
  for (double w : {0.4, 0.9, 1.2, 3.0})
    EXPECT_NEAR(tma(w), js(w) * kitaigorodskii_depth(w, 15), 1e-14 * js(w));
  // The depth factor moves the maximum up from omega_p.
  EXPECT_GT(tma.peak(), js.omega_peak);
  EXPECT_GT(tma(tma.peak()), tma(js.omega_peak));
  EXPECT_GT(tma(tma.peak()), tma(tma.peak() * 1.001));
  EXPECT_GT(tma(tma.peak()), tma(tma.peak() * 0.999));
}

TEST(Spectra, TmaTendsToJonswapInDeepWater) {
  const Spectrum js = jonswap_spectrum(10, 100e3, 3.3);
  // Relative difference at the peak's half frequency (where kh is smallest in the band
  // that holds energy) shrinks with depth; beyond half the longest wavelength it is nil.
  double previous = 1;
  for (double h : {5.0, 20.0, 50.0, 200.0, 1000.0}) {
    const Spectrum tma = tma_spectrum(10, 100e3, 3.3, h);
    double worst = 0;
    for (double w = 0.5 * js.omega_peak; w < 10; w *= 1.05)
      worst = std::max(worst, std::fabs(tma(w) / js(w) - 1));
    EXPECT_LT(worst, previous) << h;
    previous = worst;
  }
  EXPECT_LT(previous, 1e-12);
  const Spectrum deep = tma_spectrum(10, 100e3, 3.3, 1e4);
  EXPECT_NEAR(deep.variance(0.3, 20), js.variance(0.3, 20), 1e-12 * js.variance(0.3, 20));
}

TEST(Spectra, VarianceIsTheIntegral) {
  const Spectrum js = jonswap_spectrum(10, 100e3, 3.3);
  const double ref =
      testing::integrate([&](double w) { return js(w); }, 0.3, 25, {js.omega_peak}, 1e-13);
  EXPECT_NEAR(js.variance(0.3, 25), ref, 1e-9 * ref);
}

TEST(Spectra, SwellHasItsSignificantHeight) {
  for (double tp : {8.0, 12.0, 18.0}) {
    const Spectrum sw = swell_spectrum(1.5, tp, 3.3);
    const double wp = kTwoPi / tp;
    EXPECT_DOUBLE_EQ(sw.omega_peak, wp);
    const double m0 =
        testing::integrate([&](double w) { return sw(w); }, 0.1 * wp, 1000 * wp, {wp}, 1e-12);
    EXPECT_NEAR(4 * std::sqrt(m0), 1.5, 1e-4) << tp;
  }
}

}  // namespace
}  // namespace sg::ocean
