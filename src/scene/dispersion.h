// The dispersion relation of linear gravity waves: how a wave's angular frequency omega
// follows from its wavenumber k = |k| and the water depth h (Airy wave theory, e.g.
// Dean and Dalrymple 1991, "Water Wave Mechanics for Engineers and Scientists",
// Eq. 3.35):
//     omega^2 = g k tanh(k h)            (finite depth)
//     omega^2 = g k                      (deep water, h -> infinity)
// The ocean generator samples waves by wavenumber, so omega(k) is explicit; the inverse
// k(omega) (needed for peak wavelengths and the spectrum's trimmed range) is solved by
// Newton's method from Eckart's (1952) explicit approximation.
#pragma once

#include <limits>

namespace sg {

inline constexpr double kGravity = 9.81;  // m/s^2, as the scene spec's dispersion note

// Water depth; infinite (the default) is deep water.
struct Dispersion {
  double depth = std::numeric_limits<double>::infinity();  // m

  bool deep() const { return !(depth < std::numeric_limits<double>::infinity()); }
  // omega(k), rad/s, for k >= 0 rad/m.
  double omega(double k) const;
  // k(omega), rad/m, for omega >= 0 rad/s: the root of omega(k) = omega (to 1e-14).
  double wavenumber(double omega) const;
  // d omega / d k, the group speed (m/s).
  double group_speed(double k) const;
};

}  // namespace sg
