// The kernel's reflection footprint (kernel/reflection_footprint.glsl): the light-plane
// derivatives dP/dpx, dP/dpy of the resolved waves' reflection against finite differences
// of neighbouring image-plane points, each re-traced (new water point, new normal, new
// view). The waves' gradient and Hessian come from the direct sums (testing/direct_waves.h),
// with some waves weighted, as the resolved share of a pixel's waves is.
#include <gtest/gtest.h>

#include "kernel/kernel_double.h"
#include "shading/kernel_frame.h"
#include "shading/water_geometry.h"
#include "testing/direct_waves.h"
#include "testing/testing.h"

namespace sg {
namespace {

kd::ReflectionFootprint reflection_at(const SceneModel& m, std::span<const double> w, double px,
                                      double py, double t) {
  const PixelFootprint fp = pixel_footprint(m, px, py, t);
  const vec2 g = testing::direct_gradient(m.waves, fp.point.x, fp.point.z, t, w);
  const Hessian H = testing::direct_hessian(m.waves, fp.point.x, fp.point.z, t, w);
  return kd::reflection_footprint(m.light.kernel_light(), kernel_footprint(m, fp), g,
                                  vec3(H.xx, H.xz, H.zz), vec2(0.0));
}

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
        const kd::ReflectionFootprint rf = reflection_at(m, w, px, py, t);
        if (!rf.valid) continue;
        auto P = [&](double qx, double qy) { return vec2(reflection_at(m, w, qx, qy, t).P); };
        const double h = 1e-4;
        const vec2 fx = (P(px + h, py) - P(px - h, py)) / (2 * h);
        const vec2 fy = (P(px, py + h) - P(px, py - h)) / (2 * h);
        EXPECT_LT(length(vec2(rf.D[0]) - fx), 1e-5 * length(fx) + 1e-12) << name << px << "," << py;
        EXPECT_LT(length(vec2(rf.D[1]) - fy), 1e-5 * length(fy) + 1e-12) << name << px << "," << py;
        ++tested;
      }
    }
    EXPECT_GT(tested, 6);
  }
}

}  // namespace
}  // namespace sg
