// The three baselines (microspec, specaa, bruneton) as whole methods:
//  - calm water (all amplitudes 0) against the exact coverage of the mirrored light disk:
//    specaa and bruneton sample one lobe at each pixel centre, so what they guarantee is
//    the light's total over the window (the lobe's mass is conserved; it is spread over
//    neighbouring pixels), not each pixel; microspec's per-pixel agreement is tested in
//    microspec_test.cpp;
//  - the four shared scenes and a displaced, Schlick, sky-and-sea variant: every value
//    finite and non-negative, and the variant's mean (dominated by sky and sea) close to the
//    reference's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "base/error.h"
#include "engine/render.h"
#include "methods/method.h"
#include "methods/stratified.h"
#include "testing/calm_coverage.h"
#include "testing/testing.h"

namespace sg {
namespace {

// Sum of a method's values and of the exact coverage over a (2 half + 1)^2 window centred
// on the mirrored light.
void calm_window_sums(const std::string& method, int half, double& sum, double& exact) {
  Scene s = testing::small_scene({Wave{0.0, {0.3, -1.2}, 3.4, 0.0}}, 640, 360);
  s.light.angular_radius_deg = 0.6;
  SceneModel m(s);
  double cx, cy;
  ASSERT_TRUE(m.camera.project(vec3(m.light.L.x, -m.light.L.y, m.light.L.z), cx, cy));
  auto meth = make_method(method, MethodOptions{});
  FrameContext ctx{m, frame_time(s, 0), 0};
  sum = exact = 0;
  for (int j = static_cast<int>(cy) - half; j <= static_cast<int>(cy) + half; ++j) {
    for (int i = static_cast<int>(cx) - half; i <= static_cast<int>(cx) + half; ++i) {
      sum += meth->shade(ctx, i, j);
      exact += testing::analytic_calm_coverage(m, i, j);
    }
  }
}

TEST(Baselines, SpecaaConservesTheMirroredDisksLightOnCalmWater) {
  // The lobe (the view's change across a pixel, sigma^2 = 0.25 of it) is about half a pixel
  // wide: a window 12 pixels beyond the disk holds it. Its mass in the disk, summed over
  // pixel centres, is a Riemann sum of the disk's image blurred by the lobe; at half a pixel
  // of blur the sum's error is a few parts in a thousand of the disk's ~95 pixels, plus the
  // linearisation of the light plane. Held to 0.5%.
  double sum, exact;
  calm_window_sums("specaa", 18, sum, exact);
  std::printf("specaa calm water: sum %.4f, exact %.4f (%.3f%%)\n", sum, exact,
              100 * (sum / exact - 1));
  EXPECT_GT(exact, 50);
  EXPECT_NEAR(sum, exact, 0.005 * exact);
}

TEST(Baselines, BrunetonConservesTheMirroredDisksLightOnCalmWater) {
  // The clamped lobe (slope variance 2e-5) spreads the sun over ~4.5 pixels (std) at this
  // resolution; the window reaches 8 std beyond the disk. Eq. 15 integrates the lobe's mass
  // over the sun's solid angle with the weight (v . h) / (h_z cos(theta_v)), which is 1 at
  // the mirror direction and second-order away from it, and Lambda ~ 0 for so narrow a
  // lobe. Held to 0.5%.
  double sum, exact;
  calm_window_sums("bruneton", 45, sum, exact);
  std::printf("bruneton calm water: sum %.4f, exact %.4f (%.3f%%)\n", sum, exact,
              100 * (sum / exact - 1));
  EXPECT_GT(exact, 50);
  EXPECT_NEAR(sum, exact, 0.005 * exact);
}

// Renders frames 0, 4, 9 and expects every value finite and >= 0; returns the mean of
// frame 4.
double expect_finite(const Scene& s, const std::string& method, MethodOptions o = {}) {
  SceneModel m(s);
  auto meth = make_method(method, o);
  double mean4 = 0;
  for (int f : {0, 4, 9}) {
    const Image img = render_frame(m, *meth, f, RenderSettings{});
    int bad = 0;
    for (float v : img.data) {
      bad += !(std::isfinite(v) && v >= 0);
      if (f == 4) mean4 += v / img.data.size();
    }
    EXPECT_EQ(bad, 0) << s.name << " " << method << " frame " << f;
  }
  return mean4;
}

TEST(Baselines, SharedScenesGiveFiniteValues) {
  for (const char* name : {"simple", "smooth", "medium", "high"}) {
    Scene s = testing::project_scene(name);
    set_image_size(s, 160, 90);
    for (const char* method : {"microspec", "specaa", "bruneton"})
      expect_finite(s, method);
  }
}

TEST(Baselines, DisplacedSchlickSkyAndSeaVariant) {
  // The simple scene, displaced, with Schlick's Fresnel, a sky and a sea: each method's
  // values are finite, and its mean, which sky and sea dominate, is within 0.01 of the
  // reference's (3x3x2 samples; the reference's own noise in the mean is ~1e-4). (The
  // other scenes' displaced intersections are 10-30 times slower to march.)
  Scene s = testing::project_scene("simple");
  set_image_size(s, 160, 90);
  s.surface.geometry = Geometry::displaced;
  s.surface.fresnel = FresnelMode::schlick;
  s.sky_radiance = 0.3;
  s.surface.sea_radiance = 0.1;
  s.light.radiance = 20;
  SceneModel m(s);
  MethodOptions ref_opt;
  ref_opt.samples = {3, 3, 2};
  auto ref = make_method("reference", ref_opt);
  const Image r = render_frame(m, *ref, 4, RenderSettings{});
  double ref_mean = 0;
  for (float v : r.data)
    ref_mean += v / r.data.size();
  for (const char* method : {"microspec", "specaa", "bruneton"}) {
    MethodOptions o;
    o.specaa.derivatives = SpecaaDerivatives::analytic;  // the other mode than the default
    o.microspec.area = MicrospecArea::approx;
    o.bruneton.fresnel = BrunetonFresnel::integral;
    for (const MethodOptions& opt : {MethodOptions{}, o}) {
      const double mean = expect_finite(s, method, opt);
      std::printf("%s: mean %.4f, reference %.4f\n", method, mean, ref_mean);
      EXPECT_NEAR(mean, ref_mean, 0.01) << method;
    }
  }
}

TEST(Baselines, BadOptionsNameTheirFlag) {
  MethodOptions o;
  o.specaa.sigma2 = -1;
  EXPECT_THROW(
      {
        try {
          make_method("specaa", o);
        } catch (const Error& e) {
          EXPECT_STREQ(e.what(), "--specaa-sigma2: must be > 0");
          throw;
        }
      },
      Error);
  o = MethodOptions{};
  o.bruneton.n_max = 0.5;
  EXPECT_THROW(make_method("bruneton", o), Error);
  o = MethodOptions{};
  o.bruneton.min_variance = 0;
  EXPECT_THROW(make_method("bruneton", o), Error);
}

}  // namespace
}  // namespace sg
