// The aliasing waves' NDF (Podee et al. 2021, Eqs. 3-7 and Appendix A) against numerical
// averages of the slopes, and the aliasing classification (Eq. 20).
#include "shading/ndf.h"

#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>

#include "math/rng.h"
#include "shading/aliasing.h"
#include "shading/water_geometry.h"
#include "testing/direct_waves.h"
#include "testing/testing.h"

namespace sg {
namespace {

using GK = boost::math::quadrature::gauss_kronrod<double, 31>;

TEST(Ndf, UniformIsTheTimeAverageOfTheSlopes) {
  // Eq. 3: the time average of the slope products at a fixed point over many periods.
  std::vector<Wave> waves = {Wave{0.1, {0.7, -1.3}, 2.3, 0.4}, Wave{0.05, {-2.0, 0.5}, 4.1, 1.0}};
  WaveField w(waves);
  std::vector<double> weights = {1.0, 0.5};
  // Average each wave's products separately (independent waves: cross terms average out
  // only over incommensurate periods), then add.
  double xx = 0, xz = 0, zz = 0;
  for (size_t i = 0; i < waves.size(); ++i) {
    std::vector<double> one(2, 0.0);
    one[i] = weights[i];
    const double T = 100 * kTwoPi / waves[i].angular_frequency;
    auto avg = [&](int c) {
      return GK::integrate(
                 [&](double t) {
                   vec2 g = testing::direct_gradient(w, 3.0, -7.0, t, one);
                   return c == 0 ? g.x * g.x : c == 1 ? g.x * g.y : g.y * g.y;
                 },
                 0, T, 15, 1e-12) /
             T;
    };
    xx += avg(0);
    xz += avg(1);
    zz += avg(2);
  }
  mat2 cov = uniform_ndf_covariance(w, weights);
  EXPECT_NEAR(cov[0][0], xx, 1e-10);
  EXPECT_NEAR(cov[0][1], xz, 1e-10);
  EXPECT_NEAR(cov[1][0], xz, 1e-10);
  EXPECT_NEAR(cov[1][1], zz, 1e-10);
}

TEST(Ndf, AppendixAMomentsMatchIntegrationOfEqs5And6) {
  Pcg32 rng(12, 1);
  for (int k = 0; k < 50; ++k) {
    const double A = 0.2 * rng.uniform();
    const vec2 kv(3 * (rng.uniform() - 0.5), 3 * (rng.uniform() - 0.5));
    const double p1 = 20 * (rng.uniform() - 0.5), p2 = p1 + 0.01 + 12 * rng.uniform();
    SlopeMoments m = wave_slope_moments(A, kv, p1, p2);
    // dy/dx = A a cos(p), dy/dz = A b cos(p) along the wave (Eq. 7's p).
    const double L = p2 - p1;
    const double mean_cos = GK::integrate([&](double p) { return std::cos(p); }, p1, p2) / L;
    const double mean_cos2 = GK::integrate([&](double p) { return sqr(std::cos(p)); }, p1, p2) / L;
    EXPECT_NEAR(m.B.x, A * kv.x * mean_cos, 1e-12);
    EXPECT_NEAR(m.B.y, A * kv.y * mean_cos, 1e-12);
    EXPECT_NEAR(m.M.x, A * A * kv.x * kv.x * mean_cos2, 1e-12);
    EXPECT_NEAR(m.M.y, A * A * kv.x * kv.y * mean_cos2, 1e-12);
    EXPECT_NEAR(m.M.z, A * A * kv.y * kv.y * mean_cos2, 1e-12);
    // Eq. 23 as printed (sin(2(.)) in K) does not give the mean slope; ours does.
    const double printed_K = A * (std::sin(2 * p2) - std::sin(2 * p1)) / L;
    if (std::fabs(mean_cos) > 0.05) {
      EXPECT_GT(std::fabs(printed_K - A * mean_cos), 1e-6);
    }
  }
  // Small ranges: the moments of the slope at the centre (no spread).
  SlopeMoments m = wave_slope_moments(0.1, vec2(1, 2), 0.7, 0.7 + 1e-9);
  EXPECT_NEAR(m.B.x, 0.1 * std::cos(0.7), 1e-9);
  EXPECT_NEAR(m.M.x - m.B.x * m.B.x, 0.0, 1e-12);
}

TEST(Ndf, FootprintPhaseHalfWidth) {
  // An axis-aligned 2 m x 0.5 m footprint: along x the phase spans k_x * 1 m each side.
  const mat2 J(vec2(2.0, 0.0), vec2(0.0, 0.5));
  EXPECT_NEAR(footprint_phase_half_width(vec2(3.0, 0.0), J), 3.0, 1e-12);
  EXPECT_NEAR(footprint_phase_half_width(vec2(0.0, 3.0), J), 0.75, 1e-12);
  // A skewed footprint: the line through the centre along k meets the boundary where
  // max(|u|, |v|) = 1/2, found here by bisection on the line.
  const mat2 S(vec2(1.0, 0.3), vec2(-0.4, 2.0));
  const vec2 k(1.2, -0.7);
  double lo = 0, hi = 100;
  for (int it = 0; it < 200; ++it) {
    double mid = 0.5 * (lo + hi);
    vec2 uv = glm::inverse(S) * (mid * normalize(k));
    (std::max(std::fabs(uv.x), std::fabs(uv.y)) < 0.5 ? lo : hi) = mid;
  }
  EXPECT_NEAR(footprint_phase_half_width(k, S), lo * length(k), 1e-9);
}

TEST(Ndf, PerPixelMatchesTheFootprintAverageForAnAlignedWave) {
  // A wave whose crests are parallel to one side of a rectangular footprint varies along
  // one axis only: the 1D average of Appendix A is then the exact 2D footprint average.
  std::vector<Wave> waves = {Wave{0.08, {1.7, 0.0}, 2.0, 0.3}};
  WaveField w(waves);
  std::vector<double> one = {1.0};
  const mat2 J(vec2(1.3, 0.0), vec2(0.0, 0.4));
  const vec2 c(2.0, -5.0);
  const double t = 0.9;
  PlaneGaussian g = per_pixel_ndf(w, one, c, J, t);
  const int n = 4000;
  double mx = 0, mxx = 0;
  for (int k = 0; k < n; ++k) {
    const double u = (k + 0.5) / n - 0.5;  // midpoint rule over the footprint's x extent
    vec2 s = testing::direct_gradient(w, c.x + 1.3 * u, c.y, t);
    mx += -s.x / n;
    mxx += s.x * s.x / n;
  }
  EXPECT_NEAR(g.mean.x, mx, 1e-7);
  EXPECT_NEAR(g.cov[0][0], mxx - mx * mx, 1e-7);
  EXPECT_NEAR(g.cov[1][1], 0.0, 1e-15);
}

TEST(Ndf, PerPixelLimits) {
  std::vector<Wave> waves = {Wave{0.05, {0.9, -2.1}, 3.0, 0.2}};
  WaveField w(waves);
  std::vector<double> one = {1.0};
  const vec2 c(1.0, -30.0);
  // A tiny footprint: no spread, mean = minus the slope at the centre.
  PlaneGaussian small = per_pixel_ndf(w, one, c, mat2(1e-7), 0.5);
  vec2 g = testing::direct_gradient(w, c.x, c.y, 0.5);
  EXPECT_NEAR(small.mean.x, -g.x, 1e-9);
  EXPECT_NEAR(small.cov[0][0], 0.0, 1e-12);
  // A huge footprint: the uniform NDF and no mean slope, up to the sinc terms of
  // Appendix A, which decay as 1/D (D ~ 1e5 rad here).
  PlaneGaussian big = per_pixel_ndf(w, one, c, mat2(1e5), 0.5);
  mat2 u = uniform_ndf_covariance(w, one);
  EXPECT_NEAR(big.cov[0][0], u[0][0], 1e-4 * u[0][0]);
  EXPECT_NEAR(big.cov[1][1], u[1][1], 1e-4 * u[1][1]);
  EXPECT_NEAR(big.mean.x, 0.0, 1e-6);
}

TEST(Aliasing, ProjectedFrequencyMatchesPhaseDifferencesOfNeighbouringPixels) {
  SceneModel m(testing::project_scene("high"));
  for (double py : {200.5, 260.5, 340.5}) {
    PixelFootprint f = pixel_footprint(m, 320.5, py, 0);
    const vec2 k(m.waves.a[5], m.waves.b[5]);
    auto phase = [&](double px, double qy) {
      PixelFootprint g = pixel_footprint(m, px, qy, 0);
      return dot(k, vec2(g.point.x, g.point.z));
    };
    const double h = 1e-3;
    const double fx = std::fabs(phase(320.5 + h, py) - phase(320.5 - h, py)) / (2 * h) / kTwoPi;
    const double fy = std::fabs(phase(320.5, py + h) - phase(320.5, py - h)) / (2 * h) / kTwoPi;
    const mat2 J = f.xz_jacobian();
    EXPECT_NEAR(projected_frequency(k, J, FrequencyNorm::max), std::max(fx, fy), 1e-6 * (fx + fy));
    EXPECT_NEAR(projected_frequency(k, J, FrequencyNorm::norm), std::hypot(fx, fy),
                1e-6 * (fx + fy));
  }
}

TEST(Aliasing, Eq20) {
  AliasingParams p;
  EXPECT_EQ(alias_fraction(0.1, p), 0.0);
  EXPECT_EQ(alias_fraction(0.2, p), 0.0);
  EXPECT_NEAR(alias_fraction(0.35, p), 0.5, 1e-15);
  EXPECT_EQ(alias_fraction(0.5, p), 1.0);
  EXPECT_EQ(alias_fraction(3.0, p), 1.0);
  // Waves classify by distance: the high scene's shortest wave aliases far away only.
  SceneModel m(testing::project_scene("high"));
  std::vector<double> near, far;
  alias_fractions(m.waves, pixel_footprint(m, 320.5, 350.5, 0).xz_jacobian(), p, near);
  alias_fractions(m.waves, pixel_footprint(m, 320.5, 190.5, 0).xz_jacobian(), p, far);
  double sn = 0, sf = 0;
  for (size_t i = 0; i < near.size(); ++i) {
    EXPECT_LE(near[i], far[i]);
    sn += near[i];
    sf += far[i];
  }
  EXPECT_LT(sn, sf);
  EXPECT_GT(sf, 10);
}

}  // namespace
}  // namespace sg
