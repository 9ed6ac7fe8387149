// F(d, sigma): the mass of the circular 2D Gaussian N(c, sigma^2 I), |c| = d, inside the unit
// disk. This is the inner integral of Podee et al. 2021, Eq. 17, for the circular Gaussian
// RDF of Sec. 3.5 (the "convolution of the light disk with the circular Gaussian" in Eq. 18)
// with the light disk scaled to radius 1.
//
// Closed form: |X|^2 / sigma^2 for X ~ N(c, sigma^2 I) is non-central chi-squared with 2
// degrees of freedom and non-centrality d^2 / sigma^2, so
//   F(d, sigma) = P[chi'^2_2(d^2 / sigma^2) <= 1 / sigma^2] = 1 - Q_1(d / sigma, 1 / sigma)
// (Marcum Q). We use Boost.Math's non_central_chi_squared CDF for 0.05 <= sigma <= 1e3.
// Outside that range Boost is slow (milliseconds at sigma = 1e-4) or throws (sigma <= 1e-5:
// its series index overflows), so:
//  * sigma < 0.05: the exact one-dimensional form. With c = (d, 0) and Z1, Z2 standard
//    normal, the point lies inside iff |sigma Z2| <= 1 and Z1 lies between (-s - d) / sigma
//    and (s - d) / sigma, s = sqrt(1 - sigma^2 Z2^2):
//      F = E_Z2[ Phi((s - d) / sigma) - Phi((-s - d) / sigma) ],
//    integrated over Z2 in [-13, 13] (the rest weighs < 1e-38) with Boost's trapezoidal rule,
//    which converges geometrically here because the integrand is analytic (sigma |Z2| < 0.65).
//  * sigma > 1e3: the wide-Gaussian expansion below, exact to rounding there.
//  * sigma = 0: the indicator of d < 1, with 0.5 at d = 1 (the limit of F(1, sigma)).
//  * |d - 1| >= 40 sigma: exactly 1 or 0. The 2D Gaussian puts mass exp(-t^2 / 2) outside
//    the circle of radius t sigma about its centre, and exp(-800) underflows to 0.
//
// The wide-Gaussian expansion (sigma >> 1): the mean of a smooth f over the unit disk is
// sum_k Delta^k f / (4^k k! (k+1)!) (the mean-value expansion of the Laplacian); for the
// Gaussian, Delta g = g (rho^2 - 2) / sigma^2 and Delta^2 g = g (rho^4 - 8 rho^2 + 8) / sigma^4,
// rho = d / sigma, so with the disk's area pi,
//   F ~ exp(-rho^2 / 2) / (2 sigma^2) [1 + (rho^2 - 2) / (8 sigma^2)
//                                        + (rho^4 - 8 rho^2 + 8) / (192 sigma^4)],
// with relative error O(sigma^-6).
#pragma once

namespace sg {

// F(d, sigma) for d >= 0, sigma >= 0. Throws sg::Error naming the argument otherwise.
double disk_gaussian(double d, double sigma);

// The three-term wide-Gaussian expansion of F (above); for sigma > 0.
double disk_gaussian_wide(double d, double sigma);

}  // namespace sg
