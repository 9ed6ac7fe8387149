// Random ordinary seas for quality tests: what a user renders, not the edges of the ranges
// that testing/random_scene.h draws for property tests. 3 to 48 deep-water waves of 0.1 to
// 80 m around a wind direction (steepness 0.005 to 0.06, scaled down as waves are added so
// the sea's slope stays a sea's), flat or displaced; a camera 1 to 40 m up with a 20 to 60
// degree lens; a light 2 to 60 degrees high, 0.27 to 2 degrees wide. Two looks:
//  - glitter (two scenes in three): no Fresnel, a black sky and sea, the camera turned so
//    that the light's mirror image in the water at rest lies in the frame (within 0.35 of
//    the field of view of its centre both ways);
//  - sky: Schlick's Fresnel, a sky gradient, a sea radiance and the light anywhere around
//    the camera (in front, to the side, behind), the glitter in the frame or not.
// A third of the cameras move over the frames (format /3 keyframes from a stream of their
// own, so the other draws are the fixed cameras' before them): a pan of 5 to 45 degrees a
// second, a tilt of up to 10, a move of up to 15 m/s along the ground and 1 m/s up or
// down, in two keys over the frames' shutters or three with a turn between.
// Each scene goes through scene_to_json and parse_scene, so it is valid by the loader's
// rules. Deterministic in the seed.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include "math/rng.h"
#include "scene/scene.h"

namespace sg::testing {

class RandomSeas {
 public:
  explicit RandomSeas(uint64_t seed) : rng_(seed, 29), motion_(seed, 31) {}

  // The next sea, `width` x `height`, `frames` frames at 30 fps with a full shutter.
  Scene next(int width, int height, int frames) {
    Scene s = draw(width, height, frames);
    return parse_scene(scene_to_json(s), s.name + ".json");
  }
  // Whether the last scene is of the glitter look (else the sky look).
  bool glitter() const { return glitter_; }

 private:
  double u() { return rng_.uniform(); }
  double logu(double lo, double hi) { return lo * std::pow(hi / lo, u()); }
  double gauss() {
    // Box-Muller; u() in [0, 1): 1 - u() in (0, 1].
    return std::sqrt(-2.0 * std::log(1.0 - u())) * std::cos(kTwoPi * u());
  }
  static vec3 direction(double elevation, double azimuth) {
    return vec3(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                -std::cos(elevation) * std::cos(azimuth));
  }

  Scene draw(int width, int height, int frames) {
    Scene s;
    s.name = "sea" + std::to_string(count_++);
    s.width = width;
    s.height = height;
    const int choices[] = {3, 6, 12, 24, 48};
    const int n = choices[static_cast<int>(u() * 5) % 5];
    const double wind = kTwoPi * u();
    const double steep_scale = std::sqrt(6.0 / std::max(n, 6));
    for (int k = 0; k < n; ++k) {
      Wave w;
      const double kk = kTwoPi / logu(0.1, 80.0);
      const double d = wind + 0.6 * gauss();
      w.amplitude = steep_scale * (0.005 + 0.055 * u()) / kk;
      w.wave_vector = vec2(kk * std::cos(d), kk * std::sin(d));
      w.angular_frequency = std::sqrt(9.81 * kk);
      w.phase = kTwoPi * u();
      s.surface.waves.push_back(w);
    }
    s.surface.geometry = u() < 0.3 ? Geometry::displaced : Geometry::flat;
    const double h = logu(1.0, 40.0);
    s.camera.vfov_deg = 20 + 40 * u();
    const double elevation = radians(2 + 58 * u());
    glitter_ = u() < 2.0 / 3.0;
    double yaw = kTwoPi * u(), pitch = 0, light_azimuth = 0;
    const double vfov = radians(s.camera.vfov_deg);
    const double hfov = 2 * std::atan(std::tan(0.5 * vfov) * width / height);
    if (glitter_) {
      // The mirror image lies at (yaw, -elevation): the view within 0.35 fov of it.
      light_azimuth = yaw;
      yaw += 0.7 * (u() - 0.5) * hfov;
      pitch = -elevation + 0.7 * (u() - 0.5) * vfov;
      s.surface.fresnel = FresnelMode::none;
      s.sky = SkyDesc::constant(Rgb(0.0));
      s.surface.sea_radiance = Rgb(0.0);
    } else {
      pitch = -radians(2 + 40 * u());
      light_azimuth = yaw + kTwoPi * u();
      s.surface.fresnel = FresnelMode::schlick;
      s.sky.gradient = true;
      s.sky.zenith = Rgb(0.01);
      s.sky.horizon = Rgb(0.03);
      s.sky.exponent = logu(0.25, 2.0);
      s.surface.sea_radiance = Rgb(0.005);
    }
    s.camera.position = vec3(0, h, 0);
    s.camera.look_at = s.camera.position + 10.0 * direction(pitch, yaw);
    s.camera.up = vec3(0, 1, 0);
    const double radii[] = {0.27, 0.27, 0.5, 2.0};
    s.light.direction = direction(elevation, light_azimuth);
    s.light.angular_radius_deg = radii[static_cast<int>(u() * 4) % 4];
    s.light.radiance = Rgb(1.0);
    s.light.visible = false;
    s.animation.t0 = 100 * u();
    s.animation.fps = 30;
    s.animation.frames = frames;
    s.animation.shutter = 1.0;
    if (motion_.uniform() < 1.0 / 3.0) move_camera(s, h, pitch, yaw);
    return s;
  }

  // Keyframes from the shutter start of frame 0 (the pose drawn) to the last frame's display
  // time, the middle key (three keys) turning the pan and the move.
  void move_camera(Scene& s, double h, double pitch, double yaw) {
    auto mu = [&] { return motion_.uniform(); };
    auto sign = [&] { return mu() < 0.5 ? -1.0 : 1.0; };
    const double t_first = s.animation.t0 - s.animation.shutter / s.animation.fps;
    const double t_last = s.animation.t0 + (s.animation.frames - 1) / s.animation.fps;
    const int keys = mu() < 0.5 ? 2 : 3;
    double yaw_rate = sign() * radians(5 + 40 * mu()), tilt_rate = radians(10) * (2 * mu() - 1);
    double speed = 15 * mu(), heading = kTwoPi * mu(), climb = 2 * mu() - 1;
    vec3 p = s.camera.position;
    CameraKey key;
    key.time = t_first;
    key.position = p;
    key.look_at = s.camera.look_at;
    s.camera.keyframes = {key};
    for (int k = 1; k < keys; ++k) {
      const double t = t_first + (t_last - t_first) * k / (keys - 1);
      const double dt = t - key.time;
      p += dt * vec3(speed * std::cos(heading), climb, speed * std::sin(heading));
      p.y = std::max(p.y, 0.5 * std::min(h, 1.0));
      yaw += yaw_rate * dt;
      pitch = std::clamp(pitch + tilt_rate * dt, radians(-80.0), radians(10.0));
      key.time = t;
      key.position = p;
      key.look_at = p + 10.0 * direction(pitch, yaw);
      s.camera.keyframes.push_back(key);
      // The turn between the segments of three keys.
      yaw_rate = sign() * radians(5 + 40 * mu());
      heading += radians(90) * (2 * mu() - 1);
    }
  }

  Pcg32 rng_;
  Pcg32 motion_;
  int count_ = 0;
  bool glitter_ = false;
};

}  // namespace sg::testing
