// The normal distribution of the aliasing waves within a pixel, as a 2D Gaussian
// (Podee et al. 2021, Sec. 3.4, Eqs. 2-7 and Appendix A).
//
// The NDF plane is the horizontal plane y = 1: the normal (-h_x, 1, -h_z) meets it at the
// point n = (-h_x, -h_z), so the NDF is the distribution of minus the slope. For the sum
// of waves it is the sum of the per-wave distributions (independent waves): covariances
// add, and so do mean slopes.
//
// uniform (Eq. 3): every aliasing wave spans whole cycles in the pixel; the mean slope is
//   0 and the covariance is sum_i (A_i^2 / 2) [a_i^2, a_i b_i; a_i b_i, b_i^2].
// per-pixel (Eqs. 4-7, Appendix A): each wave's phase runs from p1 to p2 across the pixel
//   along the wave's direction; with theta = phase at the pixel centre (+ c t + phi) and
//   half-width D = (p2 - p1) / 2, the slope moments are (a, b) K and (a^2, ab, b^2) J:
//     K = A (sin(p2 + ct) - sin(p1 + ct)) / (p2 - p1)         = A cos(theta) sin(D) / D
//     J = A^2 (sin(2(p2+ct)) - sin(2(p1+ct)) + 2(p2-p1)) / (4 (p2-p1))
//       = A^2 / 2 (1 + cos(2 theta) sin(2D) / (2D))
//   Eq. 23 of the paper prints sin(2(.)) in K; the mean of A cos(p + ct) over [p1, p2] has
//   sin(.) (tested against numerical integration of Eq. 5). Covariance: M - B B^T (Eq. 4).
//   p1, p2 (Appendix A): the line through the footprint's centre along the wave direction
//   crosses the footprint parallelogram at centre +- s k/|k|, s = 1/2 / max(|u|, |v|) with
//   (u, v) = J^-1 k/|k| in pixel units.
// Whether the per-pixel mean slope -sum B shifts the NDF's centre is an option (see
// docs/results.md for the measurement that chose the default).
#pragma once

#include <span>

#include "math/vec.h"
#include "scene/waves.h"

namespace sg {

// A 2D Gaussian on the NDF plane: mean (a shift from the centre n_c) and covariance.
struct PlaneGaussian {
  vec2 mean{0, 0};
  mat2 cov{0.0};
};

// Eq. 3 for amplitudes weighted by w_i (the aliasing fractions).
mat2 uniform_ndf_covariance(const WaveField& waves, std::span<const double> weights);

// Appendix A for one wave of amplitude A and wave vector k whose phase (including c t +
// phi) runs from p1 to p2: the mean slope B (Eq. 21) and the second moments M = (xx, xz,
// zz) (Eq. 22).
struct SlopeMoments {
  vec2 B{0, 0};
  vec3 M{0, 0, 0};
};
SlopeMoments wave_slope_moments(double A, const vec2& k, double p1, double p2);

// Half of the phase range p2 - p1 that the footprint spans along wave vector k.
double footprint_phase_half_width(const vec2& k, const mat2& xz_jacobian);

// Eqs. 4-7: the per-pixel NDF of the waves weighted by w_i at horizontal point `xz` and
// time t. The mean is minus the summed mean slopes (NDF-plane coordinates).
PlaneGaussian per_pixel_ndf(const WaveField& waves, std::span<const double> weights, const vec2& xz,
                            const mat2& xz_jacobian, double t);

}  // namespace sg
