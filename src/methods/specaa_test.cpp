// specaa: the analytic screen-space derivatives of the projected half vector against the
// quad finite differences of neighbouring pixel centres (flat and displaced water), quad
// derivatives shared within a quad, and tiles equal to pixels in both derivative modes.
#include "methods/specaa.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "engine/render.h"
#include "kernel/kernel_double.h"
#include "math/rng.h"
#include "testing/testing.h"
#include "testing/tiles.h"

namespace sg {
namespace {

using kd::SpecaaSample;

// The kernel's specaa functions on model m's inputs at time t (camera-relative points).
class Kernel {
 public:
  Kernel(const SceneModel& m, double t)
      : in_(1, Precision::float64, 0.0, 1, true, cascade_reads_of("specaa")) {
    in_.build(FrameContext{m, FrameTime{0, t, t}, 0});
  }
  const kd::Frame& frame() const { return in_.d().frame; }
  SpecaaSample sample(double px, double py) const {
    return kd::specaa_sample(wave_buffer(in_.d()), frame(), px, py);
  }
  // (ddx, ddy): the analytic derivatives of h_perp at a sample.
  std::pair<vec2, vec2> derivatives(const SpecaaSample& s) const {
    const kd::vec4 d = kd::specaa_analytic_derivatives(wave_buffer(in_.d()), frame(), s);
    return {vec2(d.x, d.y), vec2(d.z, d.w)};
  }
  RadianceWeights lobe(const SpecaaSample& s, const vec2& ddx, const vec2& ddy,
                       const SpecaaOptions& o) const {
    return kd::specaa_lobe_weights(frame(), specaa_kernel_params<kd::SpecaaParams>(o), s, ddx, ddy);
  }

 private:
  KernelFrameInputs in_;
};

// Over the pixel pairs of a window, the one-pixel difference h_perp(i + 1) - h_perp(i) (what
// a quad gives) against the analytic derivative at the midpoint of the two centres, where
// the difference is accurate to second order. Returns the worst error relative to the
// window's largest derivative. On displaced water some pairs have no derivative to
// compare: a crest hides the water behind it (the hit point jumps), or the rays graze a
// crest (the footprint changes by more than 20% across the pair); they are counted in
// `jumps`.
double quad_vs_analytic(const SceneModel& m, double t, int i0, int j0, int w, int h, int& jumps) {
  double worst = 0, scale = 0;
  const Kernel k(m, t);
  auto smooth = [](const SpecaaSample& a, const SpecaaSample& mid, const SpecaaSample& b, bool x) {
    auto dp = [x](const SpecaaSample& s) { return x ? s.dp_dpx : s.dp_dpy; };
    const double size = length(dp(mid));
    return length(b.point - a.point - dp(mid)) <= 0.2 * size &&
           length(dp(a) - dp(mid)) <= 0.2 * size && length(dp(b) - dp(mid)) <= 0.2 * size;
  };
  for (int j = j0; j < j0 + h; ++j) {
    for (int i = i0; i < i0 + w; ++i) {
      const SpecaaSample a = k.sample(i + 0.5, j + 0.5);
      const SpecaaSample bx = k.sample(i + 1.5, j + 0.5);
      const SpecaaSample by = k.sample(i + 0.5, j + 1.5);
      const SpecaaSample mx = k.sample(i + 1.0, j + 0.5);
      const SpecaaSample my = k.sample(i + 0.5, j + 1.0);
      EXPECT_TRUE(a.hit && bx.hit && by.hit);
      const vec2 ddx = k.derivatives(mx).first, ddy = k.derivatives(my).second;
      if (!smooth(a, mx, bx, true) || !smooth(a, my, by, false)) {
        ++jumps;
        continue;
      }
      worst =
          std::max({worst, length(bx.h_perp - a.h_perp - ddx), length(by.h_perp - a.h_perp - ddy)});
      scale = std::max({scale, length(ddx), length(ddy)});
    }
  }
  return worst / scale;
}

TEST(Specaa, AnalyticDerivativesMatchQuadDifferencesOfNeighbouringCentres) {
  for (Geometry geometry : {Geometry::flat, Geometry::displaced}) {
    Scene s = testing::project_scene("simple");
    s.surface.geometry = geometry;
    SceneModel m(s);
    const double t = s.frame_time(4);
    // Near the glints (rows 270-300 at 640x360) and further down.
    int jumps = 0;
    const double e1 = quad_vs_analytic(m, t, 300, 270, 30, 20, jumps);
    const double e2 = quad_vs_analytic(m, t, 100, 330, 30, 20, jumps);
    std::printf("%s: max |quad - analytic| / max |analytic| = %.2e, %.2e (%d occluded pairs)\n",
                geometry == Geometry::flat ? "flat" : "displaced", e1, e2, jumps);
    EXPECT_LT(jumps, 150);  // of 1200 pixels: most are compared
    // Second-order agreement: the third derivative over one pixel is a few per cent of the
    // first at this resolution.
    EXPECT_LT(e1, 0.03);
    EXPECT_LT(e2, 0.03);
  }
}

TEST(Specaa, AnalyticDerivativesMatchSmallStepDifferences) {
  Scene s = testing::project_scene("medium");
  s.surface.geometry = Geometry::displaced;
  SceneModel m(s);
  // A step of 1e-4 pixel: the footprint of a distant pixel spans several of these short
  // waves, so larger steps see their curvature. The displaced intersection stops within
  // 1e-9 m of the surface (kernel/intersect.glsl: root_tolerance), independently at each of
  // the two points 2e-4 pixel apart: up to 7.4e-6 in the difference here (3.6e-6 allowed
  // below 1e-4 relative), so 1e-5 absolute.
  const double t = s.frame_time(2), e = 1e-4;
  const Kernel k(m, t);
  for (int j = 200; j < 360; j += 37) {
    for (int i = 10; i < 640; i += 61) {
      const auto [ddx, ddy] = k.derivatives(k.sample(i + 0.5, j + 0.5));
      const vec2 fx =
          (k.sample(i + 0.5 + e, j + 0.5).h_perp - k.sample(i + 0.5 - e, j + 0.5).h_perp) / (2 * e);
      const vec2 fy =
          (k.sample(i + 0.5, j + 0.5 + e).h_perp - k.sample(i + 0.5, j + 0.5 - e).h_perp) / (2 * e);
      EXPECT_LT(length(ddx - fx), 1e-4 * length(fx) + 1e-5) << i << "," << j;
      EXPECT_LT(length(ddy - fy), 1e-4 * length(fy) + 1e-5) << i << "," << j;
    }
  }
}

TEST(Specaa, TilesEqualPixelsInBothDerivativeModes) {
  Scene s = testing::project_scene("high");
  s.width = 63;  // odd: the last column's quad neighbour lies outside the image
  s.height = 35;
  SceneModel m(s);
  for (SpecaaDerivatives d : {SpecaaDerivatives::quad, SpecaaDerivatives::analytic}) {
    SpecaaOptions o;
    o.derivatives = d;
    SpecaaMethod method(o);
    testing::expect_tiles_equal_pixels(m, method, 1, 5);
  }
}

TEST(Specaa, QuadPartnersShareTheirDerivatives) {
  // Fine derivatives (ddx_fine, ddy_fine): in a 2x2 quad both pixels of a row use that
  // row's difference, both pixels of a column that column's. Checked on the quad of the
  // glint window (simple scene, frame 0) where the four values vary most.
  Scene s = testing::project_scene("simple");
  SceneModel m(s);
  const double t = s.frame_time(0);
  SpecaaOptions o;
  SpecaaMethod method(o);
  FrameContext ctx{m, frame_time(s, 0), 0};
  method.begin_frame(ctx);
  int qi = -1, qj = -1;
  double best = 0;
  for (int j = 270; j < 300; j += 2) {
    for (int i = 300; i < 340; i += 2) {
      const double lo = std::min({method.shade(ctx, i, j), method.shade(ctx, i + 1, j),
                                  method.shade(ctx, i, j + 1), method.shade(ctx, i + 1, j + 1)});
      if (lo > best) {
        best = lo;
        qi = i;
        qj = j;
      }
    }
  }
  ASSERT_GT(best, 1e-3) << "a quad whose four pixels all see some light";
  const Kernel k(m, t);
  auto h = [&](int i, int j) { return k.sample(i + 0.5, j + 0.5); };
  const SpecaaSample h00 = h(qi, qj), h10 = h(qi + 1, qj), h01 = h(qi, qj + 1),
                     h11 = h(qi + 1, qj + 1);
  const vec2 dx0 = h10.h_perp - h00.h_perp, dx1 = h11.h_perp - h01.h_perp;
  const vec2 dy0 = h01.h_perp - h00.h_perp, dy1 = h11.h_perp - h10.h_perp;
  EXPECT_EQ(method.shade(ctx, qi, qj), grey_value(m, k.lobe(h00, dx0, dy0, o)));
  EXPECT_EQ(method.shade(ctx, qi + 1, qj), grey_value(m, k.lobe(h10, dx0, dy1, o)));
  EXPECT_EQ(method.shade(ctx, qi, qj + 1), grey_value(m, k.lobe(h01, dx1, dy0, o)));
  EXPECT_EQ(method.shade(ctx, qi + 1, qj + 1), grey_value(m, k.lobe(h11, dx1, dy1, o)));
  // The coarse alternative (one difference for the whole quad) differs here.
  EXPECT_NE(method.shade(ctx, qi + 1, qj + 1), grey_value(m, k.lobe(h11, dx0, dy0, o)));
}

TEST(Specaa, ValueIsTheLobesMassInTheLightDisk) {
  // The value (no Fresnel, no sky) is the mass in the light disk of the mirror lobe widened
  // by the kernel. Against Monte Carlo: tangent slopes drawn from the kernel's covariance
  // about the pixel's normal, turned into normals in its shading frame, reflected exactly
  // and tested against the light's cone. The pixel is the one whose normal tilts most
  // across the view (large g.x: its shading frame is well turned against the NDF plane's
  // axes), and the light is moved to half a radius from its centre reflection; the
  // derivatives are scaled so that the lobe's reflections spread over about twice the
  // disk. Agreement within 4 standard errors plus 1.5% of the mass for the light plane's
  // linearisation.
  Scene s = testing::small_scene(
      {Wave{0.25, {0.9, -0.9}, 3.4, 0.0}, Wave{0.1, {-1.3, -0.4}, 2.0, 1.0}}, 320, 180);
  const SceneModel m0(s);
  const double t = s.frame_time(0);
  const Kernel k0(m0, t);
  SpecaaSample best = kd::specaa_no_sample();
  for (int j = 120; j < 180; ++j) {
    for (int i = 0; i < 320; ++i) {
      const SpecaaSample c = k0.sample(i + 0.5, j + 0.5);
      if (c.hit && std::fabs(c.g.x * c.g.y) > std::fabs(best.g.x * best.g.y)) best = c;
    }
  }
  ASSERT_TRUE(best.hit);
  std::printf("pixel normal's gradient (%.3f, %.3f)\n", best.g.x, best.g.y);
  ASSERT_GT(std::fabs(best.g.x * best.g.y), 0.01);
  const vec3& v = best.view;
  const kd::ShadingFrame f = kd::water_shading_frame(best.g);
  const vec3 rc = 2 * dot(f.n, v) * f.n - v;
  ASSERT_GT(rc.y, 0.05);
  s.light.direction = normalize(rc + 0.5 * m0.light.radius * normalize(cross(rc, vec3(0, 1, 0))));
  const SceneModel m(s);
  const Kernel km(m, t);  // the same camera and waves: the samples are the same
  const auto [ddx, ddy] = k0.derivatives(best);
  for (KernelShape shape : {KernelShape::rect, KernelShape::full}) {
    SpecaaOptions o;
    o.kernel = shape;
    const bool full = shape == KernelShape::full;
    const mat2 c0 = kd::specaa_kernel_covariance(ddx, ddy, o.sigma2, o.kappa, full);
    const double scale = m.light.radius / std::sqrt(c0[0][0] + c0[1][1]);
    const vec2 dx = scale * ddx, dy = scale * ddy;
    const mat2 cov = kd::specaa_kernel_covariance(dx, dy, o.sigma2, o.kappa, full);
    const double value = grey_value(m, km.lobe(best, dx, dy, o));
    // Monte Carlo in the tangent frame (Cholesky of the 2x2 covariance).
    const double a = std::sqrt(cov[0][0]), b = cov[0][1] / a,
                 c = std::sqrt(std::max(0.0, cov[1][1] - b * b));
    Pcg32 rng(41, static_cast<uint64_t>(shape));
    const int n = 200000;
    long hits = 0;
    for (int k = 0; k < n; ++k) {
      const double r = std::sqrt(-2 * std::log(1 - rng.uniform())), ang = kTwoPi * rng.uniform();
      const double z1 = r * std::cos(ang), z2 = r * std::sin(ang);
      const vec2 slope(a * z1, b * z1 + c * z2);
      const vec3 nm = normalize(f.n - slope.x * f.t - slope.y * f.b);
      hits += m.light.contains(2 * dot(nm, v) * nm - v);
    }
    const double mc = double(hits) / n, se = std::sqrt(mc * (1 - mc) / n);
    std::printf("lobe mass in the disk: %.4f, Monte Carlo %.4f +- %.4f\n", value, mc, se);
    EXPECT_GT(mc, 0.05);
    EXPECT_NEAR(value, mc, 4 * se + 0.015 * mc);
  }
}

}  // namespace
}  // namespace sg
