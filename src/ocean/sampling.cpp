#include "ocean/sampling.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "base/error.h"
#include "math/rng.h"
#include "math/vec.h"

namespace sg::ocean {
namespace {

// The frequency in [lo, hi] where S crosses `level`, for S monotonic on [lo, hi] (rising
// when `rising`); bisection in ln omega to 1e-12.
double crossing(const Spectrum& s, double lo, double hi, double level, bool rising) {
  for (int it = 0; it < 200 && hi - lo > 1e-12 * hi; ++it) {
    const double mid = std::sqrt(lo * hi);
    if ((s(mid) < level) == rising) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return rising ? lo : hi;
}

std::string metres(double v) {
  std::ostringstream o;
  o.precision(4);
  o << v << " m";
  return o.str();
}

}  // namespace

double travel_direction(const Wave& w) {
  // k = -|k| (sin theta, -cos theta) for omega > 0; the opposite for omega < 0.
  const double sign = w.angular_frequency < 0 ? -1.0 : 1.0;
  return std::atan2(-sign * w.wave_vector.x, sign * w.wave_vector.y);
}

Band trimmed_band(const Component& c, const Dispersion& water, double k_min, double k_max,
                  const char* band_flag) {
  const Spectrum& S = c.spectrum;
  const double w_peak = S.peak(), s_peak = S(w_peak);
  double w_lo = water.omega(k_min), w_hi = water.omega(k_max);
  const auto no_energy = [&] {
    throw Error(std::string(band_flag) + ": the " + to_string(S.kind) + " spectrum has no energy " +
                "between " + metres(kTwoPi / k_max) + " and " + metres(kTwoPi / k_min) +
                " (its peak wavelength is " + metres(kTwoPi / water.wavenumber(w_peak)) + ")");
  };
  if (c.low_cut > 0 && w_lo < w_peak && S(w_lo) < c.low_cut * s_peak) {
    if (S(std::min(w_hi, w_peak)) < c.low_cut * s_peak) no_energy();
    w_lo = crossing(S, w_lo, std::min(w_hi, w_peak), c.low_cut * s_peak, true);
  }
  if (c.high_cut > 0 && w_hi > w_peak && S(w_hi) < c.high_cut * s_peak) {
    if (S(std::max(w_lo, w_peak)) < c.high_cut * s_peak) no_energy();
    w_hi = crossing(S, std::max(w_lo, w_peak), w_hi, c.high_cut * s_peak, false);
  }
  Band b;
  b.omega_min = w_lo;
  b.omega_max = w_hi;
  b.k_min = water.wavenumber(w_lo);
  b.k_max = water.wavenumber(w_hi);
  if (w_lo == water.omega(k_min)) b.k_min = k_min;  // exact where untrimmed
  if (w_hi == water.omega(k_max)) b.k_max = k_max;
  if (!(b.k_max > b.k_min) || !(S.variance(w_lo, w_hi) > 0)) no_energy();
  return b;
}

SampledComponent sample_component(const Component& c, const Dispersion& water, double k_min,
                                  double k_max, uint64_t seed, const char* band_flag) {
  const Spectrum& S = c.spectrum;
  const Band band = trimmed_band(c, water, k_min, k_max, band_flag);
  const double w_lo = band.omega_min, w_hi = band.omega_max;
  SampledComponent out;
  out.k_min = band.k_min;
  out.k_max = band.k_max;

  const int n = c.waves;
  Pcg32 rng(seed, c.stream);
  std::vector<double> jitter_k(n), phase(n);
  for (int i = 0; i < n; ++i)
    jitter_k[i] = rng.uniform();
  // The direction quantiles: u_i = (perm(i) + jitter) / size of i's block, perm a
  // Fisher-Yates permutation of each block.
  const int block = std::max(1, c.direction_block);
  std::vector<double> u_dir(n);
  std::vector<int> perm;
  for (int b0 = 0; b0 < n; b0 += block) {
    const int m = std::min(block, n - b0);
    perm.resize(m);
    std::iota(perm.begin(), perm.end(), 0);
    for (int i = m - 1; i > 0; --i) {
      const int j = static_cast<int>(rng.uniform() * (i + 1));
      std::swap(perm[i], perm[std::min(j, i)]);
    }
    for (int i = 0; i < m; ++i)
      u_dir[b0 + i] = (perm[i] + rng.uniform()) / m;
  }
  for (int i = 0; i < n; ++i)
    phase[i] = kTwoPi * rng.uniform();

  const double u0 = std::log(out.k_min), du = (std::log(out.k_max) - u0) / n;
  out.waves.resize(n);
  double w_prev = w_lo;
  for (int i = 0; i < n; ++i) {
    const double w_next = i + 1 == n ? w_hi : water.omega(std::exp(u0 + (i + 1) * du));
    const double variance = S.variance(w_prev, w_next);
    w_prev = w_next;
    const double k = std::exp(u0 + (i + jitter_k[i]) * du);
    const double omega = water.omega(k);
    const double theta = c.direction_rad + c.spreading.sample(u_dir[i], omega);
    Wave& w = out.waves[i];
    w.amplitude = std::sqrt(2 * variance);
    w.wave_vector = vec2(-k * std::sin(theta), k * std::cos(theta));
    w.angular_frequency = omega;
    w.phase = phase[i];
    out.variance += variance;
    out.max_steepness = std::max(out.max_steepness, w.amplitude * k);
  }
  return out;
}

}  // namespace sg::ocean
