// The wave field's arrays and bounds: each wave's parameters in file order, and the
// bounds of the height and slope that the displaced intersection relies on, sum |A_i| and
// sum |A_i| |k_i| (the sums themselves are the kernel's, tested in
// shading/water_geometry_test.cpp against the direct sum and its derivatives).
#include "scene/waves.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sg {
namespace {

TEST(Waves, ArraysHoldEachWaveInFileOrder) {
  const std::vector<Wave> waves = {Wave{0.3, {0.5, -1.0}, 2.0, 0.1},
                                   Wave{-0.1, {2.0, 0.5}, 3.0, 0.7},
                                   Wave{0.05, {-3.0, 1.0}, 4.0, 2.0}};
  const WaveField w(waves);
  ASSERT_EQ(w.size(), 3u);
  for (size_t i = 0; i < waves.size(); ++i) {
    EXPECT_EQ(w.A[i], waves[i].amplitude);
    EXPECT_EQ(w.a[i], waves[i].wave_vector.x);
    EXPECT_EQ(w.b[i], waves[i].wave_vector.y);
    EXPECT_EQ(w.c[i], waves[i].angular_frequency);
    EXPECT_EQ(w.phi[i], waves[i].phase);
  }
}

TEST(Waves, BoundsAreTheSumsOfAmplitudesAndSlopeAmplitudes) {
  // A negative amplitude counts by its magnitude.
  const WaveField w({Wave{0.3, {0.5, -1.0}, 2.0, 0.1}, Wave{-0.1, {2.0, 0.5}, 3.0, 0.7},
                     Wave{0.05, {-3.0, 1.0}, 4.0, 2.0}});
  EXPECT_NEAR(w.amplitude_bound(), 0.3 + 0.1 + 0.05, 1e-15);
  EXPECT_NEAR(w.slope_bound(),
              0.3 * std::sqrt(1.25) + 0.1 * std::sqrt(4.25) + 0.05 * std::sqrt(10.0), 1e-15);
  const WaveField none;
  EXPECT_EQ(none.size(), 0u);
  EXPECT_EQ(none.amplitude_bound(), 0.0);
  EXPECT_EQ(none.slope_bound(), 0.0);
}

}  // namespace
}  // namespace sg
