#include "viewer/view_edits.h"

#include <algorithm>
#include <cmath>

namespace sg::viewer {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

}  // namespace

ViewEdits edits_of(const Scene& scene) {
  const vec3 d = glm::normalize(scene.light.direction);
  ViewEdits e;
  e.sun_elevation_deg = std::asin(std::clamp(d.y, -1.0, 1.0)) / kDeg;
  e.sun_azimuth_deg = (d.x == 0 && d.z == 0) ? 0.0 : std::atan2(d.x, -d.z) / kDeg;
  e.sun_radius_deg = scene.light.angular_radius_deg;
  e.amplitude_scale = 1;
  e.camera = scene.camera;
  return e;
}

Scene edited_scene(const Scene& base, const ViewEdits& e) {
  Scene s = base;
  const ViewEdits unedited = edits_of(base);
  if (e.sun_elevation_deg != unedited.sun_elevation_deg ||
      e.sun_azimuth_deg != unedited.sun_azimuth_deg) {
    const double el = e.sun_elevation_deg * kDeg, az = e.sun_azimuth_deg * kDeg;
    s.light.direction =
        vec3(std::cos(el) * std::sin(az), std::sin(el), -std::cos(el) * std::cos(az));
  }
  s.light.angular_radius_deg = e.sun_radius_deg;
  s.camera = e.camera;
  if (e.amplitude_scale != 1) {
    for (Wave& w : s.surface.waves)
      w.amplitude *= e.amplitude_scale;
  }
  // The loader's checks, on the edited values.
  return parse_scene(scene_to_json(s), "the view's edits", s.source_dir);
}

FrameTime view_time(const Scene& scene, double position) {
  const double f = std::floor(position);
  if (f == position) return frame_time(scene, static_cast<int>(f));
  const double t = scene.animation.t0 + position / scene.animation.fps;
  return FrameTime{static_cast<int>(f), t - scene.animation.shutter / scene.animation.fps, t};
}

}  // namespace sg::viewer
