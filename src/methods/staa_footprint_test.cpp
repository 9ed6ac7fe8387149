// The pixel-footprint term: `--footprint none` is the paper's method bit for bit,
// and on a one-wave scene whose glints are smaller than a pixel each footprint mode comes
// closer to the reference than the paper's centre sample; a glint smaller than a pixel keeps
// its light as it crosses the pixels (the pixel square's Gaussian, reflection_footprint.glsl).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

#include "engine/render.h"
#include "image/image_io.h"
#include "kernel/cpu/wave_sums.h"
#include "kernel/kernel_double.h"
#include "methods/kernel_inputs.h"
#include "methods/method.h"
#include "methods/staa.h"
#include "methods/supersample.h"
#include "metrics/metrics.h"
#include "scene/scene.h"
#include "shading/kernel_frame.h"
#include "testing/path_tables.h"
#include "testing/testing.h"

namespace sg {
namespace {

// Images of the method of Part 2 (tests/golden/), rendered with
//   sunglint render scenes/S.json -m staa --footprint none --wave-remainder each --width 96
//            --frame 4 -o staa_S_96x54_f4.pfm
//   sunglint render scenes/S.json -m staa --footprint none --ndf uniform --kernels 3
//            --segments 2 --width 96 --frame 7 -o staa_uniform_k3_s2_S_96x54_f7.pfm
// They were first made by the commit before the footprint term. The speed-ups that followed
// (shared wave phases, vectorised sums, the fallback's 30-node quadrature) moved pixels by
// rounding or by the quadrature's stated 4e-6, and the images were regenerated with them;
// so did the move of the shading into the kernel (src/kernel/: waves sorted by |k|, phases
// camera-relative, the kernel's erfc): 1.4e-11 RMSE from the previous images, RMSE against
// a 12x12x8 reference unchanged to six digits (0.00162154, 0.000775986, 0.000326899,
// 0.000345487). The split of the pixels that the horizon crosses (kernel/horizon_coverage.glsl)
// moved high's horizon row by up to 3.6e-15 (its light there is ~0) and the images were
// regenerated. One sinc for the kernel (special.glsl, sinc_from: sin(D) / D where Appendix
// A's factors multiplied by 1 / D) moved one pixel of high by 1.2e-18, and high's image was
// regenerated. The path tables' 8 MiB layout (shading/path_table.h: half the u axis, the
// radial axes crowded about the disk's edge, 192 x 168 x 64) moved high's frame 4 by up to
// 1.11e-6 (3.3e-8 RMSE; the other three images unchanged), and it was regenerated. The
// fallback's average along the path in closed form in time (gaussian_disk_mass_along, for
// a fixed camera too, where the midpoint rule took up to 32 instants) moved the images by
// 3.5e-7 to 2.8e-6 RMSE (at most 2.0e-4), each a little closer to a 12x12x8 reference
// (RMSE 0.00155522 -> 0.00155489, 0.000771289 -> 0.000770255, 0.000222655 -> 0.000222623,
// 0.000243916 -> 0.00024384), and they were regenerated. The CPU engine's SIMD lanes
// running the kernel's own per-wave text (kernel/cpu/lane_passes.inc, where a hand-written
// mirror of it fused other multiply-adds) moved one pixel of high's frame 4 by 6.7e-18, and
// it was regenerated. The fallback's quadrature along the path taking as many nodes as its
// integrand's features ask (kernel/gaussian.glsl, 8-point rules on sub-intervals, where 30
// nodes a piece erred by up to 8e-6) moved the four images by 3e-15 to 1.5e-11 RMSE (at
// most 7e-10), and they were regenerated. A segment of length 0 taking that closed form's
// limit (not the instant's 30-node quadrature) and up to 9 sub-intervals for the marginal
// moved simple's frame 4 by 7.9e-8 RMSE (at most 5.7e-6; its RMSE against a 48x48x8
// reference 0.00156045 both ways) and the others by at most 7.3e-12 RMSE; regenerated.
// The Mahalanobis cull before the light's integrators (staa.glsl, staa_light_share: a mass
// below 1.3e-14 left out) moved high's frame 4 by 6.0e-13 RMSE (at most 4.3e-11) and the
// other three by at most 2.6e-18 RMSE; regenerated. Any later change to the `none`
// path fails here: regenerate only for a deliberate change.
//
// Bit for bit holds between optimised builds (Release, the images' build) on processors
// whose vectorised sums over the waves (kernel/cpu/wave_sums.h) run on the images'
// instruction set, AVX-512 ("AVX3"): they sum in a fixed order there. The sanitizer build
// (-O1 with AddressSanitizer) contracts other multiply-adds, and another instruction set
// rounds the sines differently, which moves the last bits of a few pixels; there the
// images must agree to 1e-6 (absolute, values of order 1).
constexpr const char* kGoldenTarget = "AVX3";

void expect_same_image(const Image& a, const Image& golden, const char* what) {
  ASSERT_EQ(a.size(), golden.size()) << what;
#if defined(__OPTIMIZE__) && !defined(__SANITIZE_ADDRESS__)
  const char* build = "optimised";
  const bool bit_exact = std::strcmp(wave_simd::target(), kGoldenTarget) == 0;
#else
  const char* build = "unoptimised or sanitized";
  const bool bit_exact = false;
#endif
  double worst = 0;
  for (size_t k = 0; k < a.size(); ++k)
    worst = std::max(worst, std::fabs(double(a.data[k]) - double(golden.data[k])));
  if (bit_exact) {
    EXPECT_EQ(0, std::memcmp(a.data.data(), golden.data.data(), a.size() * sizeof(float)))
        << what << ": max |difference| " << worst;
    return;
  }
  std::printf("%s: %s build on %s, max |difference| %.3g\n", what, build, wave_simd::target(),
              worst);
  EXPECT_LE(worst, 1e-6) << what;
}

TEST(StaaFootprint, NoneIsThePaperMethodBitForBit) {
  for (const char* scene : {"simple", "high"}) {
    Scene s = testing::project_scene(scene);
    s.width = 96;
    s.height = 54;
    SceneModel m(s);
    StaaOptions a;
    a.footprint = FootprintMode::none;
    StaaOptions b = a;
    // The paper's per-pixel NDF sums every wave's Appendix A moments: the O(1) remainder,
    // their limit for the waves far past the pixel's Nyquist rate, is off. The uniform NDF's
    // remainder is the sum itself: on.
    a.wave_remainder = false;
    b.ndf = NdfMode::uniform;
    b.kernels = 3;
    b.segments = 2;
    const std::string dir = sg::testing::source_dir() + "/tests/golden/";
    StaaMethod ma(a, testing::path_tables()), mb(b, testing::path_tables());
    Image ia = render_frame(m, ma, 4, {}), ib = render_frame(m, mb, 7, {});
    Image ga = read_image(dir + "staa_" + scene + "_96x54_f4.pfm");
    Image gb = read_image(dir + "staa_uniform_k3_s2_" + scene + "_96x54_f7.pfm");
    expect_same_image(ia, ga, scene);
    expect_same_image(ib, gb, scene);
  }
}

TEST(StaaFootprint, EachModeBeatsTheCentreSampleOnOneWave) {
  // The simple scene's third wave alone (wavelength 6 m, slope amplitude 0.1) at 160x90:
  // near the camera it is resolved (< 0.2 cycles per pixel) but its glints are smaller
  // than a pixel, the case the footprint term is for.
  Scene s = testing::project_scene("simple");
  s.surface.waves = {s.surface.waves[2]};
  s.width = 160;
  s.height = 90;
  SceneModel m(s);
  StratifiedMethod ref("reference", {{12, 12, 8}, false});
  std::vector<Image> r;
  const int frames = 6;
  for (int f = 0; f < frames; ++f)
    r.push_back(render_frame(m, ref, f, {}));
  double rmse[3];
  const FootprintMode modes[3] = {FootprintMode::none, FootprintMode::gaussian,
                                  FootprintMode::exact};
  for (int k = 0; k < 3; ++k) {
    StaaOptions o;
    o.footprint = modes[k];
    StaaMethod staa(o, testing::path_tables());
    std::vector<Image> a;
    for (int f = 0; f < frames; ++f)
      a.push_back(render_frame(m, staa, f, {}));
    rmse[k] = compare_sequences(a, r).rmse;
  }
  std::printf("one wave, 160x90, frames 0-5: rmse none %.5f gaussian %.5f exact %.5f\n", rmse[0],
              rmse[1], rmse[2]);
  EXPECT_LT(rmse[1], 0.7 * rmse[0]);
  EXPECT_LT(rmse[2], 0.7 * rmse[0]);
}

// The footprint term along the path (kernel/staa.glsl, staa_footprint_covariance) takes
// each instant's Hessian: the pass's sums at instant k are the water's Hessian at time t_k
// (finite differences of the gradient), vectorised and not.
TEST(StaaFootprint, InstantsHessiansAreTheWaterHessianAtTheirTimes) {
  Scene s = testing::project_scene("simple");
  s.width = 160;
  s.height = 90;
  s.animation.fps = 4;  // a quarter-second shutter: the curvature turns over it
  const SceneModel m(s);
  for (const int K : {1, 3}) {
    KernelInputsD in;
    build_kernel_inputs(m, frame_time(s, 2), K, 0, in);
    const kd::Frame& f = in.frame;
    StaaOptions o;
    o.alias_start = 1e6;  // every wave resolved
    o.alias_end = 2e6;
    const kd::StaaParams p = staa_kernel_params<kd::StaaParams>(o);
    double worst = 0, scale = 0, turned = 0;
    for (const bool vectorised : {true, false}) {
      const kd::WaveBuffer w = wave_buffer(in, vectorised);
      for (int j = 50; j < 90; j += 9) {
        for (int i = 5; i < 160; i += 31) {
          const kd::Footprint fp = kd::pixel_footprint(w, f, i + 0.5, j + 0.5, 0.0, false);
          ASSERT_TRUE(fp.hit);
          const kd::PathViews v = kd::path_views_fixed(fp.point, fp.view);
          const kd::StaaSums sums = kd::staa_wave_pass(w, f, p, fp, v);
          turned = std::max(turned, length(sums.hess[0] - sums.hess[K]));
          for (int k = 0; k <= K; ++k) {
            const double dt = kd::path_instant_dt(f, k), e = 1e-4;
            const kd::vec2 gx = (kd::water_gradient(w, f, fp.point.x + e, fp.point.z, dt) -
                                 kd::water_gradient(w, f, fp.point.x - e, fp.point.z, dt)) /
                                (2 * e);
            const kd::vec2 gz = (kd::water_gradient(w, f, fp.point.x, fp.point.z + e, dt) -
                                 kd::water_gradient(w, f, fp.point.x, fp.point.z - e, dt)) /
                                (2 * e);
            const kd::vec3 h = sums.hess[k];
            worst = std::max({worst, std::fabs(h.x - gx.x), std::fabs(h.y - gz.x),
                              std::fabs(h.y - gx.y), std::fabs(h.z - gz.y)});
            scale = std::max({scale, std::fabs(gx.x), std::fabs(gz.y)});
          }
        }
      }
    }
    std::printf(
        "K %d: the instants' Hessians within %.2e of the finite differences (largest %.2e; "
        "instant 0 from the display time's by up to %.2e)\n",
        K, worst, scale, turned);
    EXPECT_GT(scale, 0.01);
    EXPECT_GT(turned, 0.1 * scale);  // the curvature turns: the display time's would fail
    EXPECT_LT(worst, 1e-6 * std::max(1.0, scale) + 1e-7);
  }
}

// A glint smaller than a pixel near the camera over displaced water (tests/scenes/
// displaced-swell.json at 160x90, frame 0, pixel (91, 83)): the reflection's path crosses
// the disk halfway through the shutter, where the resolved waves' curvature is 2 to 4
// times the display time's. The stored reference (tests/data/displaced-targets/, 24x24x1)
// has 0.0399 (supersample 32x32x4: 0.0369). With the display time's footprint alone
// `staa` gave 0.106; with the footprint along the path, measured 0.047.
TEST(StaaFootprint, FootprintAlongThePathOnANearGlint) {
  Scene s = load_scene(testing::source_dir() + "/tests/scenes/displaced-swell.json");
  s.width = 160;
  s.height = 90;
  const SceneModel m(s);
  const Image ref =
      read_image(testing::source_dir() + "/tests/data/displaced-targets/swell_00.exr");
  const Image var =
      read_image(testing::source_dir() + "/tests/data/displaced-targets/swell_variance_00.exr");
  StaaMethod staa(StaaOptions{}, testing::path_tables());
  const Image a = render_frame(m, staa, 0, {});
  const double r = ref.at(91, 83, 0), se = std::sqrt(var.at(91, 83, 0)), v = a.at(91, 83, 0);
  std::printf("near glint: staa %.4f, reference %.4f (standard error %.4f)\n", v, r, se);
  EXPECT_GT(r, 0.03);
  EXPECT_LT(std::fabs(v - r), 0.25 * r + 3 * se);
}

// A glint of one long swell (66 m; tests/scenes/subpixel-glint.json, a camera 7.6 m up,
// 64x36 pixels of 1.5 degrees, the sun 14 degrees up), smaller than the pixel it lies in and
// moving by one pixel over the 60 frames: the frame's light is the glint's, 0.091 to 0.110
// of a pixel in the reference. The pixel square taken as the Gaussian of the box's own
// variance (1/12) gave 0.48 to 1.71 times the reference's light as the glint moved across
// the pixel (1.66 times at frame 0, where it lies near the pixel's centre), and RMSE 6.5e-4
// over the 60 frames; the kernel's variance (footprint_box_variances) 0.67 to 1.39 times,
// RMSE 5.5e-4.
TEST(StaaFootprint, ASubPixelGlintKeepsItsLightAcrossThePixels) {
  const SceneModel m(load_scene(testing::source_dir() + "/tests/scenes/subpixel-glint.json"));
  MethodOptions o;
  o.samples = SampleCounts{24, 24, 1};
  o.samples_given = true;
  std::unique_ptr<Method> ref = make_method("reference", testing::with_tables(o));
  StaaMethod staa(StaaOptions{}, testing::path_tables());
  auto total = [](const Image& im) {
    double t = 0;
    for (int j = 0; j < im.height; ++j)
      for (int i = 0; i < im.width; ++i)
        t += im.at(i, j, 0);
    return t;
  };
  double lo = 1e9, hi = 0;
  for (int f = 0; f < 60; f += 2) {
    const double r = total(render_frame(m, *ref, f, {})), a = total(render_frame(m, staa, f, {}));
    ASSERT_GT(r, 0.08) << "frame " << f;
    lo = std::min(lo, a / r);
    hi = std::max(hi, a / r);
  }
  std::printf("a sub-pixel glint: staa's light over the reference's %.3f to %.3f\n", lo, hi);
  EXPECT_GT(lo, 0.6);
  EXPECT_LT(hi, 1.5);
}

}  // namespace
}  // namespace sg
