// The mass of a 2D Gaussian in a disk against direct 2D quadrature, and its time average
// along a segment (kernel/gaussian.glsl, gaussian_disk_mass_along) against many instants.
#include "shading/gaussian_disk.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <vector>

#include "kernel/kernel_double.h"
#include "kernel/kernel_float.h"
#include "math/rng.h"

namespace sg {
namespace {

// Direct integration of the density over the disk in polar coordinates about the disk's
// centre (adaptive Gauss-Kronrod in both variables).
double brute_mass(const vec2& mean, const mat2& cov, double R) {
  const mat2 inv = glm::inverse(cov);
  const double norm = 1.0 / (kTwoPi * std::sqrt(glm::determinant(cov)));
  using GK = boost::math::quadrature::gauss_kronrod<double, 31>;
  auto ring = [&](double rho) {
    auto f = [&](double phi) {
      vec2 d = vec2(rho * std::cos(phi), rho * std::sin(phi)) - mean;
      return std::exp(-0.5 * dot(d, inv * d));
    };
    return rho * GK::integrate(f, 0, kTwoPi, 12, 1e-12);
  };
  return norm * GK::integrate(ring, 0, R, 12, 1e-11);
}

// The same mass for Gaussians too narrow for brute_mass's 2D grid: in the principal frame,
// the major marginal times the minor conditional's probability of the disk's chord (an erf
// difference), one adaptive Gauss-Kronrod integral over s = c_s + R sin(u).
double chord_mass(const vec2& mean, const mat2& cov, double R) {
  const kd::PrincipalAxes p = kd::principal_axes(cov);
  const vec2 w(-p.u.y, p.u.x), c = -mean;
  const double cs = dot(c, p.u), cw = dot(c, w);
  auto f = [&](double u) {
    const double x = cs + R * std::sin(u), h = R * std::cos(u);
    const double dens = std::exp(-0.5 * sqr(x / p.s1)) / (std::sqrt(kTwoPi) * p.s1);
    const double chord = p.s2 > 0 ? 0.5 * (std::erfc((cw - h) / (p.s2 * std::sqrt(2.0))) -
                                           std::erfc((cw + h) / (p.s2 * std::sqrt(2.0))))
                                  : (std::fabs(cw) < h ? 1.0 : 0.0);
    return dens * chord * h;
  };
  // Broken where the chord's half-length passes |c_w| (the conditional's steps) and a few
  // minor deviations either side, so that each piece is smooth.
  std::vector<double> cuts = {-0.5 * kPi, 0.5 * kPi};
  for (double k : {-6.0, -2.0, 0.0, 2.0, 6.0}) {
    const double hk = std::fabs(cw) + k * p.s2;
    if (hk > 0 && hk < R)
      for (double sign : {-1.0, 1.0})
        cuts.push_back(sign * std::acos(hk / R));
  }
  std::sort(cuts.begin(), cuts.end());
  using GK = boost::math::quadrature::gauss_kronrod<double, 61>;
  double sum = 0;
  for (size_t i = 0; i + 1 < cuts.size(); ++i)
    if (cuts[i + 1] > cuts[i]) sum += GK::integrate(f, cuts[i], cuts[i + 1], 15, 1e-10);
  return sum;
}

// A covariance of the tests along segments: major deviation R 10^(decades U - 1.5), minor
// 0 (a line) or s1 10^(-decades U), the major axis at a uniform angle.
struct RandomCovariance {
  kd::mat2 cov;
  double s1, s2;
};
RandomCovariance random_covariance(Pcg32& rng, double R, bool line, double decades) {
  RandomCovariance c;
  c.s1 = R * std::pow(10.0, decades * rng.uniform() - 1.5);
  c.s2 = line ? 0.0 : c.s1 * std::pow(10.0, -decades * rng.uniform());
  const double ang = kTwoPi * rng.uniform();
  const vec2 u(std::cos(ang), std::sin(ang)), w(-u.y, u.x);
  c.cov = c.s1 * c.s1 * glm::outerProduct(u, u) + c.s2 * c.s2 * glm::outerProduct(w, w);
  return c;
}

TEST(GaussianDisk, PrincipalAxes) {
  mat2 c(vec2(4, 1.5), vec2(1.5, 1));
  PrincipalAxes p = principal_axes(c);
  EXPECT_NEAR(p.s1 * p.s1 + p.s2 * p.s2, 5, 1e-12);
  EXPECT_NEAR(sqr(p.s1 * p.s2), 4 - 2.25, 1e-12);
  vec2 cu = c * p.u;
  EXPECT_NEAR(cu.x, p.s1 * p.s1 * p.u.x, 1e-12);
  EXPECT_NEAR(cu.y, p.s1 * p.s1 * p.u.y, 1e-12);
  PrincipalAxes iso = principal_axes(mat2(2.0));
  EXPECT_NEAR(iso.s1, std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(iso.s2, std::sqrt(2.0), 1e-15);
}

TEST(GaussianDisk, MatchesQuadrature) {
  Pcg32 rng(21, 3);
  double worst = 0;
  for (int k = 0; k < 60; ++k) {
    const double R = 0.5 + rng.uniform();
    const double s1 = R * std::exp(3 * (rng.uniform() - 0.5) * 2);  // 0.05 R .. 20 R
    const double s2 = s1 * (0.05 + 0.95 * rng.uniform());
    const double ang = kPi * rng.uniform();
    const vec2 u(std::cos(ang), std::sin(ang)), w(-u.y, u.x);
    const mat2 cov = s1 * s1 * glm::outerProduct(u, u) + s2 * s2 * glm::outerProduct(w, w);
    const vec2 mean = (R + 2 * s1) * 1.5 * vec2(rng.uniform() - 0.5, rng.uniform() - 0.5);
    const double a = gaussian_disk_mass(mean, cov, R), b = brute_mass(mean, cov, R);
    worst = std::max(worst, std::fabs(a - b));
    EXPECT_NEAR(a, b, 5e-6) << "R " << R << " s1 " << s1 << " s2 " << s2;
  }
  std::printf("max |quadrature - brute| = %.2e\n", worst);
}

TEST(GaussianDisk, DegenerateAndLimitingCases) {
  // Rank one: all mass on a line through the mean along u; the mass is the 1D Gaussian's
  // share of the chord.
  const vec2 u = normalize(vec2(1, 2));
  const mat2 line = 0.25 * glm::outerProduct(u, u);  // s1 = 0.5
  const vec2 mean(0.3, -0.1);
  const double c = dot(-mean, u), w = dot(-mean, vec2(-u.y, u.x));
  const double h = std::sqrt(1 - w * w);  // chord half-length in the unit disk
  const double expect = 0.5 * (std::erf((c + h) / (0.5 * std::sqrt(2.0))) -
                               std::erf((c - h) / (0.5 * std::sqrt(2.0))));
  EXPECT_NEAR(gaussian_disk_mass(mean, line, 1.0), expect, 1e-9);
  // A point: the indicator of the disk.
  EXPECT_EQ(gaussian_disk_mass(vec2(0.5, 0.5), mat2(0.0), 1.0), 1.0);
  EXPECT_EQ(gaussian_disk_mass(vec2(1.5, 0.0), mat2(0.0), 1.0), 0.0);
  // Very wide: density at the centre times the disk's area.
  const double s = 300;
  EXPECT_NEAR(gaussian_disk_mass(vec2(0), mat2(s * s), 1.0), kPi / (kTwoPi * s * s), 1e-9);
  // Narrow, well inside or outside.
  EXPECT_NEAR(gaussian_disk_mass(vec2(0.2, 0), mat2(1e-6), 1.0), 1.0, 1e-12);
  EXPECT_NEAR(gaussian_disk_mass(vec2(1.2, 0), mat2(1e-6), 1.0), 0.0, 1e-12);
}

TEST(GaussianDisk, RiemannSumConvergesToTheQuadrature) {
  const mat2 cov(vec2(0.3, 0.1), vec2(0.1, 0.05));
  const vec2 mean(0.4, 0.2);
  const double exact = gaussian_disk_mass(mean, cov, 1.0);
  const double e16 = std::fabs(gaussian_disk_mass_riemann(mean, cov, 1.0, 16) - exact);
  const double e64 = std::fabs(gaussian_disk_mass_riemann(mean, cov, 1.0, 64) - exact);
  EXPECT_LT(e64, 2e-3);
  EXPECT_LT(e64, e16);
}

TEST(GaussianDisk, FarAndDeepCasesAgreeWithQuadratureAtTheNineSigmaEdge) {
  // The early outs (nothing beyond 9 major standard deviations, everything when the disk
  // holds the 9-sigma ball) against direct quadrature just inside those limits.
  const mat2 cov(vec2(0.04, 0.01), vec2(0.01, 0.02));
  const double s1 = principal_axes(cov).s1, R = 0.5;
  const vec2 u = normalize(vec2(1, 0.4));
  EXPECT_EQ(gaussian_disk_mass(u * (R + 9.001 * s1), cov, R), 0.0);
  EXPECT_LT(brute_mass(u * (R + 8.9 * s1), cov, R), 1e-16);
  // Short of the limits the quadrature still runs, tails included.
  for (double k : {2.0, 4.0, 6.0}) {
    const double m = gaussian_disk_mass(u * (R + k * s1), cov, R);
    EXPECT_NEAR(m, brute_mass(u * (R + k * s1), cov, R), 1e-6 * m) << k;
    EXPECT_GT(m, 0.0);
  }
  const double big = 9 * s1 + 0.3;
  EXPECT_EQ(gaussian_disk_mass(u * 0.3, cov, big), 1.0);
  EXPECT_NEAR(gaussian_disk_mass(u * 0.29, cov, big), 1.0, 1e-15);
}

TEST(GaussianDisk, HalfPlaneMassMatchesMonteCarlo) {
  Pcg32 rng(2, 9);
  const mat2 cov(vec2(0.04, 0.015), vec2(0.015, 0.02));
  const vec2 mean(0.1, -0.05);
  // Cholesky factor of cov.
  const double a = std::sqrt(cov[0][0]), b = cov[0][1] / a, c = std::sqrt(cov[1][1] - b * b);
  for (const vec3 line : {vec3(1, 0, -0.1), vec3(0.6, -0.8, 0.05), vec3(0, 1, 0.3)}) {
    const vec2 n(line.x, line.y);
    long in = 0;
    const int N = 100000;
    for (int k = 0; k < N; ++k) {
      const double r = std::sqrt(-2 * std::log(1 - rng.uniform())), t = kTwoPi * rng.uniform();
      const double z1 = r * std::cos(t), z2 = r * std::sin(t);
      const vec2 p = mean + vec2(a * z1, b * z1 + c * z2);
      in += dot(n, p) + line.z <= 0;
    }
    const double f = double(in) / N;
    EXPECT_NEAR(gaussian_half_plane_mass(mean, cov, n, line.z), f,
                5 * std::sqrt(f * (1 - f) / N) + 1e-12);
  }
  EXPECT_EQ(gaussian_half_plane_mass(mean, mat2(0.0), vec2(1, 0), -0.2), 1.0);
  EXPECT_EQ(gaussian_half_plane_mass(mean, mat2(0.0), vec2(1, 0), 0.0), 0.0);
}

TEST(GaussianDisk, MassAlongASegmentEqualsTheMeanOverItsInstants) {
  // Random segments (short to 40 disk radii), covariances (round to 1e4:1, and one of rank
  // 1), against the midpoint rule with 4000 instants of gaussian_disk_mass (error ~1e-7).
  Pcg32 rng(7, 3);
  const double R = 0.0047;
  double worst = 0;
  for (int q = 0; q < 60; ++q) {
    const RandomCovariance rc = random_covariance(rng, R, q % 10 == 0, 2);
    const double s1 = rc.s1, s2 = rc.s2;
    const kd::mat2 cov = rc.cov;
    const double len = R * 40 * rng.uniform() * rng.uniform();
    const double dir = kTwoPi * rng.uniform();
    const vec2 mid = R * vec2(3 * rng.uniform() - 1.5, 3 * rng.uniform() - 1.5);
    const vec2 a = mid - 0.5 * len * vec2(std::cos(dir), std::sin(dir)), b = 2.0 * mid - a;
    const int n = 4000;
    double avg = 0;
    for (int k = 0; k < n; ++k)
      avg += kd::gaussian_disk_mass(a + (k + 0.5) / n * (b - a), cov, R) / n;
    const double got = kd::gaussian_disk_mass_along(a, b, cov, R);
    worst = std::max(worst, std::fabs(got - avg));
    EXPECT_NEAR(got, avg, 2e-4 * std::max(avg, 0.01))
        << q << " s1/R " << s1 / R << " s2/s1 " << s2 / s1 << " len/R " << len / R;
  }
  std::printf("mass along a segment: worst |error| %.3g\n", worst);
  // The largest error over the 60 segments: 1.0e-5 with the pieces' sub-intervals (and
  // with the former fixed 30 nodes a piece); 6.4e-5 without the ends' sub-intervals.
  EXPECT_LT(worst, 2e-5);
  // A line along the segment (rank 1, no spread across it): its one chord.
  {
    const vec2 a(-0.02, 0.001), b(0.015, 0.001);
    const kd::mat2 line = 1e-6 * glm::outerProduct(vec2(1, 0), vec2(1, 0));
    double avg = 0;
    for (int k = 0; k < 4000; ++k)
      avg += kd::gaussian_disk_mass(a + (k + 0.5) / 4000 * (b - a), line, R) / 4000;
    EXPECT_NEAR(kd::gaussian_disk_mass_along(a, b, line, R), avg, 2e-4 * avg);
  }
}

TEST(GaussianDisk, MahalanobisCullBoundsEveryInstantsMass) {
  // staa_light_share's Mahalanobis cull (kernel/staa.glsl): with d the least Mahalanobis
  // distance of the path of the RDF's centres from the disk's centre, each instant's mass
  // in the disk is at most exp(-(d - R / s2)^2 / 2). Random elongated covariances (1:1 to
  // 300:1), segments placed in the whitened frame at a margin d - R / s2 of 0.3 to 6:
  // kd::path_min_distance through kd::staa_whitening against the whitened segment's own
  // distance, and the bound against five instants' masses (gaussian_disk_mass, and on
  // every tenth path adaptive quadrature, chord_mass). Some paths are culled by it where
  // the axis-wise culls keep them.
  Pcg32 rng(29, 7);
  const double R = 0.0047;
  double tightest = 0;
  int culled_only_here = 0;
  for (int q = 0; q < 150; ++q) {
    const RandomCovariance rc = random_covariance(rng, R, false, 2.5);
    const kd::PrincipalAxes ax = kd::principal_axes(rc.cov);
    const vec2 u = ax.u, w(-u.y, u.x);
    // Whitened endpoints: the nearest point of the segment at distance D from the origin.
    const double margin =
        q % 5 == 0 ? kd::kStaaCullTail + 1.0 + 2.0 * rng.uniform() : 0.3 + 5.7 * rng.uniform();
    const double D = R / ax.s2 + margin;
    const double phi = kTwoPi * rng.uniform();
    const vec2 n(std::cos(phi), std::sin(phi)), along(-n.y, n.x);
    const double t0 = -4.0 * rng.uniform(), t1 = 4.0 * rng.uniform();
    auto plane = [&](vec2 wp) { return ax.s1 * wp.x * u + ax.s2 * wp.y * w; };
    kd::StaaPath path;
    path.centre[0] = plane(D * n + t0 * along);
    path.centre[1] = plane(D * n + t1 * along);
    path.valid[0] = path.valid[1] = true;
    const double d = kd::path_min_distance(path, 1, kd::staa_whitening(ax));
    ASSERT_NEAR(d, D, 1e-9 * D) << q;
    const double bound = std::exp(-0.5 * sqr(d - R / ax.s2));
    for (int k = 0; k < 5; ++k) {
      const vec2 c = path.centre[0] + (k / 4.0) * (path.centre[1] - path.centre[0]);
      const double mass =
          q % 10 == 0 ? chord_mass(c, rc.cov, R) : kd::gaussian_disk_mass(c, rc.cov, R);
      EXPECT_LE(mass, bound) << q << " k " << k << " margin " << margin;
      tightest = std::max(tightest, mass / bound);
    }
    const double min_minor = kd::path_min_abs_projection(path, 1, w);
    const double min_major = kd::path_min_abs_projection(path, 1, u);
    const bool axis_culled = min_minor > R + 12.0 * ax.s2 || min_major > R + 12.0 * ax.s1;
    if (margin > kd::kStaaCullTail && !axis_culled) ++culled_only_here;
  }
  std::printf(
      "Mahalanobis cull: largest mass / bound %.3g; %d of 30 culled paths kept by the "
      "axis-wise culls\n",
      tightest, culled_only_here);
  EXPECT_GT(tightest, 1e-3);  // the bound is not vacuous on these paths
  EXPECT_GT(culled_only_here, 0);
}

TEST(GaussianDisk, MassAlongASegmentOfLengthZeroIsTheInstantsMass) {
  // A segment of length 0 (a pixel whose path stands still) takes the closed form's own
  // limit (segment_chord_average), not the instant's quadrature; so do segments far
  // shorter than the conditional's spread, where the tails' differences would cancel. On
  // random covariances (round to lines, oblique, near and far from the disk) against an
  // adaptive integral (chord_mass), in double; gaussian_disk_mass's own error beside it
  // (its 30 nodes a piece err most on the narrowest lines); in float against double.
  Pcg32 rng(11, 5);
  const double R = 0.0047;
  double worst = 0, worst_instant = 0, worst_short = 0, worst_float = 0;
  for (int q = 0; q < 120; ++q) {
    const RandomCovariance rc = random_covariance(rng, R, q % 10 == 0, 2.5);
    const double s1 = rc.s1, s2 = rc.s2;
    const kd::mat2 cov = rc.cov;
    const vec2 a = (R + 2 * s1) * vec2(3 * rng.uniform() - 1.5, 3 * rng.uniform() - 1.5);
    const double want = chord_mass(a, cov, R);
    const double got = kd::gaussian_disk_mass_along(a, a, cov, R);
    worst = std::max(worst, std::fabs(got - want));
    worst_instant = std::max(worst_instant, std::fabs(kd::gaussian_disk_mass(a, cov, R) - want));
    EXPECT_NEAR(got, want, 2e-5) << q << " s1/R " << s1 / R << " s2/s1 " << s2 / s1;
    // A segment 1e-9 R long in a random direction: the same mass.
    const double dir = kTwoPi * rng.uniform();
    const vec2 b = a + 1e-9 * R * vec2(std::cos(dir), std::sin(dir));
    const double short_mass = kd::gaussian_disk_mass_along(a, b, cov, R);
    worst_short = std::max(worst_short, std::fabs(short_mass - want));
    EXPECT_NEAR(short_mass, want, 2e-5) << q;
    // Float (the GL engine's precision) on a segment 1e-4 R long, against double.
    const vec2 c = a + 1e-4 * R * vec2(std::cos(dir), std::sin(dir));
    const double f = kf::float_gaussian_disk_mass_along(kf::vec2(a), kf::vec2(c), kf::mat2(cov),
                                                        static_cast<float>(R));
    const double d = kd::gaussian_disk_mass_along(a, c, cov, R);
    worst_float = std::max(worst_float, std::fabs(f - d));
    // Float's cuts are placed to its rounding, which on the narrowest lines (s2 below a
    // hundredth of s1) moves a step of the chord's average off its sub-interval: 4.5e-4
    // of a mass near 1 (measured), left so.
    EXPECT_NEAR(f, d, 1e-3) << q;
  }
  std::printf(
      "length 0: worst %.3g (gaussian_disk_mass %.3g); 1e-9 R: %.3g; float against double, "
      "1e-4 R: %.3g\n",
      worst, worst_instant, worst_short, worst_float);
}

}  // namespace
}  // namespace sg
