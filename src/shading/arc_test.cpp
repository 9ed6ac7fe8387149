// The arc fractions (Podee et al. 2021, Sec. 3.3) against dense sampling of the slerp in
// time, on named cases built explicitly, on thousands of random arcs and disks, on
// degenerate arcs, and under reversal of the arc.
#include "shading/arc.h"

#include <gtest/gtest.h>

#include <cmath>

#include "base/error.h"
#include "math/rng.h"

namespace sg {
namespace {

LightModel make_light(double elevation_deg, double azimuth_deg, double radius_deg) {
  const double el = radians(elevation_deg), az = radians(azimuth_deg);
  LightDesc d;
  d.direction = vec3(std::cos(el) * std::sin(az), std::sin(el), -std::cos(el) * std::cos(az));
  d.angular_radius_deg = radius_deg;
  d.radiance = Rgb(1.0);
  d.visible = false;
  return LightModel(d);
}

// The scene spec's tests on one direction.
void classify(const vec3& r, const LightModel& light, long& in_light, long& below) {
  if (r.y <= 0) {
    ++below;
  } else if (dot(normalize(r), light.L) >= light.cos_radius) {
    ++in_light;
  }
}

// Midpoint sampling in time of the textbook slerp sin((1-t) theta)/sin(theta) r0 +
// sin(t theta)/sin(theta) r1: independent of the closed form under test.
ArcFractions sample_slerp(const vec3& r0, const vec3& r1, const LightModel& light, int n) {
  const double theta = std::acos(clamp(dot(r0, r1), -1.0, 1.0));
  const double inv_sin = 1.0 / std::sin(theta);
  long in = 0, below = 0;
  for (int k = 0; k < n; ++k) {
    const double t = (k + 0.5) / n;
    const vec3 r = std::sin((1 - t) * theta) * inv_sin * r0 + std::sin(t * theta) * inv_sin * r1;
    classify(r, light, in, below);
  }
  return {double(in) / n, double(below) / n};
}

// Midpoint sampling of an arc of the circle cos(psi) m + sin(psi) q, psi in [p0, p1].
ArcFractions sample_circle(const vec3& m, const vec3& q, double p0, double p1,
                           const LightModel& light, int n) {
  long in = 0, below = 0;
  for (int k = 0; k < n; ++k) {
    const double psi = p0 + (p1 - p0) * (k + 0.5) / n;
    classify(std::cos(psi) * m + std::sin(psi) * q, light, in, below);
  }
  return {double(in) / n, double(below) / n};
}

// A great circle at angular distance beta from L, parametrised from its point closest to L:
// c(psi) = cos(psi) m + sin(psi) q, with m = cos(beta) L + sin(beta) p. (p, q) is the
// light-plane frame rotated by gamma.
struct Circle {
  vec3 m, q;
  vec3 at(double psi) const { return std::cos(psi) * m + std::sin(psi) * q; }
};
Circle circle_near(const LightModel& light, double beta, double gamma) {
  const vec3 p = std::cos(gamma) * light.e2 + std::sin(gamma) * light.e1;
  const vec3 q = -std::sin(gamma) * light.e2 + std::cos(gamma) * light.e1;
  return {std::cos(beta) * light.L + std::sin(beta) * p, q};
}

vec3 random_unit(Pcg32& rng) {
  const double z = 2 * rng.uniform() - 1, a = kTwoPi * rng.uniform();
  const double s = std::sqrt(1 - z * z);
  return vec3(s * std::cos(a), z, s * std::sin(a));
}

// Midpoint sampling with n steps misplaces each boundary of a set by at most half a step:
// each fraction has at most 4 boundaries (the cone and the horizon each cut the arc at most
// twice), so it is off by at most 4 * 0.5 / n. The closed form is exact to rounding.
double sampling_tolerance(int n) {
  return 2.0 / n + 1e-12;
}

constexpr int kSteps = 200000;

TEST(ArcFractions, NamedCasesThroughTheCentre) {
  const LightModel light = make_light(30, 10, 5);
  const Circle c = circle_near(light, 0, 0.3);
  struct Case {
    const char* name;
    double p0_deg, p1_deg, expect;
  };
  // Through the centre the light arc is psi in [-rho, rho]: the expected fraction is
  // |[p0, p1] and [-5, 5]| / (p1 - p0), exactly.
  const Case cases[] = {
      {"misses_before", -40, -6, 0.0},
      {"enters", -20, 2, 7.0 / 22},
      {"leaves", -3, 15, 8.0 / 18},
      {"passes_through", -20, 30, 10.0 / 50},
      {"lies_inside", -2, 3, 1.0},
      {"touches_edge_inside", -5, 5, 1.0},
      {"whole_disk_long_arc", -60, 60, 10.0 / 120},
      {"misses_after", 5.5, 50, 0.0},
  };
  for (const Case& k : cases) {
    for (bool reversed : {false, true}) {
      vec3 r0 = c.at(radians(k.p0_deg)), r1 = c.at(radians(k.p1_deg));
      if (reversed) std::swap(r0, r1);
      const ArcFractions f = arc_fractions(r0, r1, light);
      EXPECT_NEAR(f.in_light, k.expect, 1e-12) << k.name << (reversed ? " reversed" : "");
      EXPECT_EQ(f.below, 0.0) << k.name;
      const ArcFractions s = sample_slerp(r0, r1, light, kSteps);
      EXPECT_NEAR(s.in_light, k.expect, sampling_tolerance(kSteps)) << k.name;
    }
  }
}

TEST(ArcFractions, NamedCasesOffCentre) {
  const LightModel light = make_light(45, -35, 3);
  const double rho = radians(3);
  struct Case {
    const char* name;
    double beta_over_rho, p0_deg, p1_deg;
  };
  const Case cases[] = {
      {"misses_wide", 1.5, -30, 30},      {"grazes_tangent", 1.0, -30, 30},
      {"nearly_grazes", 0.999, -30, 30},  {"passes_off_centre", 0.6, -30, 30},
      {"enters_off_centre", 0.6, -30, 0}, {"inside_off_centre", 0.6, -0.5, 1},
  };
  for (const Case& k : cases) {
    const double beta = k.beta_over_rho * rho;
    const Circle c = circle_near(light, beta, 1.1);
    const double p0 = radians(k.p0_deg), p1 = radians(k.p1_deg);
    const ArcFractions f = arc_fractions(c.at(p0), c.at(p1), light);
    // Spherical right triangle L, closest point, cone edge: cos(rho) = cos(beta) cos(alpha).
    const double alpha = beta < rho ? std::acos(std::cos(rho) / std::cos(beta)) : 0.0;
    const double expect = std::max(0.0, std::min(p1, alpha) - std::max(p0, -alpha)) / (p1 - p0);
    // acos near 1 loses digits: the reference is good to about 1e-8 of alpha here.
    EXPECT_NEAR(f.in_light, expect, 1e-9) << k.name;
    const ArcFractions s = sample_slerp(c.at(p0), c.at(p1), light, kSteps);
    EXPECT_NEAR(f.in_light, s.in_light, sampling_tolerance(kSteps)) << k.name;
    EXPECT_EQ(f.below, 0.0) << k.name;
  }
}

TEST(ArcFractions, HorizonCutsTheArcAndTheDisk) {
  // A light 2 degrees above the horizon with a 5 degree radius: the disk straddles the
  // horizon. The vertical circle through L and the zenith has elevation 2 deg + psi.
  const LightModel light = make_light(2, 40, 5);
  const Circle c{light.L, light.e2};
  const vec3 r0 = c.at(radians(-20)), r1 = c.at(radians(20));
  const ArcFractions f = arc_fractions(r0, r1, light);
  EXPECT_NEAR(f.below, 18.0 / 40, 1e-12);    // psi <= -2 deg
  EXPECT_NEAR(f.in_light, 7.0 / 40, 1e-12);  // psi in (-2, 5] deg: only the part above
  const ArcFractions s = sample_slerp(r0, r1, light, kSteps);
  EXPECT_NEAR(s.below, f.below, sampling_tolerance(kSteps));
  EXPECT_NEAR(s.in_light, f.in_light, sampling_tolerance(kSteps));

  // Entirely below the horizon, inside the cone's lower half.
  const ArcFractions g = arc_fractions(c.at(radians(-4)), c.at(radians(-3)), light);
  EXPECT_EQ(g.in_light, 0.0);
  EXPECT_NEAR(g.below, 1.0, 1e-12);

  // An arc in the horizon plane: r.y = 0 throughout, which the spec counts as below.
  const ArcFractions h = arc_fractions(vec3(1, 0, 0), vec3(0, 0, -1), make_light(0, 45, 10));
  EXPECT_EQ(h.below, 1.0);
  EXPECT_EQ(h.in_light, 0.0);
}

TEST(ArcFractions, TheSunsDiskKeepsFullPrecision) {
  // rho = 0.27 deg: cos(rho) = 1 - 1.1e-5. An arc through the centre of 1 degree.
  const LightModel light = make_light(12, 0, 0.27);
  const Circle c = circle_near(light, 0.5 * radians(0.27), 0.2);
  const double alpha = std::atan(
      std::sqrt(std::pow(std::sin(radians(0.27)), 2) - std::pow(std::sin(0.5 * radians(0.27)), 2)) /
      std::cos(radians(0.27)));
  const ArcFractions f = arc_fractions(c.at(radians(-0.5)), c.at(radians(0.5)), light);
  EXPECT_NEAR(f.in_light, 2 * alpha / radians(1), 1e-12);
  const ArcFractions s = sample_slerp(c.at(radians(-0.5)), c.at(radians(0.5)), light, kSteps);
  EXPECT_NEAR(f.in_light, s.in_light, sampling_tolerance(kSteps));
}

TEST(ArcFractions, RandomArcsMatchDenseSampling) {
  Pcg32 rng(20210107, 3);
  const int kArcs = 3000, kSamples = 40000;
  double worst = 0;
  int crossing = 0, horizon = 0, partial = 0;
  for (int i = 0; i < kArcs; ++i) {
    // Radii log-uniform in [0.1, 20] degrees; lights from just below the horizon to 70 deg.
    const double radius_deg = 0.1 * std::pow(200.0, rng.uniform());
    const LightModel light = make_light(-radius_deg + (70 + radius_deg) * rng.uniform(),
                                        360 * rng.uniform(), radius_deg);
    vec3 r0, r1;
    if (i % 4 == 3) {
      // Arbitrary arcs anywhere on the sphere.
      r0 = random_unit(rng);
      r1 = random_unit(rng);
    } else {
      // Arcs of 0 to 120 degrees on circles that miss, graze or cross the disk, placed so
      // that they often start, end or lie inside it.
      const double rho = radians(radius_deg);
      const double beta = (i % 50 == 0 ? 1.0 : 1.3 * rng.uniform()) * rho;
      const Circle c = circle_near(light, beta, kTwoPi * rng.uniform());
      const double theta = radians(120) * std::pow(rng.uniform(), 2.0);
      const double start = -theta - 1.5 * rho + (theta + 3 * rho) * rng.uniform();
      r0 = c.at(start);
      r1 = c.at(start + theta);
      if (rng.uniform() < 0.5) std::swap(r0, r1);
    }
    if (length(cross(r0, r1)) < 1e-9) continue;  // degenerate: tested separately
    const ArcFractions f = arc_fractions(r0, r1, light);
    const ArcFractions s = sample_slerp(r0, r1, light, kSamples);
    ASSERT_NEAR(f.in_light, s.in_light, sampling_tolerance(kSamples))
        << "arc " << i << " radius " << radius_deg;
    ASSERT_NEAR(f.below, s.below, sampling_tolerance(kSamples)) << "arc " << i;
    ASSERT_LE(f.in_light + f.below, 1.0 + 1e-15);
    const ArcFractions b = arc_fractions(r1, r0, light);
    ASSERT_NEAR(b.in_light, f.in_light, 1e-12) << "reversed arc " << i;
    ASSERT_NEAR(b.below, f.below, 1e-12) << "reversed arc " << i;
    worst = std::max({worst, std::abs(f.in_light - s.in_light), std::abs(f.below - s.below)});
    crossing += f.in_light > 0;
    partial += f.in_light > 0 && f.in_light < 1;
    horizon += f.below > 0 && f.below < 1;
  }
  // The generator must actually exercise the interesting cases.
  EXPECT_GT(crossing, kArcs / 3);
  EXPECT_GT(partial, kArcs / 4);
  EXPECT_GT(horizon, kArcs / 5);
  std::printf(
      "random arcs: worst |closed form - sampling| = %.3g (bound %.3g), %d meet the "
      "disk, %d cross the horizon\n",
      worst, sampling_tolerance(kSamples), crossing, horizon);
}

TEST(ArcFractions, DegenerateArcsUseTheEndpoint) {
  const LightModel light = make_light(25, 80, 2);
  const vec3 inside = light.from_plane(vec2(0.3, -0.2) * light.tan_radius);
  const vec3 outside = light.from_plane(vec2(1.5, 0.1) * light.tan_radius);
  const vec3 under = normalize(vec3(0.3, -0.1, -1));
  const vec3 nudge(1e-15, -2e-15, 1e-15);
  for (const vec3& eps : {vec3(0), nudge}) {
    ArcFractions f = arc_fractions(inside, inside + eps, light);
    EXPECT_EQ(f.in_light, 1.0);
    EXPECT_EQ(f.below, 0.0);
    f = arc_fractions(outside, outside + eps, light);
    EXPECT_EQ(f.in_light, 0.0);
    EXPECT_EQ(f.below, 0.0);
    f = arc_fractions(under, under + eps, light);
    EXPECT_EQ(f.in_light, 0.0);
    EXPECT_EQ(f.below, 1.0);
  }
  // Lengths do not matter.
  const ArcFractions g = arc_fractions(3.0 * inside, 0.5 * inside, light);
  EXPECT_EQ(g.in_light, 1.0);
}

TEST(ArcFractions, TinyArcsStayAccurate) {
  // A 2e-9 rad arc centred on the cone's edge spends half its time inside.
  const LightModel light = make_light(40, 0, 1);
  const Circle c = circle_near(light, 0, 0.7);
  const double rho = radians(1), h = 1e-9;
  const ArcFractions f = arc_fractions(c.at(rho - h), c.at(rho + h), light);
  // Endpoint rounding (1e-16 rad) over a 2e-9 rad arc: 1e-7 at most.
  EXPECT_NEAR(f.in_light, 0.5, 1e-6);
}

TEST(ArcFractions, AntipodalArcsGoOverTheZenithSide) {
  const LightModel light = make_light(30, 0, 10);
  Pcg32 rng(5, 5);
  for (int i = 0; i < 50; ++i) {
    const vec3 r0 = random_unit(rng);
    const vec3 r1 = -r0;
    const vec3 w = normalize(vec3(0, 1, 0) - r0.y * r0);
    const ArcFractions f = arc_fractions(r0, r1, light);
    const ArcFractions s = sample_circle(r0, w, 0, kPi, light, kSteps);
    EXPECT_NEAR(f.in_light, s.in_light, sampling_tolerance(kSteps)) << i;
    EXPECT_NEAR(f.below, s.below, sampling_tolerance(kSteps)) << i;
    const ArcFractions b = arc_fractions(r1, r0, light);
    EXPECT_NEAR(b.in_light, f.in_light, 1e-12) << i;
    EXPECT_NEAR(b.below, f.below, 1e-12) << i;
  }
  // Vertical endpoints: the half circle through the light's azimuth, which here passes
  // through the light's centre: 2 rho of the pi radians are in the light.
  const ArcFractions z = arc_fractions(vec3(0, 1, 0), vec3(0, -1, 0), light);
  EXPECT_NEAR(z.in_light, 2 * radians(10) / kPi, 1e-12);
  EXPECT_NEAR(z.below, 0.5, 1e-12);
}

TEST(ArcFractions, BadInputNamesTheArgument) {
  const LightModel light = make_light(30, 0, 1);
  try {
    arc_fractions(vec3(0), vec3(0, 1, 0), light);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("r0 must be a finite non-zero vector"), std::string::npos)
        << e.what();
  }
  try {
    arc_fractions(vec3(0, 1, 0), vec3(NAN, 0, 1), light);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("r1 must be"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sg
