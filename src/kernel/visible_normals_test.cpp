// The normals a displaced surface shows a view (kernel/visible_normals.glsl) against brute
// force: the Gaussian weighted by (m . v)+ on a dense midpoint grid in its standard
// coordinates, its mean and covariance, for views from grazing (1 degree) to steep,
// round, elongated and correlated spreads, and centres turned towards the view, away from
// it and level with it.
#include <gtest/gtest.h>

#include <cmath>

#include "kernel/kernel_double.h"

namespace sg {
namespace {

struct Weighted {
  kd::vec2 mean;
  kd::mat2 cov;
};

// N(mu, A A^T) weighted by (v.y + s . (v.x, v.z))+ on an n x n grid over +-8 deviations.
Weighted brute_force(kd::vec2 mu, kd::mat2 A, kd::vec3 v, int n) {
  const double h = 16.0 / n;
  double w0 = 0, wx = 0, wz = 0, wxx = 0, wxz = 0, wzz = 0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const kd::vec2 x(-8 + (i + 0.5) * h, -8 + (j + 0.5) * h);
      const kd::vec2 s = mu + A * x;
      const double w = std::max(v.y + s.x * v.x + s.y * v.z, 0.0) * std::exp(-0.5 * kd::dot(x, x)) /
                       (2 * M_PI) * h * h;
      w0 += w;
      wx += w * s.x;
      wz += w * s.y;
      wxx += w * s.x * s.x;
      wxz += w * s.x * s.y;
      wzz += w * s.y * s.y;
    }
  }
  Weighted r;
  r.mean = kd::vec2(wx / w0, wz / w0);
  const double cxz = wxz / w0 - r.mean.x * r.mean.y;
  r.cov = kd::mat2(kd::vec2(wxx / w0 - r.mean.x * r.mean.x, cxz),
                   kd::vec2(cxz, wzz / w0 - r.mean.y * r.mean.y));
  return r;
}

kd::vec3 view(double elevation_deg, double azimuth_deg) {
  const double e = elevation_deg * M_PI / 180, a = azimuth_deg * M_PI / 180;
  return kd::vec3(std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a));
}

TEST(VisibleNormals, MomentsOfTheGaussianWeightedByTheProjectedArea) {
  struct Case {
    double elevation, azimuth;
    kd::vec2 mu;
    kd::mat2 A;  // the covariance's factor, columns
  };
  const kd::mat2 round(kd::vec2(0.06, 0), kd::vec2(0, 0.06));
  const kd::mat2 along(kd::vec2(0.01, 0.0), kd::vec2(0.0, 0.12));    // long along z
  const kd::mat2 across(kd::vec2(0.12, 0.0), kd::vec2(0.0, 0.015));  // long along x
  const kd::mat2 tilted(kd::vec2(0.08, 0.05), kd::vec2(-0.02, 0.04));
  const Case cases[] = {
      {1, 0, kd::vec2(0, 0), round},          {1, 0, kd::vec2(0, 0.04), round},
      {1, 0, kd::vec2(0, -0.05), round},      {3, 30, kd::vec2(0.02, -0.01), along},
      {3, 90, kd::vec2(0, 0), across},        {2, 200, kd::vec2(-0.03, 0.05), tilted},
      {10, 45, kd::vec2(0.01, 0.02), tilted}, {40, 0, kd::vec2(0, 0), round},
      {6, -60, kd::vec2(0.05, 0), along},     {0.5, 10, kd::vec2(0, -0.02), across},
  };
  double worst_mean = 0, worst_cov = 0;
  for (const Case& c : cases) {
    const kd::vec3 v = view(c.elevation, c.azimuth);
    const kd::mat2 cov = c.A * transpose(c.A);
    const kd::VisibleNormals r = kd::visible_normals(c.mu, cov, v);
    const Weighted b = brute_force(c.mu, c.A, v, 1600);
    const double scale = std::sqrt(cov[0][0] + cov[1][1]);
    const double dm = kd::length(r.mean - b.mean) / scale;
    double dc = 0;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        dc = std::max(dc, std::abs(r.cov[i][j] - b.cov[i][j]) / (scale * scale));
    worst_mean = std::max(worst_mean, dm);
    worst_cov = std::max(worst_cov, dc);
    EXPECT_LT(dm, 1e-5) << "mean, view " << c.elevation << " deg, azimuth " << c.azimuth;
    EXPECT_LT(dc, 1e-5) << "covariance, view " << c.elevation << " deg, azimuth " << c.azimuth;
  }
  std::printf("largest differences from the grid (over the spread): mean %.2e, covariance %.2e\n",
              worst_mean, worst_cov);
}

// The weighting matters where the slopes along the view are comparable to the view's height
// and fades where they are small against it: at 1 degree a round spread of 0.06 moves by
// most of a deviation towards the view; at 40 degrees by Sigma e / (v . m), a few hundredths
// of one.
TEST(VisibleNormals, GrazingViewsSeeTheFacetsTurnedTowardsThem) {
  const kd::mat2 cov(kd::vec2(0.0036, 0), kd::vec2(0, 0.0036));
  const kd::vec3 grazing = view(1, 0), steep = view(40, 0);
  const kd::VisibleNormals g = kd::visible_normals(kd::vec2(0), cov, grazing);
  const kd::VisibleNormals s = kd::visible_normals(kd::vec2(0), cov, steep);
  // Towards the view: along +z (the view's horizontal direction), in NDF-plane units.
  EXPECT_GT(g.mean.y, 0.5 * 0.06);
  EXPECT_LT(g.cov[1][1], 0.6 * 0.0036);
  EXPECT_NEAR(g.mean.x, 0.0, 1e-15);
  EXPECT_NEAR(s.mean.y, 0.0036 * steep.z / steep.y, 2e-4);
  EXPECT_LT(s.mean.y, 0.01);
  // No spread: nothing moves.
  const kd::VisibleNormals p = kd::visible_normals(kd::vec2(0.1, 0.2), kd::mat2(0.0), grazing);
  EXPECT_EQ(p.mean.x, 0.1);
  EXPECT_EQ(p.mean.y, 0.2);
}

}  // namespace
}  // namespace sg
