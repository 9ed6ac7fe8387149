// A moving camera (format /3) in the methods: a /3 scene whose camera is fixed (or keyed
// but still) renders bit for bit as its /2 twin with every method; the reference's image
// of a fast pan equals, within its noise, a brute-force estimate written here on its own
// (random pixel points and times, the camera interpolated and its ray traced in this
// file), which an estimator that held the camera at the shutter's end would miss.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "engine/render.h"
#include "methods/method.h"
#include "testing/path_tables.h"
#include "testing/render_range.h"
#include "testing/testing.h"

namespace sg {
namespace {

std::vector<Image> render(const Scene& s, const std::string& method, int first, int last) {
  return testing::render_range(s, method, first, last);
}

// A /2 file's text with its format set to /3.
std::string as_v3(std::string text) {
  const std::string v2 = "\"sunglint-scene/2\"";
  text.replace(text.find(v2), v2.size(), "\"sunglint-scene/3\"");
  return text;
}

TEST(MovingCamera, AFixedCameraInFormat3RendersAsFormat2BitForBit) {
  const std::string path = testing::source_dir() + "/tests/scenes/fresnel-sky.json";
  Scene v2 = load_scene(path);
  ASSERT_EQ(v2.format_version(), 2);
  std::string text = scene_to_json(v2);
  Scene v3 = parse_scene(as_v3(text), "v3");
  ASSERT_FALSE(v3.camera.moving());
  // The same camera as keys that do not move (before, over and after the frames).
  Scene still = v2;
  still.camera.keyframes = {{-10.0, v2.camera.position, v2.camera.look_at},
                            {0.05, v2.camera.position, v2.camera.look_at},
                            {20.0, v2.camera.position, v2.camera.look_at}};
  still = parse_scene(scene_to_json(still), "still");
  ASSERT_TRUE(still.camera.moving());
  for (Scene* s : {&v2, &v3, &still})
    set_image_size(*s, 40, 24);
  for (const MethodInfo& info : method_catalog()) {
    SCOPED_TRACE(info.name);
    const std::vector<Image> a = render(v2, info.name, 1, 2);
    for (const Scene* s : {&v3, &still}) {
      const std::vector<Image> b = render(*s, info.name, 1, 2);
      ASSERT_EQ(a.size(), b.size());
      for (size_t k = 0; k < a.size(); ++k)
        EXPECT_EQ(a[k].data, b[k].data) << "frame " << k + 1;
    }
  }
}

// A fast pan over flat water under a wide light: the camera moves 10 m and turns about 55
// degrees in 1 s; frame 1 (fps 2, shutter 1) integrates [0, 0.5], a quarter of the frame's
// width of motion.
Scene pan_scene() {
  Scene s =
      testing::small_scene({Wave{0.02, {0.6, -0.9}, 2.4, 0.3}, Wave{0.012, {-1.1, -1.4}, 3.7, 1.1},
                            Wave{0.006, {2.3, -0.7}, 4.9, 2.0}},
                           32, 18);
  s.light.angular_radius_deg = 4;
  s.light.direction = {0.1, 0.2, -1};
  s.camera.keyframes = {{0.0, {0, 2.5, 0}, {-30, 0, -60}}, {1.0, {0, 2.5, -10}, {30, 0, -60}}};
  s.animation = AnimationDesc{0, 2, 3, 1.0};
  return s;
}

// The spec's pixel value by brute force: n uniform points of the pixel square and the
// shutter, each through the camera interpolated at its time, on flat water, no Fresnel,
// light 1 and sky and sea 0: the fraction whose reflection falls in the light disk.
struct Estimate {
  double mean, variance;  // of the mean
};
Estimate brute_force(const Scene& s, int frame, int i, int j, int n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  const double end = s.animation.t0 + frame / s.animation.fps;
  const double start = end - s.animation.shutter / s.animation.fps;
  const auto& k = s.camera.keyframes;
  const vec3 L = normalize(s.light.direction);
  const double cos_r = std::cos(s.light.angular_radius_deg * M_PI / 180);
  const double th = std::tan(s.camera.vfov_deg * M_PI / 360), tw = th * s.width / s.height;
  double sum = 0;
  for (int q = 0; q < n; ++q) {
    const double t = start + u(rng) * (end - start);
    const double w = std::clamp((t - k[0].time) / (k[1].time - k[0].time), 0.0, 1.0);
    const vec3 o = (1 - w) * k[0].position + w * k[1].position;
    const vec3 at = (1 - w) * k[0].look_at + w * k[1].look_at;
    const vec3 f = normalize(at - o), r = normalize(cross(f, vec3(0, 1, 0))), up = cross(r, f);
    const double px = i + u(rng), py = j + u(rng);
    const vec3 d =
        normalize(f + (2 * px / s.width - 1) * tw * r + (1 - 2 * py / s.height) * th * up);
    if (d.y >= 0) continue;  // the sky: 0
    const vec3 p = o - (o.y / d.y) * d;
    double gx = 0, gz = 0;
    for (const Wave& wv : s.surface.waves) {
      const double c = wv.amplitude * std::cos(wv.wave_vector.x * p.x + wv.wave_vector.y * p.z +
                                               wv.angular_frequency * t + wv.phase);
      gx += c * wv.wave_vector.x;
      gz += c * wv.wave_vector.y;
    }
    const vec3 m = normalize(vec3(-gx, 1, -gz)), v = -d;
    const vec3 refl = 2 * dot(m, v) * m - v;
    if (refl.y > 0 && dot(refl, L) >= cos_r) sum += 1;
  }
  const double mean = sum / n;
  return {mean, mean * (1 - mean) / n};
}

TEST(MovingCamera, ReferenceMatchesBruteForceTimeSampling) {
  const Scene s = pan_scene();
  const int frame = 1;
  MethodOptions o;
  o.samples = SampleCounts{4, 4, 8};
  o.samples_given = true;
  o.batches = 4;
  auto ref = make_method("reference", testing::with_tables(o));
  const Image img = render_frame(SceneModel(s), *ref, frame, {});
  const Image* var = ref->pixel_variance();
  ASSERT_NE(var, nullptr);
  // The reference with the camera held at the shutter's end: what a method that ignored the
  // motion would converge to.
  Scene held = s;
  held.camera = CameraDesc{{0, 2.5, -5}, {0, 0, -60}, {0, 1, 0}, 40, {}};
  auto ref_held = make_method("reference", testing::with_tables(o));
  const Image still = render_frame(SceneModel(held), *ref_held, frame, {});
  std::mt19937_64 rng(12345);
  double se = 0, se_held = 0, noise = 0, lit = 0;
  for (int j = 0; j < s.height; ++j) {
    for (int i = 0; i < s.width; ++i) {
      const Estimate b = brute_force(s, frame, i, j, 3000, rng);
      const double a = img.at(i, j), h = still.at(i, j);
      se += (a - b.mean) * (a - b.mean);
      se_held += (h - b.mean) * (h - b.mean);
      noise += var->at(i, j) + b.variance;
      lit += b.mean;
    }
  }
  const double n = s.width * s.height;
  const double rmse = std::sqrt(se / n), rmse_held = std::sqrt(se_held / n),
               sigma = std::sqrt(noise / n);
  std::printf(
      "moving reference vs brute force: RMSE %.4g (noise %.4g); held camera %.4g; mean %.3g\n",
      rmse, sigma, rmse_held, lit / n);
  EXPECT_GT(lit / n, 0.01);  // the light is in view
  EXPECT_LE(rmse, 1.3 * sigma);
  EXPECT_GT(rmse_held, 5 * sigma);  // the test can tell a camera held still
}

}  // namespace
}  // namespace sg
