// What the horizon takes from `staa`'s shares, against direct integration:
//  - the share of a Gaussian NDF whose normals reflect the view below the horizon, taken
//    in the NDF plane (kernel/reflection_footprint.glsl, ndf_below_horizon_share: the
//    circle r.y = 0 by its tangent line), against the Gaussian's mass over the normals n
//    with r(n).y <= 0 summed on a fine grid in its whitened coordinates: views from a
//    third of a degree to 60 degrees above the water, NDF centres from the flat normal to
//    tilts that reflect below the horizon, spreads from a calm sea's to a rough one's.
//    `staa` takes it for the pixels whose reflection turns away from the light;
//  - the RDF's mass in the light disk's segment below the horizon (kernel/gaussian.glsl,
//    gaussian_disk_segment_mass), which comes off the light's share where a low light's
//    disk crosses the horizon, against nested adaptive Gauss-Kronrod over the segment.
#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <cstdio>

#include "kernel/kernel_double.h"
#include "math/rng.h"

namespace sg {
namespace {

// The NDF's mass below the horizon by an N x N midpoint grid over +-7 deviations of the
// whitened Gaussian (error about 1e-4 at N = 700: measured against N = 1400).
double direct_below(const kd::vec3& v, kd::vec2 nc, double s1, double s2, kd::vec2 u, int N) {
  const kd::vec2 w(-u.y, u.x);
  const double h = 14.0 / N;
  double mass = 0, total = 0;
  for (int i = 0; i < N; ++i) {
    const double a = -7 + (i + 0.5) * h;
    for (int j = 0; j < N; ++j) {
      const double b = -7 + (j + 0.5) * h;
      const double wt = std::exp(-0.5 * (a * a + b * b));
      const kd::vec2 n = nc + a * s1 * u + b * s2 * w;
      total += wt;
      if (kd::reflect_about_ndf_point(n, v).y <= 0.0) mass += wt;
    }
  }
  return mass / total;
}

TEST(NdfBelowHorizonShare, MatchesDirectIntegration) {
  Pcg32 rng(2027, 11);
  double worst = 0, worst_grazing = 0;
  int partial = 0;
  for (int c = 0; c < 160; ++c) {
    const double el = std::exp(std::log(0.3) + (std::log(60.0) - std::log(0.3)) * rng.uniform());
    const double az = kd::kTwoPi * rng.uniform();
    const double e = el * kd::kPi / 180;
    const kd::vec3 v(std::cos(e) * std::sin(az), std::sin(e), -std::cos(e) * std::cos(az));
    const double s1 = 0.01 + 0.29 * rng.uniform(), s2 = s1 * (0.2 + 0.8 * rng.uniform());
    const double th = kd::kPi * rng.uniform();
    const kd::vec2 u(std::cos(th), std::sin(th)), w(-u.y, u.x);
    const kd::mat2 cov = s1 * s1 * kd::outerProduct(u, u) + s2 * s2 * kd::outerProduct(w, w);
    // The centre: the flat normal, moved away from the camera by up to the tilt that puts
    // the reflection on the horizon (v.y / 2 at a grazing view) and twice it, and sideways.
    const kd::vec2 away = -kd::vec2(v.x, v.z) / std::sqrt(v.x * v.x + v.z * v.z);
    const double tilt = std::tan(0.5 * e) * 2.0 * rng.uniform();
    const kd::vec2 nc = tilt * away + 0.2 * (rng.uniform() - 0.5) * kd::vec2(-away.y, away.x);
    const double share = kd::ndf_below_horizon_share(v, nc, cov);
    const double exact = direct_below(v, nc, s1, s2, u, 700);
    const double err = std::abs(share - exact);
    if (exact > 0.01 && exact < 0.99) ++partial;
    worst = std::max(worst, err);
    if (el < 10) worst_grazing = std::max(worst_grazing, err);
    // The tangent line misses the circle's curvature: measured at most 0.042 here (a
    // spread of 0.28 by 0.19 at a 57 degree view, where the circle of radius 1 / v.y
    // bends within the Gaussian), at most 0.0085 at views under 10 degrees.
    EXPECT_LT(err, el < 10 ? 0.012 : 0.05)
        << "case " << c << " view " << el << " deg, s1 " << s1 << " s2 " << s2 << " centre " << nc.x
        << "," << nc.y << ": share " << share << " direct " << exact;
  }
  std::printf("largest error %.3g (views under 10 degrees: %.3g); %d of 160 cases partial\n", worst,
              worst_grazing, partial);
  EXPECT_GT(partial, 60);
}

// A flat NDF point reflects a view of elevation e to elevation e; tilted away from the
// camera by e / 2 it reflects along the horizon. A narrow NDF there is half below.
TEST(NdfBelowHorizonShare, HalfAtTheHorizonsTilt) {
  for (double el : {0.5, 4.0, 20.0}) {
    const double e = el * kd::kPi / 180;
    const kd::vec3 v(0, std::sin(e), std::cos(e));  // the camera towards +z
    const kd::vec2 nc(0, -std::tan(0.5 * e));       // tilted away from it
    const kd::mat2 cov(1e-8, 0, 0, 1e-8);
    EXPECT_NEAR(kd::ndf_below_horizon_share(v, nc, cov), 0.5, 1e-3) << el;
    EXPECT_LT(kd::ndf_below_horizon_share(v, kd::vec2(0), cov), 1e-12) << el;
  }
}

// The density of N(mean, cov) integrated over the segment |p| <= R, n . p <= -d (n unit):
// over t = n . p in [-R, min(-d, R)], the chord s in [-h, h] (nested adaptive
// Gauss-Kronrod on the smooth density).
double brute_segment(kd::vec2 mean, const kd::mat2& cov, double R, kd::vec2 n, double d) {
  using GK = boost::math::quadrature::gauss_kronrod<double, 31>;
  const kd::mat2 inv = kd::inverse(cov);
  const double norm = 1.0 / (kd::kTwoPi * std::sqrt(kd::determinant(cov)));
  const kd::vec2 w(-n.y, n.x);
  // The domain trimmed to 10 deviations of each coordinate (the mass beyond is < 1e-22).
  const double st = std::sqrt(dot(n, cov * n)), ss = std::sqrt(dot(w, cov * w));
  const double lo = std::max(-R, dot(n, mean) - 10 * st);
  const double hi = std::min({-d, R, dot(n, mean) + 10 * st});
  if (hi <= lo) return 0;
  auto chord = [&](double t) {
    const double h = std::sqrt(std::max(0.0, R * R - t * t));
    const double a = std::max(-h, dot(w, mean) - 10 * ss - 10 * st),
                 b = std::min(h, dot(w, mean) + 10 * ss + 10 * st);
    auto f = [&](double s) {
      const kd::vec2 q = t * n + s * w - mean;
      return std::exp(-0.5 * dot(q, inv * q));
    };
    return b > a ? GK::integrate(f, a, b, 8, 1e-12) : 0.0;
  };
  return norm * GK::integrate(chord, lo, hi, 8, 1e-11);
}

TEST(DiskSegmentMass, MatchesQuadrature) {
  Pcg32 rng(2033, 7);
  double worst = 0;
  for (int c = 0; c < 120; ++c) {
    const double R = 0.005 + 0.15 * rng.uniform();
    const double s1 = R * std::exp(2.5 * (2 * rng.uniform() - 1)),
                 s2 = s1 * (0.1 + 0.9 * rng.uniform());
    const double th = kd::kPi * rng.uniform();
    const kd::vec2 u(std::cos(th), std::sin(th)), w(-u.y, u.x);
    const kd::mat2 cov = s1 * s1 * kd::outerProduct(u, u) + s2 * s2 * kd::outerProduct(w, w);
    const kd::vec2 mean = (R + 2 * s1) * kd::vec2(2 * rng.uniform() - 1, 2 * rng.uniform() - 1);
    const double ph = kd::kTwoPi * rng.uniform();
    const kd::vec2 a = (0.2 + 2 * rng.uniform()) * kd::vec2(std::cos(ph), std::sin(ph));
    const double d = R * (2.4 * rng.uniform() - 1.2);  // the line from beyond one rim to the other
    const double got = kd::gaussian_disk_segment_mass(mean, cov, R, a, d * length(a));
    const double want = brute_segment(mean, cov, R, a / length(a), d);
    worst = std::max(worst, std::abs(got - want));
    EXPECT_NEAR(got, want, 5e-6) << "case " << c << " R " << R << " s1 " << s1 << " s2 " << s2
                                 << " d " << d;
  }
  std::printf("largest |segment - quadrature| %.2e\n", worst);
  // The line beyond the rim: nothing, or the whole disk.
  const kd::mat2 cov(0.01, 0.002, 0.002, 0.004);
  EXPECT_EQ(kd::gaussian_disk_segment_mass(kd::vec2(0.01, 0), cov, 0.1, kd::vec2(0, 1), 0.2), 0.0);
  EXPECT_DOUBLE_EQ(
      kd::gaussian_disk_segment_mass(kd::vec2(0.01, 0), cov, 0.1, kd::vec2(0, 1), -0.2),
      kd::gaussian_disk_mass(kd::vec2(0.01, 0), cov, 0.1));
}

}  // namespace
}  // namespace sg
