// The building blocks of temporal anti-aliasing (methods/taa.h), on one channel of an
// image (a colour image is resolved channel by channel): sub-pixel jitter, history resampling,
// neighbourhood clamping and the exponential blend. References: Karis 2014, "High Quality Temporal
// Supersampling" (SIGGRAPH course); Salvi 2016, "An Excursion in Temporal Supersampling" (GDC;
// variance clipping); Yang, Liu and Salvi 2020, "A Survey of Temporal Antialiasing Techniques"
// (Computer Graphics Forum, Secs. 3-5: jitter sequences, reprojection, history rectification).
//
//  - Jitter: the Halton (2, 3) sequence (radical inverses in bases 2 and 3, Survey Sec. 3.1),
//    indices 1..K cycling with the frame (index (f mod K) + 1: index 0 is the origin, which
//    engines skip), as an offset in [-1/2, 1/2)^2 from the pixel centre: the sample is at
//    (i + H2, j + H3) inside the pixel square [i, i+1] x [j, j+1].
//  - History resampling at a reprojected image-plane point (pixel centres at i + 1/2):
//    bilinear, or Catmull-Rom (the cubic convolution of Keys 1981 with a = -1/2, 4 x 4
//    texels; Karis 2014 and Jimenez's filmic SMAA use it to keep the history sharp), whose
//    overshoot is clamped to the range of the 2 x 2 nearest texels (anti-ringing). Texel
//    indices clamp to the image's edge; a point outside [0, W] x [0, H] has no history
//    (rejected: the pixel shows its current sample).
//  - Neighbourhood box of the current frame's samples in the 3 x 3 pixels around (i, j)
//    (those inside the image): minmax is [min, max] (Karis 2014); variance is
//    [mu - gamma sigma, mu + gamma sigma] with mu, sigma the mean and standard deviation
//    (Salvi 2016). Clipping the history towards the box's centre (Salvi's "clip towards
//    the mean") and clamping it to the box are the same operation on one channel.
//  - Blend: out = lerp(history, current, alpha) = (1 - alpha) history + alpha current
//    (alpha = 1 gives the current sample exactly).
#pragma once

#include "image/image.h"
#include "math/vec.h"
#include "methods/options.h"

namespace sg {

// Radical inverse of `index` (>= 0) in `base` (>= 2).
double halton(int index, int base);

// The jitter offset of frame `frame` (any integer) for a cycle of `count` (>= 1) offsets.
vec2 taa_jitter(int frame, int count);

// Channel c of the history at image-plane point p; false when p lies outside [0, W] x [0, H].
bool sample_history(const Image& history, const vec2& p, TaaHistoryFilter filter, double& value,
                    int c = 0);

struct NeighbourhoodBox {
  double lo = 0, hi = 0;
};
// The box of channel c.
NeighbourhoodBox neighbourhood_box(const Image& current, int i, int j, TaaClamp mode, double gamma,
                                   int c = 0);

inline double clip_to_box(double history, const NeighbourhoodBox& box) {
  return history < box.lo ? box.lo : (history > box.hi ? box.hi : history);
}

inline double taa_blend(double history, double current, double alpha) {
  return (1.0 - alpha) * history + alpha * current;
}

}  // namespace sg
