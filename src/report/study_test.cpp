// The study end to end on a tiny scene: references and method frames are cached and
// reused (other thread counts included), a killed run resumes by rendering exactly the
// missing frames, a stateful method renders its whole range in order whenever one of its
// frames is missing, and the results hold every method, region and figure.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "base/error.h"
#include "methods/point.h"
#include "report/cache.h"
#include "report/regions.h"
#include "report/results.h"
#include "report/study.h"
#include "scene/camera_path.h"
#include "testing/testing.h"

namespace sg {
namespace {
namespace fs = std::filesystem;

// A stateful method for the test: point sampling averaged with its previous frame, so
// each frame depends on the history (as TAA's would).
class Ema final : public Method {
 public:
  explicit Ema(int* frames_rendered) : count_(frames_rendered) {}
  std::string name() const override { return "ema"; }
  bool stateful() const override { return true; }
  void begin_frame(const FrameContext& ctx) override { point_.begin_frame(ctx); }
  RadianceWeights weights(const FrameContext& ctx, int i, int j) const override {
    return point_.weights(ctx, i, j);
  }
  void end_frame(const FrameContext&, Image& img) override {
    if (!prev_.data.empty()) {
      for (size_t k = 0; k < img.size(); ++k)
        img.data[k] = 0.5f * img.data[k] + 0.5f * prev_.data[k];
    }
    prev_ = img;
    ++*count_;
  }

 private:
  PointMethod point_;
  Image prev_;
  int* count_;
};

StudyVariant variant(const std::string& label, const std::string& name, SampleCounts samples = {}) {
  StudyVariant v;
  v.label = label;
  v.name = name;
  v.options.samples = samples;
  v.options.samples_given = true;
  return v;
}

class StudyTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = (fs::path(sg::testing::binary_dir()) / "test_out/study" /
            ::testing::UnitTest::GetInstance()->current_test_info()->name())
               .string();
    fs::remove_all(dir_);
    Scene s =
        testing::small_scene({Wave{0.12, {0.1, -0.9}, 2.9, 0.3}, Wave{0.04, {-0.5, -2.2}, 4.6, 1.2},
                              Wave{0.02, {1.1, -3.0}, 5.8, 2.0}},
                             24, 14);
    s.name = "tiny";
    c_.scenes.push_back({"tiny.json", s});
    c_.reference = variant("reference --samples 2x2x2", "reference", {2, 2, 2});
    c_.methods = {variant("point", "point"),
                  variant("supersample --samples 2x2x1", "supersample", {2, 2, 1})};
    StudyVariant ema = variant("ema", "ema");
    ema.make = [this] { return std::make_unique<Ema>(&ema_frames_); };
    c_.methods.push_back(ema);
    c_.budgets = {variant("supersample --samples 1x1x1", "supersample", {1, 1, 1}),
                  variant("supersample --samples 2x2x1", "supersample", {2, 2, 1}),
                  variant("supersample --samples 2x2x2", "supersample", {2, 2, 2})};
    c_.equal_cost_target = "point";
    c_.first_frame = 0;
    c_.last_frame = 3;
    c_.out_dir = dir_;
    c_.threads = 1;
    c_.video = false;  // ffmpeg is exercised by video_test and the report test
  }
  const VariantResult& method(const StudyResults& r, const std::string& label) {
    for (const auto& m : r.scenes.at(0).methods) {
      if (m.label == label) return m;
    }
    throw Error("no method " + label);
  }
  std::string dir_;
  StudyConfig c_;
  int ema_frames_ = 0;
};

TEST_F(StudyTest, CachesResumesAndKeepsStatefulHistoryWhole) {
  const StudyResults first = run_study(c_);
  ASSERT_EQ(first.scenes.size(), 1u);
  const SceneResult& s = first.scenes[0];
  EXPECT_EQ(s.reference.frames_rendered, 4);
  for (const auto& m : s.methods)
    EXPECT_EQ(m.frames_rendered, 4) << m.label;
  EXPECT_EQ(ema_frames_, 4);
  EXPECT_TRUE(method(first, "ema").stateful);
  // The budget that is also a method was rendered once and found in the cache after.
  EXPECT_EQ(s.budgets[1].label, "supersample --samples 2x2x1");
  EXPECT_EQ(s.budgets[1].frames_cached, 4);
  for (const char* f : {"results.json", "results.csv", "results.md", "index.html",
                        "chart.umd.min.js", "report.js", "report.css", "chart.js-LICENSE.md"})
    EXPECT_TRUE(fs::exists(fs::path(dir_) / f)) << f;
  ASSERT_FALSE(s.grid.empty());
  EXPECT_TRUE(fs::exists(fs::path(dir_) / s.grid));
  for (const auto& m : s.methods) {
    EXPECT_TRUE(fs::exists(fs::path(dir_) / m.picture)) << m.picture;
    EXPECT_TRUE(fs::exists(fs::path(dir_) / m.error_map)) << m.error_map;
  }

  // Again, on another thread count: everything comes from the cache, same figures.
  c_.threads = 2;
  const StudyResults again = run_study(c_);
  EXPECT_EQ(again.scenes[0].reference.frames_rendered, 0);
  for (const auto& m : again.scenes[0].methods) {
    EXPECT_EQ(m.frames_rendered, 0) << m.label;
    EXPECT_EQ(m.frames_cached, 4) << m.label;
    EXPECT_EQ(m.at(Region::image).rmse, method(first, m.label).at(Region::image).rmse);
    EXPECT_EQ(m.ms_per_frame, method(first, m.label).ms_per_frame);  // recorded times
  }
  EXPECT_EQ(ema_frames_, 4);

  // A killed run: the reference lost frame 2's image, point lost frame 1's sidecar, ema
  // lost frame 3. Exactly those are redone - and all of ema, whose frames need history.
  FrameCache cache(dir_ + "/cache");
  const Scene& sc = c_.scenes[0].scene;
  fs::remove(
      cache.path(c_.reference.label, reference_batch_key(frame_key(sc, c_.reference.label, 2), 1)));
  fs::remove(cache.path("point", frame_key(sc, "point", 1)) + ".json");
  fs::remove(cache.path("ema", frame_key(sc, "ema", 3, 0)));
  const StudyResults resumed = run_study(c_);
  EXPECT_EQ(resumed.scenes[0].reference.frames_rendered, 1);
  EXPECT_EQ(resumed.scenes[0].reference.frames_cached, 3);
  EXPECT_EQ(method(resumed, "point").frames_rendered, 1);
  EXPECT_EQ(method(resumed, "supersample --samples 2x2x1").frames_rendered, 0);
  EXPECT_EQ(method(resumed, "ema").frames_rendered, 4);
  EXPECT_EQ(ema_frames_, 8);
  for (const auto& m : resumed.scenes[0].methods) {
    for (int k = 0; k < 4; ++k) {
      EXPECT_EQ(m.regions[k].rmse, method(first, m.label).regions[k].rmse) << m.label;
      EXPECT_EQ(m.regions[k].temporal_error, method(first, m.label).regions[k].temporal_error);
    }
  }

  // Another frame range: stateless frames 1-3 are reused; ema's history now starts at 1.
  c_.first_frame = 1;
  const StudyResults shifted = run_study(c_);
  EXPECT_EQ(shifted.scenes[0].reference.frames_rendered, 0);
  EXPECT_EQ(method(shifted, "point").frames_rendered, 0);
  EXPECT_EQ(method(shifted, "ema").frames_rendered, 3);
}

TEST_F(StudyTest, ResultsHoldEveryMethodRegionAndTheEqualCostComparison) {
  c_.methods.pop_back();  // no ema
  c_.pictures = false;
  c_.html = false;
  double last = -1;
  bool monotone = true;
  bool estimated = false;
  const StudyResults r = run_study(c_, [&](const StudyStatus& st) {
    monotone = monotone && st.fraction >= last;
    last = st.fraction;
    estimated = estimated || st.seconds_left > 0;
  });
  EXPECT_TRUE(estimated);
  EXPECT_TRUE(monotone);
  EXPECT_DOUBLE_EQ(last, 1.0);
  const SceneResult& s = r.scenes[0];
  EXPECT_EQ(s.water_pixels, s.near_pixels + s.far_pixels);
  EXPECT_GT(s.water_pixels, 0);
  for (const auto& m : s.methods) {
    EXPECT_EQ(m.at(Region::image).pixels, 24 * 14);
    EXPECT_EQ(m.at(Region::water).pixels, s.water_pixels);
    EXPECT_EQ(m.at(Region::near).pixels, s.near_pixels);
    EXPECT_EQ(m.at(Region::far).pixels, s.far_pixels);
    EXPECT_GT(m.ms_per_frame, 0);
    // The water's squared error is the near and far halves' together.
    const double w2 = std::pow(m.at(Region::water).rmse, 2) * s.water_pixels;
    const double nf2 = std::pow(m.at(Region::near).rmse, 2) * s.near_pixels +
                       std::pow(m.at(Region::far).rmse, 2) * s.far_pixels;
    EXPECT_NEAR(w2, nf2, 1e-9 * (1 + w2));
  }
  // The reference against itself, and the flicker of the reference seen by every method.
  EXPECT_EQ(s.reference.at(Region::image).rmse, 0);
  EXPECT_EQ(s.methods[0].at(Region::near).flicker_reference, s.reference.at(Region::near).flicker);
  ASSERT_EQ(s.budgets.size(), 3u);
  EXPECT_EQ(s.budgets[0].spp, 1);
  EXPECT_EQ(s.budgets[2].spp, 8);
  ASSERT_TRUE(s.equal_cost);
  EXPECT_EQ(s.equal_cost->target, "point");
  EXPECT_EQ(s.equal_cost->target_rmse, s.methods[0].at(Region::image).rmse);
  EXPECT_TRUE(fs::exists(fs::path(dir_) / "results.json"));
  EXPECT_FALSE(fs::exists(fs::path(dir_) / "index.html"));
  // The reference's noise: measured per region, beside every variant's RMSE, which is
  // corrected by it; it is the spread of the reference's batches, each cached alone (a
  // missing batch is rendered again).
  for (int k = 0; k < 4; ++k) {
    const double se = s.reference.regions[k].reference_se;
    EXPECT_GT(se, 0) << kRegionNames[k];
    for (const auto& m : s.methods) {
      const RegionMetrics& g = m.regions[k];
      EXPECT_EQ(g.reference_se, se) << m.label;
      EXPECT_NEAR(g.rmse_corrected, std::sqrt(std::max(0.0, g.rmse * g.rmse - se * se)), 1e-15);
      EXPECT_LT(g.rmse_corrected, g.rmse) << m.label;
    }
  }
  const FrameCache cache(dir_ + "/cache");
  const std::string key = frame_key(c_.scenes[0].scene, c_.reference.label, 2);
  ASSERT_TRUE(cache.has(c_.reference.label, reference_batch_key(key, 0)));
  fs::remove(cache.path(c_.reference.label, reference_batch_key(key, 0)));
  const StudyResults again = run_study(c_);
  EXPECT_EQ(again.scenes[0].reference.frames_rendered, 1);
  EXPECT_EQ(again.scenes[0].reference.at(Region::image).reference_se,
            s.reference.at(Region::image).reference_se);
}

// A colour scene: frames cached as RGB, figures over all channels and per channel, the
// flicker pixel where point sampling's temporal error is largest, crops at 2:1 pixels.
TEST_F(StudyTest, ColourSceneHasPerChannelFiguresCropsAndAFlickerTrace) {
  c_.methods.pop_back();  // no ema
  Scene& s = c_.scenes[0].scene;
  s.light.radiance = Rgb(3, 2, 1);
  s.sky = SkyDesc{Rgb(0.02, 0.05, 0.1), Rgb(0.1, 0.06, 0.04), 0.5, true};
  s.surface.fresnel = FresnelMode::schlick;
  s.surface.sea_radiance = Rgb(0, 0.01, 0.02);
  const StudyResults r = run_study(c_);
  const SceneResult& sc = r.scenes[0];
  EXPECT_EQ(sc.channels, 3);
  const RegionMetrics& m = method(r, "point").at(Region::image);
  ASSERT_EQ(m.channels.size(), 3u);
  // The whole is the root mean square of the channels (equal pixel counts).
  const double ms = (std::pow(m.channels[0].rmse, 2) + std::pow(m.channels[1].rmse, 2) +
                     std::pow(m.channels[2].rmse, 2)) /
                    3;
  EXPECT_NEAR(m.rmse, std::sqrt(ms), 1e-12 * m.rmse);
  EXPECT_GT(m.channels[0].rmse, m.channels[2].rmse);  // the light is redder than blue
  // Frames are cached in colour and reused.
  FrameCache cache(dir_ + "/cache");
  const auto f = cache.load("point", frame_key(s, "point", 2));
  ASSERT_TRUE(f);
  EXPECT_EQ(f->image.channels, 3);
  EXPECT_EQ(run_study(c_).scenes[0].methods[0].frames_rendered, 0);
  // The flicker pixel and its traces: one value per frame per column.
  ASSERT_GE(sc.flicker_pixel.x, 0);
  EXPECT_EQ(sc.flicker_pixel.chosen_by, "point");
  EXPECT_EQ(sc.reference.trace.size(), 4u);
  for (const auto& v : sc.methods)
    EXPECT_EQ(v.trace.size(), 4u);
  // Crops: kCropScale:1 of a quarter of each side.
  ASSERT_FALSE(sc.crops.empty());
  EXPECT_TRUE(fs::exists(fs::path(dir_) / sc.crops));
  EXPECT_TRUE(fs::exists(fs::path(dir_) / sc.methods[0].near_crop_picture));
  EXPECT_EQ(sc.near_crop.width, 24 / 4);
}

TEST_F(StudyTest, MovingCameraStatesItsMotionAndTheFirstFramesRegions) {
  // A /3 camera that turns and moves over the frames studied (frames 0-3 at 30 fps): the
  // results give its fastest speed and turn rate there, in results.json and the report's
  // text; the water regions are those of the camera at the first frame.
  c_.methods.pop_back();  // no ema
  Scene& s = c_.scenes[0].scene;
  const CameraDesc fixed = s.camera;
  s.camera.keyframes = {{-1.0, {0, 2.5, 0}, {-20, 0, -60}},
                        {1.0, {0, 2.5, -4}, {20, 0, -60}},
                        {5.0, {0, 2.5, -4}, {20, 0, -60}}};  // stands after 1 s
  const StudyResults r = run_study(c_);
  const SceneResult& sc = r.scenes[0];
  EXPECT_TRUE(sc.moving_camera);
  EXPECT_NEAR(sc.camera_speed, 2.0, 1e-12);  // 4 m in 2 s
  EXPECT_GT(sc.camera_turn_deg, 10);
  EXPECT_LT(sc.camera_turn_deg, 20);  // about 37 degrees in 2 s
  const FrameTime f0 = frame_time(s, 0);
  const WaterRegions w = water_regions(frame_model(s, f0), f0.end);
  EXPECT_EQ(sc.water_pixels, w.water_pixels);
  EXPECT_EQ(sc.split_distance, w.split_distance);
  Scene unmoved = s;
  unmoved.camera = fixed;
  EXPECT_NE(sc.split_distance, water_regions(SceneModel(unmoved), f0.end).split_distance);
  const StudyResults back = results_from_json(results_to_json(r), "results");
  EXPECT_TRUE(back.scenes[0].moving_camera);
  EXPECT_EQ(back.scenes[0].camera_speed, sc.camera_speed);
  EXPECT_EQ(back.scenes[0].camera_turn_deg, sc.camera_turn_deg);
  EXPECT_NE(camera_motion_sentence(sc).find("up to 2 m/s"), std::string::npos);
  EXPECT_NE(results_to_markdown(r).find(camera_motion_sentence(sc)), std::string::npos);
  // A fixed camera states nothing.
  s.camera = fixed;
  const StudyResults still = run_study(c_);
  EXPECT_FALSE(still.scenes[0].moving_camera);
  EXPECT_EQ(camera_motion_sentence(still.scenes[0]), "");
}

// The flicker pixel is where point sampling's temporal error is largest: checked against a
// brute-force search on a grey study.
TEST_F(StudyTest, FlickerPixelIsThePointOfLargestTemporalError) {
  c_.methods.pop_back();
  c_.pictures = false;
  c_.html = false;
  c_.scenes[0].scene.light.angular_radius_deg = 3;  // glints at this size
  const StudyResults r = run_study(c_);
  const SceneResult& sc = r.scenes[0];
  ASSERT_GE(sc.flicker_pixel.x, 0);
  FrameCache cache(dir_ + "/cache");
  const Scene& s = c_.scenes[0].scene;
  std::vector<Image> p, ref;
  for (int f = 0; f < 4; ++f) {
    p.push_back(cache.load("point", frame_key(s, "point", f))->image);
    const std::string k = frame_key(s, c_.reference.label, f);
    Image mean = cache.load(c_.reference.label, reference_batch_key(k, 0))->image;
    const Image b1 = cache.load(c_.reference.label, reference_batch_key(k, 1))->image;
    for (size_t q = 0; q < mean.data.size(); ++q)
      mean.data[q] = float((double(mean.data[q]) + b1.data[q]) / 2);
    ref.push_back(mean);
  }
  auto te = [&](int i, int j) {
    double e = 0;
    for (int f = 1; f < 4; ++f) {
      const double d =
          (p[f].at(i, j) - p[f - 1].at(i, j)) - (ref[f].at(i, j) - ref[f - 1].at(i, j));
      e += d * d;
    }
    return e;
  };
  const double chosen = te(sc.flicker_pixel.x, sc.flicker_pixel.y);
  EXPECT_GT(chosen, 0);
  const WaterRegions w = water_regions(SceneModel(s), frame_time(s, 0).end);
  for (int j = 0; j < s.height; ++j) {
    for (int i = 0; i < s.width; ++i) {
      if (w.water[size_t(j) * s.width + i]) {
        EXPECT_LE(te(i, j), chosen) << i << "," << j;
      }
    }
  }
  EXPECT_EQ(sc.methods[0].trace[2], p[2].at(sc.flicker_pixel.x, sc.flicker_pixel.y));
  EXPECT_EQ(sc.reference.trace[3], ref[3].at(sc.flicker_pixel.x, sc.flicker_pixel.y));
}

TEST_F(StudyTest, BadConfigurationNamesTheOption) {
  StudyConfig c = c_;
  c.equal_cost_target = "staa";
  EXPECT_THROW(
      {
        try {
          run_study(c);
        } catch (const Error& e) {
          EXPECT_NE(std::string(e.what()).find("--equal-cost-target"), std::string::npos);
          throw;
        }
      },
      Error);
  c = c_;
  c.last_frame = 60;
  EXPECT_THROW(run_study(c), Error);
  c = c_;
  c.methods.push_back(variant("point ", "point"));
  EXPECT_THROW(run_study(c), Error);  // given twice
}

TEST(DefaultTarget, StaaThenNonBaselineThenPoint) {
  auto v = [](const std::string& n) { return StudyVariant{n, n, {}, {}, {}}; };
  EXPECT_EQ(default_equal_cost_target({v("point"), v("lean"), v("staa")}), "staa");
  EXPECT_EQ(default_equal_cost_target({v("point"), v("supersample"), v("lean")}), "lean");
  EXPECT_EQ(default_equal_cost_target({v("supersample"), v("point")}), "point");
  EXPECT_EQ(default_equal_cost_target({v("reference")}), "");
}

}  // namespace
}  // namespace sg
