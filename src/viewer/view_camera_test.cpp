// The viewer's camera moves: home is the scene's camera exactly (an unedited view renders
// as the file does); an orbit keeps the distances to its target, turns back to the start
// after 360 degrees and raises the camera for a positive pitch; the target is where the
// view ray meets the water; a look turns the view about the position; fly moves along the
// view direction without turning it; a dolly keeps the direction and scales the distance;
// moves that would leave the viewer's ranges are refused.
#include "viewer/view_camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scene/camera.h"
#include "scene/scene.h"
#include "testing/paths.h"
#include "viewer/view_edits.h"

namespace sg::viewer {
namespace {

constexpr double kPi = std::numbers::pi;

Scene simple() {
  return load_scene(sg::testing::source_dir() + "/scenes/simple.json");
}

// A camera with a look_at off the target, so that a rigid motion and a "look at the
// target" differ.
CameraDesc tilted() {
  CameraDesc c;
  c.position = vec3(1.5, 4, 2);
  c.look_at = vec3(-3, 0.5, -40);
  c.up = vec3(0, 1, 0);
  c.vfov_deg = 35;
  return c;
}

void expect_near(const vec3& a, const vec3& b, double tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}
vec3 dir(const CameraDesc& c) {
  return glm::normalize(c.look_at - c.position);
}

TEST(ViewCamera, HomeIsTheScenesCameraExactly) {
  const Scene s = simple();
  const ViewEdits home = edits_of(s);
  const Scene v = edited_scene(s, home);
  EXPECT_EQ(v.camera.position, s.camera.position);
  EXPECT_EQ(v.camera.look_at, s.camera.look_at);
  EXPECT_EQ(v.camera.up, s.camera.up);
  EXPECT_EQ(v.camera.vfov_deg, s.camera.vfov_deg);
  // A moved camera is what the view's scene holds, and going home restores the file's.
  ViewEdits moved = home;
  moved.camera = orbit(s.camera, orbit_target(s.camera), 0.3, 0.1);
  const Scene m = edited_scene(s, moved);
  EXPECT_EQ(m.camera.position, moved.camera.position);
  EXPECT_NE(m.camera.position, s.camera.position);
  moved.camera = home.camera;
  EXPECT_EQ(scene_to_json(edited_scene(s, moved)), scene_to_json(s));
}

TEST(ViewCamera, TargetIsWhereTheViewMeetsTheWater) {
  const CameraDesc c = tilted();
  const vec3 t = orbit_target(c);
  EXPECT_NEAR(t.y, 0, 1e-12);
  EXPECT_NEAR(glm::length(glm::cross(glm::normalize(t - c.position), dir(c))), 0, 1e-12);
  // Looking above the horizon: a point on the ray at the look_at's distance.
  CameraDesc up = c;
  up.look_at = vec3(0, 10, -50);
  const vec3 u = orbit_target(up);
  expect_near(u, up.look_at, 1e-9);
}

TEST(ViewCamera, OrbitKeepsTheDistancesToItsTarget) {
  const CameraDesc c = tilted();
  const vec3 t = orbit_target(c);
  const CameraDesc o = orbit(c, t, 0.7, 0.2);
  EXPECT_NE(o.position, c.position);
  EXPECT_NEAR(glm::length(o.position - t), glm::length(c.position - t), 1e-9);
  EXPECT_NEAR(glm::length(o.look_at - t), glm::length(c.look_at - t), 1e-9);
  // A rigid motion: the view ray still passes through the target.
  EXPECT_NEAR(glm::length(glm::cross(glm::normalize(t - o.position), dir(o))), 0, 1e-9);
  EXPECT_EQ(o.up, c.up);
  EXPECT_EQ(o.vfov_deg, c.vfov_deg);
}

TEST(ViewCamera, OrbitBy360DegreesReturnsToTheStart) {
  const CameraDesc c = tilted();
  const vec3 t = orbit_target(c);
  CameraDesc o = c;
  for (int k = 0; k < 36; ++k)
    o = orbit(o, t, 2 * kPi / 36, 0);
  expect_near(o.position, c.position, 1e-9);
  expect_near(o.look_at, c.look_at, 1e-9);
  // Half way round the camera is on the other side of the target.
  const CameraDesc half = orbit(c, t, kPi, 0);
  expect_near(half.position - t, vec3(-(c.position - t).x, (c.position - t).y, -(c.position - t).z),
              1e-9);
  // Pitch up and back down returns too; a positive pitch raises the camera.
  const CameraDesc raised = orbit(c, t, 0, 0.3);
  EXPECT_GT(raised.position.y, c.position.y + 1);
  const CameraDesc back = orbit(raised, t, 0, -0.3);
  expect_near(back.position, c.position, 1e-9);
  expect_near(back.look_at, c.look_at, 1e-9);
}

TEST(ViewCamera, OrbitUnderTheWaterIsRefused) {
  const CameraDesc c = tilted();
  const CameraDesc o = orbit(c, orbit_target(c), 0, -1.0);  // would sink the camera
  EXPECT_EQ(o.position, c.position);
  EXPECT_EQ(o.look_at, c.look_at);
}

TEST(ViewCamera, LookTurnsTheViewAboutThePosition) {
  const CameraDesc c = tilted();
  const CameraDesc l = look(c, 0.4, 0.1);
  EXPECT_EQ(l.position, c.position);
  EXPECT_NEAR(glm::length(l.look_at - l.position), glm::length(c.look_at - c.position), 1e-9);
  EXPECT_NEAR(std::acos(glm::dot(dir(l), dir(c))), 0.4, 0.15);  // about the turn
  EXPECT_GT(dir(l).y, dir(c).y);                                // positive pitch looks up
  // Straight up is refused.
  EXPECT_EQ(look(c, 0, kPi / 2).look_at, c.look_at);
}

TEST(ViewCamera, FlyMovesAlongTheViewDirection) {
  const CameraDesc c = tilted();
  const CameraDesc f = fly(c, 0, 0, 5);
  expect_near(f.position - c.position, 5.0 * dir(c), 1e-9);
  expect_near(f.look_at - c.look_at, 5.0 * dir(c), 1e-9);
  expect_near(dir(f), dir(c), 1e-12);
  // Sideways: horizontal and perpendicular to the view; up: vertical.
  const vec3 side = fly(c, 2, 0, 0).position - c.position;
  EXPECT_NEAR(glm::length(side), 2, 1e-12);
  EXPECT_NEAR(side.y, 0, 1e-12);
  EXPECT_NEAR(glm::dot(side, dir(c)), 0, 1e-12);
  // To the right in the image: along the camera model's right axis.
  EXPECT_NEAR(glm::dot(side, CameraModel(c, 160, 90).right()), 2, 1e-9);
  expect_near(fly(c, 0, 1.5, 0).position - c.position, vec3(0, 1.5, 0), 1e-12);
  // Below the water is refused.
  EXPECT_EQ(fly(c, 0, -10, 0).position, c.position);
}

TEST(ViewCamera, DollyScalesTheDistanceAndKeepsTheDirection) {
  const CameraDesc c = tilted();
  const vec3 t = orbit_target(c);
  const CameraDesc d = dolly(c, t, 0.5);
  EXPECT_NEAR(glm::length(d.position - t), 0.5 * glm::length(c.position - t), 1e-9);
  expect_near(dir(d), dir(c), 1e-12);
  EXPECT_EQ(dolly(c, t, 1e-9).position, c.position);  // into the target: refused
}

}  // namespace
}  // namespace sg::viewer
