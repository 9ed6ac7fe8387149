// An elliptical Gaussian RDF approximated by circular Gaussian kernels on its major axis
// (Podee, Max, Iwasaki, Dobashi 2021, Sec. 3.6 and Appendix C, a Feline-like scheme).
//
// The renderer can integrate a *circular* Gaussian against the light disk along a segment
// from a precomputed table (Sec. 3.5); an elongated RDF is therefore replaced by a weighted
// sum of circular Gaussians whose centres lie on its major axis, each swept along its own
// offset segment (Fig. 10). This file holds the model and its error, all in closed form:
//   - the L2 error of Eq. 25 for any list of kernels, with its gradient (for the fitter);
//   - the mixture density of Eq. 26 at a point;
//   - the single-kernel optima in closed form (N = 0);
//   - the runtime entry point `elliptical_kernels`, which interpolates the fitted table
//     (kernel_table.h, written by tools/fit_kernels) and scales it to the real RDF.
// The fitted parameters minimise Eq. 25 subject to unit total mass and non-negative
// weights (an L2 fit alone loses up to 10% of the mass at ratio 9 with 5 kernels, and the
// mass is the brightness of a reflection much narrower than the light disk);
// docs/kernel-fits.md says how they were fitted and how well they fit.
//
// Conventions: the ellipse G has standard deviations (sigma_minor, sigma_major) along
// (x, y) and is a unit-mass density (Eq. 27 with Eq. 2); a kernel's `weight` is its mass,
// so the weights of a unit-mass mixture sum to 1.
#pragma once

#include <span>
#include <vector>

namespace sg {

// One circular Gaussian: isotropic standard deviation `sigma`, mass `weight`, centred at
// `offset` on the major axis of the ellipse (x = 0, y = offset).
struct CircularKernel {
  double offset = 0;
  double sigma = 1;
  double weight = 1;
};

// Appendix C's parameterisation of 2N + 1 kernels: a central kernel (w_a, sigma_a) and N
// pairs at +-d_i with (w_i, sigma_i). Fitted tables use unit minor standard deviation.
struct KernelPair {
  double distance = 0;  // d_i
  double sigma = 1;     // sigma_i
  double weight = 0;    // w_i, the mass of *each* kernel of the pair
};
struct SymmetricKernels {
  double center_weight = 1;  // w_a
  double center_sigma = 1;   // sigma_a
  std::vector<KernelPair> pairs;
};

// The 2N + 1 kernels of Eq. 26: the central one, then +d_1, -d_1, +d_2, -d_2, ...
std::vector<CircularKernel> expand(const SymmetricKernels& p);

// G(x, y): the unit-mass normal density with covariance diag(sigma_minor^2,
// sigma_major^2) (Eq. 27) at (x, y), x across and y along the major axis.
double ellipse_density(double x, double y, double sigma_minor, double sigma_major);

// C(x, y) of Eq. 26, generalised to any list of kernels on the major axis.
double mixture_density(std::span<const CircularKernel> kernels, double x, double y);

// The integral of C_a C_b over the plane, in closed form (see mixture_error); with it,
// ||C_a - C_b||^2 = <C_a, C_a> - 2 <C_a, C_b> + <C_b, C_b>.
double mixture_inner_product(std::span<const CircularKernel> a, std::span<const CircularKernel> b);

// ||G||^2 = integral of G^2 = 1 / (4 pi sigma_minor sigma_major).
double ellipse_norm_sq(double sigma_minor, double sigma_major);

// epsilon of Eq. 25, the integral of (G - C)^2 over the plane, in closed form for any list
// of kernels. Eq. 28 is the case of three symmetric kernels times 4 pi, with its "b^2"
// read as w_1^2 (a typo in the paper).
double mixture_error(std::span<const CircularKernel> kernels, double sigma_minor,
                     double sigma_major);

// The same, and its partial derivatives with respect to every kernel's offset, sigma and
// weight, written into `gradient` (same length as `kernels`).
double mixture_error(std::span<const CircularKernel> kernels, double sigma_minor,
                     double sigma_major, std::span<CircularKernel> gradient);

// The same, summed in long double. epsilon is a difference of terms of the size of ||G||^2,
// so in double it is known to about 1e-16 ||G||^2 (a relative L2 error of 1e-8); the
// fitter needs more where the fits are that good (ratios near 1, many kernels).
double mixture_error_extended(std::span<const CircularKernel> kernels, double sigma_minor,
                              double sigma_major, std::span<CircularKernel> gradient);

// sqrt(epsilon) / ||G||: the L2 error relative to the ellipse.
double relative_l2_error(std::span<const CircularKernel> kernels, double sigma_minor,
                         double sigma_major);

// The best single circular kernel for the ellipse (1, ratio) in the sense of Eq. 25 with a
// free weight (N = 0, closed form): sigma^2 = ratio and weight 2 sqrt(ratio) / (1 + ratio).
CircularKernel single_kernel_l2_optimum(double ratio);

// Sec. 3.5's circular approximation for the ellipse (1, ratio): the equal-area variance
// sigma^2 = sigma_x sigma_y = ratio, with unit weight. It is the L2 optimum above
// renormalised to unit mass.
CircularKernel equal_area_kernel(double ratio);

// The kernel counts a user can pick (--kernels).
inline constexpr int kKernelCounts[] = {1, 3, 5, 9};
bool valid_kernel_count(int count);

// The fitted table covers ratios sigma_major / sigma_minor in [1, kernel_table_max_ratio()].
double kernel_table_max_ratio();

// The fit for `count` kernels at `ratio` >= 1, with unit minor standard deviation: for 3, 5
// or 9 the compiled-in table interpolated (kernel_table.h; the ratio is clamped to the
// table); for 1, the equal-area kernel.
SymmetricKernels tabulated_kernels(int count, double ratio);

// The kernels that approximate an RDF with the given standard deviations, in its units.
struct KernelSet {
  std::vector<CircularKernel> kernels;  // offsets along the major axis, stds, weights
  double ratio = 1;                     // sigma_major / sigma_minor
  // ratio > count: past the paper's elongation threshold (Sec. 3.6), where it renders with
  // its fallback (a Riemann sum of RDF times light) instead of these kernels.
  bool past_threshold = false;
  // ratio > kernel_table_max_ratio() (count 3, 5, 9): the kernels are the fit for the
  // table's last ratio R, scaled by sigma_major / R, so that they match the major std and
  // are ratio / R times too wide across it: a stand-in, not a fit. Always past_threshold.
  bool beyond_table = false;
};

// The runtime entry point: `count` kernels (1, 3, 5 or 9) for the elliptical Gaussian RDF
// with standard deviations sigma_minor <= sigma_major (finite, > 0; a ratio within 1e-9
// below 1 is taken as 1). Offsets along the major axis and stds in the RDF's units; weights
// sum to 1. The kernels come whatever the ratio; `past_threshold` says where the paper
// would not use them. Throws sg::Error for another count or invalid standard deviations.
KernelSet elliptical_kernels(int count, double sigma_minor, double sigma_major);

}  // namespace sg
