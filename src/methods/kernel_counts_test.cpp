// The kernel's work counters (methods/kernel_counts.h) against scenes whose counts are
// known: `point` on flat water visits each of its N waves once per pixel that sees water
// and none where the pixel sees the sky; `supersample` S_x S_y times that; `specaa` once with
// its quads' derivatives and twice with the analytic ones; `lean` none (its map's 40 floats
// a trilinear lookup); the counting
// build renders what the double kernel renders; displaced water counts march steps and
// flat water none.
#include "methods/kernel_counts.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "base/error.h"
#include "kernel/kernel_counting.h"
#include "kernel/kernel_double.h"
#include "methods/kernel_inputs.h"
#include "testing/path_tables.h"
#include "testing/testing.h"

namespace sg {
namespace {

std::vector<Wave> some_waves(int n) {
  std::vector<Wave> w;
  for (int i = 0; i < n; ++i) {
    const double a = 0.37 * i;
    w.push_back(Wave{0.01 + 0.002 * i,
                     {0.4 * std::cos(a) * (1 + i), 0.4 * std::sin(a) * (1 + i)},
                     0.3 * i,
                     0.0});
  }
  return w;
}

// A camera that sees water in every pixel (looking down at 40 degrees of view).
Scene water_only(int n) {
  Scene s = testing::small_scene(some_waves(n), 24, 16);
  s.camera = CameraDesc{{0, 2.5, 0}, {0, 0, -2}, {0, 1, 0}, 40, {}};
  return s;
}

TEST(KernelCounts, PointVisitsEachWaveOncePerWaterPixel) {
  for (int n : {1, 7, 33}) {
    const SceneModel m(water_only(n));
    const KernelWork k = count_kernel_work(m, "point", testing::with_tables({}), 3);
    EXPECT_EQ(k.pixels, 24 * 16);
    EXPECT_DOUBLE_EQ(k.waves.mean, n) << n;
    EXPECT_EQ(k.waves.max, uint64_t(n)) << n;
    EXPECT_EQ(k.march_steps.max, 0u) << "flat water has no march";
    EXPECT_EQ(k.nodes.max, 0u) << "point integrates nothing";
    // A wave's texels are read as it is visited (two per wave), and its phase takes one
    // cosine at least.
    EXPECT_GE(k.buffer_fetches.mean, 2.0 * n);
    EXPECT_GE(k.transcendentals.mean, double(n));
  }
}

TEST(KernelCounts, SkyPixelsVisitNoWave) {
  // The shared camera of small_scene sees the horizon: the pixels above it visit no wave.
  const int n = 5;
  const SceneModel m(testing::small_scene(some_waves(n), 24, 16));
  const KernelWork k = count_kernel_work(m, "point", testing::with_tables({}), 0);
  EXPECT_EQ(k.waves.max, uint64_t(n));
  EXPECT_GT(k.waves.mean, 0.0);
  EXPECT_LT(k.waves.mean, double(n)) << "some pixels see the sky";
}

TEST(KernelCounts, SupersampleVisitsEachWavePerSample) {
  const int n = 6;
  const SceneModel m(water_only(n));
  MethodOptions o;
  o.samples = SampleCounts{3, 2, 1};
  o.samples_given = true;
  const KernelWork k = count_kernel_work(m, "supersample", testing::with_tables(o), 1);
  EXPECT_DOUBLE_EQ(k.waves.mean, 6.0 * n);
  EXPECT_EQ(k.waves.max, uint64_t(6 * n));
}

TEST(KernelCounts, SpecaaVisitsTheWavesOnceWithQuadsAndTwiceAnalytic) {
  // On flat water an invocation sums the gradient at its point (N waves); its quad's
  // neighbours give the derivatives (their samples are theirs), while the analytic form sums
  // the Hessian too (N more). Nothing is integrated by nodes.
  const int n = 9;
  const SceneModel m(water_only(n));
  MethodOptions o;
  const KernelWork quad = count_kernel_work(m, "specaa", testing::with_tables(o), 1);
  EXPECT_DOUBLE_EQ(quad.waves.mean, double(n));
  EXPECT_EQ(quad.waves.max, uint64_t(n));
  o.specaa.derivatives = SpecaaDerivatives::analytic;
  const KernelWork analytic = count_kernel_work(m, "specaa", testing::with_tables(o), 1);
  EXPECT_DOUBLE_EQ(analytic.waves.mean, 2.0 * n);
  EXPECT_EQ(analytic.nodes.max, quad.nodes.max);
}

TEST(KernelCounts, MicrospecVisitsTheWavesOncePerCorner) {
  // An invocation traces its own corner on flat water (N waves at its point) and shades from
  // the corners it shares with its neighbours; the light's disk-polygon area has no nodes.
  const int n = 5;
  const SceneModel m(water_only(n));
  const KernelWork k = count_kernel_work(m, "microspec", testing::with_tables({}), 1);
  EXPECT_DOUBLE_EQ(k.waves.mean, double(n));
  EXPECT_EQ(k.nodes.max, 0u);
}

TEST(KernelCounts, StaaCountsItsQuadratureAndTables) {
  Scene s = testing::project_scene("medium");
  set_image_size(s, 32, 18);
  const SceneModel small(s);
  const KernelWork k = count_kernel_work(small, "staa", testing::with_tables({}), 2);
  EXPECT_GE(k.waves.max, small.waves.size()) << "a pixel of water visits every wave";
  EXPECT_GT(k.table_fetches.mean, 0.0) << "the path tables are read";
  EXPECT_GT(k.transcendentals.mean, k.waves.mean);
  EXPECT_EQ(k.march_steps.max, 0u);
}

TEST(KernelCounts, StaaFallbackCostDoesNotGrowWithThePath) {
  // The fallback's average along each sub-segment is in closed form in time
  // (gaussian_disk_mass_along): at most 5 pieces of at most 6 8-point rules (48 nodes) a
  // sub-segment, however long the path. (A midpoint rule over the path took up to 32 instants of up
  // to 3 pieces: 720 to 1,260 nodes in one pixel of these scenes.) The scenes have no Fresnel and
  // no sky gradient, so no other node is counted.
  for (const char* name : {"simple", "medium", "high"}) {
    Scene s = testing::project_scene(name);
    set_image_size(s, 160, 90);
    const SceneModel m(s);
    for (int segments : {1, 4}) {
      MethodOptions o;
      o.staa.segments = segments;
      const KernelWork k = count_kernel_work(m, "staa", testing::with_tables(o), 2);
      EXPECT_GT(k.nodes.max, 0u) << name << ": some pixel takes the fallback";
      EXPECT_LE(k.nodes.max, uint64_t(240 * segments)) << name << " K " << segments;
    }
  }
}

TEST(KernelCounts, DisplacedWaterMarches) {
  const SceneModel m(testing::displaced_variant(water_only(4)));
  const KernelWork k = count_kernel_work(m, "point", testing::with_tables({}), 0);
  EXPECT_GT(k.march_steps.mean, 1.0);
  EXPECT_GE(k.waves.mean, 4.0 * k.march_steps.mean) << "each step sums the waves' heights";
}

TEST(KernelCounts, TheCountingKernelRendersWhatTheDoubleKernelRenders) {
  const SceneModel m(water_only(9));
  KernelFrameInputs in(1, Precision::float64);
  in.build(FrameContext{m, frame_time(m.scene, 2), 0});
  const KernelInputsD& d = in.d();
  const kd::WaveBuffer wd = wave_buffer(d, false);
  const kc::WaveBuffer wc{d.texels.data(), static_cast<int>(d.texels.size()), {}};
  kc::Frame fc;
  static_assert(sizeof(fc) == sizeof(d.frame));
  std::memcpy(static_cast<void*>(&fc), &d.frame, sizeof fc);
  for (int j = 0; j < 16; j += 3) {
    for (int i = 0; i < 24; i += 5) {
      const kd::vec4 a = kd::point_pixel(wd, d.frame, i, j);
      const kc::vec4 b = kc::point_pixel(wc, fc, i, j);
      EXPECT_EQ(a, b) << i << ", " << j;
      const kd::vec4 sa = kd::staa_temporal_pixel(wd, d.frame, i, j);
      const kc::vec4 sb = kc::staa_temporal_pixel(wc, fc, i, j);
      EXPECT_EQ(sa, sb) << i << ", " << j;
    }
  }
}

TEST(KernelCounts, LeanReadsItsMapAndVisitsNoWave) {
  // On flat water a pixel reads the map (a trilinear lookup: two levels of four texels of
  // five floats, 40 floats; one level where the level of detail is clamped) and visits no
  // wave, however many waves the map holds; anisotropic probes read up to --lean-max-aniso
  // lookups.
  for (int n : {1, 33}) {
    const SceneModel m(water_only(n));
    MethodOptions o;
    o.lean.size = 64;
    const KernelWork k = count_kernel_work(m, "lean", testing::with_tables(o), 2);
    EXPECT_EQ(k.waves.max, 0u) << n;
    EXPECT_EQ(k.table_fetches.max, 40u) << n;
    EXPECT_GE(k.table_fetches.mean, 20.0) << n;
    o.lean.filter = LeanFilter::aniso;
    o.lean.max_aniso = 4;
    const KernelWork a = count_kernel_work(m, "lean", testing::with_tables(o), 2);
    EXPECT_EQ(a.waves.max, 0u) << n;
    EXPECT_LE(a.table_fetches.max, 4u * 40u) << n;
    EXPECT_GT(a.table_fetches.mean, k.table_fetches.mean) << n;
  }
}

TEST(KernelCounts, TaaVisitsTheWavesOnceAndReadsItsNeighbourhood) {
  // Its sample is point's (n waves on water); its resolve reads, per channel, the current
  // sample, the history's 2 x 2 (bilinear) or 4 x 4 (Catmull-Rom) texels and the 3 x 3
  // neighbourhood's box: 14 or 30 texels inside the image.
  for (int n : {1, 33}) {
    const SceneModel m(water_only(n));
    ASSERT_TRUE(m.scene.grey());
    MethodOptions o;
    const KernelWork k = count_kernel_work(m, "taa", testing::with_tables(o), 3);
    EXPECT_EQ(k.waves.max, uint64_t(n)) << n;
    EXPECT_DOUBLE_EQ(k.waves.mean, n) << n;
    EXPECT_EQ(k.table_fetches.max, 14u) << n;
    o.taa.history = TaaHistoryFilter::catmull_rom;
    EXPECT_EQ(count_kernel_work(m, "taa", testing::with_tables(o), 3).table_fetches.max, 30u);
    o.taa.clamp = TaaClamp::none;
    EXPECT_EQ(count_kernel_work(m, "taa", testing::with_tables(o), 3).table_fetches.max, 21u);
  }
}

TEST(KernelCounts, MethodsWithoutACountingRenderAreRefused) {
  const SceneModel m(water_only(2));
  EXPECT_THROW(count_kernel_work(m, "reference", testing::with_tables({}), 0), Error);
}

}  // namespace
}  // namespace sg
