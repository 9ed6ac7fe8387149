// Filmic tone mapping for pictures and videos (never for metrics, which stay on linear
// values): the ACES filmic curve as fitted by Narkowicz ("ACES Filmic Tone Mapping
// Curve", blog post, 2016-01-06, knarkowicz.wordpress.com),
//
//     f(x) = x (a x + b) / (x (c x + d) + e),  a = 2.51, b = 0.03, c = 2.43, d = 0.59,
//     e = 0.14,
//
// clamped to [0, 1]: a toe that keeps the dark sea dark, a shoulder that rolls highlights
// off instead of clipping them, so the sun's glints and their glare stay distinguishable.
// f(0) = 0 and f is increasing on x >= 0; f(x) reaches 1 at x = (0.56 + sqrt(0.3584)) / 0.16
// ~ 7.24.
//
// The display pipeline of `sunglint compare` and `render --display` (identical for every
// method): value * 2^exposure, then glare (image/glare.h), then f, then the sRGB encoding
// (display.h); on each channel of a colour image alone (glare included).
#pragma once

#include <cstdint>
#include <vector>

#include "image/glare.h"
#include "image/image.h"

namespace sg {

// Narkowicz's fit of the ACES filmic curve, clamped to [0, 1]; non-finite or negative
// input maps to 1 or 0.
double aces_filmic(double x);

struct DisplaySettings {
  double exposure = 0.0;  // stops: the linear value is scaled by 2^exposure first
  bool glare = true;
  GlareSettings glare_settings;
};

// Linear image -> 8-bit picture, grey or RGB like the image (one byte per value):
// exposure, glare (if enabled), ACES curve, sRGB.
std::vector<uint8_t> display_srgb8(const Image& img, const DisplaySettings& settings);

}  // namespace sg
