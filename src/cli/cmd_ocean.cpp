// `sunglint ocean -o OUT.json [--spectrum ...] [--template FILE] [--geometry flat|displaced]`:
// a scene whose waves are sampled from a directional wave spectrum (ocean/ocean.h), written
// as explicit waves so that every renderer reads it. Without a template the scene looks
// like the sea (ocean::sea_template: a sun, a sky, Fresnel); a template gives its view and
// look instead (scripts/templates/plain.json: the measurement scenes' black sky). docs/ocean.md
// describes the spectra, the sampling and every flag's range.
//
// Exit codes: 2 for a bad flag value (the message names the flag), 1 when the work fails
// (an unreadable template, an unwritable output).
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "base/atomic_file.h"
#include "base/error.h"
#include "cli/commands.h"
#include "math/vec.h"
#include "ocean/lattice_ocean.h"
#include "ocean/ocean.h"
#include "scene/lattice.h"

namespace sg {
namespace {

// A usage error: CLI11 prints it and exits with status 2.
[[noreturn]] void usage(const std::string& message) {
  throw CLI::ParseError(message, 2);
}

struct OceanArgs {
  std::string out, template_path, name, geometry;
  std::string spectrum = "jonswap", spreading = "cos2s";
  std::string wind_speed, wind_direction, fetch, depth, gamma, waves, wavelengths, seed;
  std::string swell_height, swell_period, swell_direction, swell_spread, swell_gamma, swell_waves;
  std::string cascades, lattice, patch_sizes;
  bool expand = false;
  CLI::App* app = nullptr;
  bool given(const std::string& flag) const { return app->count(flag) > 0; }
};

double parse_double(const std::string& text, const std::string& flag) {
  double v = 0;
  auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || p != text.data() + text.size() || !std::isfinite(v))
    usage(flag + ": expected a finite number (got '" + text + "')");
  return v;
}

int parse_int(const std::string& text, const std::string& flag) {
  int v = 0;
  auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || p != text.data() + text.size())
    usage(flag + ": expected an integer (got '" + text + "')");
  return v;
}

uint64_t parse_u64(const std::string& text, const std::string& flag) {
  uint64_t v = 0;
  auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || p != text.data() + text.size())
    usage(flag + ": expected an integer in [0, 2^64) (got '" + text + "')");
  return v;
}

// "MIN-MAX": the dash that separates them is the first one after a digit or a dot (not
// an exponent's sign).
void parse_band(const std::string& text, double& lo, double& hi) {
  size_t dash = std::string::npos;
  for (size_t i = 1; i < text.size(); ++i) {
    const char prev = text[i - 1];
    if (text[i] == '-' && (std::isdigit(static_cast<unsigned char>(prev)) || prev == '.')) {
      dash = i;
      break;
    }
  }
  if (dash == std::string::npos)
    usage("--wavelengths: expected MIN-MAX in metres, e.g. 0.1-1000 (got '" + text + "')");
  lo = parse_double(text.substr(0, dash), "--wavelengths");
  hi = parse_double(text.substr(dash + 1), "--wavelengths");
}

ocean::OceanParams params_of(const OceanArgs& a) {
  using namespace ocean;
  OceanParams p;
  if (a.spectrum == "jonswap") {
    p.spectrum = SpectrumKind::jonswap;
  } else if (a.spectrum == "pierson-moskowitz") {
    p.spectrum = SpectrumKind::pierson_moskowitz;
  } else if (a.spectrum == "tma") {
    p.spectrum = SpectrumKind::tma;
  } else {
    usage("--spectrum: must be jonswap, pierson-moskowitz or tma (got '" + a.spectrum + "')");
  }
  if (a.spreading == "cos2s") {
    p.spreading = SpreadingKind::cos2s;
  } else if (a.spreading == "hasselmann") {
    p.spreading = SpreadingKind::hasselmann;
  } else if (a.spreading == "donelan-banner") {
    p.spreading = SpreadingKind::donelan_banner;
  } else {
    usage("--spreading: must be cos2s, hasselmann or donelan-banner (got '" + a.spreading + "')");
  }
  const bool pm = p.spectrum == SpectrumKind::pierson_moskowitz;
  const bool tma = p.spectrum == SpectrumKind::tma;
  if (pm && a.given("--fetch"))
    usage("--fetch: only with --spectrum jonswap or tma (Pierson-Moskowitz is fully developed)");
  if (pm && a.given("--gamma"))
    usage(
        "--gamma: only with --spectrum jonswap or tma (Pierson-Moskowitz has no peak "
        "enhancement)");
  if (!tma && a.given("--depth"))
    usage("--depth: only with --spectrum tma (the others are deep water)");
  if (tma && !a.given("--depth")) usage("--depth: required with --spectrum tma");
  if (a.given("--wind-speed")) p.wind_speed = parse_double(a.wind_speed, "--wind-speed");
  if (a.given("--wind-direction"))
    p.wind_direction_deg = parse_double(a.wind_direction, "--wind-direction");
  if (a.given("--fetch")) p.fetch_km = parse_double(a.fetch, "--fetch");
  if (a.given("--gamma")) p.gamma = parse_double(a.gamma, "--gamma");
  if (a.given("--depth")) p.depth = parse_double(a.depth, "--depth");
  if (a.given("--waves")) p.waves = parse_int(a.waves, "--waves");
  if (a.given("--wavelengths")) parse_band(a.wavelengths, p.wavelength_min, p.wavelength_max);
  if (a.given("--seed")) p.seed = parse_u64(a.seed, "--seed");

  p.swell.enabled = a.given("--swell-height");
  for (const char* f : {"--swell-period", "--swell-direction", "--swell-spread", "--swell-gamma",
                        "--swell-waves"}) {
    if (!p.swell.enabled && a.given(f)) usage(std::string(f) + ": needs --swell-height");
  }
  if (p.swell.enabled) {
    p.swell.height = parse_double(a.swell_height, "--swell-height");
    if (a.given("--swell-period")) p.swell.period = parse_double(a.swell_period, "--swell-period");
    if (a.given("--swell-direction"))
      p.swell.direction_deg = parse_double(a.swell_direction, "--swell-direction");
    if (a.given("--swell-spread")) p.swell.spread = parse_double(a.swell_spread, "--swell-spread");
    if (a.given("--swell-gamma")) p.swell.gamma = parse_double(a.swell_gamma, "--swell-gamma");
    if (a.given("--swell-waves")) p.swell.waves = parse_int(a.swell_waves, "--swell-waves");
  }
  try {
    validate(p);
  } catch (const Error& e) {
    usage(e.what());
  }
  return p;
}

// `--cascades C --lattice N [--patch-sizes ...] [--expand]`: the sea as lattice cascades in
// sidecar files beside the scene (ocean/lattice_ocean.h), or expanded into explicit waves.
void run_lattice_ocean(const OceanArgs& a, const ocean::OceanParams& p, Scene scene) {
  if (!a.given("--cascades")) usage("--lattice, --patch-sizes, --expand: need --cascades");
  if (a.given("--waves") || a.given("--swell-waves"))
    usage("--waves, --swell-waves: not with --cascades (the lattice sets the waves)");
  ocean::CascadeParams cp;
  cp.cascades = parse_int(a.cascades, "--cascades");
  if (a.given("--lattice")) cp.lattice = parse_int(a.lattice, "--lattice");
  if (a.given("--patch-sizes")) {
    std::string rest = a.patch_sizes;
    while (true) {
      const size_t comma = rest.find(',');
      cp.patch_sizes.push_back(parse_double(rest.substr(0, comma), "--patch-sizes"));
      if (comma == std::string::npos) break;
      rest = rest.substr(comma + 1);
    }
  }
  ocean::LatticeOcean o;
  try {
    o = ocean::generate_lattice(p, cp);
  } catch (const Error& e) {
    usage(e.what());
  }
  const std::filesystem::path out(a.out);
  const std::string name = a.name.empty() ? out.stem().string() : a.name;
  scene.name = name;
  scene.surface.waves.clear();
  scene.surface.cascades.clear();
  scene.surface.depth = o.depth;
  if (a.expand) {
    size_t waves = 0;
    for (const CascadeDesc& c : o.cascades)
      for (double amp : c.data->amplitude)
        waves += amp > 0;
    if (waves > static_cast<size_t>(ocean::kWavesRange.hi)) {
      usage("--expand: the lattices hold " + std::to_string(waves) +
            " waves, more than a scene's explicit list takes (65536): a smaller --lattice or "
            "fewer --cascades");
    }
    const Dispersion water{o.depth};
    for (const CascadeDesc& c : o.cascades) {
      const std::vector<Wave> w = cascade_waves(c, water);
      scene.surface.waves.insert(scene.surface.waves.end(), w.begin(), w.end());
    }
    // Explicit waves carry their frequencies; the depth is the lattices' only.
    scene.surface.depth = std::numeric_limits<double>::infinity();
  } else {
    scene.surface.cascades = o.cascades;
  }
  write_scene(a.out, scene);  // the lattices beside it
  load_scene(a.out);          // what was written reads back (the loader's checks)

  std::printf(
      "%s: %zu cascades of %d x %d, Hs %.4g m (the spectrum's over the bands: %.4g m, "
      "%+.2f%%) -> %s%s\n",
      name.c_str(), o.cascades.size(), cp.lattice, cp.lattice, 4 * std::sqrt(o.variance),
      4 * std::sqrt(o.spectrum_variance), 100 * (std::sqrt(o.variance / o.spectrum_variance) - 1),
      a.out.c_str(), a.expand ? " (expanded into explicit waves)" : "");
  if (o.k_reached < o.k_max * (1 - 1e-12)) {
    std::printf(
        "  note: the lattices reach wavelengths down to %.4g m; the spectrum's %.4g to %.4g m "
        "is left out (more --cascades, a larger --lattice or smaller --patch-sizes)\n",
        kTwoPi / o.k_reached, kTwoPi / o.k_max, kTwoPi / o.k_reached);
  }
  for (size_t c = 0; c < o.cascades.size(); ++c) {
    const CascadeDesc& d = o.cascades[c];
    size_t waves = 0;
    for (double amp : d.data->amplitude)
      waves += amp > 0;
    std::printf("  cascade %zu  patch %.4g m, wavelengths %.4g to %.4g m, %zu waves, Hs %.4g m%s\n",
                c, d.patch_size, kTwoPi / d.band_max, kTwoPi / d.band_min, waves,
                4 * std::sqrt(cascade_variance(d)),
                a.expand ? ""
                         : ("  " + (out.parent_path() /
                                    (out.stem().string() + ".cascade" + std::to_string(c) + ".npy"))
                                       .string())
                               .c_str());
  }
}

void run_ocean(const OceanArgs& a) {
  const ocean::OceanParams p = params_of(a);
  const std::filesystem::path out(a.out);
  if (out.extension() != ".json") usage("--out: must name a .json file (got '" + a.out + "')");
  Geometry geometry = Geometry::flat;
  if (a.given("--geometry")) {
    if (a.geometry == "displaced") {
      geometry = Geometry::displaced;
    } else if (a.geometry != "flat") {
      usage("--geometry: must be flat or displaced (got '" + a.geometry + "')");
    }
  }
  Scene templ = a.template_path.empty() ? ocean::sea_template() : load_scene(a.template_path);
  if (a.given("--geometry")) templ.surface.geometry = geometry;
  if (a.given("--cascades") || a.given("--lattice") || a.given("--patch-sizes") || a.expand) {
    run_lattice_ocean(a, p, templ);
    return;
  }
  ocean::Ocean o;
  try {
    o = ocean::generate(p);
  } catch (const Error& e) {
    usage(e.what());  // a band without energy: a bad --wavelengths
  }
  const std::string name = a.name.empty() ? out.stem().string() : a.name;
  const Scene scene = ocean::ocean_scene(templ, o, name);
  write_file_atomic(a.out, scene_to_json(scene) + "\n");

  const Dispersion water = ocean::water(p);
  auto describe = [&](const char* what, const ocean::SampledComponent& c,
                      const ocean::Spectrum& s) {
    const double wp = s.peak(), kp = water.wavenumber(wp);
    std::printf(
        "  %-6s %5zu waves, wavelengths %.4g to %.4g m, Hs %.4g m, peak %.4g m (%.4g s), "
        "max steepness A|k| %.3g\n",
        what, c.waves.size(), kTwoPi / c.k_max, kTwoPi / c.k_min, 4 * std::sqrt(c.variance),
        kTwoPi / kp, kTwoPi / wp, c.max_steepness);
  };
  std::printf("%s: %zu waves, Hs %.4g m -> %s\n", name.c_str(), o.waves.size(),
              4 * std::sqrt(o.variance), a.out.c_str());
  describe(ocean::to_string(p.spectrum).c_str(), o.wind, o.wind_spectrum);
  if (p.swell.enabled) describe("swell", o.swell, o.swell_spectrum);
  std::printf("  look   %s, %s water; `sunglint info %s` says more%s\n",
              a.template_path.empty() ? "the default sea (a sun 12 degrees up, a sky, Fresnel)"
                                      : ("the template's (" + a.template_path + ")").c_str(),
              scene.surface.geometry == Geometry::flat ? "flat" : "displaced", a.out.c_str(),
              a.template_path.empty() ? " (--template FILE: another view or look)" : "");
}

}  // namespace

void add_ocean_command(CLI::App& app) {
  auto a = std::make_shared<OceanArgs>();
  CLI::App* c = app.add_subcommand(
      "ocean", "Write a scene whose waves are sampled from a directional wave spectrum");
  a->app = c;
  c->footer(
      "Directions (--wind-direction, --swell-direction) are where the waves travel towards, in "
      "degrees in the x-z plane measured from -z (straight ahead of the default camera) towards "
      "+x (to its right): 0 runs away from the camera towards the sun, 90 to the right, 180 "
      "towards the camera. See docs/ocean.md.");
  c->add_option("-o,--out", a->out, "Output scene file (.json)")->required();
  c->add_option("--template", a->template_path,
                "Scene whose camera, light, sky, image, animation and surface settings are kept "
                "(default: the sea as it looks: a camera 2.5 m above it looking ahead, the sun "
                "12 degrees high ahead and drawn, a blue sky graded to the horizon, Schlick "
                "Fresnel, a dark sea; 640x360, 60 frames at 30 fps. "
                "scripts/templates/plain.json: the measurement scenes' light 1, black sky, "
                "no Fresnel)");
  c->add_option("--geometry", a->geometry,
                "flat (the water at rest, as the methods assume; default) or displaced (the "
                "waves' heights intersected: slower, the reference's cost grows with the waves); "
                "overrides the template's");
  c->add_option("--name", a->name, "Scene name (default: the output file's stem)");
  c->add_option("--spectrum", a->spectrum, "jonswap, pierson-moskowitz or tma")
      ->capture_default_str();
  c->add_option("--wind-speed", a->wind_speed, "Wind speed 10 m above the sea, m/s, 1 to 30 (10)");
  c->add_option("--wind-direction", a->wind_direction,
                "Direction the wind sea travels towards, degrees, -360 to 360 (0)");
  c->add_option("--fetch", a->fetch, "Fetch, km, 1 to 10000 (100); jonswap and tma");
  c->add_option("--depth", a->depth, "Water depth, m, 1 to 10000; tma only (required there)");
  c->add_option("--gamma", a->gamma, "Peak enhancement, 1 to 10 (3.3); jonswap and tma");
  c->add_option("--spreading", a->spreading, "cos2s, hasselmann or donelan-banner")
      ->capture_default_str();
  c->add_option("--waves", a->waves, "Waves of the wind sea, 16 to 65536 (256)");
  c->add_option("--wavelengths", a->wavelengths,
                "Band of wavelengths MIN-MAX, m, within 0.01-10000 (0.1-1000); trimmed where "
                "the spectrum has no energy");
  c->add_option("--seed", a->seed, "Random seed of the wavenumbers, directions and phases (0)");
  c->add_option("--swell-height", a->swell_height,
                "Add a swell of this significant height, m, 0.01 to 10");
  c->add_option("--swell-period", a->swell_period, "Swell peak period, s, 4 to 25 (12)");
  c->add_option("--swell-direction", a->swell_direction,
                "Direction the swell travels towards, degrees (0)");
  c->add_option("--swell-spread", a->swell_spread,
                "Swell's cos-2s spreading parameter s_max, 1 to 200 (75: a long-travelled swell)");
  c->add_option("--swell-gamma", a->swell_gamma, "Swell's peak enhancement, 1 to 10 (3.3)");
  c->add_option("--swell-waves", a->swell_waves, "Waves of the swell, 16 to 65536 (64)");
  c->add_option("--cascades", a->cascades,
                "Write the sea as C lattice cascades (1 to 8) in .npy files beside the scene, "
                "as FFT oceans are made (format /3; docs/ocean.md, \"Cascades\")");
  c->add_option("--lattice", a->lattice,
                "Lattice of each cascade, N x N wave vectors, a power of two 4 to 1024 (256)");
  c->add_option("--patch-sizes", a->patch_sizes,
                "Patch sides L1,L2,... in m, decreasing, one per cascade (default: 20 peak "
                "wavelengths, then shrinking by a power of two that reaches the band's top)");
  c->add_flag("--expand", a->expand,
              "With --cascades: write the lattices' waves as explicit waves instead (the same "
              "sea; at most 65536 waves)");
  c->callback([a] { run_ocean(*a); });
}

}  // namespace sg
