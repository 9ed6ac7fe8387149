// The reflection's light-plane derivatives against finite differences of neighbouring
// image-plane points (each re-traced: new water point, new normal, new view).
#include "shading/reflection_footprint.h"

#include <gtest/gtest.h>

#include "shading/water_geometry.h"
#include "testing/testing.h"

namespace sg {
namespace {

TEST(ReflectionFootprint, MatchesFiniteDifferences) {
  for (const char* name : {"simple", "medium"}) {
    SceneModel m(testing::project_scene(name));
    std::vector<double> w(m.waves.size(), 1.0);
    for (size_t k = 0; k < w.size(); k += 3)
      w[k] = 0.5;  // weighted waves
    int tested = 0;
    for (double py : {220.5, 270.5, 330.5}) {
      for (double px : {280.5, 320.5, 350.5}) {
        const double t = 0.7;
        PixelFootprint fp = pixel_footprint(m, px, py, t);
        ReflectionFootprint rf = reflection_footprint(m, fp, w, t);
        if (!rf.valid) continue;
        auto P = [&](double qx, double qy) {
          return reflection_footprint(m, pixel_footprint(m, qx, qy, t), w, t).P;
        };
        const double h = 1e-4;
        const vec2 fx = (P(px + h, py) - P(px - h, py)) / (2 * h);
        const vec2 fy = (P(px, py + h) - P(px, py - h)) / (2 * h);
        EXPECT_LT(length(rf.D[0] - fx), 1e-5 * length(fx) + 1e-12) << name << px << "," << py;
        EXPECT_LT(length(rf.D[1] - fy), 1e-5 * length(fy) + 1e-12) << name << px << "," << py;
        ++tested;
      }
    }
    EXPECT_GT(tested, 6);
  }
}

}  // namespace
}  // namespace sg
