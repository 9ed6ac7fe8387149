// Scene loading: every validation rule rejects its example file with a message that names
// the key and the rule; good scenes load with their values and defaults.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "base/atomic_file.h"
#include "base/error.h"
#include "scene/scene.h"
#include "scene/scene_limits.h"
#include "scene/waves.h"
#include "testing/testing.h"
#include "testing/wind_sea.h"

namespace sg {
namespace {

struct BadCase {
  const char* file;
  const char* message;  // the whole message after "<path>: "
};

const BadCase kBad[] = {
    {"missing_camera", "camera: missing (required)"},
    {"missing_t0", "animation.t0: missing (required)"},
    {"bad_format",
     "format: must be \"sunglint-scene/1\", \"sunglint-scene/2\" or \"sunglint-scene/3\" (got "
     "\"sunglint-scene/4\")"},
    {"unknown_top_key", "foo: unknown key"},
    {"unknown_camera_key", "camera.fov: unknown key"},
    {"width_string", "image.width: must be a number"},
    {"width_fraction", "image.width: must be an integer"},
    {"width_zero", "image.width: must be an integer in [1, 16384]"},
    {"height_zero", "image.height: must be an integer in [1, 16384]"},
    {"image_not_object", "image: must be an object"},
    {"name_number", "name: must be a string"},
    {"vfov_zero", "camera.vfov_deg: must be in [0.001, 179] degrees, got 0"},
    {"vfov_180", "camera.vfov_deg: must be in [0.001, 179] degrees, got 180"},
    {"look_at_position", "camera.look_at: must differ from camera.position"},
    {"up_zero", "camera.up: must not be zero-length"},
    {"up_parallel", "camera.up: must not be parallel to the viewing direction"},
    {"camera_below_water", "camera.position: must be above the water at rest (y >= 0.001 m)"},
    {"position_two", "camera.position: must be an array of 3 numbers"},
    {"position_string", "camera.position[1]: must be a number"},
    {"light_zero", "light.direction: must not be zero-length"},
    {"light_radius_zero", "light.angular_radius_deg: must be in [0.001, 89] degrees, got 0"},
    {"light_radius_90", "light.angular_radius_deg: must be in [0.001, 89] degrees, got 90"},
    {"light_radiance_negative", "light.radiance: must be >= 0"},
    {"light_visible_string", "light.visible: must be true or false"},
    {"sky_negative", "sky.radiance: must be >= 0"},
    {"geometry_unknown",
     "surface.geometry: must be one of \"flat\", \"displaced\" (got \"bumpy\")"},
    {"fresnel_unknown", "surface.fresnel: must be one of \"none\", \"schlick\" (got \"fancy\")"},
    {"sea_negative", "surface.sea_radiance: must be >= 0"},
    {"waves_not_array", "surface.waves: must be an array of wave objects"},
    {"amplitude_negative", "surface.waves[3].amplitude: must be >= 0"},
    {"wave_vector_three", "surface.waves[0].wave_vector: must be an array of 2 numbers"},
    {"wave_missing_frequency", "surface.waves[1].angular_frequency: missing (required)"},
    {"wave_unknown_key", "surface.waves[2].speed: unknown key"},
    {"wave_not_object", "surface.waves[4]: must be an object"},
    {"fps_zero", "animation.fps: must be in [0.001, 1e+06] frames per second, got 0"},
    {"frames_zero", "animation.frames: must be >= 1"},
    {"shutter_negative", "animation.shutter: must be in [0, 1] of the frame interval, got -1"},
    // Physical ranges (scene/scene_limits.h).
    {"camera_high",
     "camera.position: must be within 100000 m of the origin (got |position| = 1e+308 m)"},
    {"camera_far",
     "camera.position: must be within 100000 m of the origin (got |position| = 200000 m)"},
    {"camera_low", "camera.position: must be above the water at rest (y >= 0.001 m)"},
    {"look_at_far",
     "camera.look_at: must be within 1e+07 m of the origin (got |look_at| = 1e+08 m)"},
    {"up_huge", "camera.up: must have a length of at most 1e+12 (got 1.41421e+300)"},
    {"vfov_tiny", "camera.vfov_deg: must be in [0.001, 179] degrees, got 0.0001"},
    {"light_huge", "light.direction: must have a length of at most 1e+12 (got 1.41421e+200)"},
    {"light_radius_tiny", "light.angular_radius_deg: must be in [0.001, 89] degrees, got 0.0001"},
    {"light_radiance_huge", "light.radiance: must be at most 1e+10 (got 1e+308)"},
    {"sky_huge", "sky.radiance: must be at most 1e+10 (got 2e+10)"},
    {"sea_huge", "surface.sea_radiance: must be at most 1e+10 (got 1e+11)"},
    {"wave_vector_huge",
     "surface.waves[0].wave_vector: the wavelength 2 pi / |k| must be in [0.001, 100000] m (got "
     "6.28319e-08 m)"},
    {"wave_vector_zero",
     "surface.waves[1].wave_vector: the wavelength 2 pi / |k| must be in [0.001, 100000] m (got "
     "|k| = 0)"},
    {"wavelength_long",
     "surface.waves[2].wave_vector: the wavelength 2 pi / |k| must be in [0.001, 100000] m (got "
     "6.28319e+06 m)"},
    {"amplitude_steep",
     "surface.waves[0].amplitude: the steepness amplitude * |wave_vector| must be at most 0.45 "
     "(Stokes' limit of breaking), got 2.0944e+15"},
    {"frequency_huge",
     "surface.waves[3].angular_frequency: must be in [-10000, 10000] rad/s, got -100000"},
    {"phase_huge", "surface.waves[4].phase: must be in [-1e+06, 1e+06] rad, got 1e+07"},
    {"t0_huge", "animation.t0: must be in [-1e+07, 1e+07] s, got 1e+308"},
    {"frames_past_time",
     "animation.frames: the last frame is at t0 + (frames - 1) / fps = 1.00233e+07 s, after 1e+07 "
     "s"},
    {"shutter_before_time",
     "animation.t0: frame 0's shutter opens at t0 - shutter / fps = -1e+07 s, before -1e+07 s"},
    {"fps_huge", "animation.fps: must be in [0.001, 1e+06] frames per second, got 1e+07"},
    {"shutter_two", "animation.shutter: must be in [0, 1] of the frame interval, got 2"},
    {"duplicate_key",
     "surface.waves[2].amplitude: duplicate key (JSON object keys must be unique)"},
    {"duplicate_top_key", "name: duplicate key (JSON object keys must be unique)"},
    {"amplitude_infinite", "surface.waves[0].amplitude: number out of range at line 45, column 22"},
    {"syntax_error", "line 94, column 10: invalid JSON (unexpected string literal; expected '}')"},
    {"top_level_array", "(top level): must be an object"},
    // Format /2: colour radiances and the sky gradient.
    {"v1_rgb_light",
     "light.radiance: an [r, g, b] radiance needs \"format\": \"sunglint-scene/2\""},
    {"v1_sky_zenith", "sky.zenith: needs \"format\": \"sunglint-scene/2\""},
    {"v1_sky_exponent", "sky.exponent: needs \"format\": \"sunglint-scene/2\""},
    {"v2_rgb_two", "light.radiance: must be a number or an array of 3 numbers [r, g, b]"},
    {"v2_rgb_string", "surface.sea_radiance: must be a number or an array of 3 numbers [r, g, b]"},
    {"v2_rgb_element_string", "light.radiance[1]: must be a number"},
    {"v2_rgb_negative", "sky.radiance[1]: must be >= 0"},
    {"v2_sea_negative", "surface.sea_radiance: must be >= 0"},
    {"v2_sky_both_forms",
     "sky.radiance: not allowed with sky.zenith and sky.horizon (a sky is constant or a gradient)"},
    {"v2_sky_zenith_only", "sky.horizon: missing (required with sky.zenith)"},
    {"v2_sky_horizon_only", "sky.zenith: missing (required with sky.horizon)"},
    {"v2_sky_exponent_zero", "sky.exponent: must be > 0"},
    {"v2_sky_exponent_string", "sky.exponent: must be a number"},
    {"v2_sky_exponent_constant",
     "sky.exponent: needs the gradient sky (sky.zenith and sky.horizon)"},
    {"v2_sky_exponent_infinite", "sky.exponent: number out of range at line 43, column 19"},
    {"v2_sky_horizon_negative", "sky.horizon[2]: must be >= 0"},
    {"v2_sky_unknown_key", "sky.color: unknown key"},
    // Format /3: camera keyframes.
    {"v2_keyframes", "camera.keyframes: needs \"format\": \"sunglint-scene/3\""},
    {"v3_keyframes_and_position",
     "camera.position: not allowed with camera.keyframes (a camera is fixed or keyframed)"},
    {"v3_keyframes_one",
     "camera.keyframes: must be an array of at least 2 keyframes {time, position, look_at}"},
    {"v3_keyframes_not_array",
     "camera.keyframes: must be an array of at least 2 keyframes {time, position, look_at}"},
    {"v3_keyframe_unknown_key", "camera.keyframes[1].roll: unknown key"},
    {"v3_keyframe_time_missing", "camera.keyframes[0].time: missing (required)"},
    {"v3_keyframe_time_infinite",
     "camera.keyframes[1].time: number out of range at line 30, column 17"},
    {"v3_keyframe_time_equal",
     "camera.keyframes[2].time: must be greater than the previous keyframe's (2 s), got 2 s"},
    {"v3_keyframe_time_decreasing",
     "camera.keyframes[2].time: must be greater than the previous keyframe's (2 s), got 1 s"},
    {"v3_keyframe_below_water",
     "camera.keyframes[1].position: must be above the water at rest (y >= 0.001 m)"},
    {"v3_keyframe_look_at_position",
     "camera.keyframes[1].look_at: must differ from camera.keyframes[1].position"},
    {"v3_keyframe_up_parallel",
     "camera.keyframes[1]: the viewing direction is parallel to camera.up (the camera's basis is "
     "undefined)"},
    {"v3_segment_meets_look_at",
     "camera.keyframes[0]: the camera's position meets its look_at point between this keyframe "
     "and the next (at t = 1 s)"},
    {"v3_segment_up_parallel",
     "camera.keyframes[0]: the viewing direction turns parallel to camera.up between this "
     "keyframe and the next (at t = 1 s)"},
};

class BadScene : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadScene, RejectedWithKeyAndRule) {
  const std::string path =
      sg::testing::source_dir() + "/tests/scenes/bad/" + GetParam().file + ".json";
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  try {
    load_scene(path);
    FAIL() << "accepted " << path;
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), path + ": " + GetParam().message);
  }
}

INSTANTIATE_TEST_SUITE_P(Rules, BadScene, ::testing::ValuesIn(kBad),
                         [](const auto& info) { return std::string(info.param.file); });

TEST(SceneLoad, EveryBadFixtureHasAnExpectedMessage) {
  int files = 0;
  for (const auto& e :
       std::filesystem::directory_iterator(sg::testing::source_dir() + "/tests/scenes/bad")) {
    ++files;
    bool listed = false;
    for (const auto& c : kBad)
      listed |= e.path().stem() == c.file;
    EXPECT_TRUE(listed) << e.path();
  }
  EXPECT_EQ(files, static_cast<int>(std::size(kBad)));
}

TEST(SceneLoad, AliasingStudyScenesLoadWithTheirViews) {
  // tests/scenes/aliasing/ (docs/aliasing-study.md): each loads, and holds the light and
  // the camera its generator describes, so a regenerated file with another view fails.
  struct View {
    const char* name;
    double light_elevation_deg, camera_height;
    size_t waves;
  };
  for (const View v : {View{"cross-swell-side", 25, 3, 40}, View{"grazing-moon", 3, 4, 48},
                       View{"high-sun-above", 62, 40, 48}, View{"elevation-02", 2, 4, 48},
                       View{"elevation-05", 5, 4, 48}, View{"elevation-10", 10, 4, 48},
                       View{"elevation-15", 15, 4, 48}, View{"elevation-20", 20, 4, 48}}) {
    const Scene s =
        load_scene(sg::testing::source_dir() + "/tests/scenes/aliasing/" + v.name + ".json");
    EXPECT_EQ(s.name, v.name);
    const vec3 L = normalize(s.light.direction);
    EXPECT_NEAR(std::asin(L.y) * 180 / kPi, v.light_elevation_deg, 1e-3) << v.name;
    EXPECT_EQ(s.camera.position.y, v.camera_height) << v.name;
    EXPECT_EQ(s.surface.waves.size(), v.waves) << v.name;
  }
}

TEST(SceneLoad, ProjectScenesLoadWithTheirValues) {
  for (const char* name : {"simple", "smooth", "medium", "high"}) {
    Scene s = testing::project_scene(name);
    EXPECT_EQ(s.name, name);
    EXPECT_EQ(s.width, 640);
    EXPECT_EQ(s.height, 360);
    EXPECT_EQ(s.surface.geometry, Geometry::flat);
    EXPECT_EQ(s.surface.fresnel, FresnelMode::none);
    EXPECT_DOUBLE_EQ(s.light.angular_radius_deg, 0.27);
    EXPECT_DOUBLE_EQ(s.animation.shutter, 1.0);
  }
  Scene simple = testing::project_scene("simple");
  ASSERT_EQ(simple.surface.waves.size(), 5u);
  EXPECT_DOUBLE_EQ(simple.surface.waves[3].amplitude, 0.101859);
  EXPECT_DOUBLE_EQ(simple.surface.waves[3].wave_vector.y, -0.768235);
  EXPECT_EQ(testing::project_scene("smooth").surface.waves.size(), 64u);
  EXPECT_EQ(testing::project_scene("medium").surface.waves.size(), 48u);
  EXPECT_EQ(testing::project_scene("high").surface.waves.size(), 32u);
}

// The picture scenes (scripts/pictures.sh): format /2, colour, a gradient sky, a visible
// light, 640x360.
TEST(SceneLoad, PictureScenesAreColourWithAGradientSky) {
  for (const char* name : {"sunset", "moonlit", "midday"}) {
    Scene s = testing::project_scene(name);
    EXPECT_EQ(s.name, name);
    EXPECT_EQ(s.width, 640);
    EXPECT_EQ(s.height, 360);
    EXPECT_FALSE(s.grey()) << name;
    EXPECT_TRUE(s.sky.gradient) << name;
    EXPECT_TRUE(s.light.visible) << name;
    EXPECT_EQ(s.surface.fresnel, FresnelMode::schlick) << name;
    EXPECT_EQ(s.format_version(), 2);
  }
}

TEST(SceneLoad, DefaultsOfOptionalKeys) {
  const std::string text = R"({
    "format": "sunglint-scene/1",
    "image": {"width": 4, "height": 2},
    "camera": {"position": [0, 1, 0], "look_at": [0, 0, -5], "up": [0, 1, 0], "vfov_deg": 30},
    "light": {"direction": [0, 1, -4], "angular_radius_deg": 0.5},
    "surface": {"waves": [{"amplitude": 0.1, "wave_vector": [1, 0], "angular_frequency": 2}]},
    "animation": {"t0": 0, "fps": 24, "frames": 2, "shutter": 0.5}
  })";
  Scene s = parse_scene(text, "dir/calm.json");
  EXPECT_EQ(s.name, "calm");
  EXPECT_EQ(s.light.radiance, Rgb(1.0));
  EXPECT_FALSE(s.light.visible);
  EXPECT_EQ(s.sky.zenith, Rgb(0.0));
  EXPECT_EQ(s.sky.horizon, Rgb(0.0));
  EXPECT_FALSE(s.sky.gradient);
  EXPECT_EQ(s.surface.geometry, Geometry::flat);
  EXPECT_EQ(s.surface.fresnel, FresnelMode::none);
  EXPECT_EQ(s.surface.sea_radiance, Rgb(0.0));
  EXPECT_DOUBLE_EQ(s.surface.waves[0].phase, 0.0);
  EXPECT_DOUBLE_EQ(s.frame_time(1), 1.0 / 24);
  EXPECT_DOUBLE_EQ(s.shutter_start(1), 1.0 / 24 - 0.5 / 24);
}

// A /2 scene: colour, the sky gradient, defaults; canonical JSON writes /2 for it and /1
// for a grey constant-sky scene, whatever the file's format.
TEST(SceneLoad, Format2ColourAndGradient) {
  const std::string text = R"({
    "format": "sunglint-scene/2",
    "image": {"width": 4, "height": 2},
    "camera": {"position": [0, 1, 0], "look_at": [0, 0, -5], "up": [0, 1, 0], "vfov_deg": 30},
    "light": {"direction": [0, 1, -4], "angular_radius_deg": 0.5, "radiance": [60, 38, 18]},
    "sky": {"zenith": [0.05, 0.09, 0.2], "horizon": 0.5},
    "surface": {"sea_radiance": [0.002, 0.01, 0.014],
                "waves": [{"amplitude": 0.1, "wave_vector": [1, 0], "angular_frequency": 2}]},
    "animation": {"t0": 0, "fps": 24, "frames": 2, "shutter": 0.5}
  })";
  Scene s = parse_scene(text, "dusk.json");
  EXPECT_EQ(s.light.radiance, Rgb(60, 38, 18));
  EXPECT_TRUE(s.sky.gradient);
  EXPECT_EQ(s.sky.zenith, Rgb(0.05, 0.09, 0.2));
  EXPECT_EQ(s.sky.horizon, Rgb(0.5));
  EXPECT_DOUBLE_EQ(s.sky.exponent, 0.5);
  EXPECT_EQ(s.surface.sea_radiance, Rgb(0.002, 0.01, 0.014));
  EXPECT_FALSE(s.grey());
  EXPECT_EQ(s.format_version(), 2);
  const std::string j = scene_to_json(s);
  EXPECT_NE(j.find("\"sunglint-scene/2\""), std::string::npos);
  EXPECT_EQ(scene_to_json(parse_scene(j, "x.json")), j);

  // A grey gradient needs /2; a grey constant sky written as /2 is a /1 scene.
  Scene g = s;
  g.light.radiance = Rgb(1);
  g.sky.zenith = Rgb(0.1);
  g.surface.sea_radiance = Rgb(0);
  EXPECT_TRUE(g.grey());
  EXPECT_EQ(g.format_version(), 2);
  EXPECT_DOUBLE_EQ(parse_scene(scene_to_json(g), "g.json").sky.exponent, 0.5);
  g.sky = SkyDesc::constant(Rgb(0.25));
  EXPECT_EQ(g.format_version(), 1);
  std::string v2 = text;
  v2.replace(v2.find("[60, 38, 18]"), 12, "2");
  v2.replace(v2.find("[0.002, 0.01, 0.014]"), 20, "0");
  const std::string gradient = "\"zenith\": [0.05, 0.09, 0.2], \"horizon\": 0.5";
  v2.replace(v2.find(gradient), gradient.size(), "\"radiance\": 0.25");
  Scene c = parse_scene(v2, "c.json");
  EXPECT_FALSE(c.sky.gradient);
  EXPECT_EQ(c.sky.zenith, Rgb(0.25));
  std::string v1 = v2;
  v1.replace(v1.find("scene/2"), 7, "scene/1");
  EXPECT_EQ(scene_to_json(c), scene_to_json(parse_scene(v1, "c.json")));
  EXPECT_NE(scene_to_json(c).find("\"sunglint-scene/1\""), std::string::npos);
}

// The /1 canonical text is the text before format /2 existed (the study's cache keys hash
// it): pinned here for a small scene.
TEST(SceneLoad, Format1CanonicalTextIsUnchanged) {
  Scene s = testing::small_scene({Wave{0.05, {0.3, -1.2}, 3.4, 0.25}}, 8, 4);
  s.sky = SkyDesc::constant(Rgb(0.125));
  s.surface.sea_radiance = Rgb(0.5);
  EXPECT_EQ(
      scene_to_json(s),
      "{\n \"animation\": {\n  \"fps\": 30.0,\n  \"frames\": 60,\n  \"shutter\": 1.0,\n  "
      "\"t0\": 0.0\n },\n \"camera\": {\n  \"look_at\": [\n   0.0,\n   0.0,\n   -60.0\n  ],\n "
      " \"position\": [\n   0.0,\n   2.5,\n   0.0\n  ],\n  \"up\": [\n   0.0,\n   1.0,\n   "
      "0.0\n  ],\n  \"vfov_deg\": 40.0\n },\n \"format\": \"sunglint-scene/1\",\n \"image\": "
      "{\n  \"height\": 4,\n  \"width\": 8\n },\n \"light\": {\n  \"angular_radius_deg\": "
      "0.27,\n  \"direction\": [\n   0.0,\n   0.207912,\n   -0.978148\n  ],\n  \"radiance\": "
      "1.0,\n  \"visible\": false\n },\n \"name\": \"test\",\n \"sky\": {\n  \"radiance\": "
      "0.125\n },\n \"surface\": {\n  \"fresnel\": \"none\",\n  \"geometry\": \"flat\",\n  "
      "\"sea_radiance\": 0.5,\n  \"waves\": [\n   {\n    \"amplitude\": 0.05,\n    "
      "\"angular_frequency\": 3.4,\n    \"phase\": 0.25,\n    \"wave_vector\": [\n     0.3,\n  "
      "   -1.2\n    ]\n   }\n  ]\n }\n}");
}

TEST(SceneLoad, CanonicalJsonRoundTrips) {
  Scene a = testing::project_scene("medium");
  Scene b = parse_scene(scene_to_json(a), "x.json");
  EXPECT_EQ(scene_to_json(a), scene_to_json(b));
}

TEST(SceneLoad, MissingFileNamesThePath) {
  try {
    load_scene("/nonexistent/dir/scene.json");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/scene.json: cannot read"),
              std::string::npos);
  }
}

// The error of loading `path`, or "" when it loads.
std::string load_error(const std::string& path) {
  try {
    load_scene(path);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

std::string scratch_dir(const std::string& name) {
  const std::string d = sg::testing::binary_dir() + "/test_out/scene_test/" + name;
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

TEST(SceneLoad, WindSeasOfThousandsOfWavesLoad) {
  // Pierson-Moskowitz seas at 5 and 15 m/s, wavelengths 5 cm to 500 m, 65536 waves (about
  // 14 MB of JSON at full precision): inside every range, under the file limit.
  const std::string dir = scratch_dir("wind_sea");
  for (double wind : {5.0, 15.0}) {
    Scene s = testing::project_scene("simple");
    s.surface.geometry = Geometry::displaced;
    s.surface.waves = testing::wind_sea_waves(wind, 65536);
    const std::string path = dir + "/wind" + std::to_string(int(wind)) + ".json";
    write_file_atomic(path, scene_to_json(s));
    const auto bytes = std::filesystem::file_size(path);
    EXPECT_GT(bytes, 8u << 20);
    EXPECT_LT(bytes, static_cast<uintmax_t>(limits::kMaxSceneFileBytes));
    const auto t0 = std::chrono::steady_clock::now();
    Scene back = load_scene(path);
    const double secs =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ASSERT_EQ(back.surface.waves.size(), 65536u);
    const WaveField w(back.surface.waves);
    std::printf("wind %.0f m/s: %ju bytes loaded in %.2f s, slope sum %.1f, amplitude sum %.1f m\n",
                wind, bytes, secs, w.slope_bound(), w.amplitude_bound());
    EXPECT_LT(w.slope_bound(), limits::kMaxSlopeSum / 10);
  }
}

TEST(SceneLoad, TheSumOfSlopesIsBounded) {
  // 2300 waves at the steepness limit sum to 1035 > 1000.
  Scene s = testing::project_scene("simple");
  s.surface.waves.assign(2300, Wave{0.45, {1.0, 0.0}, 3.0, 0.0});
  try {
    parse_scene(scene_to_json(s), "steep.json");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "steep.json: surface.waves: the sum of the steepnesses amplitude * |wave_vector| "
              "must be at most 1000 (got 1035)");
  }
  s.surface.waves.resize(2200);  // 990
  EXPECT_NO_THROW(parse_scene(scene_to_json(s), "steep.json"));
}

TEST(SceneLoad, OnlyRegularFilesOfBoundedSizeAreRead) {
  // A device, a folder and a fifo fail at once (opening a fifo would block, reading
  // /dev/zero would never end); so does a file over the limit (a sparse one: no disk used).
  EXPECT_EQ(load_error("/dev/zero"),
            "/dev/zero: cannot read: not a regular file (a device, fifo or socket)");
  const std::string dir = scratch_dir("files");
  EXPECT_EQ(load_error(dir), dir + ": cannot read: a folder, not a file");
  const std::string fifo = dir + "/fifo.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(load_error(fifo),
            fifo + ": cannot read: not a regular file (a device, fifo or socket)");
  const std::string big = dir + "/big.json";
  { std::ofstream(big) << "{"; }
  std::filesystem::resize_file(big, limits::kMaxSceneFileBytes + 1);
  EXPECT_EQ(load_error(big), big + ": cannot read: 67108865 bytes, more than the 67108864 allowed");
  std::filesystem::remove(big);
}

TEST(SceneLoad, ImageSizeOverridesAreChecked) {
  Scene s = testing::project_scene("simple");
  set_image_size(s, 160, 90);
  EXPECT_EQ(s.width, 160);
  EXPECT_EQ(s.height, 90);
  EXPECT_THROW(set_image_size(s, 0, 90), Error);
  try {
    set_image_size(s, 160, 20000);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "--height: must be in [1, 16384]");
  }
}

}  // namespace
}  // namespace sg
