// Colour is linear: every method of the catalogue renders a colour scene, channel by
// channel, equal to grey renders of the same scene with each channel's radiances (the
// scene spec's format /2 defines each channel by the rules of a grey scene). Methods
// return weights of the four radiances (method.h), so this holds to float rounding; a
// method that mixed channels, post-processed only channel 0 (TAA's resolve) or let its
// weights depend on a radiance's value would fail it.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/render.h"
#include "methods/method.h"
#include "metrics/metrics.h"
#include "testing/path_tables.h"
#include "testing/render_range.h"
#include "testing/testing.h"

namespace sg {
namespace {

// A colour scene with every radiance distinct per channel: a visible sun in the frame, a
// gradient sky, Fresnel, a sea, displaced waves.
Scene colour_scene() {
  Scene s = testing::small_scene(testing::project_scene("simple").surface.waves, 40, 24);
  s.surface.geometry = Geometry::displaced;
  s.surface.fresnel = FresnelMode::schlick;
  s.light.visible = true;
  s.light.angular_radius_deg = 2.0;  // a few pixels at this size
  s.light.radiance = Rgb(30, 14, 5);
  s.sky = SkyDesc{Rgb(0.05, 0.12, 0.4), Rgb(0.6, 0.35, 0.2), 0.7, true};
  s.surface.sea_radiance = Rgb(0.004, 0.02, 0.03);
  return s;
}

// The grey scene of channel c.
Scene channel_scene(const Scene& colour, int c) {
  Scene s = colour;
  s.light.radiance = Rgb(colour.light.radiance[c]);
  s.sky.zenith = Rgb(colour.sky.zenith[c]);
  s.sky.horizon = Rgb(colour.sky.horizon[c]);
  s.surface.sea_radiance = Rgb(colour.surface.sea_radiance[c]);
  return s;
}

std::vector<Image> render(const Scene& s, const std::string& method, int first, int last) {
  return testing::render_range(s, method, first, last);
}

TEST(Colour, EveryMethodRendersEachChannelAsTheGreySceneOfThatChannel) {
  const Scene colour = colour_scene();
  ASSERT_FALSE(colour.grey());
  for (const MethodInfo& info : method_catalog()) {
    SCOPED_TRACE(info.name);
    const std::vector<Image> rgb = render(colour, info.name, 3, 4);
    ASSERT_EQ(rgb.size(), 2u);
    ASSERT_EQ(rgb[0].channels, 3);
    double largest = 0;
    for (int c = 0; c < 3; ++c) {
      const Scene g = channel_scene(colour, c);
      ASSERT_TRUE(g.grey());
      const std::vector<Image> grey = render(g, info.name, 3, 4);
      for (size_t f = 0; f < rgb.size(); ++f) {
        ASSERT_EQ(grey[f].channels, 1);
        int bad = 0;
        for (int j = 0; j < colour.height; ++j) {
          for (int i = 0; i < colour.width; ++i) {
            const double x = rgb[f].at(i, j, c), y = grey[f].at(i, j);
            largest = std::max(largest, y);
            if (std::fabs(x - y) > 1e-6 * std::fabs(y) + 1e-9 && bad++ < 3) {
              ADD_FAILURE() << "frame " << f << " pixel " << i << "," << j << " channel " << c
                            << ": colour " << x << ", grey " << y;
            }
          }
        }
      }
    }
    EXPECT_GT(largest, 1.0);  // the sun or its glints are in the picture
  }
}

// A grey scene renders one channel, whatever its format: its files stay as they were.
TEST(Colour, GreySceneRendersOneChannel) {
  Scene s = channel_scene(colour_scene(), 1);
  EXPECT_EQ(render(s, "point", 0, 0)[0].channels, 1);
  s.light.radiance = Rgb(1, 1, 0.5);
  EXPECT_EQ(render(s, "point", 0, 0)[0].channels, 3);
}

// Frame 0 of a scene against a 12x12x1 reference of 4 batches, rendered once; each
// method's RMSE against it (the Fresnel-and-sky tests).
struct FrameZeroAgainstReference {
  const SceneModel& m;
  Image ref;
  explicit FrameZeroAgainstReference(const SceneModel& model) : m(model) {
    MethodOptions o;
    o.samples = {12, 12, 1};
    o.samples_given = true;
    o.batches = 4;
    ref = render_frame(m, *make_method("reference", testing::with_tables(o)), 0, {});
  }
  ImageMetrics against(const std::string& method, const MethodOptions& o) const {
    return compare_images(render_frame(m, *make_method(method, testing::with_tables(o)), 0, {}),
                          ref);
  }
  double rmse(const std::string& method, const MethodOptions& o) const {
    return against(method, o).rmse;
  }
};

MethodOptions supersample_6x6x1() {
  MethodOptions o;
  o.samples = {6, 6, 1};
  o.samples_given = true;
  return o;
}

// Far displaced water under Fresnel and a sky gradient (tests/scenes/displaced-far-sky.json:
// three waves, two swells of 0.2 and 0.3 m and a 0.37 m wave of slope 0.043, a camera 2.4 m
// up whose top rows graze the water at under a degree, the light's radiance 0). A displaced
// surface shows each facet in proportion to its projected area, so grazing views see the
// slopes turned towards them (kernel/visible_normals.glsl). At 96x54 against the exact
// reference (every wave intersected, 12x12x1, 4 batches: about 1.3e-4 of noise), staa's
// RMSE 2.69e-4, supersample 6x6x1 2.31e-4; staa with the normals taken as the water's,
// unweighted, 1.02e-3 (4.4 times supersampling's).
TEST(Colour, DisplacedFarWaterShowsTheNormalsTurnedTowardsTheView) {
  const SceneModel m(load_scene(testing::source_dir() + "/tests/scenes/displaced-far-sky.json"));
  const FrameZeroAgainstReference r(m);
  const double super = r.rmse("supersample", supersample_6x6x1());
  const double staa = r.rmse("staa", {});
  std::printf("displaced-far-sky 96x54: staa %.3g, supersample 6x6x1 %.3g\n", staa, super);
  EXPECT_LT(staa, 1.3 * super);
}

// The sampling baselines intersect every wave by default (intersect_tolerance_for): a wave
// left out of a sample's intersection loses the weighting of its slopes by projected area,
// whatever its amplitude. On the scene above, frame 0, against the same reference: point's
// image mean 9.434e-3 against the reference's 9.435e-3 (with the 0.25-pixel tolerance
// 9.194e-3, 2.6% dark) and its RMSE 1.28e-3 (2.64e-3); supersample 6x6x1's 2.31e-4 (9.44e-4
// with the tolerance per sample cell, 0.25 / 6). The bounds: the means within 0.5%, the
// supersampling's RMSE below 5e-4.
TEST(Colour, SamplingBaselinesSeeTheDisplacedSurfaceWhole) {
  const SceneModel m(load_scene(testing::source_dir() + "/tests/scenes/displaced-far-sky.json"));
  const FrameZeroAgainstReference r(m);
  for (const char* name : {"point", "supersample", "staa-temporal"}) {
    const MethodOptions o =
        std::string(name) == "supersample" ? supersample_6x6x1() : MethodOptions{};
    const ImageMetrics e = r.against(name, o);
    std::printf("displaced-far-sky 96x54: %s mean %.4g (reference %.4g), RMSE %.3g\n", name,
                e.mean_a, e.mean_b, e.rmse);
    EXPECT_NEAR(e.mean_a / e.mean_b, 1.0, 0.005) << name;
    if (std::string(name) == "supersample") {
      EXPECT_LT(e.rmse, 5e-4);
    }
  }
}

}  // namespace
}  // namespace sg

namespace sg {
namespace {

// The visible sun over the sky's pixels (kernel/disk_coverage.glsl): on the sunset scene
// the methods that integrate over the pixel take the disk's coverage of each pixel, where
// `point` tests the centre ray. Against a 12x12x2 reference at 160x90, frame 0, staa's
// RMSE is 0.051 and point's 0.73 (before the coverage, staa's was 0.66, as point's).
TEST(Colour, VisibleSunIsAntiAliasedOverThePixel) {
  Scene s = testing::project_scene("sunset");
  s.width = 160;
  s.height = 90;
  const SceneModel m(s);
  RenderSettings rs;
  MethodOptions ro;
  ro.samples = {12, 12, 2};
  const Image ref = render_frame(m, *make_method("reference", testing::with_tables(ro)), 0, rs);
  const double point =
      compare_images(render_frame(m, *make_method("point", testing::with_tables({})), 0, rs), ref)
          .rmse;
  for (const char* name : {"staa", "lean", "bruneton", "specaa"}) {
    const double e =
        compare_images(render_frame(m, *make_method(name, testing::with_tables({})), 0, rs), ref)
            .rmse;
    EXPECT_LT(e, 0.15 * point) << name << " RMSE " << e << ", point " << point;
  }
}

// The smooth terms over the pixel's normals (kernel/smooth_terms.glsl, docs/method.md): on a
// 64-wave scene with Schlick's Fresnel, a sky gradient, a sea and the light's radiance 0,
// at 160x90, staa's RMSE at most supersample 6x6x1's (measured 3.76e-4 against 4.20e-4
// with a 16x16x2 reference of 4 batches), and well below its own with the terms at the
// centre normal (1.40e-3). Against the 12x12x1 reference here (about 6e-5 of noise) the
// bounds are the same; both RMSEs carry that noise.
TEST(Colour, FresnelSkyAndSeaOverTheNormalsBeatSupersampling) {
  Scene s = load_scene(testing::source_dir() + "/tests/scenes/fresnel-sky.json");
  set_image_size(s, 160, 90);
  const SceneModel m(s);
  const FrameZeroAgainstReference r(m);
  const double super = r.rmse("supersample", supersample_6x6x1());
  const double staa = r.rmse("staa", {});
  MethodOptions mean;
  mean.staa.smooth_over_normals = false;
  const double at_mean = r.rmse("staa", mean);
  std::printf("fresnel-sky 160x90: staa %.3g, --smooth-terms mean %.3g, supersample 6x6x1 %.3g\n",
              staa, at_mean, super);
  EXPECT_LT(staa, super);
  EXPECT_LT(staa, 0.4 * at_mean);
}

}  // namespace
}  // namespace sg
