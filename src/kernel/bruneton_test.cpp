// `bruneton`'s kernel (kernel/bruneton.glsl): the filtered surface's intersection against
// the geometry of a model that holds exactly the weighted waves (the kernel's own march over
// a sea of amplitudes w_i A_i), and the prefix of the waves a pixel keeps against the weights
// of every wave (every wave past it has weight 0 exactly).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "kernel/kernel_double.h"
#include "scene/model.h"
#include "shading/kernel_frame.h"
#include "shading/water_geometry.h"
#include "testing/testing.h"

namespace sg {
namespace {

kd::BrunetonParams params() {
  kd::BrunetonParams p{};
  p.n_min = 1.0;
  p.n_max = 2.5;
  p.min_variance = 2e-5;
  p.fresnel_integral = false;
  return p;
}

Scene displaced_scene(const char* name) {
  Scene s = testing::project_scene(name);
  s.surface.geometry = Geometry::displaced;
  s.width = 64;
  s.height = 36;
  return s;
}

TEST(BrunetonKernel, FilteredIntersectionIsTheWeightedSea) {
  // Per pixel of a displaced `medium` (and `high`) at 64x36: the first n waves in |k| order
  // at their weights w_i (the pixel's rest-plane footprint) against a model holding those
  // waves at amplitudes w_i A_i, intersected by the kernel's march (intersect.glsl). The
  // hits agree to the root tolerance, and are not all the unweighted sea's.
  for (const char* name : {"medium", "high"}) {
    const Scene s = displaced_scene(name);
    const SceneModel m(s);
    const FrameTime ft{0, 0.5, 0.5};
    KernelInputsD in;
    build_kernel_inputs(m, ft, 1, 0, in, 0.0);
    const kd::WaveBuffer wb = wave_buffer(in);
    const kd::BrunetonParams p = params();
    int hits = 0, weighted = 0;
    for (int j = 0; j < s.height; j += 2) {
      for (int i = 0; i < s.width; i += 3) {
        const double px = i + 0.5, py = j + 0.5;
        const kd::Footprint rest = kd::pixel_footprint(wb, in.frame, px, py, 0.0, false);
        if (!rest.hit) continue;
        const mat2 J = kd::footprint_xz_jacobian(rest);
        const int n = kd::lod_filtered_from(wb, in.frame, J, p.n_min);
        // The weighted sea, in world coordinates at the display time.
        std::vector<Wave> kept;
        bool any_below_one = false;
        for (int q = 0; q < n; ++q) {
          const kd::Wave w = kd::wave_at(wb, in.frame, q);
          const double wt = kd::wave_lod_weight(vec2(w.a, w.b), J, p.n_min, p.n_max);
          any_below_one = any_below_one || wt < 1;
          const int src = in.order[q];
          const Wave& orig = s.surface.waves[size_t(src)];
          kept.push_back(
              Wave{orig.amplitude * wt, orig.wave_vector, orig.angular_frequency, orig.phase});
        }
        weighted += any_below_one;
        Scene sk = s;
        sk.surface.waves = kept;
        const SceneModel mk(sk);
        const WaterGeometry g(mk, ft);
        const vec3 d = normalize(m.camera.direction(px, py));
        const RayHit b = g.intersect(m.camera.position(), d, ft.end);
        const vec3 o = in.frame.camera.position;
        const kd::RayHit a = kd::filtered_intersect(wb, in.frame, p, J, n, o, d);
        ASSERT_EQ(a.hit, b.hit) << name << " " << i << "," << j;
        if (!a.hit) continue;
        ++hits;
        EXPECT_NEAR(a.s, b.s, 1e-7 * b.s + 1e-9) << name << " " << i << "," << j;
      }
    }
    EXPECT_GT(hits, 200) << name;
    EXPECT_GT(weighted, 20) << name;  // not the unweighted sea everywhere
  }
}

TEST(BrunetonKernel, EveryWavePastThePrefixHasWeightZero) {
  const Scene s = displaced_scene("high");
  const SceneModel m(s);
  KernelInputsD in;
  build_kernel_inputs(m, FrameTime{0, 0.5, 0.5}, 1, 0, in, 0.0);
  const kd::WaveBuffer wb = wave_buffer(in);
  int cut = 0;
  for (int j = 0; j < s.height; j += 3) {
    for (int i = 0; i < s.width; i += 3) {
      const kd::Footprint rest = kd::pixel_footprint(wb, in.frame, i + 0.5, j + 0.5, 0.0, false);
      if (!rest.hit) continue;
      const mat2 J = kd::footprint_xz_jacobian(rest);
      const int n = kd::lod_filtered_from(wb, in.frame, J, 1.0);
      cut += n < in.frame.wave_count;
      for (int q = n; q < in.frame.wave_count; ++q) {
        const kd::Wave w = kd::wave_at(wb, in.frame, q);
        EXPECT_EQ(kd::wave_lod_weight(vec2(w.a, w.b), J, 1.0, 2.5), 0.0) << i << "," << j;
      }
    }
  }
  EXPECT_GT(cut, 50);  // the prefix leaves waves out in most of the picture
}

}  // namespace
}  // namespace sg
