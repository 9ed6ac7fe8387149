// Turning linear values into 8-bit pictures for viewing. Metrics never see these: they
// are computed on the linear values (scene spec, "Quality figures").
//
// PNG output: value * 2^exposure, clamped to [0, 1], sRGB-encoded (IEC 61966-2-1), each
// channel alone.
// Difference images: a signed difference (the mean over the channels of a colour image)
// mapped through Moreland's "cool to warm"
// diverging colour map (Moreland 2009, "Diverging Color Maps for Scientific
// Visualization"): blue where the image is darker than the reference, red where brighter.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "image/image.h"

namespace sg {

// sRGB opto-electronic transfer function for a linear value in [0, 1].
double srgb_encode(double linear);

// 8-bit values of `img` (grey or RGB, as its channels) after exposure (in stops) and
// sRGB encoding.
std::vector<uint8_t> tonemap_srgb8(const Image& img, double exposure_stops);

// RGB colour of a signed value t in [-1, 1] under the cool-to-warm map.
std::array<uint8_t, 3> diverging_colour(double t);

// RGB 8-bit pixels of a - b (mean over the channels; a grey image counts as three equal
// channels), scaled so that +-range maps to the ends of the colour map.
std::vector<uint8_t> difference_rgb8(const Image& a, const Image& b, double range);

}  // namespace sg
