// A moving camera (format /3): its pose at hand-picked times between and outside the keys,
// the same from the host (camera_pose) and from the kernel's own keys of a frame
// (camera_at in kernel/camera.glsl, through build_kernel_inputs), a still camera left as
// the fixed one bit for bit, and the motion `info` reports.
#include <gtest/gtest.h>

#include <cmath>

#include "kernel/kernel_double.h"
#include "scene/camera_path.h"
#include "shading/kernel_frame.h"
#include "testing/testing.h"

namespace sg {
namespace {

// A pan: 4 m forward in 2 s while the look-at point sweeps 20 m across, then 3 m up in 1 s.
CameraDesc pan() {
  CameraDesc c;
  c.up = {0, 2, 0};  // any length
  c.vfov_deg = 40;
  c.keyframes = {{0.0, {0, 2.5, 0}, {-10, 0, -60}},
                 {2.0, {0, 2.5, -4}, {10, 0, -60}},
                 {3.0, {0, 5.5, -4}, {10, 0, -60}}};
  c.position = c.keyframes[0].position;
  c.look_at = c.keyframes[0].look_at;
  return c;
}

void expect_near(const vec3& a, const vec3& b, double tol = 1e-12) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

TEST(CameraPath, PoseAtHandPickedTimes) {
  const CameraDesc c = pan();
  struct Case {
    double t;
    vec3 position, look_at;
  };
  for (const Case& k : {Case{-5.0, {0, 2.5, 0}, {-10, 0, -60}},     // before the first: held
                        Case{0.0, {0, 2.5, 0}, {-10, 0, -60}},      // at the first key
                        Case{0.5, {0, 2.5, -1}, {-5, 0, -60}},      // a quarter of the way
                        Case{1.0, {0, 2.5, -2}, {0, 0, -60}},       // halfway
                        Case{2.0, {0, 2.5, -4}, {10, 0, -60}},      // the middle key
                        Case{2.25, {0, 3.25, -4}, {10, 0, -60}},    // into the second segment
                        Case{3.0, {0, 5.5, -4}, {10, 0, -60}},      // the last key
                        Case{99.0, {0, 5.5, -4}, {10, 0, -60}}}) {  // after the last: held
    SCOPED_TRACE(k.t);
    const CameraPoseAt p = camera_pose(c, k.t);
    expect_near(p.position, k.position);
    expect_near(p.look_at, k.look_at);
  }
  // At t = 1 the camera looks straight ahead: the basis of /1 for that pose.
  const CameraModel m(camera_at(c, 1.0), 64, 36);
  expect_near(m.forward(), normalize(vec3(0, -2.5, -58)));
  expect_near(m.right(), vec3(1, 0, 0));
  const CameraModel fixed(CameraDesc{{0, 2.5, -2}, {0, 0, -60}, {0, 1, 0}, 40, {}}, 64, 36);
  EXPECT_EQ(m.forward(), fixed.forward());
  EXPECT_EQ(m.up(), fixed.up());
}

TEST(CameraPath, FrameKeysGiveTheHostsPoseInTheKernel) {
  Scene s = testing::small_scene({Wave{0.01, {0.5, -1.0}, 2.2, 0}});
  s.camera = pan();
  s.animation = AnimationDesc{1.95, 10, 10, 1.0};  // frame 0: [1.85, 1.95]; frame 1 spans key 2
  for (int frame : {0, 1, 5}) {
    SCOPED_TRACE(frame);
    const FrameTime ft = frame_time(s, frame);
    const SceneModel m = frame_model(s, ft);
    KernelInputsD in;
    build_kernel_inputs(m, ft, 4, 0, in);
    const kd::CameraKeys& k = in.frame.camera_keys;
    ASSERT_GE(k.count, 2);
    EXPECT_EQ(k.count, frame == 1 ? 3 : 2);  // the key at t = 2 inside frame 1's shutter
    EXPECT_DOUBLE_EQ(k.time[0], -ft.duration());
    EXPECT_DOUBLE_EQ(k.time[k.count - 1], 0.0);
    const vec3 origin = m.camera.position();
    for (double u : {0.0, 0.1, 0.37, 0.5, 0.99, 1.0}) {
      const double t = ft.start + u * ft.duration();
      const kd::Camera kc = kd::camera_at(in.frame, t - ft.end);
      const CameraModel host(camera_at(s.camera, t), s.width, s.height);
      expect_near(kc.position + vec3(origin.x, 0, origin.z), host.position(), 1e-12);
      expect_near(kc.forward, host.forward(), 1e-12);
      expect_near(kc.right, host.right(), 1e-12);
      expect_near(kc.up, host.up(), 1e-12);
    }
    // At the display time the kernel's camera is the frame model's.
    const kd::Camera end = kd::camera_at(in.frame, 0.0);
    expect_near(end.forward, m.camera.forward(), 1e-15);
  }
}

TEST(CameraPath, AStillCameraIsTheFixedCameraBitForBit) {
  Scene s = testing::small_scene({Wave{0.01, {0.5, -1.0}, 2.2, 0}});
  Scene moving = s;
  moving.camera.keyframes = {{-1.0, s.camera.position, s.camera.look_at},
                             {5.0, s.camera.position, s.camera.look_at}};
  Scene late = s;  // past its last key: held there
  late.camera.keyframes = {{-3.0, {0, 9, 9}, {0, 0, -60}},
                           {-2.0, s.camera.position, s.camera.look_at}};
  for (const Scene* v : {&moving, &late}) {
    const FrameTime ft = frame_time(*v, 3);
    KernelInputsD a, b;
    build_kernel_inputs(SceneModel(s), ft, 4, 0, a);
    build_kernel_inputs(frame_model(*v, ft), ft, 4, 0, b);
    EXPECT_EQ(b.frame.camera_keys.count, 0);
    EXPECT_EQ(a.frame.camera.position, b.frame.camera.position);
    EXPECT_EQ(a.frame.camera.forward, b.frame.camera.forward);
    EXPECT_EQ(a.frame.camera.right, b.frame.camera.right);
    EXPECT_EQ(a.texels, b.texels);
  }
}

TEST(CameraPath, MotionPerSegment) {
  const std::vector<CameraSegmentMotion> m = camera_motion(pan());
  ASSERT_EQ(m.size(), 2u);
  EXPECT_DOUBLE_EQ(m[0].speed, 2.0);  // 4 m in 2 s
  EXPECT_DOUBLE_EQ(m[1].speed, 3.0);  // 3 m up in 1 s
  // The first segment turns the view from (-10, -2.5, -60) to (10, -2.5, -56) about the
  // vertical (and a little in pitch): about 19.6 degrees in 2 s.
  const double yaw =
      degrees(std::acos(dot(normalize(vec3(-10, -2.5, -60)), normalize(vec3(10, -2.5, -56)))));
  EXPECT_NEAR(m[0].turn_rate_deg, yaw / 2, 0.05);
  EXPECT_GT(m[1].turn_rate_deg, 0);
  EXPECT_TRUE(camera_motion(CameraDesc{}).empty());
}

}  // namespace
}  // namespace sg
