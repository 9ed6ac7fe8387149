// How many waves each part of the image resolves, for `sunglint info`: for bands of the
// image rows that see the water, the number of waves whose projected frequency
// (shading/aliasing.h, Podee et al. 2021 Sec. 3.2) is below the start of Eq. 20's
// transition region (resolved: the method integrates them along the reflection path),
// inside it (split between both treatments), and above its end (fully aliasing: they
// only enter the pixel's reflection distribution). The footprint is that of the water at
// rest (scene/footprint.h), so the answer depends on the view and the image size only.
//
// And what that costs the kernel (kernel/staa.glsl, kernel/intersect.glsl), with the waves
// sorted by |k|: the waves staa visits one by one (those below its O(1) remainder, which
// starts where every wave certainly aliases fully and, for the per-pixel NDF, spans
// 8 half-cycles of phase), and the waves the displaced intersection sums at the pixel's
// distance with the default tolerance (the shortest left out while their amplitudes sum
// to at most a quarter of the pixel's ray bundle).
//
// A band's figures are means over pixels: up to 16 rows and 33 columns of the band,
// evenly spaced, at their centres.
#pragma once

#include <vector>

#include "scene/scene.h"
#include "shading/aliasing.h"

namespace sg {

struct ResolutionBand {
  int row_first = 0, row_last = 0;                    // image rows, 0 at the top
  double distance_first = 0, distance_last = 0;       // m, centre column, rows first and last
  double resolved = 0, transition = 0, aliasing = 0;  // mean waves per pixel
  double visited = 0;    // mean waves staa visits one by one (per-pixel NDF)
  double intersect = 0;  // mean waves the displaced intersection sums
};

struct WaveResolution {
  int water_row_first = -1;           // the first row whose centre pixel sees the water (-1: none)
  std::vector<ResolutionBand> bands;  // far (top) to near (bottom)
};

// `bands` equal groups of the water rows of `scene` at its image size, classified with
// the transition region [start, end] (cycles per pixel) and the frequency norm.
WaveResolution wave_resolution(const Scene& scene, int bands, const AliasingParams& p);

}  // namespace sg
