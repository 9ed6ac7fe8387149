// `staa` against the reference where the light's geometry leaves the ordinary: two scenes
// a random check of the spec met (tests/spec/, docs/method.md), each at its own small size,
// frame 0, against `reference --samples 16x16x1` (2 batches, its noise taken out):
//  - tests/scenes/light-edges/low-large-light.json: a light 6.4 degrees wide, 2.5 degrees
//    up (its disk crosses the horizon), water 9 degrees from it seen 4 degrees down. The
//    RDF linearised at the light (kernel/rdf.glsl, light_anchor) took, through a nearly
//    singular J_L, the flat normals into the disk's preimage and gave a row of pixels half
//    the light (staa's RMSE 5.2 against point's 4.05); the anchor is now refused where Phi
//    bends over the preimage (1.17), and the disk's part below the horizon taken off the
//    light's share (0.93).
//  - tests/scenes/light-edges/light-behind-grazing.json: a light behind the camera, a
//    constant sky and a dark sea, no Fresnel, the horizon near the frame's top. A
//    reflection turned away from the light took its share below the horizon from its
//    centre normal alone, 0 or 1 (RMSE 0.099 against point's 0.109); it is now the NDF's
//    mass beyond the horizon's circle in the NDF plane (0.025; supersample 6x6x1: 0.015).
// Bound: staa's RMSE at most half of point's on each.
//  - tests/scenes/light-edges/setting-sun.json: a sun 0.8 degrees wide, its centre 0.3
//    degrees below the horizon, over a calm sea seen from 4 m: reflections into the disk's
//    part below the horizon meet the sea. The light's share counted them, bounded only by
//    the share above the horizon: the image's mean 6.1% over the reference's (RMSE 0.149);
//    the segment below the horizon now comes off (kernel/staa.glsl,
//    staa_light_below_horizon): 0.9% (0.098; point 0.373, supersample 6x6x1 0.072).
// Bound: staa's image mean within 3% (and 3 standard errors) of the reference's.
// And on all three, every method's pixels within the scene's largest radiance (a pixel is a
// mean of what its rays see), but `bruneton`, whose Eq. 15 takes the light as a point and
// exceeds it under a light of several degrees at a grazing view (docs/baselines.md: as
// published).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "engine/render.h"
#include "methods/method.h"
#include "methods/reference.h"
#include "metrics/metrics.h"
#include "testing/paths.h"
#include "testing/stored_reference.h"

namespace sg {
namespace {

double rmse_against(const SceneModel& m, const std::string& method, const Image& ref, double se) {
  const SequenceMetrics s =
      compare_sequences(testing::render_sequence(m, method, {}, 1), std::vector<Image>{ref});
  return testing::noise_corrected(s.rmse, se * se);
}

struct Reference {
  Image image;
  double se;  // its RMS standard error
};

Reference render_reference(const SceneModel& m) {
  MethodOptions o;
  o.samples = SampleCounts{16, 16, 1};
  o.samples_given = true;
  std::unique_ptr<Method> ref = make_method("reference", testing::with_tables(o));
  Reference r{render_frame(m, *ref, 0, {}), 0};
  r.se = sequence_standard_error({*ref->pixel_variance()});
  return r;
}

class LightEdges : public ::testing::TestWithParam<const char*> {};

TEST_P(LightEdges, StaaWithinHalfOfPointsError) {
  const std::string path = sg::testing::source_dir() + "/tests/scenes/light-edges/" + GetParam();
  const SceneModel m(load_scene(path));
  const Reference ref = render_reference(m);
  const Image& r = ref.image;
  const double se = ref.se;
  const double point = rmse_against(m, "point", r, se), staa = rmse_against(m, "staa", r, se);
  std::printf("%s: reference se %.3g, RMSE point %.4g, staa %.4g\n", GetParam(), se, point, staa);
  EXPECT_LE(staa, 0.5 * point) << GetParam();
}

TEST(LightEdges, TheSetSunsDiskIsNotReflected) {
  const SceneModel m(
      load_scene(sg::testing::source_dir() + "/tests/scenes/light-edges/setting-sun.json"));
  const Reference ref = render_reference(m);
  const Image& r = ref.image;
  const double se = ref.se;
  const Image a = testing::render_sequence(m, "staa", {}, 1)[0];
  double mean_r = 0, mean_a = 0;
  for (size_t k = 0; k < r.data.size(); ++k) {
    mean_r += r.data[k];
    mean_a += a.data[k];
  }
  mean_r /= double(r.data.size());
  mean_a /= double(a.data.size());
  // The mean's standard error: the pixels' noise is independent, se / sqrt(values).
  const double se_mean = se / std::sqrt(double(r.data.size()));
  std::printf("setting-sun.json: image mean reference %.5g (se %.2g), staa %.5g (%+.2f%%)\n",
              mean_r, se_mean, mean_a, 100 * (mean_a / mean_r - 1));
  EXPECT_LE(std::abs(mean_a - mean_r), 0.03 * mean_r + 3 * se_mean);
}

TEST_P(LightEdges, EveryMethodWithinTheScenesLargestRadiance) {
  const std::string path = sg::testing::source_dir() + "/tests/scenes/light-edges/" + GetParam();
  const Scene scene = load_scene(path);
  const SceneModel m(scene);
  double top = 0;
  for (const Rgb& c :
       {scene.light.radiance, scene.sky.zenith, scene.sky.horizon, scene.surface.sea_radiance})
    top = std::max({top, c.x, c.y, c.z});
  for (const char* method :
       {"point", "supersample", "staa", "staa-temporal", "lean", "specaa", "microspec", "taa"}) {
    const Image a = testing::render_sequence(m, method, {}, 1)[0];
    float lo = 0, hi = 0;
    for (float x : a.data) {
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
    EXPECT_GE(lo, 0.0f) << method << " on " << GetParam();
    EXPECT_LE(hi, top * (1 + 1e-3)) << method << " on " << GetParam();
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, LightEdges,
                         ::testing::Values("low-large-light.json", "light-behind-grazing.json",
                                           "setting-sun.json"));

}  // namespace
}  // namespace sg
