// The sampled waves against the spectrum they sample: significant height against the
// spectrum's integral over the band (integrated here, from the formulas written out
// again), the peak of the sampled energy per frequency bin, and the energy-weighted
// circular mean and spread of the directions against the spreading functions'.
#include "ocean/sampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "math/vec.h"
#include "ocean/ocean.h"
#include "testing/quadrature.h"

namespace sg::ocean {
namespace {

constexpr double g = 9.81;

// The formulas again, independently of spectra.h.
double k_of(double w, double h) {
  if (!std::isfinite(h)) return w * w / g;
  double lo = 0, hi = w * w / g + 10 / h;  // bisection on g k tanh(k h) = w^2
  for (int i = 0; i < 80; ++i) {
    const double m = 0.5 * (lo + hi);
    (g * m * std::tanh(m * h) < w * w ? lo : hi) = m;
  }
  return 0.5 * (lo + hi);
}
double w_of(double k, double h) {
  return std::sqrt(g * k * (std::isfinite(h) ? std::tanh(k * h) : 1.0));
}
double reference_spectrum(const OceanParams& p, double w) {
  if (p.spectrum == SpectrumKind::pierson_moskowitz) {
    const double u19_5 = 1.026 * p.wind_speed;  // Pierson and Moskowitz 1964's form
    return 8.1e-3 * g * g / std::pow(w, 5) * std::exp(-0.74 * std::pow(g / (u19_5 * w), 4));
  }
  const double x = std::min(g * p.fetch_km * 1000 / (p.wind_speed * p.wind_speed), 1.88e4);
  const double alpha = 0.076 * std::pow(x, -0.22);
  const double wp = 2 * kPi * 3.5 * g / p.wind_speed * std::pow(x, -0.33);
  const double sigma = w <= wp ? 0.07 : 0.09;
  double s = alpha * g * g / std::pow(w, 5) * std::exp(-1.25 * std::pow(wp / w, 4)) *
             std::pow(p.gamma, std::exp(-std::pow(w - wp, 2) / (2 * sigma * sigma * wp * wp)));
  if (p.spectrum == SpectrumKind::tma) {
    const double kh = k_of(w, p.depth) * p.depth;
    s *= std::pow(std::tanh(kh), 2) / (1 + 2 * kh / std::sinh(2 * kh));
  }
  return s;
}
// The maximum of the spectrum: a scan in steps of 0.1%, then of 1e-6 around the best.
double reference_peak(const OceanParams& p) {
  double best = 0, arg = 0;
  for (double w = 0.1; w < 10; w *= 1.001) {
    const double s = reference_spectrum(p, w);
    if (s > best) best = s, arg = w;
  }
  const double lo = arg / 1.001, hi = arg * 1.001;
  for (double w = lo; w < hi; w *= 1.000001) {
    const double s = reference_spectrum(p, w);
    if (s > best) best = s, arg = w;
  }
  return arg;
}

OceanParams sea(SpectrumKind kind, int waves) {
  OceanParams p;
  p.spectrum = kind;
  p.wind_speed = 10;
  p.fetch_km = 100;
  p.gamma = 3.3;
  if (kind == SpectrumKind::tma) p.depth = 15;
  p.waves = waves;
  p.wind_direction_deg = 30;
  return p;
}

TEST(Sampling, SignificantHeightIsTheSpectrumsOverTheBand) {
  double worst = 0;
  for (SpectrumKind kind :
       {SpectrumKind::pierson_moskowitz, SpectrumKind::jonswap, SpectrumKind::tma}) {
    for (int n : {16, 256, 4096}) {
      for (auto band : {std::pair{0.1, 1000.0}, std::pair{0.5, 40.0}, std::pair{0.02, 2.0}}) {
        OceanParams p = sea(kind, n);
        p.wavelength_min = band.first;
        p.wavelength_max = band.second;
        const Ocean o = generate(p);
        double sum = 0;
        for (const Wave& w : o.waves)
          sum += w.amplitude * w.amplitude / 2;
        const double h = p.spectrum == SpectrumKind::tma ? p.depth : INFINITY;
        const double w0 = w_of(kTwoPi / band.second, h), w1 = w_of(kTwoPi / band.first, h);
        const double m0 = testing::integrate([&](double w) { return reference_spectrum(p, w); }, w0,
                                             w1, {reference_peak(p)}, 1e-10, 1e-300);
        const double hs = 4 * std::sqrt(sum), hs_ref = 4 * std::sqrt(m0);
        const double err = std::fabs(hs / hs_ref - 1);
        worst = std::max(worst, err);
        EXPECT_LT(err, 0.05) << to_string(kind) << " " << n << " waves, " << band.first << "-"
                             << band.second << " m: Hs " << hs << " vs " << hs_ref;
      }
    }
  }
  std::printf("[ figure ] worst relative Hs error over 27 seas: %.3g\n", worst);
}

// One wave per stratum: wave i's ln k lies in [i, i + 1] strata widths from ln k_min.
TEST(Sampling, OneWavePerStratumOfLnK) {
  for (SpectrumKind kind : {SpectrumKind::jonswap, SpectrumKind::tma}) {
    const Ocean o = generate(sea(kind, 300));
    const double du = std::log(o.wind.k_max / o.wind.k_min) / 300;
    for (int i = 0; i < 300; ++i) {
      const double u = std::log(length(o.wind.waves[i].wave_vector) / o.wind.k_min) / du;
      EXPECT_GE(u, i - 1e-9) << i;
      EXPECT_LE(u, i + 1 + 1e-9) << i;
    }
  }
}

// Energy per frequency bin of width 0.1 omega_peak, bins centred on the formula's peak:
// the fullest bin is the one holding the peak.
TEST(Sampling, SampledEnergyPeaksAtTheFormulasPeak) {
  for (SpectrumKind kind :
       {SpectrumKind::pierson_moskowitz, SpectrumKind::jonswap, SpectrumKind::tma}) {
    for (int n : {1024, 4096}) {
      const OceanParams p = sea(kind, n);
      const double wp = reference_peak(p), width = 0.1 * wp;
      const Ocean o = generate(p);
      std::vector<double> bins(200, 0.0);
      const int centre = 100;
      for (const Wave& w : o.waves) {
        const int b =
            centre + static_cast<int>(std::floor((w.angular_frequency - wp) / width + 0.5));
        if (b >= 0 && b < 200) bins[b] += w.amplitude * w.amplitude / 2;
      }
      const int fullest =
          static_cast<int>(std::max_element(bins.begin(), bins.end()) - bins.begin());
      EXPECT_EQ(fullest, centre) << to_string(kind) << " " << n << " waves: peak at "
                                 << wp + (fullest - centre) * width << " rad/s, formula " << wp;
    }
  }
}

// The first circular moment of D(.; omega), integrated from the formulas written out again.
double mean_cosine(SpreadingKind kind, double w, double wp, double u, double cp) {
  const double r = w / wp;
  std::function<double(double)> d;
  if (kind == SpreadingKind::donelan_banner) {
    const double b = r < 0.95  ? 2.61 * std::pow(r, 1.3)
                     : r < 1.6 ? 2.28 * std::pow(r, -1.3)
                               : std::pow(10, -0.4 + 0.8393 * std::exp(-0.567 * std::log(r * r)));
    d = [b](double t) { return std::pow(1 / std::cosh(b * t), 2); };
  } else {
    const double s = kind == SpreadingKind::cos2s
                         ? 11.5 * std::pow(wp * u / g, -2.5) * std::pow(r, r < 1 ? 5 : -2.5)
                         : 6.97 * std::pow(r, r < 1 ? 4.06 : -2.33 - 1.45 * (u / cp - 1.17));
    d = [s](double t) { return std::pow(std::cos(t / 2), 2 * s); };
  }
  const double norm = testing::integrate(d, 0, kPi, {}, 1e-8);
  return testing::integrate([&](double t) { return d(t) * std::cos(t); }, 0, kPi, {}, 1e-8) / norm;
}

TEST(Sampling, DirectionalSpreadMatchesTheSpreadingFunction) {
  for (SpreadingKind kind :
       {SpreadingKind::cos2s, SpreadingKind::hasselmann, SpreadingKind::donelan_banner}) {
    for (int n : {1024, 4096}) {
      OceanParams p = sea(SpectrumKind::jonswap, n);
      p.spreading = kind;
      const Ocean o = generate(p);
      const double wp = o.wind_spectrum.omega_peak;
      const double mean = radians(p.wind_direction_deg);
      double e = 0, c = 0, s = 0, expected = 0;
      for (const Wave& w : o.waves) {
        const double energy = w.amplitude * w.amplitude / 2;
        // The direction the wave travels towards: -k for a positive angular frequency.
        const double theta = std::atan2(-w.wave_vector.x, w.wave_vector.y);
        e += energy;
        c += energy * std::cos(theta - mean);
        s += energy * std::sin(theta - mean);
        expected += energy * mean_cosine(kind, w.angular_frequency, wp, 10, g / wp);
      }
      const double r = std::hypot(c, s) / e, r_ref = expected / e;
      const double mean_err = degrees(std::atan2(s, c));
      const double sd = degrees(std::sqrt(-2 * std::log(r)));
      const double sd_ref = degrees(std::sqrt(-2 * std::log(r_ref)));
      std::printf(
          "[ figure ] %s, %d waves: mean %+.3f deg off, circular sd %.3f deg (function "
          "%.3f deg)\n",
          to_string(kind).c_str(), n, mean_err, sd, sd_ref);
      // Bounds: twice the worst error over 20 seeds (sampling.h).
      EXPECT_NEAR(mean_err, 0, n >= 4096 ? 0.6 : 1.5) << to_string(kind) << " " << n;
      EXPECT_NEAR(sd / sd_ref, 1, n >= 4096 ? 0.05 : 0.1) << to_string(kind) << " " << n;
    }
  }
}

TEST(Sampling, TravelDirectionIsTheCrestsMotion) {
  // A swell towards +x (90 degrees): each crest moves with the phase velocity
  // -omega k / |k|^2 (h = A sin(k . x + omega t + phi)); its azimuth, measured from -z
  // towards +x, is the wave's travel direction, and their energy-weighted mean is 90.
  OceanParams p = sea(SpectrumKind::jonswap, 16);
  p.swell.enabled = true;
  p.swell.direction_deg = 90;
  p.swell.waves = 256;
  const Ocean o = generate(p);
  double c = 0, s = 0;
  for (const Wave& w : o.swell.waves) {
    const vec2 v = -w.angular_frequency * w.wave_vector / dot(w.wave_vector, w.wave_vector);
    const double azimuth = std::atan2(v.x, -v.y);
    EXPECT_NEAR(std::remainder(azimuth - travel_direction(w), kTwoPi), 0, 1e-12);
    const double e = w.amplitude * w.amplitude / 2;
    c += e * std::cos(azimuth);
    s += e * std::sin(azimuth);
  }
  EXPECT_NEAR(degrees(std::atan2(s, c)), 90, 2.0);
}

}  // namespace
}  // namespace sg::ocean
