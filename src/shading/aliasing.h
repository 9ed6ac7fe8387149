// Spatial-aliasing detection (Podee et al. 2021, Sec. 3.2 and 3.7).
//
// A wave's phase p = a x + b z changes across the screen at the rate
//     dp/dpx = k . dX/dpx,   dp/dpy = k . dX/dpy     (k = (a, b), X = (x, z) on the water)
// so its projected frequency is f = |grad_screen p| / 2pi cycles per pixel. On a square
// pixel grid the Nyquist region is |f_x|, |f_y| < 1/2, so by default f is the larger axis
// frequency ("max"); the Euclidean norm ("norm") is the alternative (a diagonal wave then
// counts as higher). The soft classification of Eq. 20 gives the aliasing fraction
//     alpha = clamp((f - f_start) / (f_end - f_start), 0, 1)
// with f_start = f_n - delta = 0.2 and f_end = f_n = 0.5 cycles per pixel (Sec. 4). Each
// wave's amplitude is split: alpha A joins the aliasing waves (the NDF), (1 - alpha) A the
// resolved ones (the reflection path).
#pragma once

#include <span>
#include <vector>

#include "math/vec.h"
#include "scene/waves.h"

namespace sg {

enum class FrequencyNorm { max, norm };

struct AliasingParams {
  double start = 0.2;  // cycles per pixel: below, a wave is resolved (alpha = 0)
  double end = 0.5;    // cycles per pixel: above, a wave aliases (alpha = 1)
  FrequencyNorm norm = FrequencyNorm::max;
};

// Projected frequency (cycles per pixel) of wave vector k for a pixel whose footprint maps
// image-plane offsets to horizontal offsets by `xz_jacobian` (footprint.h).
double projected_frequency(const vec2& k, const mat2& xz_jacobian, FrequencyNorm norm);

// Eq. 20.
double alias_fraction(double frequency, const AliasingParams& p);

// alpha_i of every wave of `waves` for one pixel.
void alias_fractions(const WaveField& waves, const mat2& xz_jacobian, const AliasingParams& p,
                     std::vector<double>& alpha);

}  // namespace sg
