// The viewer's scene edits: an unedited view is the scene exactly (so a saved view renders
// as the file does), the light's angles round-trip through a direction, the amplitude
// scale scales every wave, the wind's sea keeps a scene's cascades (and saves them beside
// the file), out-of-range edits are refused with the key's name, and
// fractional frame positions land between the frames' shutter intervals.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "base/error.h"
#include "ocean/lattice_ocean.h"
#include "scene/scene.h"
#include "testing/paths.h"
#include "viewer/view_edits.h"

namespace sg::viewer {
namespace {

Scene simple() {
  return load_scene(sg::testing::source_dir() + "/scenes/simple.json");
}

TEST(ViewEdits, UneditedViewIsTheSceneExactly) {
  const Scene s = simple();
  EXPECT_EQ(scene_to_json(edited_scene(s, edits_of(s))), scene_to_json(s));
}

TEST(ViewEdits, LightAnglesRoundTrip) {
  const Scene s = simple();
  ViewEdits e = edits_of(s);
  e.sun_elevation_deg = 12.5;
  e.sun_azimuth_deg = -30;
  const Scene t = edited_scene(s, e);
  const vec3 d = glm::normalize(t.light.direction);
  EXPECT_NEAR(std::asin(d.y) * 180 / M_PI, 12.5, 1e-12);
  EXPECT_NEAR(std::atan2(d.x, -d.z) * 180 / M_PI, -30, 1e-12);
  const ViewEdits back = edits_of(t);
  EXPECT_NEAR(back.sun_elevation_deg, 12.5, 1e-12);
  EXPECT_NEAR(back.sun_azimuth_deg, -30, 1e-12);
  // Azimuth 0 looks along -z: the light straight ahead of the default camera.
  e.sun_azimuth_deg = 0;
  const vec3 ahead = glm::normalize(edited_scene(s, e).light.direction);
  EXPECT_NEAR(ahead.x, 0, 1e-15);
  EXPECT_LT(ahead.z, 0);
}

TEST(ViewEdits, AmplitudeScaleAndRadius) {
  const Scene s = simple();
  ASSERT_FALSE(s.surface.waves.empty());
  ViewEdits e = edits_of(s);
  e.amplitude_scale = 0.5;
  e.sun_radius_deg = 1.5;
  const Scene t = edited_scene(s, e);
  ASSERT_EQ(t.surface.waves.size(), s.surface.waves.size());
  for (size_t i = 0; i < s.surface.waves.size(); ++i)
    EXPECT_DOUBLE_EQ(t.surface.waves[i].amplitude, 0.5 * s.surface.waves[i].amplitude);
  EXPECT_EQ(t.light.angular_radius_deg, 1.5);
  EXPECT_EQ(t.light.direction, s.light.direction);  // angles unedited: the file's vector
}

TEST(ViewEdits, AmplitudeScaleScalesTheCascades) {
  Scene s = simple();
  CascadeDesc c;
  c.file = "unused.npy";
  c.patch_size = 64;
  c.lattice = 8;
  c.band_min = 0.05;
  c.band_max = 0.5;
  auto d = std::make_shared<LatticeData>();
  d->n = 8;
  d->amplitude.assign(64, 0.0);
  d->phase.assign(64, 0.0);
  d->amplitude[1] = 0.5;  // |k| = 2 pi / 64: steepness 0.049
  c.data = d;
  const std::string dir = sg::testing::binary_dir() + "/test_out/view_edits_test";
  std::filesystem::create_directories(dir);
  write_lattice(dir + "/unused.npy", *d);
  s.source_dir = dir;
  s.surface.waves.clear();  // the cascade alone meets the limit below
  s.surface.cascades.push_back(c);
  ViewEdits e = edits_of(s);
  e.amplitude_scale = 2;
  const Scene t = edited_scene(s, e);
  ASSERT_EQ(t.surface.cascades.size(), 1u);
  EXPECT_DOUBLE_EQ(t.surface.cascades[0].data->amplitude[1], 1.0);
  EXPECT_NE(t.surface.cascades[0].data->fingerprint,
            edited_scene(s, edits_of(s)).surface.cascades[0].data->fingerprint);
  // Past Stokes' limit: refused, naming the cascade.
  e.amplitude_scale = 10;
  try {
    edited_scene(s, e);
    FAIL() << "a steepness of 0.49 was accepted";
  } catch (const Error& err) {
    EXPECT_NE(std::string(err.what()).find("surface.cascades[0]"), std::string::npos) << err.what();
  }
}

TEST(ViewEdits, SeaFromAWindSpectrum) {
  const Scene s = simple();
  ViewEdits e = edits_of(s);
  EXPECT_FALSE(e.sea);
  EXPECT_EQ(e.sea_params.waves, 16);  // the scene's 4 waves, raised to the least
  e.sea = true;
  e.sea_params.wind_speed = 7;
  e.sea_params.wind_direction_deg = 30;
  const Scene t = edited_scene(s, e);
  const std::vector<Wave> want = ocean::generate(e.sea_params).waves;
  ASSERT_EQ(t.surface.waves.size(), want.size());
  for (size_t i = 0; i < want.size(); ++i)
    EXPECT_EQ(t.surface.waves[i].amplitude, want[i].amplitude);
  // Another wind, another sea; a wind out of range refused by its flag's name.
  e.sea_params.wind_speed = 12;
  EXPECT_NE(edited_scene(s, e).surface.waves[10].amplitude, t.surface.waves[10].amplitude);
  e.sea_params.wind_speed = 45;
  try {
    edited_scene(s, e);
    FAIL() << "a 45 m/s wind was accepted";
  } catch (const Error& err) {
    EXPECT_NE(std::string(err.what()).find("--wind-speed"), std::string::npos) << err.what();
  }
}

TEST(ViewEdits, SeaFromAWindSpectrumKeepsTheCascades) {
  // A scene of two 32 x 32 cascades: the wind's sea is two cascades of 32 x 32 again, the
  // lattices `sunglint ocean --cascades 2 --lattice 32` writes for that wind (no explicit
  // waves), fingerprinted; another wind, other lattices and a higher sea; saved with its
  // lattices beside it, the file loads back to the same lattices.
  Scene s = simple();
  ocean::CascadeParams cp;
  cp.cascades = 2;
  cp.lattice = 32;
  s.surface.waves.clear();
  s.surface.cascades = ocean::generate_lattice(ocean::OceanParams{}, cp).cascades;
  ViewEdits e = edits_of(s);
  e.sea = true;
  e.sea_params.wind_speed = 7;
  const Scene t = edited_scene(s, e);
  const ocean::LatticeOcean want = ocean::generate_lattice(e.sea_params, cp);
  ASSERT_EQ(t.surface.cascades.size(), 2u);
  EXPECT_TRUE(t.surface.waves.empty());
  auto variance = [](const Scene& sc) {
    double v = 0;
    for (const CascadeDesc& c : sc.surface.cascades)
      for (double a : c.data->amplitude)
        v += 0.5 * a * a;
    return v;
  };
  for (size_t c = 0; c < 2; ++c) {
    EXPECT_EQ(t.surface.cascades[c].lattice, 32);
    EXPECT_EQ(t.surface.cascades[c].patch_size, want.cascades[c].patch_size);
    EXPECT_EQ(t.surface.cascades[c].data->amplitude, want.cascades[c].data->amplitude);
    EXPECT_NE(t.surface.cascades[c].data->fingerprint, 0u);
  }
  e.sea_params.wind_speed = 12;
  const Scene u = edited_scene(s, e);
  EXPECT_NE(u.surface.cascades[1].data->fingerprint, t.surface.cascades[1].data->fingerprint);
  EXPECT_GT(variance(u), 2 * variance(t));
  // Saved: the lattices beside the scene file, read back the same.
  const std::string dir = sg::testing::binary_dir() + "/test_out/view_edits_test";
  std::filesystem::create_directories(dir);
  write_scene(dir + "/windy.json", u);
  EXPECT_TRUE(std::filesystem::exists(dir + "/windy.cascade1.npy"));
  const Scene back = load_scene(dir + "/windy.json");
  ASSERT_EQ(back.surface.cascades.size(), 2u);
  for (size_t c = 0; c < 2; ++c) {
    EXPECT_EQ(back.surface.cascades[c].data->amplitude, u.surface.cascades[c].data->amplitude);
    EXPECT_EQ(back.surface.cascades[c].data->fingerprint, u.surface.cascades[c].data->fingerprint);
  }
  EXPECT_EQ(back.surface.depth, u.surface.depth);
  // A wind out of range refused by its flag's name.
  e.sea_params.wind_speed = 45;
  try {
    edited_scene(s, e);
    FAIL() << "a 45 m/s wind was accepted";
  } catch (const Error& err) {
    EXPECT_NE(std::string(err.what()).find("--wind-speed"), std::string::npos) << err.what();
  }
}

TEST(ViewEdits, OutOfRangeIsRefusedByName) {
  const Scene s = simple();
  ViewEdits e = edits_of(s);
  e.sun_radius_deg = 120;
  try {
    edited_scene(s, e);
    FAIL() << "a 120 degree light was accepted";
  } catch (const Error& err) {
    EXPECT_NE(std::string(err.what()).find("angular_radius_deg"), std::string::npos) << err.what();
  }
}

TEST(ViewEdits, ViewTime) {
  const Scene s = simple();
  const FrameTime f3 = view_time(s, 3.0), want = frame_time(s, 3);
  EXPECT_EQ(f3.frame, 3);
  EXPECT_EQ(f3.start, want.start);
  EXPECT_EQ(f3.end, want.end);
  const FrameTime half = view_time(s, 3.5);
  EXPECT_EQ(half.frame, 3);
  EXPECT_NEAR(half.end, s.animation.t0 + 3.5 / s.animation.fps, 1e-15);
  EXPECT_NEAR(half.duration(), want.duration(), 1e-15);
}

}  // namespace
}  // namespace sg::viewer
