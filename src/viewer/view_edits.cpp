#include "viewer/view_edits.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include "base/error.h"
#include "base/fnv1a.h"
#include "ocean/lattice_ocean.h"
#include "scene/lattice.h"
#include "scene/scene_limits.h"

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
  e.sea_params = sea_params_of(scene);
  return e;
}

ocean::OceanParams sea_params_of(const Scene& scene) {
  ocean::OceanParams p;
  size_t waves = scene.surface.waves.size();
  for (const CascadeDesc& c : scene.surface.cascades)
    for (double a : c.data->amplitude)
      waves += a > 0;
  p.waves = static_cast<int>(std::clamp<size_t>(waves, 16, 4096));
  return p;
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
  // A cascaded scene's sea from the wind stays cascaded: `sunglint ocean --cascades C
  // --lattice N` with the sliders' wind, C the scene's cascades, N its first one's lattice.
  ocean::LatticeOcean lattices;
  const bool cascaded = e.sea && !base.surface.cascades.empty();
  if (e.sea) {
    // ocean::generate's own checks name the flag of a bad value ("--wind-speed: ...").
    s.surface.cascades.clear();
    if (cascaded) {
      ocean::CascadeParams cp;
      cp.cascades = static_cast<int>(base.surface.cascades.size());
      cp.lattice = base.surface.cascades[0].lattice;
      lattices = ocean::generate_lattice(e.sea_params, cp);
      s.surface.waves.clear();
      s.surface.depth = lattices.depth;
    } else {
      s.surface.waves = ocean::generate(e.sea_params).waves;
      s.surface.depth = std::numeric_limits<double>::infinity();
    }
  }
  if (e.amplitude_scale != 1) {
    for (Wave& w : s.surface.waves)
      w.amplitude *= e.amplitude_scale;
  }
  // The loader's checks, on the edited values (the cascades read again from their files).
  Scene out = parse_scene(scene_to_json(s), "the view's edits", s.source_dir);
  if (cascaded) {
    // The generated lattices (no files: write_scene writes them), each fingerprinted
    // by its bytes as a file would be (frame cache keys).
    for (CascadeDesc c : lattices.cascades) {
      auto data = std::make_shared<LatticeData>(*c.data);
      data->fingerprint = fnv1a64(lattice_npy_bytes(*data));
      c.data = data;
      out.surface.cascades.push_back(c);
    }
  }
  if (e.amplitude_scale != 1) {
    // The cascades' amplitudes scale too, checked by the loader's steepness rule; their
    // fingerprints change with the scale (frame cache keys).
    for (size_t c = 0; c < out.surface.cascades.size(); ++c) {
      CascadeDesc& cascade = out.surface.cascades[c];
      auto data = std::make_shared<LatticeData>(*cascade.data);
      const int n = data->n;
      for (size_t i = 0; i < data->amplitude.size(); ++i) {
        data->amplitude[i] *= e.amplitude_scale;
        const double k = length(lattice_wave_vector(cascade.patch_size, n, static_cast<int>(i % n),
                                                    static_cast<int>(i / n)));
        if (!(data->amplitude[i] * k <= limits::kMaxSteepness)) {
          throw Error("the view's edits: amplitude scale " + std::to_string(e.amplitude_scale) +
                      ": surface.cascades[" + std::to_string(c) +
                      "]: a wave would be steeper than Stokes' limit " +
                      std::to_string(limits::kMaxSteepness));
        }
      }
      char scale[32];
      std::snprintf(scale, sizeof scale, "%.17g", e.amplitude_scale);
      data->fingerprint = fnv1a64(scale, data->fingerprint);
      cascade.data = data;
    }
  }
  return out;
}

FrameTime view_time(const Scene& scene, double position) {
  const double f = std::floor(position);
  if (f == position) return frame_time(scene, static_cast<int>(f));
  const double t = scene.animation.t0 + position / scene.animation.fps;
  return FrameTime{static_cast<int>(f), t - scene.animation.shutter / scene.animation.fps, t};
}

}  // namespace sg::viewer
