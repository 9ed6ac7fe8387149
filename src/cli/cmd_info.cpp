// `sunglint info SCENE [--json] [--waves] [--width W] [--height H] [--bands N]`: what a
// scene holds, what it will look like (where the light and its glitter fall in the frame,
// the sky, the Fresnel term, the sea; `look`), and how many of its waves each band of the
// image resolves at that size (cli/wave_resolution.h).
//
// The slope statistics are those of the sum of sines averaged over space and time
// (Podee et al. 2021, Eq. 3, summed over waves): covariance
//     Sigma = sum_i (A_i^2 / 2) [a_i^2  a_i b_i; a_i b_i  b_i^2],
// slope variance = trace(Sigma).
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "base/error.h"
#include "cli/args.h"
#include "cli/commands.h"
#include "cli/wave_resolution.h"
#include "scene/camera.h"
#include "scene/camera_path.h"
#include "scene/light.h"
#include "scene/scene.h"
#include "scene/waves.h"
#include "shading/radiance.h"

namespace sg {
namespace {

// A radiance as one number when grey, else [r, g, b].
nlohmann::json rgb_json(const Rgb& c) {
  if (c.x == c.y && c.y == c.z) return c.x;
  return nlohmann::json::array({c.x, c.y, c.z});
}
std::string rgb_text(const Rgb& c) {
  char buf[96];
  if (c.x == c.y && c.y == c.z) {
    std::snprintf(buf, sizeof buf, "%g", c.x);
  } else {
    std::snprintf(buf, sizeof buf, "[%g, %g, %g]", c.x, c.y, c.z);
  }
  return buf;
}

bool is_black(const Rgb& c) {
  return c.x == 0 && c.y == 0 && c.z == 0;
}

// Where direction `d` from the camera falls in the frame: "at pixel (x, y)", or where
// outside it.
struct Placement {
  bool in_frame = false;
  double x = 0, y = 0;
  std::string text;
};
Placement place(const CameraModel& cam, const vec3& d, int width, int height) {
  Placement p;
  if (!cam.project(d, p.x, p.y)) {
    p.text = "out of view (more than 90 degrees from where the camera looks)";
    return p;
  }
  char buf[96];
  if (p.x >= 0 && p.x < width && p.y >= 0 && p.y < height) {
    p.in_frame = true;
    std::snprintf(buf, sizeof buf, "in the frame at pixel (%.0f, %.0f)", p.x, p.y);
  } else {
    std::snprintf(buf, sizeof buf, "outside the frame (%s%s%s)",
                  p.y < 0         ? "above it"
                  : p.y >= height ? "below it"
                                  : "",
                  (p.y < 0 || p.y >= height) && (p.x < 0 || p.x >= width) ? ", " : "",
                  p.x < 0        ? "left of it"
                  : p.x >= width ? "right of it"
                                 : "");
  }
  p.text = buf;
  return p;
}

// What the scene will look like, in words (the `look` lines of `info`) and as JSON.
struct Look {
  std::vector<std::string> lines;
  nlohmann::json json;
};
Look look_of(const Scene& s, double elevation) {
  Look k;
  const CameraModel cam(s.camera, s.width, s.height);
  const vec3 L = normalize(s.light.direction);
  char buf[256];
  const Placement light = place(cam, L, s.width, s.height);
  std::snprintf(buf, sizeof buf, "the light %.1f deg %s the horizon, %s%s", std::fabs(elevation),
                elevation >= 0 ? "above" : "below", light.text.c_str(),
                s.light.visible ? ", drawn in the sky" : ", not drawn (only its reflection)");
  k.lines.push_back(buf);
  // The glitter's centre: the light's mirror image in the water at rest (far away, the
  // camera's height does not matter).
  const vec3 mirror(L.x, -L.y, L.z);
  Placement glitter;
  double f_glitter = 0;
  if (elevation > 0) {
    glitter = place(cam, mirror, s.width, s.height);
    f_glitter = fresnel(s.surface.fresnel, L.y);
    std::snprintf(buf, sizeof buf, "its glitter (the light's mirror image) %s",
                  glitter.text.c_str());
  } else {
    std::snprintf(buf, sizeof buf, "no glitter: the light is below the horizon");
  }
  k.lines.push_back(buf);
  std::string sky;
  if (!s.sky.gradient && is_black(s.sky.zenith)) {
    sky = "a black sky";
  } else if (!s.sky.gradient) {
    sky = "a uniform sky of " + rgb_text(s.sky.zenith);
  } else {
    std::snprintf(buf, sizeof buf, "a sky graded from %s at the zenith to %s at the horizon",
                  rgb_text(s.sky.zenith).c_str(), rgb_text(s.sky.horizon).c_str());
    sky = buf;
  }
  std::string water;
  if (s.surface.fresnel == FresnelMode::none) {
    water = "no Fresnel term: the water mirrors all of the light and the sky";
  } else {
    std::snprintf(buf, sizeof buf,
                  "Schlick's Fresnel: the water mirrors %.0f%% looking straight down, %.0f%% "
                  "of the light at its glitter, all at grazing",
                  100 * kSchlickR0, 100 * f_glitter);
    water = buf;
  }
  k.lines.push_back(sky);
  k.lines.push_back(water);
  const bool only_glints =
      is_black(s.sky.zenith) && is_black(s.sky.horizon) && is_black(s.surface.sea_radiance);
  if (only_glints) {
    k.lines.push_back(
        "no sky and no sea light: only the glints are lit, a picture is black elsewhere (the "
        "measurement look; `sunglint ocean` without --template writes the sea as it looks)");
  } else if (is_black(s.surface.sea_radiance)) {
    k.lines.push_back("the sea beneath is black: the water shows only what it mirrors");
  } else {
    k.lines.push_back("the sea beneath, " + rgb_text(s.surface.sea_radiance) +
                      ", shows through what the water does not mirror");
  }
  auto pixel = [](const Placement& p) {
    return p.in_frame ? nlohmann::json::array({p.x, p.y}) : nlohmann::json(nullptr);
  };
  k.json = {{"light_pixel", pixel(light)},
            {"light_in_frame", light.in_frame},
            {"glitter_pixel", pixel(glitter)},
            {"fresnel_at_glitter", s.surface.fresnel == FresnelMode::none ? 1.0 : f_glitter},
            {"sky", !s.sky.gradient && is_black(s.sky.zenith) ? "black"
                    : s.sky.gradient                          ? "gradient"
                                                              : "uniform"},
            {"only_glints", only_glints},
            {"text", k.lines}};
  return k;
}

struct InfoArgs {
  std::string scene;
  bool json = false, waves = false;
  int width = 0, height = 0, bands = 3;
  double alias_start = kFootprintAliasRange.start, alias_end = kFootprintAliasRange.end;
};

void run_info(const InfoArgs& a) {
  Scene s = load_scene(a.scene);
  apply_image_size(s, a.width, a.height);
  if (a.bands < 1 || a.bands > 1000) throw Error("--bands: must be in [1, 1000]");
  if (!(a.alias_start >= 0 && a.alias_start < a.alias_end && std::isfinite(a.alias_end)))
    throw Error("--alias-start, --alias-end: need 0 <= start < end");
  AliasingParams ap;
  ap.start = a.alias_start;
  ap.end = a.alias_end;
  const WaveResolution res = wave_resolution(s, a.bands, ap);
  nlohmann::json jbands = nlohmann::json::array();
  for (const ResolutionBand& b : res.bands) {
    jbands.push_back({{"rows", {b.row_first, b.row_last}},
                      {"distance_m", {b.distance_first, b.distance_last}},
                      {"resolved", b.resolved},
                      {"transition", b.transition},
                      {"aliasing", b.aliasing},
                      {"staa_visited", b.visited},
                      {"intersection_summed", b.intersect}});
  }
  const std::vector<Wave> all_waves = surface_waves(s.surface);  // cascades' included
  WaveField w(all_waves);
  LightModel light(s.light);
  double lmin = std::numeric_limits<double>::infinity(), lmax = 0;
  double sxx = 0, sxz = 0, szz = 0;
  for (const Wave& wv : all_waves) {
    double k = length(wv.wave_vector);
    if (k > 0) {
      lmin = std::min(lmin, kTwoPi / k);
      lmax = std::max(lmax, kTwoPi / k);
    }
    double e = wv.amplitude * wv.amplitude / 2;
    sxx += e * wv.wave_vector.x * wv.wave_vector.x;
    sxz += e * wv.wave_vector.x * wv.wave_vector.y;
    szz += e * wv.wave_vector.y * wv.wave_vector.y;
  }
  const double elevation = degrees(std::asin(clamp(light.L.y, -1.0, 1.0)));
  const double azimuth = degrees(std::atan2(light.L.x, -light.L.z));
  const Look look = look_of(s, elevation);
  nlohmann::json j = {
      {"name", s.name},
      {"image", {s.width, s.height}},
      {"geometry", s.surface.geometry == Geometry::flat ? "flat" : "displaced"},
      {"fresnel", s.surface.fresnel == FresnelMode::none ? "none" : "schlick"},
      {"waves", all_waves.size()},
      {"wavelength_min_m", std::isfinite(lmin) ? lmin : 0.0},
      {"wavelength_max_m", lmax},
      {"amplitude_sum_m", w.amplitude_bound()},
      {"slope_bound", w.slope_bound()},
      {"slope_covariance", {sxx, sxz, szz}},
      {"slope_variance", sxx + szz},
      {"light",
       {{"direction", {light.L.x, light.L.y, light.L.z}},
        {"elevation_deg", elevation},
        {"azimuth_deg", azimuth},
        {"angular_radius_deg", s.light.angular_radius_deg},
        {"radiance", rgb_json(s.light.radiance)},
        {"visible", s.light.visible}}},
      {"sky",
       {{"zenith", rgb_json(s.sky.zenith)},
        {"horizon", rgb_json(s.sky.horizon)},
        {"exponent", s.sky.exponent},
        {"gradient", s.sky.gradient}}},
      {"sea_radiance", rgb_json(s.surface.sea_radiance)},
      {"look", look.json},
      {"animation",
       {{"t0", s.animation.t0},
        {"fps", s.animation.fps},
        {"frames", s.animation.frames},
        {"shutter", s.animation.shutter}}},
      {"wave_resolution",
       {{"alias_range_cycles_per_pixel", {ap.start, ap.end}},
        {"water_row_first", res.water_row_first},
        {"bands", jbands}}},
  };
  // Lattice cascades (format /3): each one's band and significant wave height.
  if (!s.surface.cascades.empty()) {
    nlohmann::json cs = nlohmann::json::array();
    for (const CascadeDesc& c : s.surface.cascades) {
      size_t waves = 0;
      for (double amp : c.data->amplitude)
        waves += amp > 0;
      cs.push_back(
          {{"file", c.file},
           {"patch_size_m", c.patch_size},
           {"lattice", c.lattice},
           {"band_rad_per_m", {c.band_min, c.band_max}},
           {"wavelengths_m", {kTwoPi / c.band_max, c.band_min > 0 ? kTwoPi / c.band_min : 0.0}},
           {"waves", waves},
           {"significant_wave_height_m", 4 * std::sqrt(cascade_variance(c))}});
    }
    j["cascades"] = cs;
    j["explicit_waves"] = s.surface.waves.size();
    if (std::isfinite(s.surface.depth)) j["depth_m"] = s.surface.depth;
  }
  // A moving camera (format /3): each segment's speed and mean turn rate.
  const std::vector<CameraSegmentMotion> motion = camera_motion(s.camera);
  if (!motion.empty()) {
    nlohmann::json segs = nlohmann::json::array();
    for (const CameraSegmentMotion& m : motion) {
      segs.push_back({{"t0", m.t0},
                      {"t1", m.t1},
                      {"speed_m_per_s", m.speed},
                      {"turn_rate_deg_per_s", m.turn_rate_deg}});
    }
    j["camera_motion"] = segs;
  }
  if (a.json) {
    std::printf("%s\n", j.dump(2).c_str());
    return;
  }
  std::printf("scene        %s (%s)\n", s.name.c_str(), a.scene.c_str());
  std::printf("image        %d x %d\n", s.width, s.height);
  std::printf("surface      %s geometry, fresnel %s, sea radiance %s\n",
              j["geometry"].get<std::string>().c_str(), j["fresnel"].get<std::string>().c_str(),
              rgb_text(s.surface.sea_radiance).c_str());
  std::printf("waves        %zu, wavelengths %.4g to %.4g m, amplitude sum %.4g m\n",
              all_waves.size(), std::isfinite(lmin) ? lmin : 0.0, lmax, w.amplitude_bound());
  if (!s.surface.cascades.empty()) {
    std::printf("             %zu explicit, the rest in %zu cascades; %s water\n",
                s.surface.waves.size(), s.surface.cascades.size(),
                std::isfinite(s.surface.depth)
                    ? (std::to_string(s.surface.depth) + " m deep").c_str()
                    : "deep");
    size_t k = 0;
    for (const nlohmann::json& c : j["cascades"]) {
      std::printf(
          "cascade %zu    %s: patch %.4g m, lattice %d, wavelengths %.4g to %.4g m, %zu waves, "
          "Hs %.4g m\n",
          k++, c["file"].get<std::string>().c_str(), c["patch_size_m"].get<double>(),
          c["lattice"].get<int>(), c["wavelengths_m"][0].get<double>(),
          c["wavelengths_m"][1].get<double>(), c["waves"].get<size_t>(),
          c["significant_wave_height_m"].get<double>());
    }
  }
  std::printf("slopes       variance %.5g (xx %.5g, xz %.5g, zz %.5g), rms %.4g, bound %.4g\n",
              sxx + szz, sxx, sxz, szz, std::sqrt(sxx + szz), w.slope_bound());
  std::printf("light        elevation %.3f deg, azimuth %.3f deg, radius %.4g deg, radiance %s%s\n",
              elevation, azimuth, s.light.angular_radius_deg, rgb_text(s.light.radiance).c_str(),
              s.light.visible ? ", visible" : "");
  if (s.sky.gradient) {
    std::printf("sky          zenith %s, horizon %s, exponent %g\n", rgb_text(s.sky.zenith).c_str(),
                rgb_text(s.sky.horizon).c_str(), s.sky.exponent);
  } else {
    std::printf("sky          radiance %s\n", rgb_text(s.sky.zenith).c_str());
  }
  for (size_t k = 0; k < look.lines.size(); ++k)
    std::printf("%s %s\n", k == 0 ? "look        " : "            ", look.lines[k].c_str());
  std::printf("animation    %d frames at %g fps from t0 = %g s, shutter %g\n", s.animation.frames,
              s.animation.fps, s.animation.t0, s.animation.shutter);
  for (size_t k = 0; k < motion.size(); ++k) {
    std::printf("%s %g to %g s: speed %.4g m/s, turn rate %.4g deg/s\n",
                k == 0 ? "camera      " : "            ", motion[k].t0, motion[k].t1,
                motion[k].speed, motion[k].turn_rate_deg);
  }
  if (res.bands.empty()) {
    std::printf("resolution   no row of the image sees the water\n");
  } else {
    std::printf(
        "resolution   waves per pixel resolved (f <= %g cycles/pixel), in transition, "
        "aliasing (f >= %g), water at rest\n",
        ap.start, ap.end);
    std::printf(
        "             visited: what staa sums one by one (the rest in O(1)); intersection: what "
        "the displaced intersection sums\n");
    std::printf(
        "             rows       distance (m)        resolved  transition  aliasing   visited  "
        "intersection\n");
    for (const ResolutionBand& b : res.bands) {
      std::printf("             %4d-%-4d  %8.1f to %-7.1f %8.1f  %10.1f  %8.1f  %8.1f  %12.1f\n",
                  b.row_first, b.row_last, b.distance_first, b.distance_last, b.resolved,
                  b.transition, b.aliasing, b.visited, b.intersect);
    }
  }
  if (a.waves) {
    std::printf("\n   #  amplitude  wavelength  direction(deg)  period(s)  phase\n");
    for (size_t k = 0; k < all_waves.size(); ++k) {
      const Wave& wv = all_waves[k];
      double kk = length(wv.wave_vector);
      std::printf(
          "%4zu  %9.5f  %10.4f  %14.2f  %9.4f  %6.3f\n", k, wv.amplitude,
          kk > 0 ? kTwoPi / kk : 0.0, degrees(std::atan2(wv.wave_vector.x, -wv.wave_vector.y)),
          wv.angular_frequency != 0 ? kTwoPi / std::fabs(wv.angular_frequency) : 0.0, wv.phase);
    }
  }
}

}  // namespace

void add_info_command(CLI::App& app) {
  auto a = std::make_shared<InfoArgs>();
  CLI::App* c = app.add_subcommand("info", "Describe a scene: waves, wavelengths, slopes, light");
  c->add_option("scene", a->scene, "Scene file")->required();
  c->add_flag("--json", a->json, "Print JSON");
  c->add_flag("--waves", a->waves, "List every wave");
  c->add_option("--width", a->width, "Image width for the resolution table (default: the scene's)");
  c->add_option("--height", a->height,
                "Image height for the resolution table (default: the scene's, or the width's "
                "aspect ratio)");
  c->add_option("--bands", a->bands, "Bands of water rows in the resolution table (3)");
  c->add_option("--alias-start", a->alias_start,
                "Start of the transition region, cycles per pixel (staa's default 0.3)");
  c->add_option("--alias-end", a->alias_end,
                "End of the transition region, cycles per pixel (staa's default 0.8)");
  c->callback([a] { run_info(*a); });
}

}  // namespace sg
