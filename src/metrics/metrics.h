// Error metrics on the linear pixel values of the scene spec (never on tone-mapped
// pictures): the figures of every comparison.
//
//   RMSE     sqrt(mean (a - b)^2) over every value: the 3 W H values of a colour image
//            (scene spec, format /2), the W H of a grey one
//   PSNR     20 log10(peak / RMSE), peak = 1 by default (the largest value with light
//            radiance 1 and sky 0); +inf for identical images
//   mean     of each image (over every value)
//   max_abs  max |a - b|
//
// Sequences (Podee et al. 2021 measure single frames; flicker needs pairs):
//   temporal error  RMS over values and frames f >= 1 of (I_f - I_{f-1}) - (R_f - R_{f-1}):
//                   the frame-to-frame change that the reference does not have
//   flicker energy  mean over values and frames f >= 1 of |I_f - I_{f-1}|, per sequence
//
// Colour: the figures above are taken over all channels together, and each channel's
// alone is given too (`channels`). A grey image (one channel) stands for three equal
// channels, so it may be compared with a colour one; two grey images give one channel,
// and the figures of a grey image equal those of the same image as three equal channels.
#pragma once

#include <vector>

#include "image/image.h"

namespace sg {

struct ChannelMetrics {
  double rmse = 0, mean_a = 0, mean_b = 0, max_abs = 0;
};

struct ImageMetrics {
  double rmse = 0;
  double psnr = 0;
  double mean_a = 0;
  double mean_b = 0;
  double max_abs = 0;
  long pixels = 0;
  // Per channel: one entry when both images are grey, three (R, G, B) otherwise.
  std::vector<ChannelMetrics> channels;
};

// Throws sg::Error when the sizes differ, or a channel count is neither 1 nor 3. `mask`,
// when given (one entry per pixel, nonzero = use), restricts the metrics to some pixels
// (e.g. the near or far half of the water).
ImageMetrics compare_images(const Image& a, const Image& b, double peak = 1.0,
                            const std::vector<unsigned char>* mask = nullptr);

struct SequenceChannelMetrics {
  double rmse = 0, temporal_error = 0, flicker_a = 0, flicker_b = 0;
};

struct SequenceMetrics {
  std::vector<ImageMetrics> frames;  // per frame, a against b
  double rmse = 0;                   // RMS over all values of all frames
  double temporal_error = 0;
  double flicker_a = 0;
  double flicker_b = 0;
  std::vector<SequenceChannelMetrics> channels;  // as ImageMetrics::channels
};

// a: the images under test, b: the reference, both in frame order (at least 1 frame).
SequenceMetrics compare_sequences(const std::vector<Image>& a, const std::vector<Image>& b,
                                  double peak = 1.0,
                                  const std::vector<unsigned char>* mask = nullptr);
// The same with a mask per frame (masks[f] null: every pixel of frame f): a frame's own
// pixels for its RMSE, and frame f's for the change from frame f-1 to f (temporal error,
// flicker), so a set of pixels that changes from frame to frame (what the pixel sees on
// moving waves) is measured where it is.
SequenceMetrics compare_sequences(const std::vector<Image>& a, const std::vector<Image>& b,
                                  double peak,
                                  const std::vector<const std::vector<unsigned char>*>& masks);

double psnr_from_rmse(double rmse, double peak);

}  // namespace sg
