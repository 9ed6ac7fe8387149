// A sea generated from a directional wave spectrum, as the explicit waves of a scene
// file: the parameters of `sunglint ocean`, their valid ranges, and the generation.
//
// A sea is a wind sea (Pierson-Moskowitz, JONSWAP or TMA, spectra.h, with a spreading
// function, spreading.h) plus, optionally, a swell (a JONSWAP-shaped spectrum of given
// height and period from its own direction, with a narrow cos-2s spreading). Each is
// sampled by sampling.h over the same band of wavelengths; the waves are merged in order
// of increasing |k|. Dispersion is deep water, or finite depth for TMA (dispersion.h).
// Same parameters, same waves, bit for bit (math/rng.h's PCG32).
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "ocean/sampling.h"
#include "ocean/spectra.h"
#include "ocean/spreading.h"
#include "scene/scene.h"

namespace sg::ocean {

// Valid ranges; each bound is a flag's (docs/ocean.md gives the reasons).
struct Range {
  double lo, hi;
};
inline constexpr Range kWindSpeedRange{1, 30};         // --wind-speed, m/s
inline constexpr Range kFetchRange{1, 10000};          // --fetch, km
inline constexpr Range kGammaRange{1, 10};             // --gamma
inline constexpr Range kDepthRange{1, 10000};          // --depth, m
inline constexpr Range kWavesRange{16, 65536};         // --waves, --swell-waves
inline constexpr Range kWavelengthRange{0.01, 10000};  // --wavelengths, m
inline constexpr Range kDirectionRange{-360, 360};     // --wind-direction, degrees
inline constexpr Range kSwellHeightRange{0.01, 10};    // --swell-height, m
inline constexpr Range kSwellPeriodRange{4, 25};       // --swell-period, s
inline constexpr Range kSwellSpreadRange{1, 200};      // --swell-spread (s_max)

struct SwellParams {
  bool enabled = false;
  double height = 1;         // --swell-height: significant height H_s, m
  double period = 12;        // --swell-period: peak period T_p, s
  double direction_deg = 0;  // --swell-direction: travel direction
  double spread = 75;        // --swell-spread: cos-2s s_max (Goda and Suzuki 1975)
  double gamma = 3.3;        // --swell-gamma
  int waves = 64;            // --swell-waves
};

struct OceanParams {
  SpectrumKind spectrum = SpectrumKind::jonswap;           // --spectrum
  double wind_speed = 10;                                  // --wind-speed: U_10, m/s
  double wind_direction_deg = 0;                           // --wind-direction: travel direction
  double fetch_km = 100;                                   // --fetch (jonswap, tma)
  double gamma = 3.3;                                      // --gamma (jonswap, tma)
  double depth = std::numeric_limits<double>::infinity();  // --depth (tma)
  SpreadingKind spreading = SpreadingKind::cos2s;          // --spreading
  int waves = 256;                                         // --waves
  double wavelength_min = 0.1, wavelength_max = 1000;      // --wavelengths MIN-MAX, m
  uint64_t seed = 0;                                       // --seed
  SwellParams swell;
};

// Checks every value against its range; throws sg::Error naming the flag
// ("--wind-speed: must be in [1, 30] m/s (got 45)").
void validate(const OceanParams& p);

// The wind sea's spectrum and spreading, as the parameters define them.
Spectrum wind_spectrum(const OceanParams& p);
Spreading wind_spreading(const OceanParams& p, const Spectrum& s);
Dispersion water(const OceanParams& p);
// The wind sea's and the swell's spectra, spreadings and directions as sampling.h takes them.
Component wind_component(const OceanParams& p);
Component swell_component(const OceanParams& p);

struct Ocean {
  std::vector<Wave> waves;  // wind sea and swell, in order of increasing |k|
  SampledComponent wind, swell;
  Spectrum wind_spectrum, swell_spectrum;
  FetchLaws fetch;      // jonswap, tma
  double variance = 0;  // sum A^2 / 2 over all waves
};

// Validates, then samples.
Ocean generate(const OceanParams& p);

// The scene of `template_scene` (camera, light, image, animation, surface settings) with
// the ocean's waves.
Scene ocean_scene(const Scene& template_scene, const Ocean& ocean, const std::string& name);

// The templates' view, that of the project's shared scenes: a camera 2.5 m above the sea
// looking 60 m ahead (-z) with a 40 degree field of view, the sun 12 degrees above the
// horizon straight ahead, 640 x 360, 60 frames at 30 fps, flat water.
//
// `sunglint ocean`'s default: that view as the sea looks (format /2, as the picture scenes
// of scenes/): an afternoon sun drawn in the sky, a blue sky graded to a pale horizon,
// Schlick's Fresnel, a dark blue-green sea beneath.
Scene sea_template();
// The measurement look of the shared scenes (format /1): light radiance 1, no sky, no
// Fresnel, no sea, so that a pixel's value is the fraction of it that mirrors the light
// (scenes/ocean-*.json, the tests; scripts/templates/plain.json is this template).
Scene plain_template();

}  // namespace sg::ocean
