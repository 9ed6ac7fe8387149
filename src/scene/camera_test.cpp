// The camera: pixel centres and corners land where the scene spec says, projection
// inverts ray generation, and ray differentials and footprints match finite differences
// of neighbouring rays.
#include "scene/camera.h"

#include <gtest/gtest.h>

#include <cmath>

#include "testing/testing.h"

namespace sg {
namespace {

// The plane y = 0 along the ray o + s d (d reaching it: d.y of the other sign than o.y).
struct PlaneHit {
  bool hit;
  double s;
  vec3 point;
};
PlaneHit plane_hit(const vec3& o, const vec3& d) {
  if (!(o.y * d.y < 0)) return PlaneHit{false, 0, vec3(0)};
  const double s = -o.y / d.y;
  return PlaneHit{true, s, o + s * d};
}

double angle(const vec3& a, const vec3& b) {
  return std::atan2(length(cross(a, b)), dot(a, b));
}

TEST(Camera, CentreCornersAndEdges) {
  Scene s = testing::project_scene("simple");  // 640x360, vfov 40
  CameraModel cam(s.camera, s.width, s.height);
  const vec3 w = normalize(s.camera.look_at - s.camera.position);
  // The image centre is the viewing direction.
  EXPECT_LT(angle(cam.direction(320, 180), w), 1e-12);
  // Top and bottom edge centres: vfov / 2 from the axis; left and right: hfov / 2 with
  // tan(hfov/2) = tan(vfov/2) * W / H.
  const double half_v = radians(20), half_h = std::atan(std::tan(half_v) * 640 / 360);
  EXPECT_NEAR(angle(cam.direction(320, 0), w), half_v, 1e-12);
  EXPECT_NEAR(angle(cam.direction(320, 360), w), half_v, 1e-12);
  EXPECT_NEAR(angle(cam.direction(0, 180), w), half_h, 1e-12);
  EXPECT_NEAR(angle(cam.direction(640, 180), w), half_h, 1e-12);
  // j grows downwards, i to the right: pixel (0, 0) is up and left.
  EXPECT_GT(dot(cam.direction(0, 0), cam.up()), 0);
  EXPECT_LT(dot(cam.direction(0, 0), cam.right()), 0);
  EXPECT_GT(cam.direction(0.5, 0.5).y, cam.direction(0.5, 359.5).y);
  // Right is horizontal when up is the world's up.
  EXPECT_NEAR(cam.right().y, 0, 1e-15);
  // The centre of pixel (i, j) is (i + 1/2, j + 1/2): the two middle pixels straddle the axis.
  EXPECT_NEAR(angle(cam.direction(319.5, 180), w), angle(cam.direction(320.5, 180), w), 1e-14);
}

TEST(Camera, ProjectInvertsDirection) {
  Scene s = testing::project_scene("high");
  CameraModel cam(s.camera, 160, 90);
  for (double px : {0.0, 3.25, 80.0, 159.9}) {
    for (double py : {0.0, 44.5, 89.99}) {
      double x, y;
      ASSERT_TRUE(cam.project(cam.direction(px, py) * 3.7, x, y));
      EXPECT_NEAR(x, px, 1e-10);
      EXPECT_NEAR(y, py, 1e-10);
    }
  }
  double x, y;
  EXPECT_FALSE(cam.project(-cam.forward(), x, y));
}

TEST(Camera, RayDifferentialsMatchDifferences) {
  Scene s = testing::project_scene("simple");
  CameraModel cam(s.camera, s.width, s.height);
  const double h = 0.5;
  vec3 dx = (cam.direction(100 + h, 300) - cam.direction(100 - h, 300)) / (2 * h);
  vec3 dy = (cam.direction(100, 300 + h) - cam.direction(100, 300 - h)) / (2 * h);
  EXPECT_LT(length(dx - cam.ddir_dpx()), 1e-14);  // d is linear in (px, py)
  EXPECT_LT(length(dy - cam.ddir_dpy()), 1e-14);
}

TEST(Camera, FootprintOnThePlaneMatchesNeighbouringRays) {
  Scene s = testing::project_scene("simple");
  CameraModel cam(s.camera, s.width, s.height);
  const vec3 o = cam.position(), up(0, 1, 0);
  for (double py : {200.5, 260.5, 359.5}) {
    for (double px : {10.5, 320.5, 600.5}) {
      const vec3 d = cam.direction(px, py);
      const PlaneHit c = plane_hit(o, d);
      ASSERT_TRUE(c.hit);
      vec3 fx = transfer_differential(d, c.s, cam.ddir_dpx(), up);
      vec3 fy = transfer_differential(d, c.s, cam.ddir_dpy(), up);
      const double h = 1e-3;  // pixels
      vec3 nx = (plane_hit(o, cam.direction(px + h, py)).point -
                 plane_hit(o, cam.direction(px - h, py)).point) /
                (2 * h);
      vec3 ny = (plane_hit(o, cam.direction(px, py + h)).point -
                 plane_hit(o, cam.direction(px, py - h)).point) /
                (2 * h);
      // Relative agreement: central differences are second order in h; the footprint
      // grows to metres per pixel near the horizon.
      EXPECT_LT(length(fx - nx), 1e-6 * length(nx)) << px << "," << py;
      EXPECT_LT(length(fy - ny), 1e-6 * length(ny)) << px << "," << py;
      EXPECT_NEAR(fx.y, 0, 1e-12);
    }
  }
}

TEST(Camera, FootprintOnATiltedTangentPlane) {
  // A plane through p0 with normal m: the transfer formula against exact intersections.
  Scene s = testing::project_scene("simple");
  CameraModel cam(s.camera, s.width, s.height);
  const vec3 o = cam.position(), m = normalize(vec3(0.2, 1, -0.3));
  const vec3 d = cam.direction(300.5, 250.5);
  const double s0 = -dot(o, m) / dot(d, m);
  auto hit = [&](const vec3& dir) { return o + dir * (-dot(o, m) / dot(dir, m)); };
  const double h = 1e-3;
  vec3 nx = (hit(cam.direction(300.5 + h, 250.5)) - hit(cam.direction(300.5 - h, 250.5))) / (2 * h);
  vec3 fx = transfer_differential(d, s0, cam.ddir_dpx(), m);
  EXPECT_LT(length(fx - nx), 1e-6 * length(nx));
}

}  // namespace
}  // namespace sg
