#include "ocean/lattice_ocean.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "base/error.h"
#include "math/rng.h"
#include "math/vec.h"
#include "ocean/sampling.h"
#include "scene/scene_limits.h"

namespace sg::ocean {
namespace {

std::string num(double v) {
  std::ostringstream o;
  o.precision(4);
  o << v;
  return o.str();
}

double wrap_angle(double a) {
  a = std::fmod(a + kPi, kTwoPi);
  if (a < 0) a += kTwoPi;
  return a - kPi;
}

struct Part {
  Component component;
  Band band;
};

// The directional density per unit wave-vector area, E(k) (lattice_ocean.h).
double density(const Part& part, const Dispersion& water, const vec2& k) {
  const double kk = length(k);
  if (!(kk >= part.band.k_min && kk <= part.band.k_max)) return 0;
  const double omega = water.omega(kk);
  const double theta = std::atan2(-k.x, k.y);  // travel direction of a wave with +omega
  const Component& c = part.component;
  const double d = c.spreading.density(wrap_angle(theta - c.direction_rad), omega);
  return c.spectrum(omega) * water.group_speed(kk) * d / kk;
}

}  // namespace

LatticeOcean generate_lattice(const OceanParams& p, const CascadeParams& cp) {
  validate(p);
  const int n = cp.lattice;
  if (n < kMinLattice || n > kMaxLattice || (n & (n - 1)) != 0) {
    throw Error("--lattice: must be a power of two in [" + std::to_string(kMinLattice) + ", " +
                std::to_string(kMaxLattice) + "] (got " + std::to_string(n) + ")");
  }
  if (cp.cascades < kCascadesRange.lo || cp.cascades > kCascadesRange.hi) {
    throw Error("--cascades: must be in [1, 8] (got " + std::to_string(cp.cascades) + ")");
  }
  const Dispersion water = ocean::water(p);
  std::vector<Part> parts;
  parts.push_back({wind_component(p), {}});
  if (p.swell.enabled) parts.push_back({swell_component(p), {}});
  const double k_lo = kTwoPi / p.wavelength_max, k_hi = kTwoPi / p.wavelength_min;
  LatticeOcean out;
  out.depth = water.depth;
  out.k_min = std::numeric_limits<double>::infinity();
  out.k_max = 0;
  double longest_peak = 0;
  for (Part& part : parts) {
    part.band = trimmed_band(part.component, water, k_lo, k_hi, "--wavelengths");
    out.k_min = std::min(out.k_min, part.band.k_min);
    out.k_max = std::max(out.k_max, part.band.k_max);
    longest_peak =
        std::max(longest_peak, kTwoPi / water.wavenumber(part.component.spectrum.peak()));
  }

  // The patches.
  const int count = cp.cascades;
  std::vector<double> L = cp.patch_sizes;
  const double max_ratio = n / 16.0;
  if (count > 1 && max_ratio < 2) {
    throw Error("--cascades: " + std::to_string(count) + " cascades need --lattice 32 or more (a " +
                "patch may be at most N / 16 times the next; with " + std::to_string(n) +
                " only one cascade)");
  }
  if (L.empty()) {
    L.push_back(std::min(20 * longest_peak, limits::kMaxWavelength));
    double r = 2;
    if (count > 1) {
      // The last lattice's Nyquist (n / 2) 2 pi / L_last must reach k_max.
      const double need = out.k_max * L[0] / (kPi * n);
      while (std::pow(r, count - 1) < need && r < max_ratio)
        r *= 2;
      r = std::min(r, max_ratio);
    }
    for (int c = 1; c < count; ++c)
      L.push_back(L[0] / std::pow(r, c));
  } else if (static_cast<int>(L.size()) != count) {
    throw Error("--patch-sizes: " + std::to_string(L.size()) + " sizes for " +
                std::to_string(count) + " cascades (--cascades)");
  }
  for (int c = 0; c < count; ++c) {
    if (!(std::isfinite(L[c]) && L[c] >= limits::kMinWavelength * n &&
          L[c] <= limits::kMaxWavelength)) {
      throw Error("--patch-sizes: each must be in [" + num(limits::kMinWavelength * n) + ", " +
                  num(limits::kMaxWavelength) + "] m for a lattice of " + std::to_string(n) +
                  " (got " + num(L[c]) + ")");
    }
    if (c > 0 && !(L[c] < L[c - 1] && L[c - 1] / L[c] <= max_ratio + 1e-9)) {
      throw Error("--patch-sizes: must decrease, each at most " + num(max_ratio) +
                  " times the next (N / 16: the finer lattice resolves its band's edge); got " +
                  num(L[c - 1]) + " then " + num(L[c]));
    }
  }

  // The bands.
  std::vector<double> b(count + 1);
  b[0] = out.k_min;
  for (int c = 1; c < count; ++c)
    b[c] = (n / 4.0) * kTwoPi / L[c - 1];
  b[count] = std::min(out.k_max, (n / 2.0) * kTwoPi / L[count - 1]);
  out.k_reached = b[count];
  for (int c = 0; c < count; ++c) {
    if (!(b[c + 1] > b[c])) {
      throw Error("--cascades: cascade " + std::to_string(c) + " (patch " + num(L[c]) +
                  " m) would hold no wavelength of the band " + num(kTwoPi / out.k_max) + "-" +
                  num(kTwoPi / out.k_min) + " m: fewer cascades or other --patch-sizes");
    }
  }

  for (int c = 0; c < count; ++c) {
    CascadeDesc desc;
    desc.patch_size = L[c];
    desc.lattice = n;
    desc.band_min = b[c];
    desc.band_max = b[c + 1];
    auto data = std::make_shared<LatticeData>();
    data->n = n;
    const size_t cells = static_cast<size_t>(n) * n;
    data->amplitude.assign(cells, 0.0);
    data->phase.assign(cells, 0.0);
    const double dk = kTwoPi / L[c];
    Pcg32 rng(p.seed, 16 + static_cast<uint64_t>(c));
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const size_t e = static_cast<size_t>(j) * n + i;
        data->phase[e] = kTwoPi * rng.uniform();  // drawn for every point: stable streams
        const vec2 k = lattice_wave_vector(L[c], n, i, j);
        const double kk = length(k);
        if (!(kk >= desc.band_min && kk < desc.band_max)) continue;
        double e_k = 0;
        for (const Part& part : parts)
          e_k += density(part, water, k);
        data->amplitude[e] = std::sqrt(2 * e_k * dk * dk);
        out.variance += e_k * dk * dk;
      }
    }
    desc.data = data;
    out.cascades.push_back(desc);
  }
  for (const Part& part : parts) {
    const double lo = std::max(b[0], part.band.k_min), hi = std::min(b[count], part.band.k_max);
    if (hi > lo)
      out.spectrum_variance += part.component.spectrum.variance(water.omega(lo), water.omega(hi));
  }
  return out;
}

}  // namespace sg::ocean
