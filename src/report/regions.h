// The near and far halves of the water, measured separately (Podee et al. 2021, Sec. 5-6:
// their method matches the reference near the camera and blurs far from it).
//
// A pixel sees water when the ray through its centre meets the water (scene/footprint.h,
// at the display time of the study's first frame). The water pixels are sorted by the
// distance from the camera to that point (ties by pixel index); the first ceil(n/2) are
// the near half, the others the far half. The two halves partition the water pixels and
// every near pixel is at most as far as every far pixel. The masks are fixed for the
// whole frame range, so temporal metrics compare the same pixels in every frame.
#pragma once

#include <vector>

#include "scene/model.h"

namespace sg {

struct WaterRegions {
  std::vector<unsigned char> water, near, far;  // nonzero: in the region (row-major)
  long water_pixels = 0, near_pixels = 0, far_pixels = 0;
  double split_distance = 0;  // distance of the farthest near pixel, metres
};

WaterRegions water_regions(const SceneModel& model, double t);

}  // namespace sg
