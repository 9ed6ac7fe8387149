// The dispersion relation against wave-table values and its own definition.
#include "scene/dispersion.h"

#include <gtest/gtest.h>

#include <cmath>

#include "math/vec.h"

namespace sg {
namespace {

// Wavelength of a wave of period T in depth h.
double wavelength(double period, double depth) {
  return kTwoPi / Dispersion{depth}.wavenumber(kTwoPi / period);
}

TEST(Dispersion, WavelengthsOfTheWaveTables) {
  // Linear-wave tables (e.g. Dean and Dalrymple 1991, Appendix C): a 10 s wave is
  // 156.1 m long in deep water, 92.3 m in 10 m of water; an 8 s wave 53.1 m in 5 m.
  EXPECT_NEAR(wavelength(10, std::numeric_limits<double>::infinity()), 156.13, 0.01);
  EXPECT_NEAR(wavelength(10, 10), 92.37, 0.01);
  EXPECT_NEAR(wavelength(8, 5), 53.08, 0.01);
  // Shallow-water limit: L = T sqrt(g h) for kh << 1 (a 60 s wave in 1 m: kh = 0.033).
  EXPECT_NEAR(wavelength(60, 1), 60 * std::sqrt(kGravity * 1), 0.2);
}

TEST(Dispersion, WavenumberSolvesTheRelation) {
  for (double h : {0.5, 3.0, 20.0, 400.0}) {
    for (double w : {0.05, 0.3, 1.0, 4.0, 30.0}) {
      const Dispersion d{h};
      const double k = d.wavenumber(w);
      EXPECT_NEAR(kGravity * k * std::tanh(k * h), w * w, 1e-12 * w * w) << h << " " << w;
      EXPECT_NEAR(d.omega(k), w, 1e-12 * w);
    }
  }
  const Dispersion deep;
  EXPECT_TRUE(deep.deep());
  EXPECT_DOUBLE_EQ(deep.wavenumber(2.0), 4.0 / kGravity);
  EXPECT_DOUBLE_EQ(deep.omega(1.0), std::sqrt(kGravity));
}

TEST(Dispersion, GroupSpeedIsTheDerivative) {
  for (double h : {2.0, 50.0, std::numeric_limits<double>::infinity()}) {
    const Dispersion d{h};
    for (double k : {0.01, 0.1, 1.0, 10.0}) {
      const double e = 1e-6 * k;
      EXPECT_NEAR(d.group_speed(k), (d.omega(k + e) - d.omega(k - e)) / (2 * e),
                  1e-7 * d.group_speed(k));
    }
  }
}

}  // namespace
}  // namespace sg
