// `staa` against the reference on random ordinary seas (testing/random_sea.h: 3 to 48
// waves of 0.1 to 80 m, flat or displaced, a camera 1 to 40 m up, the glitter in the frame
// or a Fresnel-weighted sky gradient lit from any side), not only on the shared scenes:
// the method must keep its lead over the baselines on scenes nobody tuned it for. Each
// scene at 64x36, frames 0-2, against `reference --samples 12x12x1` (2 batches; its noise
// from its own per-pixel variances, taken out of every error as in
// testing/stored_reference.h, and allowed once more in each bound: se):
//  - per scene, loose bounds that a broken method fails: `staa`'s RMSE and temporal error
//    at most 1.5 times `lean`'s (LEAN mapping, Olano and Baker 2010: the Gaussian of
//    normals at the display time, the baseline to beat), its temporal error at most 1.25
//    times `point`'s, and, where `point`'s RMSE stands above 3 reference standard errors,
//    its RMSE at most `point`'s. On a tiny image a few aliasing waves' arrangement in a
//    pixel moves the errors either way (docs/aliasing-study.md): measured up to 1.36 times
//    `lean`'s RMSE on one scene of 80;
//  - over the scenes above the noise, the geometric means of `staa`'s RMSE over `point`'s
//    and over `lean`'s at most 0.35 and 0.7.
// What 80 scenes measured is in docs/targets.md ("Random seas"). It fails with
// `staa-temporal` in `staa`'s place (SG_RANDOM_SEAS_METHOD) and with the paper's method
// (`--footprint none`: the means 0.53 and 1.07 over the first 10 scenes). A longer search:
// SG_RANDOM_SEAS=40 SG_RANDOM_SEAS_SEED=2 build/tests/random_seas_test (each scene's figures
// printed; a scene that fails a bound is written to test_out/random_seas/ to be rendered by hand).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "engine/render.h"
#include "methods/method.h"
#include "methods/reference.h"
#include "metrics/metrics.h"
#include "testing/paths.h"
#include "testing/random_sea.h"
#include "testing/stored_reference.h"

namespace sg {
namespace {

#ifdef __OPTIMIZE__
constexpr int kScenes = 8;
#else
constexpr int kScenes = 1;
#endif
constexpr int kWidth = 64, kHeight = 36, kFrames = 3;
// The geometric means over the scenes above the noise (8 scenes, seed 1: 0.233 and 0.456;
// 40 scenes, seeds 1 and 2: 0.158 / 0.575 and 0.105 / 0.572).
constexpr double kPointBound = 0.35, kLeanBound = 0.7;

int env_int(const char* name, int fallback) {
  const char* v = std::getenv(name);
  return v ? std::atoi(v) : fallback;
}

struct Rendered {
  std::vector<Image> frames, variances;
};

Rendered render_reference(const SceneModel& m) {
  MethodOptions o;
  o.samples = SampleCounts{12, 12, 1};
  o.samples_given = true;
  std::unique_ptr<Method> ref = make_method("reference", testing::with_tables(o));
  Rendered r;
  for (int f = 0; f < kFrames; ++f) {
    r.frames.push_back(render_frame(m, *ref, f, {}));
    r.variances.push_back(*ref->pixel_variance());
  }
  return r;
}

struct Errors {
  double rmse, temporal;
};

Errors errors(const SceneModel& m, const std::string& method, const Rendered& ref, double se) {
  const SequenceMetrics s =
      compare_sequences(testing::render_sequence(m, method, {}, kFrames), ref.frames);
  return {testing::noise_corrected(s.rmse, se * se),
          testing::noise_corrected(s.temporal_error, 2 * se * se)};
}

TEST(RandomSeas, StaaLeadsPointAndLeanOnOrdinarySeas) {
  const int scenes = env_int("SG_RANDOM_SEAS", kScenes);
  // Another method in staa's place (to see the test fail, or to measure it).
  const char* method_env = std::getenv("SG_RANDOM_SEAS_METHOD");
  const std::string method = method_env ? method_env : "staa";
  testing::RandomSeas seas(static_cast<uint64_t>(env_int("SG_RANDOM_SEAS_SEED", 1)));
  const std::string dump = sg::testing::binary_dir() + "/test_out/random_seas";
  std::printf("%-6s %-7s %-9s %-6s %9s | %9s %9s %9s | %9s %9s %9s\n", "scene", "look", "geometry",
              "camera", "ref se", "point", "lean", "staa", "t point", "t lean", "t staa");
  int lit = 0, moving = 0;
  double log_point = 0, log_lean = 0;
  for (int i = 0; i < scenes; ++i) {
    const Scene s = seas.next(kWidth, kHeight, kFrames);
    const bool glitter = seas.glitter();
    moving += s.camera.moving();
    const SceneModel m(s);
    const Rendered ref = render_reference(m);
    const double se = sequence_standard_error(ref.variances);
    const Errors p = errors(m, "point", ref, se), l = errors(m, "lean", ref, se),
                 a = errors(m, method, ref, se);
    std::printf("%-6s %-7s %-9s %-6s %9.3g | %9.3g %9.3g %9.3g | %9.3g %9.3g %9.3g\n",
                s.name.c_str(), glitter ? "glitter" : "sky",
                s.surface.geometry == Geometry::flat ? "flat" : "displaced",
                s.camera.moving() ? "moving" : "fixed", se, p.rmse, l.rmse, a.rmse, p.temporal,
                l.temporal, a.temporal);
    // Per scene, loose bounds that a broken method fails (the pixel-scale arrangement of
    // a few aliasing waves moves a tiny image's errors either way); over the scenes, the
    // geometric means of the ratios, tight.
    const double allow = se;  // what the noise correction leaves uncertain
    bool ok = a.rmse <= 1.5 * l.rmse + allow && a.temporal <= 1.5 * l.temporal + allow &&
              a.temporal <= 1.25 * p.temporal + allow;
    EXPECT_LE(a.rmse, 1.5 * l.rmse + allow) << s.name << ": staa's RMSE against lean's";
    EXPECT_LE(a.temporal, 1.5 * l.temporal + allow)
        << s.name << ": staa's temporal error against lean's";
    EXPECT_LE(a.temporal, 1.25 * p.temporal + allow)
        << s.name << ": staa's temporal error against point's";
    if (p.rmse > 3 * se) {
      // Scenes whose point error stands above the reference's noise: the ratios.
      // Plus the noise: point's error may stand only a few standard errors above it, where
      // both corrected errors carry about one standard error of the noise's estimate.
      EXPECT_LE(a.rmse, p.rmse + allow) << s.name << ": staa's RMSE against point's";
      ok = ok && a.rmse <= p.rmse + allow;
      log_point += std::log(std::max(a.rmse, se) / p.rmse);
      log_lean += std::log(std::max(a.rmse, se) / std::max(l.rmse, se));
      ++lit;
    }
    if (!ok) {
      std::filesystem::create_directories(dump);
      write_scene(dump + "/" + s.name + ".json", s);
    }
  }
  const double gm_point = std::exp(log_point / std::max(lit, 1)),
               gm_lean = std::exp(log_lean / std::max(lit, 1));
  std::printf(
      "%d scenes above the noise: staa's RMSE over point's %.3f, over lean's %.3f "
      "(geometric means); %d of %d scenes with a moving camera\n",
      lit, gm_point, gm_lean, moving, scenes);
  EXPECT_LE(gm_point, kPointBound);
  EXPECT_LE(gm_lean, kLeanBound);
  // The draw must give scenes where the comparison with point says something.
  EXPECT_GE(lit, scenes / 2) << "scenes whose point error is above the reference's noise";
}

}  // namespace
}  // namespace sg
