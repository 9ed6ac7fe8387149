#include "ocean/ocean.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "base/error.h"
#include "math/vec.h"

namespace sg::ocean {
namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

void check_range(double v, Range r, const std::string& flag, const std::string& unit) {
  if (!std::isfinite(v) || v < r.lo || v > r.hi) {
    throw Error(flag + ": must be in [" + num(r.lo) + ", " + num(r.hi) + "]" +
                (unit.empty() ? "" : " " + unit) + " (got " + num(v) + ")");
  }
}

}  // namespace

void validate(const OceanParams& p) {
  check_range(p.wind_speed, kWindSpeedRange, "--wind-speed", "m/s");
  check_range(p.wind_direction_deg, kDirectionRange, "--wind-direction", "degrees");
  check_range(p.fetch_km, kFetchRange, "--fetch", "km");
  check_range(p.gamma, kGammaRange, "--gamma", "");
  if (p.spectrum == SpectrumKind::tma) check_range(p.depth, kDepthRange, "--depth", "m");
  check_range(p.waves, kWavesRange, "--waves", "");
  check_range(p.wavelength_min, kWavelengthRange, "--wavelengths", "m");
  check_range(p.wavelength_max, kWavelengthRange, "--wavelengths", "m");
  if (!(p.wavelength_min < p.wavelength_max)) {
    throw Error("--wavelengths: need MIN < MAX (got " + num(p.wavelength_min) + "-" +
                num(p.wavelength_max) + ")");
  }
  if (p.spectrum == SpectrumKind::swell) throw Error("--spectrum: the swell is added by --swell-*");
  if (p.swell.enabled) {
    check_range(p.swell.height, kSwellHeightRange, "--swell-height", "m");
    check_range(p.swell.period, kSwellPeriodRange, "--swell-period", "s");
    check_range(p.swell.direction_deg, kDirectionRange, "--swell-direction", "degrees");
    check_range(p.swell.spread, kSwellSpreadRange, "--swell-spread", "");
    check_range(p.swell.gamma, kGammaRange, "--swell-gamma", "");
    check_range(p.swell.waves, kWavesRange, "--swell-waves", "");
  }
}

Dispersion water(const OceanParams& p) {
  Dispersion d;
  if (p.spectrum == SpectrumKind::tma) d.depth = p.depth;
  return d;
}

Spectrum wind_spectrum(const OceanParams& p) {
  switch (p.spectrum) {
    case SpectrumKind::pierson_moskowitz:
      return pierson_moskowitz_spectrum(p.wind_speed);
    case SpectrumKind::tma:
      return tma_spectrum(p.wind_speed, p.fetch_km * 1000, p.gamma, p.depth);
    case SpectrumKind::jonswap:
    case SpectrumKind::swell:
      break;
  }
  return jonswap_spectrum(p.wind_speed, p.fetch_km * 1000, p.gamma);
}

Spreading wind_spreading(const OceanParams& p, const Spectrum& s) {
  Spreading d;
  d.kind = p.spreading;
  d.omega_peak = s.omega_peak;
  d.wind_speed = p.wind_speed;
  d.peak_speed = s.omega_peak / s.water.wavenumber(s.omega_peak);
  return d;
}

Component wind_component(const OceanParams& p) {
  Component wind;
  wind.spectrum = wind_spectrum(p);
  wind.spreading = wind_spreading(p, wind.spectrum);
  wind.direction_rad = radians(p.wind_direction_deg);
  wind.waves = p.waves;
  wind.stream = 1;
  return wind;
}

Component swell_component(const OceanParams& p) {
  Component swell;
  swell.spectrum = swell_spectrum(p.swell.height, p.swell.period, p.swell.gamma);
  swell.spreading.kind = SpreadingKind::cos2s;
  swell.spreading.omega_peak = swell.spectrum.omega_peak;
  swell.spreading.s_peak = p.swell.spread;
  swell.direction_rad = radians(p.swell.direction_deg);
  swell.waves = p.swell.waves;
  // A swell has no tail of its own under the wind sea: sampled where its spectrum is
  // above 1e-3 of its peak (the tail beyond holds under 0.1% of its variance).
  swell.low_cut = swell.high_cut = 1e-3;
  swell.stream = 2;
  return swell;
}

Ocean generate(const OceanParams& p) {
  validate(p);
  Ocean o;
  const Dispersion w = water(p);
  const double k_min = kTwoPi / p.wavelength_max, k_max = kTwoPi / p.wavelength_min;

  const Component wind = wind_component(p);
  o.wind_spectrum = wind.spectrum;
  if (p.spectrum != SpectrumKind::pierson_moskowitz)
    o.fetch = jonswap_fetch_laws(p.wind_speed, p.fetch_km * 1000);
  o.wind = sample_component(wind, w, k_min, k_max, p.seed, "--wavelengths");
  o.waves = o.wind.waves;

  if (p.swell.enabled) {
    const Component swell = swell_component(p);
    o.swell_spectrum = swell.spectrum;
    o.swell = sample_component(swell, w, k_min, k_max, p.seed, "--wavelengths");
    o.waves.insert(o.waves.end(), o.swell.waves.begin(), o.swell.waves.end());
    std::stable_sort(o.waves.begin(), o.waves.end(), [](const Wave& a, const Wave& b) {
      return length(a.wave_vector) < length(b.wave_vector);
    });
  }
  o.variance = o.wind.variance + o.swell.variance;
  return o;
}

Scene ocean_scene(const Scene& t, const Ocean& ocean, const std::string& name) {
  Scene s = t;
  s.name = name;
  s.surface.waves = ocean.waves;
  return s;
}

Scene plain_template() {
  Scene s;
  s.name = "ocean";
  s.width = 640;
  s.height = 360;
  s.camera.position = vec3(0, 2.5, 0);
  s.camera.look_at = vec3(0, 0, -60);
  s.camera.up = vec3(0, 1, 0);
  s.camera.vfov_deg = 40;
  s.light.direction = vec3(0, 0.207912, -0.978148);  // 12 degrees above the horizon, ahead
  s.light.angular_radius_deg = 0.27;
  s.light.radiance = Rgb(1.0);
  s.light.visible = false;
  s.sky = SkyDesc::constant(Rgb(0.0));
  s.surface.geometry = Geometry::flat;
  s.surface.fresnel = FresnelMode::none;
  s.surface.sea_radiance = Rgb(0.0);
  s.animation.t0 = 0;
  s.animation.fps = 30;
  s.animation.frames = 60;
  s.animation.shutter = 1;
  return s;
}

Scene sea_template() {
  Scene s = plain_template();
  // Radiances in the picture scenes' units (scenes/sunset.json, scenes/midday.json): the
  // sun's disk a few hundred times the sky, yellowish at 12 degrees; a blue sky paling
  // towards the horizon; a dark blue-green sea. Shown at exposure 0 by `render --display`.
  s.light.radiance = Rgb(620, 540, 400);
  s.light.visible = true;
  SkyDesc sky;
  sky.gradient = true;
  sky.zenith = Rgb(0.07, 0.15, 0.36);
  sky.horizon = Rgb(0.52, 0.58, 0.66);
  sky.exponent = 0.5;
  s.sky = sky;
  s.surface.fresnel = FresnelMode::schlick;
  s.surface.sea_radiance = Rgb(0.004, 0.018, 0.028);
  return s;
}

}  // namespace sg::ocean
