// Property: every method returns finite pixels on every valid scene. 200 random scenes
// (testing/random_scene.h: random waves, camera (a third of them moving), light, flat or
// displaced water, Fresnel, sky and sea radiances, times), each rendered at 24x16 by every method
// of the catalogue, one frame of its animation; every pixel must be finite. Scenes and methods that
// fail are written to test_out/finite_property/ as scene files, with the frame in their name, to be
// rendered by hand (`sunglint render FILE -m METHOD --frame F`).
//
// Cheap settings where the method's cost does not change what is tested: 2x2x2 samples for
// reference and supersample, a 256-texel LEAN map, two TAA warm-up frames. In unoptimised
// builds (the sanitizer job) 25 scenes, so that the suite stays fast there too. A longer
// search: SG_PROPERTY_SCENES=20000 SG_PROPERTY_SEED=7 build/tests/finite_property_test.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "base/atomic_file.h"
#include "engine/render.h"
#include "gl_engine/engines.h"
#include "gl_engine/gl_engine.h"
#include "image/image_io.h"
#include "methods/method.h"
#include "testing/gl_context.h"
#include "testing/path_tables.h"
#include "testing/paths.h"
#include "testing/random_scene.h"

namespace sg {
namespace {

#ifdef __OPTIMIZE__
constexpr int kScenes = 200;
#else
constexpr int kScenes = 25;
#endif

MethodOptions cheap_options() {
  MethodOptions o;
  o.samples = SampleCounts{2, 2, 2};
  o.lean.size = 256;
  o.taa.warmup = 2;
  return o;
}

// Methods whose non-finite pixels are known (their cases are in tests/scenes/extreme/) and
// not yet fixed: their failures are reported, not asserted.
const std::set<std::string> kPending = {};

TEST(FiniteProperty, EveryMethodIsFiniteOnRandomValidScenes) {
  const std::string dump = sg::testing::binary_dir() + "/test_out/finite_property";
  std::filesystem::remove_all(dump);
  std::filesystem::create_directories(dump);
  const char* env_n = std::getenv("SG_PROPERTY_SCENES");
  const char* env_seed = std::getenv("SG_PROPERTY_SEED");
  const int scenes = env_n ? std::atoi(env_n) : kScenes;
  testing::RandomScenes gen(env_seed ? std::strtoull(env_seed, nullptr, 10) : 20240611);
  const MethodOptions opt = cheap_options();
  std::map<std::string, double> seconds;
  std::map<std::string, int> failures;
  RenderSettings rs;
  rs.threads = 1;  // the test runs beside others (ctest -j2)
  int moving = 0;
  for (int k = 0; k < scenes; ++k) {
    int frame = 0;
    const Scene s = gen.next(24, 16, frame);
    moving += s.camera.moving();
    const SceneModel model(s);
    for (const MethodInfo& info : method_catalog()) {
      auto m = make_method(info.name, testing::with_tables(opt));
      const auto t0 = std::chrono::steady_clock::now();
      Image img;
      std::string error;
      try {
        render_frames(model, *m, frame, frame, rs, [&](int, const Image& i) { img = i; });
      } catch (const std::exception& e) {
        error = e.what();
      }
      seconds[info.name] +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const size_t bad = error.empty() ? count_nonfinite(img) : img.size();
      if (bad == 0 && error.empty()) continue;
      ++failures[info.name];
      const std::string file = dump + "/" + info.name + "_scene" + std::to_string(k) + "_frame" +
                               std::to_string(frame) + ".json";
      write_file_atomic(file, scene_to_json(s));
      if (kPending.count(info.name)) {
        std::printf("pending %s: %zu non-finite pixels %s, %s\n", info.name.c_str(), bad,
                    error.c_str(), file.c_str());
      } else {
        ADD_FAILURE() << info.name << ": " << bad << " non-finite pixels of " << img.size()
                      << (error.empty() ? "" : " (error: " + error + ")") << " on random scene "
                      << k << " frame " << frame << " (" << file << ")";
      }
    }
  }
  std::printf("%d scenes, %d of them with a moving camera (%d drawings rejected by the loader)\n",
              scenes, moving, gen.rejected());
  // The generator's moving cameras reach the methods (a third of the scenes are drawn so).
  if (scenes >= 100) {
    EXPECT_GT(moving, scenes / 5);
  }
  for (const auto& [name, secs] : seconds) {
    std::printf("  %-14s %6.2f s, %d scenes with non-finite pixels\n", name.c_str(), secs,
                failures[name]);
  }
}

// The same property on the GL engine: its nine methods (one program each, compiled once)
// on the first 10 of the same random scenes (5 in the sanitizer build): llvmpipe compiles
// the programs in about two minutes and takes up to seconds a render on the
// displaced scenes (200 scenes took 592 s here, all finite); every pixel read back must be
// finite. A longer search: SG_PROPERTY_SCENES=N, as above.
class FinitePropertyGl : public testing::GlTest {};

TEST_F(FinitePropertyGl, GlEngineIsFiniteOnRandomValidScenes) {
  const char* env_n = std::getenv("SG_PROPERTY_SCENES");
#ifdef __OPTIMIZE__
  const int gl_scenes = 10;
#else
  const int gl_scenes = 5;
#endif
  const int scenes = env_n ? std::atoi(env_n) : gl_scenes;
  testing::RandomScenes gen(20240611);
  const MethodOptions opt = cheap_options();
  std::vector<std::pair<std::string, std::unique_ptr<Method>>> methods;
  for (const char* n : {"point", "supersample", "reference", "staa-temporal", "staa", "specaa",
                        "microspec", "bruneton", "lean"})
    methods.emplace_back(n, make_method_on(Engine::gl, n, testing::with_tables(opt)));
  RenderSettings rs;
  rs.threads = 1;
  std::map<std::string, int> failures;
  for (int k = 0; k < scenes; ++k) {
    int frame = 0;
    const Scene s = gen.next(24, 16, frame);
    const SceneModel model(s);
    for (auto& [name, m] : methods) {
      Image img;
      std::string error;
      try {
        render_frames(model, *m, frame, frame, rs, [&](int, const Image& i) { img = i; });
      } catch (const std::exception& e) {
        error = e.what();
      }
      const size_t bad = error.empty() ? count_nonfinite(img) : img.size();
      if (bad == 0 && error.empty()) continue;
      ++failures[name];
      ADD_FAILURE() << name << " --engine gl: " << bad << " non-finite pixels of " << img.size()
                    << (error.empty() ? "" : " (error: " + error + ")") << " on random scene " << k
                    << " frame " << frame;
    }
  }
  std::printf("GL engine: %d scenes\n", scenes);
  for (const auto& [name, m] : methods)
    std::printf("  %-14s %d scenes with non-finite pixels\n", name.c_str(), failures[name]);
}

// Every method on every scene of `dir`, at 24x16, frame 0: the non-finite pixels (or the
// error) of each, as "scene method: what" lines.
std::vector<std::string> non_finite_renders(const std::string& dir) {
  std::vector<std::string> bad;
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().extension() == ".json") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  RenderSettings rs;
  rs.threads = 1;
  for (const auto& f : files) {
    Scene s = load_scene(f.string());
    s.width = 24;
    s.height = 16;
    const SceneModel model(s);
    for (const MethodInfo& info : method_catalog()) {
      auto m = make_method(info.name, testing::with_tables(cheap_options()));
      const std::string what = f.filename().string() + " " + info.name + ": ";
      try {
        Image img;
        render_frames(model, *m, 0, 0, rs, [&](int, const Image& i) { img = i; });
        if (const size_t n = count_nonfinite(img)) {
          bad.push_back(what + std::to_string(n) + " non-finite pixels");
        }
      } catch (const std::exception& e) {
        bad.push_back(what + e.what());
      }
    }
  }
  return bad;
}

TEST(EdgeScenes, EveryMethodIsFinite) {
  // tests/scenes/edge: valid scenes at the ends of every range (make_edge_scenes.py).
  for (const std::string& b : non_finite_renders(sg::testing::source_dir() + "/tests/scenes/edge"))
    ADD_FAILURE() << b;
}

// tests/scenes/extreme: valid scenes on which a method is not yet finite (their README
// lists each case; none is open). Run on demand (--gtest_also_run_disabled_tests).
TEST(ExtremeScenes, DISABLED_EveryMethodIsFinite) {
  for (const std::string& b :
       non_finite_renders(sg::testing::source_dir() + "/tests/scenes/extreme")) {
    ADD_FAILURE() << b;
  }
}

}  // namespace
}  // namespace sg
