#include "cli/wave_resolution.h"

#include <algorithm>
#include <cmath>

#include "scene/model.h"
#include "shading/kernel_frame.h"
#include "shading/water_geometry.h"
#include "shading/wave_lod.h"

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
  // The waves sorted by |k| (as the kernel sums them) and their suffix amplitudes.
  std::vector<double> k(n), A(n);
  for (size_t i = 0; i < n; ++i) {
    k[i] = std::hypot(wf.a[i], wf.b[i]);
    A[i] = wf.A[i];
  }
  std::vector<size_t> order(n);
  for (size_t i = 0; i < n; ++i)
    order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](size_t x, size_t y) { return k[x] < k[y]; });
  std::vector<double> ks(n), suffix(n + 1, 0.0);
  for (size_t q = 0; q < n; ++q)
    ks[q] = k[order[q]];
  for (size_t q = n; q-- > 0;)
    suffix[q] = suffix[q + 1] + A[order[q]];
  // kernel/staa.glsl, staa_remainder_wavenumbers (per-pixel NDF: 8 half-cycles).
  const double nyquist = p.norm == FrequencyNorm::max ? std::sqrt(2.0) : 1.0;
  const CameraModel& cam = m.camera;
  const double pixel = std::min(2 * cam.half_w() / w, 2 * cam.half_h() / h);
  for (int b = 0; b < bands; ++b) {
    ResolutionBand r;
    r.row_first = first + static_cast<int>(static_cast<long>(rows) * b / bands);
    r.row_last = first + static_cast<int>(static_cast<long>(rows) * (b + 1) / bands) - 1;
    r.distance_first = rest_plane_footprint(m, cx, r.row_first + 0.5).distance;
    r.distance_last = rest_plane_footprint(m, cx, r.row_last + 0.5).distance;
    const int band_rows = r.row_last - r.row_first + 1, sample_rows = std::min(band_rows, 16);
    long pixels = 0, resolved = 0, aliasing = 0, total = 0, visited = 0, summed = 0;
    for (int sr = 0; sr < sample_rows; ++sr) {
      const int j = r.row_first + (sample_rows == 1 ? 0 : sr * (band_rows - 1) / (sample_rows - 1));
      for (int sc = 0; sc < columns; ++sc) {
        const double px = columns == 1 ? cx : (sc + 0.5) * w / columns;
        const PixelFootprint f = rest_plane_footprint(m, px, j + 0.5);
        if (!f.hit) continue;
        const mat2 J = f.xz_jacobian();
        ++pixels;
        total += static_cast<long>(n);
        const double sigma = smallest_singular_value(J);
        if (sigma > 0) {
          const double k_alias = 1.001 * kTwoPi * p.end * nyquist / sigma;
          const double k_rem = std::max(k_alias, 1.001 * 2 * 8 / sigma);
          visited += std::lower_bound(ks.begin(), ks.end(), k_rem) - ks.begin();
        } else {
          visited += static_cast<long>(n);
        }
        // kernel/intersect.glsl, pixel_angle and first_wave_below.
        const vec3 d = normalize(cam.direction(px, j + 0.5));
        const double c = std::max(dot(d, cam.forward()), 0.0);
        const double e = kDefaultIntersectTolerance * pixel * c * c * f.distance;
        size_t q = 0;
        while (q < n && suffix[q] > e)
          ++q;
        summed += static_cast<long>(q);
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
      r.visited = static_cast<double>(visited) / pixels;
      r.intersect = static_cast<double>(summed) / pixels;
    }
    out.bands.push_back(r);
  }
  return out;
}

}  // namespace sg
