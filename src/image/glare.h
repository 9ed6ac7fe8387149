// Glare for pictures and videos: the bright part of the image scattered by the eye or a
// lens, as Podee et al. (2021, Sec. 5) apply to every image "to show the Sun's high
// brightness reflection". Metrics never see it.
//
// With b = max(x - threshold, 0) the bright part of image x (after exposure), the glare
// redistributes a fraction W of b through a point spread function and keeps the rest:
//
//     out = x - W b + sum_k w_k (G_{sigma_k} * b) + w_s (S * b),   W = sum_k w_k + w_s,
//
// where G_sigma is a normalised Gaussian (bloom; a sum of Gaussians approximates the
// long-tailed glare PSF of Spencer et al. 1995, "Physically-based glare effects for
// digital images") and S a star of n_s/2 streaks through the pixel (n_s = 4 or 6
// points), each streak a normalised two-sided exponential exp(-|t|/L) along its
// direction. Every kernel sums to 1, so the glare moves energy and creates none: the sum
// of out equals the sum of x, except for what falls outside the frame (pixels beyond
// the border are black, as outside the camera's view).
//
// Sizes are fractions of the image height so a picture looks the same at every size.
#pragma once

#include <vector>

#include "image/image.h"
#include "math/vec.h"

namespace sg {

struct GlareBlur {
  double sigma = 0;   // standard deviation, fraction of the image height
  double weight = 0;  // w_k
};

struct GlareSettings {
  double threshold = 1.0;  // values above it glare (after exposure)
  std::vector<GlareBlur> blurs = {{0.003, 0.10}, {0.012, 0.06}, {0.04, 0.04}};
  int star_points = 6;         // 0 (no star), 4 or 6
  double star_length = 0.04;   // L, fraction of the image height
  double star_weight = 0.06;   // w_s, split evenly between the streaks
  double star_angle_deg = 15;  // angle of the first streak from the horizontal
};

// Normalised discrete Gaussian of standard deviation sigma pixels on [-r, r],
// r = ceil(3 sigma) (at least 0: sigma <= 0 gives the identity {1}).
std::vector<double> gaussian_kernel(double sigma_px);

// Normalised two-sided exponential exp(-|t|/L) at t = -r..r, r = ceil(4 L).
std::vector<double> streak_kernel(double length_px);

// Separable Gaussian blur, black outside the image.
Image gaussian_blur(const Image& img, double sigma_px);

// Each pixel's value spread along direction `dir` (unit) with streak_kernel weights,
// splatted bilinearly; black outside the image.
Image streak_blur(const Image& img, vec2 dir, double length_px);

// The glare of the header on image x (already exposed).
Image apply_glare(const Image& x, const GlareSettings& settings);

}  // namespace sg
