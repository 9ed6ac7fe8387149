// The viewer's camera in motion (viewer/camera_record.h): a frame whose camera moved is
// keyed from the previous camera at the shutter's opening to the current one at its end
// (and left alone when nothing moved, the camera is keyed already or the shutter is empty);
// the recorder keeps keys at increasing times at least its gap apart, the pose of a
// standing clock replacing the last; the recorded scene written to a file loads back
// through the scene loader with the very keys recorded and an animation covering them.
#include "viewer/camera_record.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "base/error.h"
#include "scene/camera_path.h"
#include "testing/paths.h"
#include "viewer/view_camera.h"

namespace sg::viewer {
namespace {

namespace fs = std::filesystem;

Scene simple() {
  return load_scene(sg::testing::source_dir() + "/scenes/simple.json");
}

TEST(MovingViewScene, KeysThePreviousCameraAtTheOpeningAndTheCurrentAtTheEnd) {
  Scene s = simple();
  const CameraDesc before = s.camera;
  s.camera = orbit(before, orbit_target(before), 0.05, 0);
  const FrameTime ft = frame_time(s, 3);
  const Scene m = moving_view_scene(s, before, ft);
  ASSERT_TRUE(m.camera.moving());
  ASSERT_EQ(m.camera.keyframes.size(), 2u);
  EXPECT_EQ(m.camera.keyframes[0].time, ft.start);
  EXPECT_EQ(m.camera.keyframes[0].position, before.position);
  EXPECT_EQ(m.camera.keyframes[0].look_at, before.look_at);
  EXPECT_EQ(m.camera.keyframes[1].time, ft.end);
  EXPECT_EQ(m.camera.keyframes[1].position, s.camera.position);
  EXPECT_EQ(m.camera.keyframes[1].look_at, s.camera.look_at);
  // At the display time the frame's camera is the current one: what a still frame shows.
  const CameraDesc at_end = camera_at(m.camera, ft.end);
  EXPECT_EQ(at_end.position, s.camera.position);
  EXPECT_EQ(at_end.look_at, s.camera.look_at);
  EXPECT_EQ(m.format_version(), 3);
}

TEST(MovingViewScene, StillCameraKeyedSceneOrEmptyShutterIsTheSceneItself) {
  Scene s = simple();
  const FrameTime ft = frame_time(s, 3);
  EXPECT_EQ(scene_to_json(moving_view_scene(s, s.camera, ft)), scene_to_json(s));
  const CameraDesc before = s.camera;
  Scene moved = s;
  moved.camera = fly(before, 1, 0, 0);
  EXPECT_EQ(scene_to_json(moving_view_scene(moved, before, FrameTime{3, ft.end, ft.end})),
            scene_to_json(moved));
  Scene keyed = s;
  keyed.camera.keyframes = {{0.0, before.position, before.look_at},
                            {1.0, moved.camera.position, moved.camera.look_at}};
  EXPECT_EQ(scene_to_json(moving_view_scene(keyed, before, ft)), scene_to_json(keyed));
}

TEST(CameraRecorder, KeysIncreaseAtLeastTheGapApartAndAStandingClockReplacesThePose) {
  const Scene s = simple();
  CameraRecorder r(0.1);
  CameraDesc c = s.camera;
  r.add(0.0, c);
  c = fly(c, 1, 0, 0);
  r.add(0.0, c);  // the clock stood: the pose replaced
  ASSERT_EQ(r.keys().size(), 1u);
  EXPECT_EQ(r.keys()[0].position, c.position);
  r.add(0.05, c);  // the second key: kept whatever the gap
  c = fly(c, 1, 0, 0);
  r.add(0.12, c);  // 0.12 - 0.0 >= 0.1: a third key
  c = fly(c, 1, 0, 0);
  r.add(0.15, c);  // 0.15 - 0.05 < 0.1: replaces the last (time and pose)
  ASSERT_EQ(r.keys().size(), 3u);
  EXPECT_EQ(r.keys()[2].time, 0.15);
  EXPECT_EQ(r.keys()[2].position, c.position);
  r.add(0.1, fly(c, 1, 0, 0));  // back in time (a scrub): the last pose replaced
  ASSERT_EQ(r.keys().size(), 3u);
  EXPECT_EQ(r.keys()[2].time, 0.15);
  for (size_t k = 1; k < r.keys().size(); ++k)
    EXPECT_GT(r.keys()[k].time, r.keys()[k - 1].time);
  // A keyed camera is recorded at its pose at the time.
  CameraDesc keyed = s.camera;
  keyed.keyframes = {{0.0, {0, 3, 0}, {0, 0, -50}}, {2.0, {0, 3, -4}, {10, 0, -50}}};
  CameraRecorder k(0.1);
  k.add(1.0, keyed);
  EXPECT_EQ(k.keys()[0].position, camera_pose(keyed, 1.0).position);
}

TEST(CameraRecorder, TheWrittenPathLoadsBackWithItsKeys) {
  const Scene s = simple();
  CameraRecorder r(0.25 / s.animation.fps);
  CameraDesc c = s.camera;
  const vec3 target = orbit_target(c);
  for (int f = 0; f < 12; ++f)  // frames 5 to 16 of the scene's clock
    r.add(s.frame_time(5 + f), orbit(c, target, 0.02 * f, 0.004 * f));
  const Scene rec = r.scene(s);
  const fs::path dir = fs::path(sg::testing::binary_dir()) / "test_out" / "camera_record";
  fs::create_directories(dir);
  const std::string path = (dir / "path.json").string();
  write_recording(path, rec);
  const Scene back = load_scene(path);  // the scene loader's checks
  EXPECT_EQ(back.format_version(), 3);
  ASSERT_EQ(back.camera.keyframes.size(), 12u);
  for (size_t k = 0; k < 12; ++k) {
    EXPECT_EQ(back.camera.keyframes[k].time, r.keys()[k].time);
    EXPECT_EQ(back.camera.keyframes[k].position, r.keys()[k].position);
    EXPECT_EQ(back.camera.keyframes[k].look_at, r.keys()[k].look_at);
  }
  // The animation: from the first key, the frames up to the last, the scene's fps.
  EXPECT_EQ(back.animation.t0, s.frame_time(5));
  EXPECT_EQ(back.animation.frames, 12);
  EXPECT_EQ(back.animation.fps, s.animation.fps);
  EXPECT_NEAR(back.frame_time(11), s.frame_time(16), 1e-12);
  // Everything else is the scene's.
  Scene same = back;
  same.camera = s.camera;
  same.animation = s.animation;
  EXPECT_EQ(scene_to_json(same), scene_to_json(s));
  // The whole file: no temporary left beside it.
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir))
    files += e.is_regular_file();
  EXPECT_EQ(files, 1);
}

TEST(CameraRecorder, OneKeyIsAFixedCameraAndNoneIsAnError) {
  const Scene s = simple();
  CameraRecorder r(0.01);
  EXPECT_THROW(r.scene(s), Error);
  r.add(0.5, fly(s.camera, 2, 0, 0));
  const Scene one = r.scene(s);
  EXPECT_FALSE(one.camera.moving());
  EXPECT_EQ(one.camera.position, fly(s.camera, 2, 0, 0).position);
  EXPECT_EQ(one.animation.t0, 0.5);
  EXPECT_EQ(one.animation.frames, 1);
}

}  // namespace
}  // namespace sg::viewer
