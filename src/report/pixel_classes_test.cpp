// What each pixel sees (report/pixel_classes.h), against an independent trace: the scene
// layer's camera, the direct sum of the waves (testing/direct_waves.h) and a plain march
// (safe steps f / Lip, then bisection) written here, not the kernel's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "report/pixel_classes.h"
#include "shading/water_geometry.h"
#include "testing/direct_waves.h"
#include "testing/testing.h"

namespace sg {
namespace {

// The first crossing of the height field along the unit ray o + s d: steps of f / Lip
// (f = y - h cannot fall faster than Lip along the ray), then 60 bisections; -1: none
// before the ray leaves the slab |y| <= sum |A|.
double traced_distance(const WaveField& w, vec3 o, vec3 d, double t) {
  auto f = [&](double s) {
    const vec3 p = o + s * d;
    return p.y - testing::direct_height(w, p.x, p.z, t);
  };
  const double lip = std::fabs(d.y) + w.slope_bound() * std::hypot(d.x, d.z);
  const double s_end = d.y < 0 ? (o.y + w.amplitude_bound()) / -d.y : 1e4;
  double s = 0, fs = f(0);
  while (s < s_end) {
    const double next = s + std::max(fs / lip, 1e-7);
    const double fn = f(next);
    if (fn <= 0) {
      double lo = s, hi = next;
      for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (lo + hi);
        (f(mid) > 0 ? lo : hi) = mid;
      }
      return hi;
    }
    s = next;
    fs = fn;
  }
  return -1;
}

// On flat water a pixel is sky when none of its 3 x 3 rays goes down, plain when all do,
// the horizon otherwise; no other class.
TEST(PixelClasses, FlatWaterIsSkyHorizonOrPlainByTheRaysThatGoDown) {
  Scene s = testing::small_scene({Wave{0.1, {0.2, -1.0}, 3.0, 0.5}}, 40, 24);
  s.camera.look_at = {0, 2.0, -60};  // the horizon in the picture
  const SceneModel m(s);
  const PixelClasses pc = classify_pixels(m, frame_time(s, 0), 0.25, 1);
  long horizon = 0;
  for (int j = 0; j < s.height; ++j) {
    for (int i = 0; i < s.width; ++i) {
      int down = 0;
      for (int b = 0; b < 3; ++b) {
        for (int a = 0; a < 3; ++a)
          down += m.camera.direction(i + (a + 0.5) / 3, j + (b + 0.5) / 3).y < 0;
      }
      const PixelClass want = down == 0   ? PixelClass::sky
                              : down == 9 ? PixelClass::plain
                                          : PixelClass::horizon;
      EXPECT_EQ(int(pc.of[size_t(j) * s.width + i]), int(want)) << i << "," << j;
      horizon += want == PixelClass::horizon;
    }
  }
  EXPECT_GT(horizon, 0);
  EXPECT_GT(pc.count[int(PixelClass::sky)], 0);
  EXPECT_GT(pc.count[int(PixelClass::plain)], 0);
  long total = 0;
  for (long c : pc.count)
    total += c;
  EXPECT_EQ(total, long(s.width) * s.height);
}

// A steep swell seen from a camera 1.2 m up: crests hide the troughs behind them. Traced
// on an 8 x 8 grid of rays per pixel with the scene layer's root finder (every wave), a
// "nearer crest" pixel's centre ray reaches well beyond the nearest of its rays (a crest
// in front of the point it sees), an "over a crest" pixel's well short of the farthest (it
// sees a crest, and its rays pass over it), and a plain pixel neither.
TEST(PixelClasses, CrestClassesMatchADenseTraceOfTheirRays) {
  Scene s = testing::small_scene(
      {Wave{0.45, {0.0, -0.6}, 2.4, 0.3}, Wave{0.1, {0.5, -1.3}, 3.6, 1.0}}, 64, 40);
  s.surface.geometry = Geometry::displaced;
  s.camera.position = {0, 1.2, 0};
  s.camera.look_at = {0, -0.5, -40};
  const SceneModel m(s);
  const FrameTime ft = frame_time(s, 0);
  const PixelClasses pc = classify_pixels(m, ft, 0.0, 1);
  EXPECT_EQ(pc.count[int(PixelClass::left_out_waves)], 0) << "tolerance 0 leaves out no wave";
  const vec3 o = m.camera.position();
  long agree[kPixelClasses] = {}, seen[kPixelClasses] = {};
  for (int j = 0; j < s.height; ++j) {
    for (int i = 0; i < s.width; ++i) {
      const PixelClass c = static_cast<PixelClass>(pc.of[size_t(j) * s.width + i]);
      if (c != PixelClass::nearer_crest && c != PixelClass::over_crest && c != PixelClass::plain)
        continue;
      auto dist = [&](double px, double py) {
        const vec3 d = normalize(m.camera.direction(px, py));
        const double s = traced_distance(m.waves, o, d, ft.end);
        return s >= 0 ? s : 1e30;
      };
      const double centre = dist(i + 0.5, j + 0.5);
      // The footprint's longer side at the centre (on one face, the rays' distances spread
      // by about that much at most).
      const PixelFootprint fp = pixel_footprint(m, i + 0.5, j + 0.5, ft.end);
      const double step = std::max(length(fp.dp_dpx), length(fp.dp_dpy));
      double lo = 1e30, hi = 0;
      for (int b = 0; b < 8; ++b) {
        for (int a = 0; a < 8; ++a) {
          const double x = dist(i + (a + 0.5) / 8, j + (b + 0.5) / 8);
          lo = std::min(lo, x);
          hi = std::max(hi, x);
        }
      }
      const double scale = std::max(step, 1e-3 * centre);
      const bool in_front = centre - lo > 2 * scale, beyond = hi - centre > 2 * scale;
      ++seen[int(c)];
      if (c == PixelClass::nearer_crest) agree[int(c)] += in_front;
      if (c == PixelClass::over_crest) agree[int(c)] += beyond;
      if (c == PixelClass::plain) agree[int(c)] += !in_front && !beyond;
    }
  }
  for (PixelClass c : {PixelClass::nearer_crest, PixelClass::over_crest, PixelClass::plain}) {
    const int k = int(c);
    std::printf("%-14s %ld pixels, %ld agree with the dense trace\n", kPixelClassNames[k], seen[k],
                agree[k]);
    EXPECT_GE(seen[k], 5) << kPixelClassNames[k];
    EXPECT_GE(double(agree[k]), 0.8 * double(seen[k])) << kPixelClassNames[k];
  }
}

}  // namespace
}  // namespace sg
