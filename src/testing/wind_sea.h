// A wind sea for tests: the waves of a Pierson-Moskowitz spectrum (deep water, fully
// developed, wind speed U at 19.5 m),
//     S(omega) = 8.1e-3 g^2 / omega^5 exp(-0.74 (g / (U omega))^4),
// with cos^2 directional spreading about the -z axis, sampled by n waves whose wave numbers
// are stratified log-uniformly between the given wavelengths; each wave's amplitude is
// sqrt(2 S(omega) d omega) times the spreading's square root, its frequency deep-water
// dispersion omega = sqrt(g k), its phase random. What the scene loader must accept:
// thousands of waves, wavelengths of centimetres to hundreds of metres.
#pragma once

#include <cmath>
#include <vector>

#include "math/rng.h"
#include "scene/scene.h"

namespace sg::testing {

inline std::vector<Wave> wind_sea_waves(double wind_speed, int n, double min_wavelength = 0.05,
                                        double max_wavelength = 500, uint64_t seed = 1) {
  const double g = 9.81;
  const double kmin = kTwoPi / max_wavelength, kmax = kTwoPi / min_wavelength;
  Pcg32 rng(seed, 7);
  std::vector<Wave> waves;
  waves.reserve(n);
  for (int i = 0; i < n; ++i) {
    const double u = (i + rng.uniform()) / n;
    const double k = kmin * std::pow(kmax / kmin, u);
    const double dk = k * std::log(kmax / kmin) / n;
    const double omega = std::sqrt(g * k);
    const double domega = 0.5 * std::sqrt(g / k) * dk;
    const double S = 8.1e-3 * g * g / std::pow(omega, 5) *
                     std::exp(-0.74 * std::pow(g / (wind_speed * omega), 4));
    const double theta = (rng.uniform() - 0.5) * kPi;
    Wave w;
    w.amplitude = std::sqrt(2 * S * domega) * std::fabs(std::cos(theta));
    w.wave_vector = vec2(k * std::sin(theta), -k * std::cos(theta));
    w.angular_frequency = omega;
    w.phase = kTwoPi * rng.uniform();
    waves.push_back(w);
  }
  return waves;
}

}  // namespace sg::testing
