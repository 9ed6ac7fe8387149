// Random valid scenes for property tests: anything the scene loader accepts, drawn so that
// both ordinary seas and the edges of every range (scene/scene_limits.h) come up: waves of
// 1 mm to 100 km at up to the breaking steepness, any dispersion and phase; cameras from
// 1 mm to 100 km high, looking anywhere (also up, and below the crests of displaced water);
// lights of any elevation, 0.001 to 89 degrees wide, radiances up to 1e10; times up to
// 1e7 s; a third of the cameras moving (format /3 keyframes: pans, tilts, dollies, climbs
// and dives, slow or abrupt, keys before, inside or after the frames' shutters; drawn from
// a stream of their own, so the scenes' other draws are those of the fixed cameras before
// them). Each scene is returned through scene_to_json and parse_scene, so it is valid by
// the loader's own rules (drawings it rejects are drawn again).
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "base/error.h"
#include "math/rng.h"
#include "scene/scene.h"
#include "scene/scene_limits.h"

namespace sg::testing {

class RandomScenes {
 public:
  explicit RandomScenes(uint64_t seed, int max_waves = 12)
      : rng_(seed, 11), motion_(seed, 29), max_waves_(max_waves) {}

  // The next valid scene, `width` x `height`, and in `frame` a frame of its animation.
  Scene next(int width, int height, int& frame) {
    for (;;) {
      Scene s = draw(width, height);
      try {
        Scene valid = parse_scene(scene_to_json(s), "random.json");
        frame = static_cast<int>(u() * valid.animation.frames);
        frame = std::min(frame, valid.animation.frames - 1);
        return valid;
      } catch (const Error&) {
        ++rejected_;
      }
    }
  }
  int rejected() const { return rejected_; }

 private:
  double u() { return rng_.uniform(); }
  bool chance(double p) { return u() < p; }
  // Log-uniform in [lo, hi].
  double logu(double lo, double hi) { return lo * std::pow(hi / lo, u()); }
  double sign() { return chance(0.5) ? 1.0 : -1.0; }
  vec3 direction(double min_elev_deg, double max_elev_deg) {
    const double e = radians(min_elev_deg + (max_elev_deg - min_elev_deg) * u());
    const double az = kTwoPi * u();
    return vec3(std::cos(e) * std::sin(az), std::sin(e), -std::cos(e) * std::cos(az));
  }

  Scene draw(int width, int height) {
    namespace L = limits;
    Scene s;
    s.name = "random";
    s.width = width;
    s.height = height;
    // Waves: mostly a sea (5 cm to 500 m), sometimes anything the ranges allow.
    int n = chance(0.05) ? 0 : 1 + static_cast<int>(u() * 12);
    if (max_waves_ > 12 && n > 0)
      n = std::min(max_waves_, static_cast<int>(logu(1.0, max_waves_ + 1.0)));
    const bool wild = chance(0.3);
    // Many waves share a sea's slope: each one's steepness scaled by sqrt(12 / n) past 12.
    const double steep_scale = n > 12 ? std::sqrt(12.0 / n) : 1.0;
    for (int k = 0; k < n; ++k) {
      Wave w;
      const double lambda = wild ? logu(L::kMinWavelength, L::kMaxWavelength) : logu(0.05, 500.0);
      const double kk = kTwoPi / lambda;
      const double steep = chance(0.2) ? L::kMaxSteepness * u() : 0.1 * u() * u();
      w.amplitude = steep_scale * steep / kk;
      const double dir = kTwoPi * u();
      w.wave_vector = vec2(kk * std::cos(dir), kk * std::sin(dir));
      w.angular_frequency =
          chance(0.7) ? std::sqrt(9.81 * kk) : sign() * logu(1e-6, L::kMaxAngularFrequency) * u();
      w.phase = chance(0.1) ? sign() * L::kMaxPhase * u() : kTwoPi * u();
      s.surface.waves.push_back(w);
    }
    s.surface.geometry = chance(0.5) ? Geometry::flat : Geometry::displaced;
    s.surface.fresnel = chance(0.5) ? FresnelMode::none : FresnelMode::schlick;
    // Radiances: grey or (format /2) colour; a constant or a gradient sky.
    auto radiance = [&](double zero_chance) {
      if (chance(zero_chance)) return Rgb(0.0);
      if (chance(0.5)) return Rgb(logu(1e-6, L::kMaxRadiance));
      return Rgb(logu(1e-6, L::kMaxRadiance), logu(1e-6, L::kMaxRadiance),
                 logu(1e-6, L::kMaxRadiance));
    };
    s.surface.sea_radiance = radiance(0.5);
    if (chance(0.5)) {
      s.sky = SkyDesc::constant(radiance(0.5));
    } else {
      s.sky.gradient = true;
      s.sky.zenith = radiance(0.3);
      s.sky.horizon = radiance(0.3);
      s.sky.exponent = logu(1e-3, 1e2);
    }
    // Camera: usually a few metres up looking at the water, sometimes anywhere.
    double amp = 0;
    for (const Wave& w : s.surface.waves)
      amp += w.amplitude;
    double h;
    if (chance(0.15) && amp > 0) {
      h = std::max(L::kMinCameraHeight, amp * u());  // below the crests
    } else if (chance(0.3)) {
      h = logu(L::kMinCameraHeight, 0.9 * L::kMaxCameraDistance);
    } else {
      h = logu(0.5, 50.0);
    }
    const double r = chance(0.2) ? std::sqrt(std::max(0.0, 0.8e10 - h * h)) * u() : 100 * u();
    const double raz = kTwoPi * u();
    s.camera.position = vec3(r * std::cos(raz), h, r * std::sin(raz));
    const vec3 view = chance(0.8) ? direction(-60, 5) : direction(-90, 90);
    s.camera.look_at = s.camera.position + logu(1e-3, 1e6) * view;
    s.camera.up = chance(0.8) ? vec3(0, 1, 0) : direction(-90, 90) * logu(1e-3, 1e3);
    s.camera.vfov_deg = chance(0.3) ? logu(L::kMinVfov, L::kMaxVfov) : 10 + 80 * u();
    // Light.
    s.light.direction = (chance(0.8) ? direction(-5, 60) : direction(-90, 90)) * logu(1e-3, 1e3);
    s.light.angular_radius_deg =
        chance(0.25) ? logu(L::kMinLightRadius, L::kMaxLightRadius) : 0.1 + 1.9 * u();
    s.light.radiance = chance(0.3) ? radiance(0.0) : Rgb(1.0);
    s.light.visible = chance(0.5);
    // Animation.
    s.animation.fps = chance(0.2) ? logu(L::kMinFps, L::kMaxFps) : 30.0;
    s.animation.shutter = chance(0.2) ? 0.0 : u();
    s.animation.frames = 1 + static_cast<int>(u() * 60);
    s.animation.t0 = chance(0.5) ? 0.0 : sign() * logu(1e-3, 0.99 * L::kMaxTime);
    if (motion_.uniform() < 0.35) move_camera(s);
    return s;
  }

  // The camera keyframed about the pose just drawn (its position and look-at the pose at
  // the first key): 2 to 4 keys over the animation's shutters, often beyond them (the pose
  // held before the first and after the last), sometimes two keys within one frame's
  // shutter (a jump); each key moves the camera by a speed of 0.01 to 300 m/s along any
  // direction (its height kept above the loader's floor) and
  // turns the view by up to 90 degrees in heading and 30 in pitch about the camera.
  void move_camera(Scene& s) {
    namespace L = limits;
    auto mu = [&] { return motion_.uniform(); };
    auto mlog = [&](double lo, double hi) { return lo * std::pow(hi / lo, mu()); };
    const double fps = s.animation.fps;
    const double first = s.animation.t0 - s.animation.shutter / fps;
    const double last = s.animation.t0 + (s.animation.frames - 1) / fps;
    const double span = std::max(last - first, 1.0 / fps);
    const int keys = 2 + static_cast<int>(mu() * 3);
    std::vector<double> times;
    if (mu() < 0.2) {
      // Two keys inside one frame's shutter (or about its display time): an abrupt move.
      const int f = static_cast<int>(mu() * s.animation.frames);
      const double t = s.animation.t0 + std::min(f, s.animation.frames - 1) / fps;
      const double w = std::max(s.animation.shutter, 0.1) / fps;
      const double a = t - w * mu(), b = t + w * (0.1 + mu());
      if (!(b > a)) return;
      times = {a, b};
    } else {
      const double lo = first - span * (mu() < 0.5 ? 0.5 * mu() : -0.5 * mu());
      const double hi = last + span * (mu() < 0.7 ? 0.5 * mu() : -0.5 * mu());
      if (!(hi > lo)) return;
      for (int k = 0; k < keys; ++k)
        times.push_back(lo + (hi - lo) * k / (keys - 1));
    }
    for (size_t k = 1; k < times.size(); ++k) {
      if (!(times[k] > times[k - 1])) return;  // below the clock's resolution at its time
    }
    const double speed = mlog(0.01, 300.0);
    CameraKey key;
    key.time = times[0];
    key.position = s.camera.position;
    key.look_at = s.camera.look_at;
    s.camera.keyframes = {key};
    for (size_t k = 1; k < times.size(); ++k) {
      const double dt = times[k] - times[k - 1];
      const double az = kTwoPi * mu(), el = radians(-60 + 120 * mu());
      const vec3 dir(std::cos(el) * std::cos(az), std::sin(el), std::cos(el) * std::sin(az));
      vec3 p = key.position + std::min(speed * dt, 1e4) * dir;
      p.y = std::max(p.y, 2 * L::kMinCameraHeight);
      // The view turned about the camera: heading by up to 90 degrees, pitch by up to 30.
      const vec3 d = key.look_at - key.position;
      const double yaw = radians(90.0) * (2 * mu() - 1), pitch = radians(30.0) * (2 * mu() - 1);
      const double c = std::cos(yaw), sn = std::sin(yaw);
      vec3 r(c * d.x - sn * d.z, d.y, sn * d.x + c * d.z);
      const double h = std::sqrt(r.x * r.x + r.z * r.z), len = length(r);
      const double e = std::clamp(std::atan2(r.y, h) + pitch, radians(-89.0), radians(89.0));
      if (h > 0) {
        r = vec3(r.x / h * std::cos(e) * len, std::sin(e) * len, r.z / h * std::cos(e) * len);
      }
      key.time = times[k];
      key.position = p;
      key.look_at = p + r;
      s.camera.keyframes.push_back(key);
    }
  }

  Pcg32 rng_;
  Pcg32 motion_;
  int max_waves_;
  int rejected_ = 0;
};

}  // namespace sg::testing
