// The visible light disk over a pixel (kernel/disk_coverage.glsl) against brute force: the
// share of a dense grid of rays through the pixel square that the disk test contains, for
// pixels across the disk's rim, inside it and beside it, a sun and a larger moon-like disk,
// and cameras looking at the light straight and at an angle; float against double.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "kernel/kernel_double.h"
#include "kernel/kernel_float.h"
#include "scene/model.h"
#include "shading/kernel_frame.h"
#include "testing/testing.h"

namespace sg {
namespace {

// The share of n x n stratified ray centres of pixel (i, j) inside the disk.
double brute_coverage(const kd::Camera& c, const kd::Light& l, int i, int j, int n) {
  long in = 0;
  for (int a = 0; a < n; ++a) {
    for (int b = 0; b < n; ++b) {
      const kd::vec3 d = kd::camera_direction(c, i + (a + 0.5) / n, j + (b + 0.5) / n);
      in += kd::light_contains(l, normalize(d));
    }
  }
  return double(in) / (double(n) * n);
}

struct View {
  const char* what;
  double radius_deg, look_off_deg;  // disk radius; camera axis off the light by this much
};

TEST(DiskCoverage, MatchesBruteForceAcrossTheRim) {
  for (const View v : {View{"sun, centred", 0.27, 0.0}, View{"sun, 12 degrees off", 0.27, 12.0},
                       View{"large disk, 25 degrees off", 2.0, 25.0}}) {
    Scene s = testing::small_scene({}, 320, 180);
    const double el = 10 * kPi / 180;
    s.light.direction = vec3(0, std::sin(el), -std::cos(el));
    s.light.angular_radius_deg = v.radius_deg;
    s.light.visible = true;
    const double look = el + v.look_off_deg * kPi / 180;  // the camera looks above the light
    s.camera.position = vec3(0, 2, 0);
    s.camera.look_at = s.camera.position + vec3(0, std::sin(look), -std::cos(look));
    s.camera.vfov_deg = 30;
    const SceneModel m(s);
    const kd::Camera c = m.camera.kernel_camera();
    const kd::Light l = m.light.kernel_light();
    // The pixel of the light's centre, and a window around it that spans the disk.
    double pcx = 0, pcy = 0;
    ASSERT_TRUE(m.camera.project(m.light.L, pcx, pcy)) << v.what;
    const double r_px = std::tan(v.radius_deg * kPi / 180) / (2 * c.half_h / c.height);
    const int span = static_cast<int>(r_px) + 2;
    double worst = 0, mass = 0, brute_mass = 0;
    int partial = 0;
    for (int j = int(pcy) - span; j <= int(pcy) + span; ++j) {
      for (int i = int(pcx) - span; i <= int(pcx) + span; ++i) {
        const double exact = kd::light_pixel_coverage(c, l, i, j);
        const double brute = brute_coverage(c, l, i, j, 200);
        worst = std::max(worst, std::fabs(exact - brute));
        mass += exact;
        brute_mass += brute;
        partial += exact > 0.01 && exact < 0.99;
      }
    }
    // A 200 x 200 grid resolves a rim crossing the pixel to about 1 / 200 per crossing row.
    EXPECT_LT(worst, 0.002) << v.what;
    EXPECT_GT(partial, 4) << v.what << ": the window holds the rim";
    EXPECT_NEAR(mass, brute_mass, 1e-3 * brute_mass + 0.01) << v.what;
    // Far from the disk nothing; at its centre (for a disk of several pixels) everything.
    EXPECT_EQ(kd::light_pixel_coverage(c, l, int(pcx) + 3 * span, int(pcy)), 0.0) << v.what;
    if (r_px > 3) {
      EXPECT_DOUBLE_EQ(kd::light_pixel_coverage(c, l, int(pcx), int(pcy)), 1.0) << v.what;
    }
    // Float: what the GL engine computes, within 1e-4 of double everywhere.
    kf::Camera cf;
    cf.position = kf::vec3(c.position);
    cf.forward = kf::vec3(c.forward);
    cf.right = kf::vec3(c.right);
    cf.up = kf::vec3(c.up);
    cf.half_w = float(c.half_w);
    cf.half_h = float(c.half_h);
    cf.width = float(c.width);
    cf.height = float(c.height);
    kf::Light lf;
    lf.L = kf::vec3(l.L);
    lf.e1 = kf::vec3(l.e1);
    lf.e2 = kf::vec3(l.e2);
    lf.radius = float(l.radius);
    lf.cos_radius = float(l.cos_radius);
    lf.sin_radius = float(l.sin_radius);
    lf.tan_radius = float(l.tan_radius);
    lf.chord2 = float(l.chord2);
    lf.visible = true;
    double worst_f = 0;
    for (int j = int(pcy) - span; j <= int(pcy) + span; ++j) {
      for (int i = int(pcx) - span; i <= int(pcx) + span; ++i) {
        worst_f = std::max(worst_f, std::fabs(double(kf::float_light_pixel_coverage(cf, lf, i, j)) -
                                              kd::light_pixel_coverage(c, l, i, j)));
      }
    }
    EXPECT_LT(worst_f, 1e-4) << v.what;
    std::printf(
        "%-28s disk %.1f px: max |exact - 200x200 grid| %.2g over %d rim pixels, "
        "float - double %.2g\n",
        v.what, r_px, worst, partial, worst_f);
  }
}

TEST(DiskCoverage, InvisibleLightCoversNothing) {
  Scene s = testing::small_scene({}, 64, 36);
  s.light.visible = false;
  const SceneModel m(s);
  double pcx = 0, pcy = 0;
  ASSERT_TRUE(m.camera.project(m.light.L, pcx, pcy));
  EXPECT_EQ(kd::light_pixel_coverage(m.camera.kernel_camera(), m.light.kernel_light(), int(pcx),
                                     int(pcy)),
            0.0);
}

}  // namespace
}  // namespace sg
