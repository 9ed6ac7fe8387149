// Loading `sunglint-scene/1` and `/2` files: parse, check every key against its rule,
// reject unknown keys. Each rule lives in one place below; docs/scene-format-notes.md lists
// them. Format /2 adds [r, g, b] radiances and the sky gradient (read_radiance, read_sky);
// a /1 file that uses them is an error naming the key.
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>

#include "base/atomic_file.h"
#include "base/error.h"
#include "scene/scene.h"

namespace sg {
namespace {

using json = nlohmann::json;

constexpr const char* kFormat = "sunglint-scene/1";
constexpr const char* kFormat2 = "sunglint-scene/2";
constexpr int kMaxImageSide = 16384;

// A JSON object being read: remembers which keys were consumed so that the rest can be
// reported as unknown, and prefixes every error with the object's key path.
class ObjectReader {
 public:
  ObjectReader(const json& j, std::string path) : j_(j), path_(std::move(path)) {
    if (!j_.is_object()) fail(path_.empty() ? "(top level)" : path_, "must be an object");
  }

  std::string key_path(const std::string& key) const {
    return path_.empty() ? key : path_ + "." + key;
  }

  [[noreturn]] static void fail(const std::string& path, const std::string& rule) {
    throw Error(path + ": " + rule);
  }

  bool has(const std::string& key) const { return j_.contains(key); }

  const json& get(const std::string& key) {
    if (!j_.contains(key)) fail(key_path(key), "missing (required)");
    seen_.insert(key);
    return j_.at(key);
  }

  double number(const std::string& key) { return as_number(get(key), key_path(key)); }
  double number_or(const std::string& key, double fallback) {
    return has(key) ? number(key) : fallback;
  }

  int integer(const std::string& key) {
    const std::string p = key_path(key);
    double v = as_number(get(key), p);
    if (v != std::floor(v) || std::fabs(v) > 2e9) fail(p, "must be an integer");
    return static_cast<int>(v);
  }

  bool boolean_or(const std::string& key, bool fallback) {
    if (!has(key)) return fallback;
    const json& v = get(key);
    if (!v.is_boolean()) fail(key_path(key), "must be true or false");
    return v.get<bool>();
  }

  std::string string(const std::string& key) {
    const json& v = get(key);
    if (!v.is_string()) fail(key_path(key), "must be a string");
    return v.get<std::string>();
  }

  std::string choice_or(const std::string& key, const std::vector<std::string>& options,
                        const std::string& fallback) {
    if (!has(key)) return fallback;
    std::string v = string(key);
    for (const auto& o : options) {
      if (v == o) return v;
    }
    std::string list;
    for (const auto& o : options)
      list += (list.empty() ? "\"" : ", \"") + o + "\"";
    fail(key_path(key), "must be one of " + list + " (got \"" + v + "\")");
  }

  template <int N>
  glm::vec<N, double> vector(const std::string& key) {
    const std::string p = key_path(key);
    const json& v = get(key);
    if (!v.is_array() || v.size() != N) {
      fail(p, "must be an array of " + std::to_string(N) + " numbers");
    }
    glm::vec<N, double> out;
    for (int k = 0; k < N; ++k)
      out[k] = as_number(v[k], p + "[" + std::to_string(k) + "]");
    return out;
  }

  ObjectReader object(const std::string& key) { return ObjectReader(get(key), key_path(key)); }

  // Every key not read is unknown: an error (the spec: "Unknown keys are an error").
  void finish() const {
    for (auto it = j_.begin(); it != j_.end(); ++it) {
      if (!seen_.count(it.key())) fail(key_path(it.key()), "unknown key");
    }
  }

  static double as_number(const json& v, const std::string& path) {
    if (!v.is_number()) fail(path, "must be a number");
    double d = v.get<double>();
    if (!std::isfinite(d)) fail(path, "must be finite");
    return d;
  }

 private:
  const json& j_;
  std::string path_;
  std::set<std::string> seen_;
};

void require(bool ok, const std::string& path, const std::string& rule) {
  if (!ok) ObjectReader::fail(path, rule);
}

void require_nonzero(const vec3& v, const std::string& path) {
  require(length(v) > 1e-12, path, "must not be zero-length");
}

const std::string kNeeds2 = std::string("needs \"format\": \"") + kFormat2 + "\"";

// A radiance (format /2): a number (grey: three equal channels) or [r, g, b], each finite
// and >= 0. Format /1 (version 1) has numbers only.
Rgb read_radiance(ObjectReader& o, const std::string& key, double fallback, int version) {
  if (!o.has(key)) return Rgb(fallback);
  const std::string p = o.key_path(key);
  const json& v = o.get(key);
  const std::string shape = "must be a number or an array of 3 numbers [r, g, b]";
  if (v.is_array()) {
    require(version >= 2, p, "an [r, g, b] radiance " + kNeeds2);
    require(v.size() == 3, p, shape);
    Rgb c;
    for (int k = 0; k < 3; ++k) {
      const std::string pk = p + "[" + std::to_string(k) + "]";
      c[k] = ObjectReader::as_number(v[k], pk);
      require(c[k] >= 0, pk, "must be >= 0");
    }
    return c;
  }
  if (version >= 2 && !v.is_number()) ObjectReader::fail(p, shape);
  const double x = ObjectReader::as_number(v, p);
  require(x >= 0, p, "must be >= 0");
  return Rgb(x);
}

// `sky`: a constant `radiance`, or (format /2) `zenith` and `horizon` with an optional
// `exponent` (default 0.5, > 0); not both forms.
SkyDesc read_sky(ObjectReader o, int version) {
  const bool z = o.has("zenith"), h = o.has("horizon");
  if (version < 2) {
    for (const char* k : {"zenith", "horizon", "exponent"}) {
      require(!o.has(k), o.key_path(k), kNeeds2);
    }
  }
  SkyDesc sky;
  if (!z && !h) {
    require(!o.has("exponent"), o.key_path("exponent"),
            "needs the gradient sky (sky.zenith and sky.horizon)");
    sky = SkyDesc::constant(read_radiance(o, "radiance", 0.0, version));
  } else {
    require(!o.has("radiance"), o.key_path("radiance"),
            "not allowed with sky.zenith and sky.horizon (a sky is constant or a gradient)");
    require(z, o.key_path("zenith"), "missing (required with sky.horizon)");
    require(h, o.key_path("horizon"), "missing (required with sky.zenith)");
    sky.gradient = true;
    sky.zenith = read_radiance(o, "zenith", 0.0, version);
    sky.horizon = read_radiance(o, "horizon", 0.0, version);
    sky.exponent = o.number_or("exponent", 0.5);
    require(sky.exponent > 0, o.key_path("exponent"), "must be > 0");
  }
  o.finish();
  return sky;
}

CameraDesc read_camera(ObjectReader o) {
  CameraDesc c;
  c.position = o.vector<3>("position");
  c.look_at = o.vector<3>("look_at");
  c.up = o.vector<3>("up");
  c.vfov_deg = o.number("vfov_deg");
  require(c.position.y > 0, o.key_path("position"), "must be above the water at rest (y > 0)");
  require(length(c.look_at - c.position) > 1e-12, o.key_path("look_at"),
          "must differ from camera.position");
  require_nonzero(c.up, o.key_path("up"));
  require(length(cross(normalize(c.look_at - c.position), normalize(c.up))) > 1e-6,
          o.key_path("up"), "must not be parallel to the viewing direction");
  require(c.vfov_deg > 0 && c.vfov_deg < 180, o.key_path("vfov_deg"), "must be in (0, 180)");
  o.finish();
  return c;
}

LightDesc read_light(ObjectReader o, int version) {
  LightDesc l;
  l.direction = o.vector<3>("direction");
  require_nonzero(l.direction, o.key_path("direction"));
  l.angular_radius_deg = o.number("angular_radius_deg");
  require(l.angular_radius_deg > 0 && l.angular_radius_deg < 90, o.key_path("angular_radius_deg"),
          "must be in (0, 90)");
  l.radiance = read_radiance(o, "radiance", 1.0, version);
  l.visible = o.boolean_or("visible", false);
  o.finish();
  return l;
}

Wave read_wave(ObjectReader o) {
  Wave w;
  w.amplitude = o.number("amplitude");
  require(w.amplitude >= 0, o.key_path("amplitude"), "must be >= 0");
  w.wave_vector = o.vector<2>("wave_vector");
  w.angular_frequency = o.number("angular_frequency");
  w.phase = o.number_or("phase", 0.0);
  o.finish();
  return w;
}

SurfaceDesc read_surface(ObjectReader o, int version) {
  SurfaceDesc s;
  s.geometry = o.choice_or("geometry", {"flat", "displaced"}, "flat") == "flat"
                   ? Geometry::flat
                   : Geometry::displaced;
  s.fresnel = o.choice_or("fresnel", {"none", "schlick"}, "none") == "none" ? FresnelMode::none
                                                                            : FresnelMode::schlick;
  s.sea_radiance = read_radiance(o, "sea_radiance", 0.0, version);
  const std::string wpath = o.key_path("waves");
  const json& waves = o.get("waves");
  require(waves.is_array(), wpath, "must be an array of wave objects");
  for (size_t k = 0; k < waves.size(); ++k) {
    s.waves.push_back(read_wave(ObjectReader(waves[k], wpath + "[" + std::to_string(k) + "]")));
  }
  o.finish();
  return s;
}

AnimationDesc read_animation(ObjectReader o) {
  AnimationDesc a;
  a.t0 = o.number("t0");
  a.fps = o.number("fps");
  require(a.fps > 0, o.key_path("fps"), "must be > 0");
  a.frames = o.integer("frames");
  require(a.frames >= 1, o.key_path("frames"), "must be >= 1");
  a.shutter = o.number("shutter");
  require(a.shutter >= 0, o.key_path("shutter"), "must be >= 0");
  o.finish();
  return a;
}

// Finds where a JSON text fails to parse: the key path of the value being read and the
// byte position (nlohmann's DOM parser reports neither for a number overflow).
class ErrorLocator : public nlohmann::json_sax<json> {
 public:
  std::string path() const {
    std::string p;
    for (const Frame& f : stack_) {
      if (f.array) {
        p += "[" + std::to_string(f.index) + "]";
      } else if (!f.key.empty()) {
        p += (p.empty() ? "" : ".") + f.key;
      }
    }
    return p;
  }
  size_t position = 0;
  std::string reason;

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override {
    stack_.push_back({false, 0, ""});
    return true;
  }
  bool key(string_t& k) override {
    stack_.back().key = k;
    return true;
  }
  bool end_object() override { return end(); }
  bool start_array(std::size_t) override {
    stack_.push_back({true, 0, ""});
    return true;
  }
  bool end_array() override { return end(); }
  bool parse_error(std::size_t pos, const std::string&,
                   const nlohmann::detail::exception& e) override {
    position = pos;
    reason = e.id == 406 ? "number out of range" : "";
    return false;
  }

 private:
  struct Frame {
    bool array;
    size_t index;
    std::string key;
  };
  bool value() {
    if (!stack_.empty() && stack_.back().array) ++stack_.back().index;
    return true;
  }
  bool end() {
    stack_.pop_back();
    return value();
  }
  std::vector<Frame> stack_;
};

std::string line_col(const std::string& text, size_t byte) {
  size_t line = 1, col = 1;
  for (size_t k = 0; k < byte && k < text.size(); ++k) {
    if (text[k] == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(col);
}

}  // namespace

Scene parse_scene(const std::string& text, const std::string& name) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::exception&) {
    ErrorLocator where;
    json::sax_parse(text, &where);
    const std::string at = line_col(text, where.position > 0 ? where.position - 1 : 0);
    const std::string path = where.path();
    throw Error(name + ": " + (path.empty() ? "" : path + ": ") +
                (where.reason.empty() ? "invalid JSON" : where.reason) + " at " + at);
  }
  try {
    ObjectReader top(j, "");
    const std::string format = top.string("format");
    require(format == kFormat || format == kFormat2, "format",
            std::string("must be \"") + kFormat + "\" or \"" + kFormat2 + "\" (got \"" + format +
                "\")");
    const int version = format == kFormat ? 1 : 2;
    Scene s;
    s.name = top.has("name") ? top.string("name") : std::filesystem::path(name).stem().string();
    {
      ObjectReader img = top.object("image");
      s.width = img.integer("width");
      s.height = img.integer("height");
      require(s.width >= 1 && s.width <= kMaxImageSide, "image.width",
              "must be an integer in [1, " + std::to_string(kMaxImageSide) + "]");
      require(s.height >= 1 && s.height <= kMaxImageSide, "image.height",
              "must be an integer in [1, " + std::to_string(kMaxImageSide) + "]");
      img.finish();
    }
    s.camera = read_camera(top.object("camera"));
    s.light = read_light(top.object("light"), version);
    if (top.has("sky")) s.sky = read_sky(top.object("sky"), version);
    s.surface = read_surface(top.object("surface"), version);
    s.animation = read_animation(top.object("animation"));
    top.finish();
    return s;
  } catch (const Error& e) {
    throw Error(name + ": " + e.what());
  }
}

Scene load_scene(const std::string& path) {
  return parse_scene(read_file(path), path);
}

bool Scene::grey() const {
  auto g = [](const Rgb& c) { return c.x == c.y && c.y == c.z; };
  return g(light.radiance) && g(sky.zenith) && g(sky.horizon) && g(surface.sea_radiance);
}

int Scene::format_version() const {
  return grey() && !sky.gradient ? 1 : 2;
}

std::string scene_to_json(const Scene& s) {
  auto v3 = [](const vec3& v) { return json::array({v.x, v.y, v.z}); };
  // Grey radiances as one number (format /1); colour and the gradient sky need format /2.
  // A scene that needs neither is written as /1, byte for byte as before /2 existed (the
  // study's cache keys hash this text).
  auto radiance = [&](const Rgb& c) { return c.x == c.y && c.y == c.z ? json(c.x) : v3(c); };
  json sky = {{"radiance", radiance(s.sky.zenith)}};
  if (s.sky.gradient) {
    sky = {{"zenith", radiance(s.sky.zenith)},
           {"horizon", radiance(s.sky.horizon)},
           {"exponent", s.sky.exponent}};
  }
  json waves = json::array();
  for (const Wave& w : s.surface.waves) {
    waves.push_back({{"amplitude", w.amplitude},
                     {"wave_vector", {w.wave_vector.x, w.wave_vector.y}},
                     {"angular_frequency", w.angular_frequency},
                     {"phase", w.phase}});
  }
  json j = {
      {"format", s.format_version() == 1 ? kFormat : kFormat2},
      {"name", s.name},
      {"image", {{"width", s.width}, {"height", s.height}}},
      {"camera",
       {{"position", v3(s.camera.position)},
        {"look_at", v3(s.camera.look_at)},
        {"up", v3(s.camera.up)},
        {"vfov_deg", s.camera.vfov_deg}}},
      {"light",
       {{"direction", v3(s.light.direction)},
        {"angular_radius_deg", s.light.angular_radius_deg},
        {"radiance", radiance(s.light.radiance)},
        {"visible", s.light.visible}}},
      {"sky", sky},
      {"surface",
       {{"geometry", s.surface.geometry == Geometry::flat ? "flat" : "displaced"},
        {"fresnel", s.surface.fresnel == FresnelMode::none ? "none" : "schlick"},
        {"sea_radiance", radiance(s.surface.sea_radiance)},
        {"waves", waves}}},
      {"animation",
       {{"t0", s.animation.t0},
        {"fps", s.animation.fps},
        {"frames", s.animation.frames},
        {"shutter", s.animation.shutter}}},
  };
  return j.dump(1);
}

void set_image_size(Scene& s, int width, int height) {
  require(width >= 1 && width <= kMaxImageSide, "--width",
          "must be in [1, " + std::to_string(kMaxImageSide) + "]");
  require(height >= 1 && height <= kMaxImageSide, "--height",
          "must be in [1, " + std::to_string(kMaxImageSide) + "]");
  s.width = width;
  s.height = height;
}

}  // namespace sg
