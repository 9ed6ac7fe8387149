#include "report/regions.h"

#include <algorithm>
#include <utility>

#include "shading/water_geometry.h"

namespace sg {

WaterRegions water_regions(const SceneModel& model, double t) {
  const int w = model.width(), h = model.height();
  const size_t n = static_cast<size_t>(w) * h;
  WaterRegions r;
  r.water.assign(n, 0);
  r.near.assign(n, 0);
  r.far.assign(n, 0);
  std::vector<std::pair<double, size_t>> seen;  // (distance, pixel index)
  const WaterGeometry water(model, FrameTime{0, t, t});
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      const PixelFootprint f = water.footprint(i + 0.5, j + 0.5, t);
      if (!f.hit) continue;
      const size_t k = static_cast<size_t>(j) * w + i;
      r.water[k] = 1;
      seen.emplace_back(f.distance, k);
    }
  }
  std::sort(seen.begin(), seen.end());
  r.water_pixels = static_cast<long>(seen.size());
  r.near_pixels = (r.water_pixels + 1) / 2;
  r.far_pixels = r.water_pixels - r.near_pixels;
  for (size_t q = 0; q < seen.size(); ++q)
    (q < static_cast<size_t>(r.near_pixels) ? r.near : r.far)[seen[q].second] = 1;
  if (r.near_pixels > 0) r.split_distance = seen[r.near_pixels - 1].first;
  return r;
}

}  // namespace sg
