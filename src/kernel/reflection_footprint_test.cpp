// The kernel's reflection footprint (kernel/reflection_footprint.glsl): the light-plane
// derivatives dP/dpx, dP/dpy of the resolved waves' reflection against finite differences
// of neighbouring image-plane points, each re-traced (new water point, new normal, new
// view). The waves' gradient and Hessian come from the direct sums (testing/direct_waves.h),
// with some waves weighted, as the resolved share of a pixel's waves is. The pixel square's
// Gaussian (footprint_box_variances) against direct integration of the box it stands for.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

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

// The box [-1/2, 1/2] convolved with N(0, s^2) at x (the pixel's response, along one of its
// axes, to light of spread s pixels at offset x), and N(0, s^2 + v) at x (the Gaussian's).
double box_response(double x, double s) {
  if (s == 0) return std::fabs(x) < 0.5 ? 1.0 : 0.0;
  return 0.5 *
         (std::erf((x + 0.5) / (std::sqrt(2.0) * s)) - std::erf((x - 0.5) / (std::sqrt(2.0) * s)));
}
double gaussian_response(double x, double s, double v) {
  const double t = s * s + v;
  return std::exp(-x * x / (2 * t)) / std::sqrt(2 * M_PI * t);
}

// The relative squared error over the light's offsets of the square pixel's Gaussian stand-in
// of variance v per axis, in 2D: || b (x) b - g (x) g || / || b (x) b || with b the box's
// response and g the Gaussian's (a product's norms and inner products are the factors').
double square_error(double s, double v) {
  const double h = 0.002;
  double bb = 0, gg = 0, bg = 0;
  for (double x = -5 + h / 2; x < 5; x += h) {
    const double b = box_response(x, s), g = gaussian_response(x, s, v);
    bb += b * b * h;
    gg += g * g * h;
    bg += b * g * h;
  }
  return std::sqrt(std::max(bb * bb + gg * gg - 2 * bg * bg, 0.0) / (bb * bb));
}

// The variance that matches the peaks: N(0, s^2 + v) at 0 equal to the box convolved with
// N(0, s^2) at 0, erf(1 / (2 sqrt(2) s)) (1 at s = 0).
double peak_variance(double s) {
  const double peak = s > 0 ? std::erf(1 / (2 * std::sqrt(2.0) * s)) : 1.0;
  return 1 / (2 * M_PI * peak * peak) - s * s;
}

// The variance the kernel gives each axis (footprint_box_variances): within 0.001 of the
// least squared error a Gaussian of the box's response can have (searched), where the box's
// own 1/12 errs by 0.06 more at s = 0 and the peaks' match by 0.04: light narrower than the
// pixel, its offset anywhere. Its limits: 1/12 + 0.0335 at s = 0, 1/12 as s grows.
TEST(ReflectionFootprint, BoxVarianceNearTheLeastSquaredError) {
  EXPECT_NEAR(kd::footprint_box_variances(kd::mat2(1.0), kd::mat2(0.0)).x, 1.0 / 12 + 0.0335,
              1e-15);
  EXPECT_NEAR(kd::footprint_box_variances(kd::mat2(1.0), kd::mat2(1e6)).x, 1.0 / 12, 1e-8);
  for (double s : {0.0, 0.05, 0.1, 0.2, 0.3, 0.5, 0.8}) {
    // An axis-aligned footprint of one light-plane unit a pixel: S = s^2 I.
    const double v = kd::footprint_box_variances(kd::mat2(1.0), kd::mat2(s * s)).x;
    double best = 1e9;
    for (double u = 1.0 / 12; u <= 1 / (2 * M_PI); u += 0.0005)
      best = std::min(best, square_error(s, u));
    const double e = square_error(s, v);
    std::printf("s %.2f: v %.4f, squared error %.4f (least %.4f, 1/12's %.4f, the peaks' %.4f)\n",
                s, v, e, best, square_error(s, 1.0 / 12), square_error(s, peak_variance(s)));
    EXPECT_LE(e, best + 0.001) << "s " << s;
    if (s <= 0.1) {
      EXPECT_LT(e, square_error(s, 1.0 / 12) - 0.05) << "s " << s;
      EXPECT_LT(e, square_error(s, peak_variance(s)) - 0.03) << "s " << s;
    }
  }
}

// The spread in the pixel's own axes is the diagonal of D^-1 S D^-T, for a sheared and
// rotated footprint and an elongated spread; a degenerate footprint takes the box's 1/12.
TEST(ReflectionFootprint, BoxVariancesTakeTheSpreadInThePixelsAxes) {
  const kd::mat2 D(0.03, -0.011, 0.007, 0.052);  // columns dP/dpx, dP/dpy
  const kd::mat2 S(4e-4, 1.5e-4, 1.5e-4, 1.2e-4);
  const kd::mat2 Di = inverse(D);
  const kd::mat2 C = Di * S * transpose(Di);
  const kd::vec2 v = kd::footprint_box_variances(D, S);
  EXPECT_NEAR(v.x, kd::footprint_box_variances(kd::mat2(1.0), kd::mat2(C[0][0])).x, 1e-14);
  EXPECT_NEAR(v.y, kd::footprint_box_variances(kd::mat2(1.0), kd::mat2(C[1][1])).x, 1e-14);
  EXPECT_GT(std::fabs(v.x - v.y), 1e-3);  // the axes differ here
  const kd::vec2 flat = kd::footprint_box_variances(kd::mat2(0.0), S);
  EXPECT_NEAR(flat.x, 1.0 / 12, 1e-15);
  const kd::vec2 none = kd::footprint_box_variances(D, kd::mat2(0.0));
  EXPECT_TRUE(std::isfinite(none.x) && std::isfinite(none.y));
  const kd::mat2 cov = kd::footprint_box_covariance(D, v);
  const kd::mat2 direct = D * kd::mat2(v.x, 0.0, 0.0, v.y) * transpose(D);
  for (int c = 0; c < 2; ++c)
    for (int r = 0; r < 2; ++r)
      EXPECT_NEAR(cov[c][r], direct[c][r], 1e-15);
}

}  // namespace
}  // namespace sg
