// Frequency spectra of wind-generated seas: the variance of the sea surface per unit
// angular frequency, S(omega) in m^2 s/rad, so that the surface's variance is the
// integral of S over omega (and the significant wave height H_s = 4 sqrt(variance)).
//
// * Pierson-Moskowitz: the fully developed sea (Pierson and Moskowitz 1964, "A proposed
//   spectral form for fully developed wind seas based on the similarity theory of S. A.
//   Kitaigorodskii", J. Geophys. Res. 69(24), 5181-5190):
//       S(omega) = alpha g^2 omega^-5 exp(-beta (g / (U_19.5 omega))^4),
//   alpha = 8.1e-3, beta = 0.74, U_19.5 the wind speed 19.5 m above the sea; with the
//   10 m wind, U_19.5 = 1.026 U_10 (Stewart 2008, "Introduction to Physical
//   Oceanography", Sec. 16.3). Its peak is at omega_p = (4 beta / 5)^(1/4) g / U_19.5
//   = 0.855 g / U_10, where the form above reads alpha g^2 omega^-5 exp(-5/4 (omega_p /
//   omega)^4).
// * JONSWAP: a sea limited by its fetch F (Hasselmann et al. 1973, "Measurements of
//   wind-wave growth and swell decay during the Joint North Sea Wave Project (JONSWAP)",
//   Erg. Dtsch. Hydrogr. Z. A8(12), 95 pp.: the spectral form and the fetch laws):
//       S(omega) = alpha g^2 omega^-5 exp(-5/4 (omega_p / omega)^4) gamma^r,
//       r = exp(-(omega - omega_p)^2 / (2 sigma^2 omega_p^2)),
//       sigma = 0.07 (omega <= omega_p), 0.09 (omega > omega_p),
//   with, for the dimensionless fetch x = g F / U_10^2,
//       alpha = 0.076 x^-0.22,   omega_p = 2 pi 3.5 (g / U_10) x^-0.33,
//   and gamma = 3.3 the mean peak enhancement. The fetch laws meet Pierson-Moskowitz's
//   peak at x = 1.88e4 (a fully developed sea); longer fetches are capped there.
// * TMA: JONSWAP in water of finite depth h (Bouws, Guenther, Rosenthal and Vincent
//   1985, "Similarity of the wind wave spectrum in finite depth water: 1. Spectral form",
//   J. Geophys. Res. 90(C1), 975-986):
//       S_TMA(omega) = S_JONSWAP(omega) Phi(omega, h),
//   with Kitaigorodskii's depth function (Kitaigorodskii, Krasitskii and Zaslavskii
//   1975, "On Phillips' theory of equilibrium range in the spectra of wind-generated
//   gravity waves", J. Phys. Oceanogr. 5, 410-420): the k^-3 saturation range mapped to
//   frequency through the finite-depth dispersion relation (dispersion.h),
//       Phi = (k(omega, h)^-3 dk/domega) / (k_deep^-3 dk_deep/domega)
//           = tanh^2(k h) / (1 + 2 k h / sinh(2 k h)),
//   which Thompson and Vincent (1983, "Prediction of wave height in shallow water",
//   Proc. Coastal Structures '83, ASCE, 1000-1008) approximate by, with
//   omega_h = omega sqrt(h / g): omega_h^2 / 2 (omega_h <= 1), 1 - (2 - omega_h)^2 / 2
//   (1 < omega_h < 2), 1 (omega_h >= 2). The peak frequency and alpha follow the JONSWAP
//   fetch laws (Bouws et al. 1985 scale them by the depth-limited wavenumber; sunglint
//   keeps the deep-water laws, so that TMA tends to JONSWAP as h grows).
// * Swell: a JONSWAP-shaped spectrum of given significant height and peak period (Goda
//   1988, "Statistical variability of sea state parameters as a function of wave
//   spectrum", Coastal Eng. in Japan 31(1), 39-52): alpha is set so that the variance
//   over all frequencies is H_s^2 / 16.
#pragma once

#include <string>

#include "scene/dispersion.h"

namespace sg::ocean {

enum class SpectrumKind { pierson_moskowitz, jonswap, tma, swell };

// Pierson-Moskowitz's constants (Pierson and Moskowitz 1964).
inline constexpr double kPmAlpha = 8.1e-3;
inline constexpr double kPmBeta = 0.74;
inline constexpr double kU19_5PerU10 = 1.026;  // Stewart 2008
// The dimensionless fetch at which JONSWAP's peak reaches Pierson-Moskowitz's.
inline constexpr double kFullyDevelopedFetch = 1.88e4;

struct Spectrum {
  SpectrumKind kind = SpectrumKind::jonswap;
  double alpha = kPmAlpha;  // Phillips' constant
  double omega_peak = 1;    // rad/s: omega_p of the formula
  double gamma = 1;         // peak enhancement (1: Pierson-Moskowitz's shape)
  Dispersion water;         // TMA's depth (deep for the others)

  // S(omega), m^2 s/rad; 0 for omega <= 0.
  double operator()(double omega) const;
  // The variance between two frequencies, integral of S (composite Gauss-Legendre on
  // sub-intervals of at most 1/50 of the peak frequency, 8 nodes each, split at omega_p).
  double variance(double omega0, double omega1) const;
  // Where S is largest: omega_p, except for TMA, whose depth function moves it.
  double peak() const;
};

// Pierson-Moskowitz's formula in its original form (wind at 19.5 m).
double pierson_moskowitz(double omega, double u19_5);
// The JONSWAP shape (alpha, omega_p, gamma), and its depth factor.
double jonswap(double omega, double alpha, double omega_peak, double gamma);
double kitaigorodskii_depth(double omega, double depth);
double thompson_vincent_depth(double omega, double depth);

// The JONSWAP fetch laws for a 10 m wind speed (m/s) and fetch (m).
struct FetchLaws {
  double dimensionless_fetch = 0;  // g F / U^2, after capping
  bool capped = false;             // the fetch was longer than a fully developed sea's
  double alpha = 0, omega_peak = 0;
};
FetchLaws jonswap_fetch_laws(double wind_speed, double fetch_m);

Spectrum pierson_moskowitz_spectrum(double wind_speed);
Spectrum jonswap_spectrum(double wind_speed, double fetch_m, double gamma);
Spectrum tma_spectrum(double wind_speed, double fetch_m, double gamma, double depth);
// A swell of significant height hs (m) and peak period tp (s), JONSWAP-shaped with
// `gamma` (no depth factor: hs and tp are those at the site).
Spectrum swell_spectrum(double hs, double tp, double gamma);

std::string to_string(SpectrumKind kind);

}  // namespace sg::ocean
