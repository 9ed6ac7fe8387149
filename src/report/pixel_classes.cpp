#include "report/pixel_classes.h"

#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "kernel/kernel_double.h"
#include "shading/kernel_frame.h"

namespace sg {

std::vector<unsigned char> PixelClasses::mask(PixelClass c) const {
  std::vector<unsigned char> m(of.size());
  for (size_t k = 0; k < of.size(); ++k)
    m[k] = of[k] == static_cast<unsigned char>(c);
  return m;
}

namespace {

constexpr int kGrid = 3;  // rays per pixel side

// The class of pixel (i, j); `tol` the inputs with the methods' tolerance, `all` with
// every wave (the same as tol on flat water).
PixelClass classify(const KernelInputsD& tol, const KernelInputsD& all, int i, int j) {
  using namespace kd;
  const kd::Frame& f = tol.frame;
  const WaveBuffer wb = wave_buffer(tol);
  const bool displaced = f.displaced;
  const Footprint c = pixel_footprint(wb, f, i + 0.5, j + 0.5, 0.0, displaced);
  // The grid's rays: hit or not, and where.
  int hits = 0;
  RayHit grid[kGrid * kGrid];
  vec3 dirs[kGrid * kGrid];
  const vec3 o = f.camera.position;
  for (int b = 0; b < kGrid; ++b) {
    for (int a = 0; a < kGrid; ++a) {
      const real px = i + (a + 0.5) / kGrid, py = j + (b + 0.5) / kGrid;
      vec3 d = camera_direction(f.camera, px, py);
      d = d / length(d);
      const int q = b * kGrid + a;
      dirs[q] = d;
      grid[q] = displaced ? intersect_displaced(wb, f, o, d, 0.0) : intersect_flat(o, d);
      hits += grid[q].hit ? 1 : 0;
    }
  }
  if (hits == 0 && !c.hit) return PixelClass::sky;
  if (hits < kGrid * kGrid || !c.hit) return PixelClass::horizon;
  if (!displaced) return PixelClass::plain;
  const vec2 g = water_gradient(wb, f, c.point.x, c.point.z, 0.0);
  const vec3 m = vec3(-g.x, 1.0, -g.y);
  const real L = std::max(length(c.dp_dpx), length(c.dp_dpy));
  bool nearer = false, over = false;
  for (int q = 0; q < kGrid * kGrid; ++q) {
    const real dm = dot(m, dirs[q]);
    if (!(dm < 0.0)) {
      over = true;  // the ray runs along or away from the tangent plane
      continue;
    }
    const real s_plane = dot(m, c.point - o) / dm;
    if (grid[q].s < s_plane - L) nearer = true;
    if (grid[q].s > s_plane + L) over = true;
  }
  if (nearer) return PixelClass::nearer_crest;
  if (over) return PixelClass::over_crest;
  const WaveBuffer wa = wave_buffer(all);
  vec3 dc = camera_direction(f.camera, i + 0.5, j + 0.5);
  dc = dc / length(dc);
  const RayHit exact = intersect_displaced(wa, all.frame, o, dc, 0.0);
  if (!exact.hit || length(exact.point - c.point) > L) return PixelClass::left_out_waves;
  const real sin_face = std::fabs(dot(dc, m)) / length(m);
  const real sin_rest = std::fabs(dc.y);
  if (sin_face < 0.5 * sin_rest) return PixelClass::tilted_face;
  return PixelClass::plain;
}

}  // namespace

PixelClasses classify_pixels(const SceneModel& model, const FrameTime& ft, double tolerance,
                             int threads) {
  KernelInputsD tol, all;
  build_kernel_inputs(model, ft, 1, 0, tol, tolerance);
  build_kernel_inputs(model, ft, 1, 0, all, 0.0);
  PixelClasses r;
  r.width = model.width();
  r.height = model.height();
  r.of.assign(static_cast<size_t>(r.width) * r.height, 0);
  std::unique_ptr<tbb::global_control> limit;
  if (threads > 0) {
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                  static_cast<size_t>(threads));
  }
  tbb::parallel_for(0, r.height, [&](int j) {
    for (int i = 0; i < r.width; ++i)
      r.of[static_cast<size_t>(j) * r.width + i] =
          static_cast<unsigned char>(classify(tol, all, i, j));
  });
  for (unsigned char c : r.of)
    ++r.count[c];
  return r;
}

}  // namespace sg
