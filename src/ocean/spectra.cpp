#include "ocean/spectra.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "math/vec.h"

namespace sg::ocean {
namespace {

// 8-point Gauss-Legendre nodes and weights on [-1, 1] (Abramowitz and Stegun 1964,
// Table 25.4).
constexpr std::array<double, 4> kGlX = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                        0.9602898564975363};
constexpr std::array<double, 4> kGlW = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                        0.1012285362903763};

template <class F>
double gauss_legendre(const F& f, double a, double b, int pieces) {
  double sum = 0;
  const double h = (b - a) / pieces;
  for (int p = 0; p < pieces; ++p) {
    const double mid = a + (p + 0.5) * h, half = 0.5 * h;
    double s = 0;
    for (int q = 0; q < 4; ++q)
      s += kGlW[q] * (f(mid - half * kGlX[q]) + f(mid + half * kGlX[q]));
    sum += s * half;
  }
  return sum;
}

}  // namespace

double pierson_moskowitz(double omega, double u19_5) {
  if (omega <= 0) return 0;
  const double g = kGravity;
  return kPmAlpha * g * g * std::pow(omega, -5.0) *
         std::exp(-kPmBeta * std::pow(g / (u19_5 * omega), 4.0));
}

double jonswap(double omega, double alpha, double omega_peak, double gamma) {
  if (omega <= 0) return 0;
  const double g = kGravity;
  const double sigma = omega <= omega_peak ? 0.07 : 0.09;
  const double d = (omega - omega_peak) / (sigma * omega_peak);
  const double r = std::exp(-0.5 * d * d);
  return alpha * g * g * std::pow(omega, -5.0) *
         std::exp(-1.25 * std::pow(omega_peak / omega, 4.0)) * std::pow(gamma, r);
}

double kitaigorodskii_depth(double omega, double depth) {
  if (omega <= 0) return 0;
  const Dispersion water{depth};
  if (water.deep()) return 1;
  const double kh = water.wavenumber(omega) * depth;
  const double t = std::tanh(kh);
  // 2kh / sinh(2kh) underflows to 0 in deep water (kh > 350), tends to 1 as kh -> 0.
  const double ratio = 2 * kh > 700 ? 0.0 : 2 * kh / std::sinh(2 * kh);
  return t * t / (1 + ratio);
}

double thompson_vincent_depth(double omega, double depth) {
  const double wh = omega * std::sqrt(depth / kGravity);
  if (wh <= 1) return 0.5 * wh * wh;
  if (wh < 2) return 1 - 0.5 * (2 - wh) * (2 - wh);
  return 1;
}

double Spectrum::operator()(double omega) const {
  double s = jonswap(omega, alpha, omega_peak, gamma);
  if (kind == SpectrumKind::tma) s *= kitaigorodskii_depth(omega, water.depth);
  return s;
}

double Spectrum::variance(double omega0, double omega1) const {
  if (!(omega1 > omega0)) return 0;
  // The peak enhancement's width changes at omega_p (a kink in S''): split there.
  if (omega0 < omega_peak && omega_peak < omega1)
    return variance(omega0, omega_peak) + variance(omega_peak, omega1);
  const double piece = omega_peak / 50;
  const int pieces = static_cast<int>(std::clamp(std::ceil((omega1 - omega0) / piece), 1.0, 1e6));
  return gauss_legendre([this](double w) { return (*this)(w); }, omega0, omega1, pieces);
}

double Spectrum::peak() const {
  if (kind != SpectrumKind::tma) return omega_peak;
  // The depth factor rises with omega, so TMA's maximum lies at or above omega_p and
  // below 2 omega_p (where the JONSWAP shape has fallen by a factor 30): golden-section
  // search on log S, which is unimodal there.
  double a = omega_peak, b = 2 * omega_peak;
  const double r = (std::sqrt(5.0) - 1) / 2;
  double c = b - r * (b - a), d = a + r * (b - a);
  for (int it = 0; it < 100 && b - a > 1e-12 * omega_peak; ++it) {
    if ((*this)(c) > (*this)(d)) {
      b = d;
    } else {
      a = c;
    }
    c = b - r * (b - a);
    d = a + r * (b - a);
  }
  return 0.5 * (a + b);
}

FetchLaws jonswap_fetch_laws(double wind_speed, double fetch_m) {
  FetchLaws f;
  const double x = kGravity * fetch_m / (wind_speed * wind_speed);
  f.capped = x > kFullyDevelopedFetch;
  f.dimensionless_fetch = std::min(x, kFullyDevelopedFetch);
  f.alpha = 0.076 * std::pow(f.dimensionless_fetch, -0.22);
  f.omega_peak = kTwoPi * 3.5 * (kGravity / wind_speed) * std::pow(f.dimensionless_fetch, -0.33);
  return f;
}

Spectrum pierson_moskowitz_spectrum(double wind_speed) {
  Spectrum s;
  s.kind = SpectrumKind::pierson_moskowitz;
  s.alpha = kPmAlpha;
  s.gamma = 1;
  s.omega_peak = std::pow(0.8 * kPmBeta, 0.25) * kGravity / (kU19_5PerU10 * wind_speed);
  return s;
}

Spectrum jonswap_spectrum(double wind_speed, double fetch_m, double gamma) {
  const FetchLaws f = jonswap_fetch_laws(wind_speed, fetch_m);
  Spectrum s;
  s.kind = SpectrumKind::jonswap;
  s.alpha = f.alpha;
  s.omega_peak = f.omega_peak;
  s.gamma = gamma;
  return s;
}

Spectrum tma_spectrum(double wind_speed, double fetch_m, double gamma, double depth) {
  Spectrum s = jonswap_spectrum(wind_speed, fetch_m, gamma);
  s.kind = SpectrumKind::tma;
  s.water.depth = depth;
  return s;
}

Spectrum swell_spectrum(double hs, double tp, double gamma) {
  Spectrum s;
  s.kind = SpectrumKind::swell;
  s.omega_peak = kTwoPi / tp;
  s.gamma = gamma;
  s.alpha = 1;
  // The variance of the shape with alpha = 1 over all frequencies: below omega_p / 4 the
  // shape is below exp(-320) of its peak; above 40 omega_p the omega^-4 tail holds
  // omega^-4 / 4 of alpha g^2, added in closed form.
  const double w_hi = 40 * s.omega_peak;
  const double unit =
      s.variance(s.omega_peak / 4, w_hi) + kGravity * kGravity / (4 * std::pow(w_hi, 4.0));
  s.alpha = hs * hs / 16 / unit;
  return s;
}

std::string to_string(SpectrumKind kind) {
  switch (kind) {
    case SpectrumKind::pierson_moskowitz:
      return "pierson-moskowitz";
    case SpectrumKind::jonswap:
      return "jonswap";
    case SpectrumKind::tma:
      return "tma";
    case SpectrumKind::swell:
      return "swell";
  }
  return "";
}

}  // namespace sg::ocean
