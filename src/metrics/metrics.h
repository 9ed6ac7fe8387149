// Error metrics on the linear pixel values of the scene spec (never on tone-mapped
// pictures): the figures of every comparison.
//
//   RMSE     sqrt(mean (a - b)^2)
//   PSNR     20 log10(peak / RMSE), peak = 1 by default (the largest value with light
//            radiance 1 and sky 0); +inf for identical images
//   mean     of each image
//   max_abs  max |a - b|
//
// Sequences (Podee et al. 2021 measure single frames; flicker needs pairs):
//   temporal error  RMS over pixels and frames f >= 1 of (I_f - I_{f-1}) - (R_f - R_{f-1}):
//                   the frame-to-frame change that the reference does not have
//   flicker energy  mean over pixels and frames f >= 1 of |I_f - I_{f-1}|, per sequence
#pragma once

#include <vector>

#include "image/image.h"

namespace sg {

struct ImageMetrics {
  double rmse = 0;
  double psnr = 0;
  double mean_a = 0;
  double mean_b = 0;
  double max_abs = 0;
  long pixels = 0;
};

// Throws sg::Error when the sizes differ. `mask`, when given (same size, nonzero = use),
// restricts the metrics to some pixels (e.g. the near or far half of the water).
ImageMetrics compare_images(const Image& a, const Image& b, double peak = 1.0,
                            const std::vector<unsigned char>* mask = nullptr);

struct SequenceMetrics {
  std::vector<ImageMetrics> frames;  // per frame, a against b
  double rmse = 0;                   // RMS over all pixels of all frames
  double temporal_error = 0;
  double flicker_a = 0;
  double flicker_b = 0;
};

// a: the images under test, b: the reference, both in frame order (at least 1 frame).
SequenceMetrics compare_sequences(const std::vector<Image>& a, const std::vector<Image>& b,
                                  double peak = 1.0,
                                  const std::vector<unsigned char>* mask = nullptr);

double psnr_from_rmse(double rmse, double peak);

}  // namespace sg
