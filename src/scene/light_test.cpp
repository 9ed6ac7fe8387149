// The light disk and the light plane (Podee et al. 2021, Eq. 8).
#include "scene/light.h"

#include <gtest/gtest.h>

#include <cmath>

#include "kernel/kernel_types.h"
#include "math/rng.h"

namespace sg {
namespace {

TEST(Light, FrameIsOrthonormalAndRightHanded) {
  for (vec3 dir : {vec3(0, 0.207912, -0.978148), vec3(0.3, 0.5, 0.1), vec3(0, 1, 0)}) {
    LightModel l(LightDesc{dir, 0.27, Rgb(1.0), false});
    EXPECT_NEAR(length(l.L), 1, 1e-15);
    EXPECT_NEAR(length(l.e1), 1, 1e-15);
    EXPECT_NEAR(length(l.e2), 1, 1e-15);
    EXPECT_NEAR(dot(l.e1, l.L), 0, 1e-15);
    EXPECT_NEAR(dot(l.e2, l.L), 0, 1e-15);
    EXPECT_LT(length(cross(l.e1, l.e2) - l.L), 1e-15);
  }
}

TEST(Light, KernelLightCarriesEveryFieldOfTheModel) {
  // What the frames and the queries hand the kernel: every field the model's (a forgotten
  // one would be the struct's zero, or garbage).
  for (bool visible : {false, true}) {
    const LightModel l(LightDesc{vec3(0.3, 0.5, 0.1), 0.27, Rgb(1.0), visible});
    const kd::Light k = l.kernel_light();
    EXPECT_EQ(k.L, l.L);
    EXPECT_EQ(k.e1, l.e1);
    EXPECT_EQ(k.e2, l.e2);
    EXPECT_EQ(k.radius, l.radius);
    EXPECT_EQ(k.cos_radius, l.cos_radius);
    EXPECT_EQ(k.sin_radius, l.sin_radius);
    EXPECT_EQ(k.tan_radius, l.tan_radius);
    EXPECT_EQ(k.chord2, l.chord2);
    EXPECT_EQ(k.visible, visible);
    EXPECT_GT(k.radius, 0.0);
  }
}

TEST(Light, ConeTestEqualsDiskTestOnThePlane) {
  LightModel l(LightDesc{{0.1, 0.3, -1}, 2.0, Rgb(1.0), false});
  Pcg32 rng(5, 5);
  int inside = 0;
  for (int k = 0; k < 20000; ++k) {
    // Directions within 4 degrees of L.
    vec2 p(rng.uniform() * 0.14 - 0.07, rng.uniform() * 0.14 - 0.07);
    vec3 r = l.from_plane(p);
    EXPECT_NEAR(length(l.to_plane(r) - p), 0, 1e-13);
    const bool by_angle = std::acos(std::min(1.0, dot(r, l.L))) <= l.radius;
    const bool by_plane = length(p) <= l.tan_radius;
    if (std::fabs(length(p) - l.tan_radius) > 1e-12) {
      EXPECT_EQ(by_angle, by_plane);
    }
    EXPECT_EQ(l.contains(r), by_plane);
    inside += by_plane;
  }
  EXPECT_GT(inside, 1000);
}

TEST(Light, PlaneCoordinatesAreAlongTheFrame) {
  // Eq. 8 in the model's frame: Phi(r) = (r . e1, r . e2) / (r . L), and the direction
  // through p is along L + p.x e1 + p.y e2 (the maps' round trip alone would not see a
  // frame swapped or turned).
  LightModel l(LightDesc{{0.3, 0.15, -1}, 0.27, Rgb(1.0), false});
  Pcg32 rng(6, 6);
  for (int k = 0; k < 200; ++k) {
    const vec3 r =
        normalize(l.L + vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5));
    const vec2 p = l.to_plane(r);
    EXPECT_NEAR(p.x, dot(r, l.e1) / dot(r, l.L), 1e-14);
    EXPECT_NEAR(p.y, dot(r, l.e2) / dot(r, l.L), 1e-14);
    const vec2 q(rng.uniform() - 0.5, rng.uniform() - 0.5);
    const vec3 d = normalize(l.L + q.x * l.e1 + q.y * l.e2);
    EXPECT_LT(length(l.from_plane(q) - d), 1e-14);
    EXPECT_NEAR(l.elevation_on_plane(q), d.y / dot(d, l.L), 1e-14);
  }
}

TEST(Light, GreatCirclesMapToLines) {
  // Gnomonic projection: three directions on one great circle project to collinear points.
  LightModel l(LightDesc{{0, 0.2, -1}, 0.27, Rgb(1.0), false});
  vec3 a = normalize(l.L + vec3(0.05, 0.02, 0)), b = normalize(l.L + vec3(-0.03, 0.04, 0.01));
  double theta = std::acos(dot(a, b));
  vec2 pa = l.to_plane(a), pb = l.to_plane(b);
  for (double s : {0.25, 0.5, 0.8}) {
    vec3 r = (std::sin((1 - s) * theta) * a + std::sin(s * theta) * b) / std::sin(theta);
    vec2 p = l.to_plane(r);
    double cr = (pb.x - pa.x) * (p.y - pa.y) - (pb.y - pa.y) * (p.x - pa.x);
    EXPECT_NEAR(cr, 0, 1e-15);
  }
}

TEST(Light, ElevationOnPlaneIsTheHeightOfTheDirectionScaledToUnitL) {
  // elevation_on_plane(p) = r.y / (r . L) for the direction r through p: its sign is r's
  // elevation's, and the horizon is the line where it vanishes.
  LightModel l(LightDesc{{0.3, 0.15, -1}, 0.27, Rgb(1.0), false});
  Pcg32 rng(5, 5);
  int below = 0;
  for (int k = 0; k < 2000; ++k) {
    const vec2 p(2 * rng.uniform() - 1, 2 * rng.uniform() - 1);
    const vec3 r = l.from_plane(p);
    EXPECT_NEAR(l.elevation_on_plane(p), r.y / dot(r, l.L), 1e-14);
    below += l.elevation_on_plane(p) <= 0;
  }
  EXPECT_GT(below, 100);  // the square reaches below the horizon
}

}  // namespace
}  // namespace sg
