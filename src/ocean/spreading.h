// Directional spreading functions D(theta; omega): how a frequency's energy is shared
// among directions theta (radians from the mean direction, in [-pi, pi]); each integrates
// to 1 over theta, so the directional spectrum is S(omega) D(theta; omega).
//
// * cos-2s (Longuet-Higgins, Cartwright and Smith 1963, "Observations of the directional
//   spectrum of sea waves using the motions of a floating buoy", Ocean Wave Spectra,
//   Prentice-Hall, 111-136):
//       D = Q(s) cos^2s(theta / 2),  Q(s) = 2^(2s-1) Gamma(s+1)^2 / (pi Gamma(2s+1)),
//   with Mitsuyasu et al.'s spreading parameter (Mitsuyasu, Tasai, Suhara, Mizuno,
//   Ohkusu, Honda and Rikiishi 1975, "Observations of the directional spectrum of ocean
//   waves using a cloverleaf buoy", J. Phys. Oceanogr. 5, 750-760):
//       s = s_p (omega / omega_p)^5 (omega < omega_p),  s_p (omega / omega_p)^-2.5
//       (omega >= omega_p),  s_p = 11.5 (omega_p U_10 / g)^-2.5.
//   A swell uses the same shape with a given s_p (Goda and Suzuki 1975: s_max = 75 for
//   a swell of long decay distance).
// * Hasselmann et al. 1980 (Hasselmann, Dunckel and Ewing, "Directional wave spectra
//   observed during JONSWAP 1973", J. Phys. Oceanogr. 10, 1264-1280): the
//   cos-2s shape with
//       s = 6.97 (omega / omega_p)^4.06 (omega < omega_p),
//       s = 6.97 (omega / omega_p)^mu,  mu = -2.33 - 1.45 (U_10 / c_p - 1.17)
//       (omega >= omega_p), c_p the phase speed at the peak.
// * Donelan-Banner: Donelan, Hamilton and Hui 1985 ("Directional spectra of
//   wind-generated waves", Phil. Trans. R. Soc. Lond. A 315, 509-562)
//       D = beta / (2 tanh(beta pi)) sech^2(beta theta),
//       beta = 2.61 (omega / omega_p)^1.3  (omega / omega_p < 0.95; their data start at
//              0.56, sunglint extends the branch below, where little energy lies),
//       beta = 2.28 (omega / omega_p)^-1.3 (0.95 <= omega / omega_p < 1.6),
//   and above, Banner 1990 ("Equilibrium spectra of wind waves", J. Phys. Oceanogr. 20,
//   966-984): beta = 10^(-0.4 + 0.8393 exp(-0.567 ln((omega / omega_p)^2))).
//
// Sampling draws theta by the inverse of D's cumulative distribution: for cos-2s,
// t = sin(theta / 2) has density proportional to (1 - t^2)^(s - 1/2), so (t + 1) / 2 is
// Beta(s + 1/2, s + 1/2) distributed and theta = 2 asin(2 I^-1(u; s + 1/2, s + 1/2) - 1)
// (I^-1 the inverse regularised incomplete beta function: Newton's method on Numerical
// Recipes' continued fraction, 1.5-3.3 us a call for a = 0.6 to 200 where
// boost::math::ibeta_inv took 4-31 us, up to 2 s for 65536 waves; tested equal to it);
// for sech^2 the distribution is closed form: theta = atanh((2u - 1) tanh(beta pi)) / beta.
#pragma once

#include <string>

namespace sg::ocean {

enum class SpreadingKind { cos2s, hasselmann, donelan_banner };

struct Spreading {
  SpreadingKind kind = SpreadingKind::cos2s;
  double omega_peak = 1;     // rad/s
  double wind_speed = 10;    // U_10, m/s (Mitsuyasu's s_p, Hasselmann's exponent)
  double peak_speed = 9.81;  // c_p = omega_p / k_p, m/s (Hasselmann's exponent)
  double s_peak = -1;        // cos2s: s_p given (a swell's s_max); negative: Mitsuyasu's law

  // The cos-2s parameter s(omega) (cos2s, hasselmann) or the sech^2 width beta(omega)
  // (donelan-banner).
  double parameter(double omega) const;
  // D(theta; omega), 1/rad, theta in [-pi, pi].
  double density(double theta, double omega) const;
  // The inverse cumulative distribution: theta in [-pi, pi] for u in [0, 1].
  double sample(double u, double omega) const;
};

// Longuet-Higgins et al.'s normalisation Q(s).
double cos2s_normalisation(double s);
// The u-quantile of the Beta(a, a) distribution, I^-1(u; a, a), to 1e-14 relative.
double symmetric_beta_quantile(double a, double u);

std::string to_string(SpreadingKind kind);

}  // namespace sg::ocean
