// The mass of a 2D Gaussian N(mean, cov) inside the disk |p| <= R: the light's share of
// a Gaussian reflection distribution at one instant (Podee et al. 2021, Eq. 17 without
// the time integral; the "convolution of the RDF with the light disk" of Sec. 3.6).
//
// gaussian_disk_mass: in the Gaussian's principal frame (major axis s, minor axis w) the
// mass is the 1D integral over s of the major marginal times the minor conditional's
// probability of falling in the disk's chord, an erf difference:
//     mass = int phi(s / s1) / s1 [Phi((c_w + h(s)) / s2) - Phi((c_w - h(s)) / s2)] ds,
//     h(s) = sqrt(R^2 - (s - c_s)^2)
// with (c_s, c_w) the disk centre relative to the mean. The substitution s = c_s + R sin(u)
// removes the chord's square-root ends, and the range is clipped to +-9 s1 about the
// mean; 30-point Gauss-Legendre then gives 4e-6 or better for any elongation (measured
// against 2D quadrature, gaussian_disk_test), degenerate (s2 = 0)
// distributions included. This is the accurate fallback. A disk further than 9 major
// standard deviations from the mean gives 0, one that holds the 9-sigma ball about the mean
// gives 1 (both within 3e-18), without quadrature.
//
// gaussian_disk_mass_riemann: the paper's fallback, a Riemann sum of the density over an
// n x n grid of cells covering the disk (cell centres inside the disk).
#pragma once

#include "math/vec.h"

namespace sg {

double gaussian_disk_mass(const vec2& mean, const mat2& cov, double R);
double gaussian_disk_mass_riemann(const vec2& mean, const mat2& cov, double R, int n);

// The mass of N(mean, cov) in the half-plane dot(a, p) + c <= 0: a . p + c is normal with
// mean a . mean + c and variance a^T cov a, so the mass is 0.5 erfc((a . mean + c) /
// sqrt(2 a^T cov a)) (a step when that variance is 0).
double gaussian_half_plane_mass(const vec2& mean, const mat2& cov, const vec2& a, double c);

// Eigen-decomposition of a symmetric 2x2 covariance: major std s1 >= minor std s2 >= 0 and
// the unit major axis u (minor axis: (-u.y, u.x)).
struct PrincipalAxes {
  double s1 = 0, s2 = 0;
  vec2 u{1, 0};
};
PrincipalAxes principal_axes(const mat2& cov);

}  // namespace sg
