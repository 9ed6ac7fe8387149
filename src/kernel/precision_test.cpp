// The kernel in float (what a GPU computes) against the kernel in double, on the four
// shared scenes at 160x90, frames 0-9, for every kernel method: the float images' error
// against the double ones must be small beside the double images' own error against the
// reference (docs/porting.md states the measured figures).
//  - staa, staa-temporal, specaa (smooth in the waves): RMSE(float - double) <= 0.05
//    RMSE(double - reference);
//  - point, supersample, microspec, taa (a binary test at the disk's rim per sample or corner
//    quad, where float's rounding flips a few samples, each by a whole pixel's or sample's
//    worth): at most 0.5%
//    of pixels differ by more than 1e-4, and the two RMSEs against the reference within 5%
//    of each other.
// Under AddressSanitizer (CI's sanitizer suite, about 10x slower) the same checks run on
// frames 0-2: what the sanitizers look for is in every frame alike, and the Release suite
// runs all ten (docs/ci.md).
#include <gtest/gtest.h>

#include <cstdio>
#include <map>

#include "engine/render.h"
#include "methods/method.h"
#include "metrics/metrics.h"
#include "testing/path_tables.h"
#include "testing/testing.h"

namespace sg {
namespace {

std::vector<Image> render(const SceneModel& m, Method& method, int frames) {
  std::vector<Image> out;
  for (int f = 0; f < frames; ++f)
    out.push_back(render_frame(m, method, f, {}));
  return out;
}

struct Variant {
  const char* label;
  const char* name;
  void (*set)(MethodOptions&);
  bool binary;
};

TEST(KernelPrecision, FloatAgreesWithDoubleWithinTheMethodsOwnError) {
#if defined(__SANITIZE_ADDRESS__)
  const int frames = 3;
#else
  const int frames = 10;
#endif
  const Variant variants[] = {
      {"point", "point", [](MethodOptions&) {}, true},
      {"staa-temporal", "staa-temporal", [](MethodOptions&) {}, false},
      {"staa", "staa", [](MethodOptions&) {}, false},
      {"staa --ndf uniform", "staa", [](MethodOptions& o) { o.staa.ndf = NdfMode::uniform; },
       false},
      {"staa --footprint none", "staa",
       [](MethodOptions& o) { o.staa.footprint = FootprintMode::none; }, false},
      {"staa --footprint none --ndf uniform", "staa",
       [](MethodOptions& o) {
         o.staa.footprint = FootprintMode::none;
         o.staa.ndf = NdfMode::uniform;
       },
       false},
      {"specaa", "specaa", [](MethodOptions&) {}, false},
      {"microspec", "microspec", [](MethodOptions&) {}, true},
      {"bruneton", "bruneton", [](MethodOptions&) {}, false},
      {"lean", "lean", [](MethodOptions& o) { o.lean.size = 512; }, false},
      {"taa", "taa", [](MethodOptions&) {}, true},
      {"supersample 6x6x1", "supersample",
       [](MethodOptions& o) {
         o.samples = {6, 6, 1};
       },
       true},
  };
  for (const char* scene : {"simple", "smooth", "medium", "high"}) {
    Scene s = testing::project_scene(scene);
    s.width = 160;
    s.height = 90;
    const SceneModel m(s);
    MethodOptions ro;
    ro.samples = {12, 12, 8};
    const std::vector<Image> ref =
        render(m, *make_method("reference", testing::with_tables(ro)), frames);
    for (const Variant& v : variants) {
      MethodOptions o;
      v.set(o);
      const std::vector<Image> d = render(m, *make_method(v.name, testing::with_tables(o)), frames);
      o.precision = Precision::float32;
      const std::vector<Image> f = render(m, *make_method(v.name, testing::with_tables(o)), frames);
      const double err_d = compare_sequences(d, ref).rmse, err_f = compare_sequences(f, ref).rmse;
      const double fd = compare_sequences(f, d).rmse;
      long differ = 0, total = 0;
      for (int k = 0; k < frames; ++k) {
        for (size_t p = 0; p < f[k].size(); ++p)
          differ += std::fabs(f[k].data[p] - d[k].data[p]) > 1e-4;
        total += f[k].size();
      }
      std::printf(
          "%-7s %-36s RMSE(float - double) %.3g, RMSE(double - ref) %.3g (ratio %.4f), "
          "float - ref %.3g, %.3f%% pixels differ > 1e-4\n",
          scene, v.label, fd, err_d, fd / err_d, err_f, 100.0 * differ / total);
      if (v.binary) {
        EXPECT_LE(differ, 0.005 * total) << scene << " " << v.label;
        EXPECT_NEAR(err_f, err_d, 0.05 * err_d) << scene << " " << v.label;
      } else {
        EXPECT_LE(fd, 0.05 * err_d) << scene << " " << v.label;
      }
    }
  }
}

}  // namespace
}  // namespace sg
