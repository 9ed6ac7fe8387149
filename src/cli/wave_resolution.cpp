#include "cli/wave_resolution.h"

#include <algorithm>
#include <cmath>

#include "scene/footprint.h"
#include "scene/model.h"

namespace sg {

WaveResolution wave_resolution(const Scene& scene, int bands, const AliasingParams& p) {
  WaveResolution out;
  const SceneModel m(scene);
  const int w = scene.width, h = scene.height;
  const double cx = 0.5 * w;
  // The water rows: from the first whose centre pixel hits the plane to the bottom (the
  // plane below a camera above it is seen by every row under the horizon).
  int first = -1;
  for (int j = 0; j < h && first < 0; ++j) {
    if (rest_plane_footprint(m, cx, j + 0.5).hit) first = j;
  }
  out.water_row_first = first;
  if (first < 0) return out;
  const int rows = h - first;
  bands = std::clamp(bands, 1, rows);
  const WaveField& wf = m.waves;
  const size_t n = wf.size();
  const int columns = std::min(w, 33);
  for (int b = 0; b < bands; ++b) {
    ResolutionBand r;
    r.row_first = first + static_cast<int>(static_cast<long>(rows) * b / bands);
    r.row_last = first + static_cast<int>(static_cast<long>(rows) * (b + 1) / bands) - 1;
    r.distance_first = rest_plane_footprint(m, cx, r.row_first + 0.5).distance;
    r.distance_last = rest_plane_footprint(m, cx, r.row_last + 0.5).distance;
    const int band_rows = r.row_last - r.row_first + 1, sample_rows = std::min(band_rows, 16);
    long pixels = 0, resolved = 0, aliasing = 0, total = 0;
    for (int sr = 0; sr < sample_rows; ++sr) {
      const int j = r.row_first + (sample_rows == 1 ? 0 : sr * (band_rows - 1) / (sample_rows - 1));
      for (int sc = 0; sc < columns; ++sc) {
        const double px = columns == 1 ? cx : (sc + 0.5) * w / columns;
        const PixelFootprint f = rest_plane_footprint(m, px, j + 0.5);
        if (!f.hit) continue;
        const mat2 J = f.xz_jacobian();
        ++pixels;
        total += static_cast<long>(n);
        for (size_t i = 0; i < n; ++i) {
          const double freq = projected_frequency(vec2(wf.a[i], wf.b[i]), J, p.norm);
          resolved += freq <= p.start;
          aliasing += freq >= p.end;
        }
      }
    }
    if (pixels > 0) {
      r.resolved = static_cast<double>(resolved) / pixels;
      r.aliasing = static_cast<double>(aliasing) / pixels;
      r.transition = static_cast<double>(total - resolved - aliasing) / pixels;
    }
    out.bands.push_back(r);
  }
  return out;
}

}  // namespace sg
