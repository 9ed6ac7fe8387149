// The generator as `sunglint ocean` uses it: ranges refused naming the flag, output that
// the scene loader accepts, the same bytes for the same parameters, other phases for
// another seed, and a swell that adds to the wind sea without changing it.
#include "ocean/ocean.h"

#include <gtest/gtest.h>

#include <cmath>

#include "base/error.h"
#include "math/vec.h"

namespace sg::ocean {
namespace {

std::string error_of(const OceanParams& p) {
  try {
    generate(p);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(Ocean, BadValuesNameTheirFlag) {
  OceanParams p;
  p.wind_speed = 45;
  EXPECT_EQ(error_of(p), "--wind-speed: must be in [1, 30] m/s (got 45)");
  p = {};
  p.wind_speed = NAN;
  EXPECT_EQ(error_of(p), "--wind-speed: must be in [1, 30] m/s (got nan)");
  p = {};
  p.waves = 8;
  EXPECT_EQ(error_of(p), "--waves: must be in [16, 65536] (got 8)");
  p = {};
  p.fetch_km = 0.5;
  EXPECT_EQ(error_of(p), "--fetch: must be in [1, 10000] km (got 0.5)");
  p = {};
  p.gamma = 0.5;
  EXPECT_EQ(error_of(p), "--gamma: must be in [1, 10] (got 0.5)");
  p = {};
  p.spectrum = SpectrumKind::tma;
  EXPECT_EQ(error_of(p), "--depth: must be in [1, 10000] m (got inf)");
  p = {};
  p.wavelength_min = 5;
  p.wavelength_max = 2;
  EXPECT_EQ(error_of(p), "--wavelengths: need MIN < MAX (got 5-2)");
  p = {};
  p.wavelength_min = 0.001;
  EXPECT_EQ(error_of(p), "--wavelengths: must be in [0.01, 10000] m (got 0.001)");
  p = {};
  p.swell.enabled = true;
  p.swell.period = 40;
  EXPECT_EQ(error_of(p), "--swell-period: must be in [4, 25] s (got 40)");
  // A band far longer than the sea's waves holds no energy.
  p = {};
  p.wavelength_min = 2000;
  p.wavelength_max = 5000;
  EXPECT_NE(error_of(p).find("--wavelengths: the jonswap spectrum has no energy between 2000 m "
                             "and 5000 m (its peak wavelength is 57.08 m)"),
            std::string::npos)
      << error_of(p);
}

TEST(Ocean, LowFrequenciesWithoutEnergyAreTrimmed) {
  OceanParams p;  // 10 m/s over 100 km: peak 57 m; nothing beyond about 230 m
  const Ocean o = generate(p);
  EXPECT_NEAR(kTwoPi / o.wind.k_max, p.wavelength_min, 1e-12);
  const double longest = kTwoPi / o.wind.k_min;
  EXPECT_GT(longest, 3 * 57.08);
  EXPECT_LT(longest, 5 * 57.08);
  EXPECT_LT(o.wind_spectrum(Dispersion{}.omega(o.wind.k_min)),
            2e-9 * o.wind_spectrum(o.wind_spectrum.peak()));
  EXPECT_EQ(static_cast<int>(o.waves.size()), p.waves);
}

TEST(Ocean, SceneFilePassesTheLoader) {
  for (int n : {16, 1024, 65536}) {
    OceanParams p;
    p.waves = n;
    p.swell.enabled = true;
    const Ocean o = generate(p);
    const Scene s = ocean_scene(plain_template(), o, "sea");
    const std::string text = scene_to_json(s);
    const Scene back = parse_scene(text, "sea.json");
    ASSERT_EQ(back.surface.waves.size(), static_cast<size_t>(n + p.swell.waves));
    EXPECT_EQ(scene_to_json(back), text);  // exact round trip of every number
    for (const Wave& w : back.surface.waves) {
      const double k = length(w.wave_vector);
      ASSERT_TRUE(std::isfinite(w.amplitude) && w.amplitude >= 0);
      // Wavelengths inside the band, steepness far below breaking (A k ~ 0.44) and below
      // the sea's as a whole (pi Hs / peak wavelength = 0.11 here). In the omega^-5 range
      // a stratum of width d ln omega holds A k = sqrt(2 alpha d ln omega): 0.08 for 16
      // waves.
      ASSERT_GE(kTwoPi / k, p.wavelength_min * (1 - 1e-12));
      ASSERT_LE(kTwoPi / k, p.wavelength_max);
      ASSERT_LT(w.amplitude * k, 0.1);
      ASSERT_NEAR(w.angular_frequency, std::sqrt(kGravity * k), 1e-12 * w.angular_frequency);
    }
  }
}

TEST(Ocean, SameParametersSameBytesOtherSeedOtherPhases) {
  OceanParams p;
  p.spreading = SpreadingKind::donelan_banner;
  p.swell.enabled = true;
  const std::string a = scene_to_json(ocean_scene(plain_template(), generate(p), "a"));
  const std::string b = scene_to_json(ocean_scene(plain_template(), generate(p), "a"));
  EXPECT_EQ(a, b);
  OceanParams q = p;
  q.seed = 1;
  const Ocean o0 = generate(p), o1 = generate(q);
  ASSERT_EQ(o0.waves.size(), o1.waves.size());
  int same_phase = 0;
  for (size_t i = 0; i < o0.waves.size(); ++i)
    same_phase += o0.waves[i].phase == o1.waves[i].phase;
  EXPECT_EQ(same_phase, 0);
  // The variance of each stratum does not depend on the seed (only where its wave sits).
  EXPECT_NEAR(o0.variance, o1.variance, 1e-12 * o0.variance);
}

TEST(Ocean, SwellAddsToTheWindSea) {
  OceanParams p;
  p.wind_direction_deg = -20;
  const Ocean wind = generate(p);
  p.swell.enabled = true;
  p.swell.height = 1.2;
  p.swell.period = 14;
  p.swell.direction_deg = 45;
  p.swell.waves = 128;
  const Ocean both = generate(p);
  ASSERT_EQ(both.waves.size(), wind.waves.size() + 128);
  // The wind sea's waves are those generated without the swell (their own stream).
  for (size_t i = 0; i < wind.waves.size(); ++i) {
    EXPECT_EQ(both.wind.waves[i].amplitude, wind.waves[i].amplitude);
    EXPECT_EQ(both.wind.waves[i].phase, wind.waves[i].phase);
  }
  // The swell's height and direction.
  EXPECT_NEAR(4 * std::sqrt(both.swell.variance), 1.2, 0.01);
  double c = 0, s = 0;
  for (const Wave& w : both.swell.waves) {
    const double e = w.amplitude * w.amplitude / 2, t = travel_direction(w);
    c += e * std::cos(t);
    s += e * std::sin(t);
  }
  EXPECT_NEAR(degrees(std::atan2(s, c)), 45, 1.0);
  // Merged in order of increasing |k|.
  for (size_t i = 1; i < both.waves.size(); ++i)
    ASSERT_LE(length(both.waves[i - 1].wave_vector), length(both.waves[i].wave_vector));
}

}  // namespace
}  // namespace sg::ocean
