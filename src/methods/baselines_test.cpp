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
#include <vector>

#include "base/error.h"
#include "engine/render.h"
#include "math/rng.h"
#include "methods/method.h"
#include "methods/stratified.h"
#include "testing/calm_water.h"
#include "testing/path_tables.h"
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
  auto meth = make_method(method, testing::with_tables(MethodOptions{}));
  FrameContext ctx{m, frame_time(s, 0), 0};
  meth->begin_frame(ctx);
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
  auto meth = make_method(method, testing::with_tables(o));
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
  Scene s = testing::displaced_variant(testing::project_scene("simple"), 0.1);
  set_image_size(s, 160, 90);
  SceneModel m(s);
  MethodOptions ref_opt;
  ref_opt.samples = {3, 3, 2};
  auto ref = make_method("reference", testing::with_tables(ref_opt));
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

// Per band of 5 rows (80 x 45 image): the sums of bruneton's values and the reference's,
// and the reference's standard error (each of its samples sees the light or not: a sum S
// over N samples per pixel is H / N for H hits, with error sqrt(H) / N).
struct Band {
  int row = 0;
  double bruneton = 0, reference = 0, se = 0;
};
std::vector<Band> glitter_bands(Scene s, int spp_side) {
  SceneModel m(s);
  MethodOptions ref_opt;
  ref_opt.samples = {spp_side, spp_side, 1};  // the waves do not move (c = 0): space only
  auto ref = make_method("reference", testing::with_tables(ref_opt));
  auto bru = make_method("bruneton", testing::with_tables(MethodOptions{}));
  const Image r = render_frame(m, *ref, 0, RenderSettings{});
  const Image b = render_frame(m, *bru, 0, RenderSettings{});
  std::vector<Band> bands;
  for (int j0 = s.height / 2; j0 < s.height; j0 += 5) {
    Band band{j0};
    for (int j = j0; j < std::min(j0 + 5, s.height); ++j) {
      for (int i = 0; i < s.width; ++i) {
        band.reference += r.at(i, j);
        band.bruneton += b.at(i, j);
      }
    }
    const double N = double(spp_side) * spp_side;
    band.se = std::sqrt(band.reference * N) / N;
    bands.push_back(band);
  }
  return bands;
}

TEST(Baselines, BrunetonMatchesTheReferenceOnUnresolvedWaves) {
  // Sixteen short waves (wavelengths 2.5 to 5 cm, slope variance 0.01) that no pixel
  // resolves: every weight w_n is 0, the normals are flat and all slopes are in the BRDF.
  // Bruneton et al. validate their model by the total radiance per image line (Sec. 7.2,
  // Fig. 10), and so does this test, per band of 5 rows, against 8x8x1 samples per pixel,
  // on displaced water: the Ross BRDF counts each facet by its area projected towards the
  // viewer and masks and shadows it (Smith), which a displaced height field does too.
  // Within 4 standard errors of the reference's noise plus 8% for the model (Gaussian
  // slopes for a sum of 16 sines, the BRDF constant over the light, the tangent frame).
  std::vector<Wave> waves;
  Pcg32 rng(77, 7);
  for (int k = 0; k < 16; ++k) {
    const double kk = kTwoPi / (0.025 + 0.025 * rng.uniform()), ang = kTwoPi * rng.uniform();
    const double A = std::sqrt(2 * 0.01 / 16) / kk;  // A^2 k^2 / 2 = 0.01 / 16
    waves.push_back(Wave{A, {kk * std::cos(ang), kk * std::sin(ang)}, 0.0, kTwoPi * rng.uniform()});
  }
  Scene s = testing::small_scene(waves, 80, 45);
  s.light.angular_radius_deg = 1.0;  // more of the glitter's samples hit it
  s.surface.geometry = Geometry::displaced;
  double total_b = 0, total_r = 0, total_var = 0;
  for (const Band& band : glitter_bands(s, 8)) {
    std::printf("displaced rows %d-%d: bruneton %.3f, reference %.3f +- %.3f\n", band.row,
                band.row + 4, band.bruneton, band.reference, band.se);
    EXPECT_NEAR(band.bruneton, band.reference, 4 * band.se + 0.08 * band.reference) << band.row;
    total_b += band.bruneton;
    total_r += band.reference;
    total_var += band.se * band.se;
  }
  EXPECT_GT(total_r, 2.0);
  EXPECT_NEAR(total_b, total_r, 4 * std::sqrt(total_var) + 0.05 * total_r);
  // The same waves on flat water (the spec's default: the waves bend the normal only, so
  // every point of the plane counts alike and nothing is masked): printed, not held; the
  // projected-area weighting brightens Bruneton's glitter towards the horizon there.
  s.surface.geometry = Geometry::flat;
  for (const Band& band : glitter_bands(s, 16)) {
    std::printf("flat rows %d-%d: bruneton %.3f, reference %.3f +- %.3f\n", band.row, band.row + 4,
                band.bruneton, band.reference, band.se);
  }
}

TEST(Baselines, BadOptionsNameTheirFlag) {
  MethodOptions o;
  o.specaa.sigma2 = -1;
  EXPECT_THROW(
      {
        try {
          make_method("specaa", testing::with_tables(o));
        } catch (const Error& e) {
          EXPECT_STREQ(e.what(), "--specaa-sigma2: must be > 0");
          throw;
        }
      },
      Error);
  o = MethodOptions{};
  o.bruneton.n_max = 0.5;
  EXPECT_THROW(make_method("bruneton", testing::with_tables(o)), Error);
  o = MethodOptions{};
  o.bruneton.min_variance = 0;
  EXPECT_THROW(make_method("bruneton", testing::with_tables(o)), Error);
}

}  // namespace
}  // namespace sg
