// `specaa`'s kernel (kernel/specaa.glsl): the chain-rule derivative of the projected half
// vector against finite differences, the tangent-slope-to-NDF-plane Jacobian against finite
// differences, and the kernel's variance against a direct evaluation (the covariance of the
// projected half vector under a Gaussian pixel filter, sampled through the exact camera,
// water and frame). The water here is the direct sum of sines (testing/direct_waves.h), an
// independent check of the kernel's.
#include <gtest/gtest.h>

#include <cmath>

#include "kernel/kernel_double.h"
#include "math/rng.h"
#include "scene/model.h"
#include "shading/water_geometry.h"
#include "testing/direct_waves.h"

namespace sg {
namespace {

using kd::projected_half_vector;
using kd::projected_half_vector_derivative;
using kd::ShadingFrame;
using kd::specaa_kernel_covariance;
using kd::specaa_tangent_to_ndf_plane;
using kd::water_shading_frame;

vec3 hessian3(const Hessian& H) {
  return vec3(H.xx, H.xz, H.zz);
}

const vec3 kL = normalize(vec3(0.0, 0.207912, -0.978148));

WaveField test_waves() {
  return WaveField({Wave{0.05, {0.3, -1.2}, 3.4, 0.2}, Wave{0.02, {-1.1, -0.7}, 2.1, 1.0},
                    Wave{0.01, {2.0, 1.5}, 5.0, 2.0}});
}

// h_perp at water point P (with its gradient), seen from `camera`.
vec2 h_perp_at(const WaveField& w, const vec3& camera, const vec3& P, double t) {
  return projected_half_vector(water_shading_frame(testing::direct_gradient(w, P.x, P.z, t)),
                               normalize(camera - P), kL);
}

TEST(SpecaaKernel, ShadingFrameIsOrthonormalAboutTheNormal) {
  const ShadingFrame f = water_shading_frame(vec2(0.3, -0.4));
  EXPECT_NEAR(length(f.n - normalize(vec3(-0.3, 1, 0.4))), 0, 1e-15);
  EXPECT_NEAR(dot(f.t, f.n), 0, 1e-15);
  EXPECT_NEAR(dot(f.b, f.n), 0, 1e-15);
  EXPECT_NEAR(dot(f.t, f.b), 0, 1e-15);
  EXPECT_NEAR(length(cross(f.t, f.b) - f.n), 0, 1e-15);
  EXPECT_NEAR(f.t.z, 0, 1e-15);  // along the surface's x direction
}

TEST(SpecaaKernel, HalfVectorDerivativeMatchesFiniteDifferences) {
  const WaveField w = test_waves();
  const vec3 camera(0.3, 2.5, 0.1);
  Pcg32 rng(6, 6);
  for (int k = 0; k < 200; ++k) {
    const double t = rng.uniform();
    // A point on the displaced surface and a tangent step.
    const double x = 10 * (rng.uniform() - 0.5), z = -5 - 30 * rng.uniform();
    const vec3 P(x, testing::direct_height(w, x, z, t), z);
    const vec2 g = testing::direct_gradient(w, x, z, t);
    const vec2 dxz(rng.uniform() - 0.5, rng.uniform() - 0.5);
    const vec3 dP(dxz.x, g.x * dxz.x + g.y * dxz.y, dxz.y);
    const vec2 analytic = projected_half_vector_derivative(
        camera, P, g, hessian3(testing::direct_hessian(w, x, z, t)), dP, kL);
    // Central differences along the surface curve (x, h(x, z), z) + s (dx, ., dz).
    const double e = 1e-5;
    auto at = [&](double s) {
      const double xs = x + s * dxz.x, zs = z + s * dxz.y;
      return h_perp_at(w, camera, vec3(xs, testing::direct_height(w, xs, zs, t), zs), t);
    };
    const vec2 fd = (at(e) - at(-e)) / (2 * e);
    EXPECT_LT(length(analytic - fd), 1e-7 * std::max(1.0, length(fd))) << k;
  }
}

TEST(SpecaaKernel, TangentSlopeJacobianMatchesFiniteDifferences) {
  Pcg32 rng(7, 7);
  for (int k = 0; k < 100; ++k) {
    const vec2 g(0.8 * (rng.uniform() - 0.5), 0.8 * (rng.uniform() - 0.5));
    const ShadingFrame f = water_shading_frame(g);
    auto q = [&](const vec2& s) {
      const vec3 m = f.n - s.x * f.t - s.y * f.b;
      return vec2(m.x / m.y, m.z / m.y);
    };
    const double e = 1e-6;
    const vec2 cx = (q(vec2(e, 0)) - q(vec2(-e, 0))) / (2 * e);
    const vec2 cz = (q(vec2(0, e)) - q(vec2(0, -e))) / (2 * e);
    const mat2 J = specaa_tangent_to_ndf_plane(f);
    EXPECT_LT(length(J[0] - cx), 1e-8);
    EXPECT_LT(length(J[1] - cz), 1e-8);
    EXPECT_LT(length(q(vec2(0.0)) - vec2(-g.x, -g.y)), 1e-15);  // the centre is -gradient
  }
}

TEST(SpecaaKernel, FullKernelIsTheVarianceOfTheHalfVectorUnderTheGaussianPixelFilter) {
  // Direct evaluation: pixel offsets drawn from the kernel's Gaussian pixel filter
  // (variance sigma^2 per axis, pixels^2), each traced to the water, shaded with its own
  // normal and frame, and its h_perp taken; the sample covariance of h_perp against the
  // kernel sigma^2 D D^T (no clamp), D from the chain-rule derivatives. The filter is
  // narrowed to sigma^2 = 0.01 (a tenth of a pixel) so that h_perp is linear across it:
  // the test is of the kernel's variance formula, not of the water's curvature.
  Scene s;
  s.width = 320;
  s.height = 180;
  s.camera = CameraDesc{{0, 2.5, 0}, {0, 0, -60}, {0, 1, 0}, 40, {}};
  s.light = LightDesc{{0, 0.207912, -0.978148}, 0.27, Rgb(1.0), false};
  s.surface.waves = {Wave{0.05, {0.3, -1.2}, 3.4, 0.2}, Wave{0.02, {-1.1, -0.7}, 2.1, 1.0}};
  const SceneModel m(s);
  const double t = 0.3, sigma2 = 0.01;
  for (const vec2 px : {vec2(100.5, 150.5), vec2(200.5, 120.5)}) {
    const PixelFootprint fp = pixel_footprint(m, px.x, px.y, t);
    ASSERT_TRUE(fp.hit);
    const vec3 P = fp.point;
    const vec2 g = testing::direct_gradient(m.waves, P.x, P.z, t);
    const vec3 H = hessian3(testing::direct_hessian(m.waves, P.x, P.z, t));
    const vec2 ddx = projected_half_vector_derivative(m.camera.position(), P, g, H, fp.dp_dpx, kL);
    const vec2 ddy = projected_half_vector_derivative(m.camera.position(), P, g, H, fp.dp_dpy, kL);
    const mat2 kernel = specaa_kernel_covariance(ddx, ddy, sigma2, 1e9, true);
    Pcg32 rng(9, 9);
    const int n = 20000;
    vec2 mean(0.0);
    double sxx = 0, sxy = 0, syy = 0;
    const vec2 h0 = h_perp_at(m.waves, m.camera.position(), P, t);
    for (int k = 0; k < n; ++k) {
      // Box-Muller.
      const double r = std::sqrt(-2 * std::log(1 - rng.uniform())), a = kTwoPi * rng.uniform();
      const vec2 off = std::sqrt(sigma2) * r * vec2(std::cos(a), std::sin(a));
      const RayHit hit =
          intersect_flat(m.camera.position(), m.camera.direction(px.x + off.x, px.y + off.y));
      const vec2 h = h_perp_at(m.waves, m.camera.position(), hit.point, t) - h0;
      mean += h / double(n);
      sxx += h.x * h.x / n;
      sxy += h.x * h.y / n;
      syy += h.y * h.y / n;
    }
    sxx -= mean.x * mean.x;
    sxy -= mean.x * mean.y;
    syy -= mean.y * mean.y;
    // Monte-Carlo standard error of a variance ~ var sqrt(2 / n) = 1% of it; allow 4%.
    EXPECT_NEAR(kernel[0][0], sxx, 0.04 * sxx) << px.x;
    EXPECT_NEAR(kernel[1][1], syy, 0.04 * syy) << px.x;
    EXPECT_NEAR(kernel[0][1], sxy, 0.04 * std::sqrt(sxx * syy)) << px.x;
  }
}

TEST(SpecaaKernel, RectKernelIsTheListingsBoundingRectangle) {
  // Tokuyoshi & Kaplanyan's listing: alpha^2 = min(2 sigma^2 (|ddx| + |ddy|)^2, kappa) per
  // axis, and slope variance alpha^2 / 2.
  const vec2 ddx(0.01, -0.002), ddy(0.004, 0.003);
  const mat2 k = specaa_kernel_covariance(ddx, ddy, 0.25, 0.18, false);
  EXPECT_NEAR(k[0][0], 0.25 * sqr(0.014), 1e-18);
  EXPECT_NEAR(k[1][1], 0.25 * sqr(0.005), 1e-18);
  EXPECT_EQ(k[0][1], 0.0);
  // It bounds the full kernel's diagonal, and equals it when one derivative vanishes.
  const mat2 f = specaa_kernel_covariance(ddx, ddy, 0.25, 0.18, true);
  EXPECT_GE(k[0][0], f[0][0]);
  EXPECT_GE(k[1][1], f[1][1]);
  const mat2 k1 = specaa_kernel_covariance(ddx, vec2(0.0), 0.25, 0.18, false);
  const mat2 f1 = specaa_kernel_covariance(ddx, vec2(0.0), 0.25, 0.18, true);
  EXPECT_NEAR(k1[0][0], f1[0][0], 1e-18);
  EXPECT_NEAR(k1[1][1], f1[1][1], 1e-18);
  // The clamp: alpha^2 <= kappa, so slope variance <= kappa / 2, for both shapes.
  const vec2 big(3.0, -2.0);
  const mat2 kc = specaa_kernel_covariance(big, big, 0.25, 0.18, false);
  EXPECT_NEAR(kc[0][0], 0.09, 1e-15);
  EXPECT_NEAR(kc[1][1], 0.09, 1e-15);
  const mat2 fc = specaa_kernel_covariance(big, vec2(0.5, 1.0), 0.25, 0.18, true);
  EXPECT_NEAR(fc[0][0] + fc[1][1], 0.18, 1e-12);  // both principal variances at 0.09
}

}  // namespace
}  // namespace sg
