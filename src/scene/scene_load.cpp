// Loading `sunglint-scene/1`, `/2` and `/3` files: parse, check every key against its rule
// and its physical range (scene_limits.h), reject unknown and duplicate keys. Each rule lives
// in one place below; docs/scene-format-notes.md lists them with their reasons. Format /2
// adds [r, g, b] radiances and the sky gradient (read_radiance, read_sky); format /3 camera
// keyframes (read_keyframes: each segment between two keys is checked whole, since the
// interpolated view can meet its look-at point or turn parallel to `up` between keys); a
// file of an earlier format that uses them is an error naming the key.
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>

#include "base/atomic_file.h"
#include "base/error.h"
#include "scene/lattice.h"
#include "scene/scene.h"
#include "scene/scene_limits.h"

namespace sg {
namespace {

using json = nlohmann::json;

constexpr const char* kFormat = "sunglint-scene/1";
constexpr const char* kFormat2 = "sunglint-scene/2";
constexpr const char* kFormat3 = "sunglint-scene/3";
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

// |v| without overflow (glm's length squares first: 1e200 components give inf).
double norm(const vec3& v) {
  return std::hypot(v.x, v.y, v.z);
}

// A number as the messages print it: "1e+07", "0.45", "6283.19".
std::string num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// lo <= v <= hi, else "PATH: must be in [lo, hi] UNIT (got v)".
void require_in(double v, double lo, double hi, const std::string& path, const std::string& unit,
                const std::string& why = "") {
  if (!(v >= lo && v <= hi)) {
    ObjectReader::fail(path, "must be in [" + num(lo) + ", " + num(hi) + "]" +
                                 (unit.empty() ? "" : " " + unit) +
                                 (why.empty() ? "" : " (" + why + ")") + ", got " + num(v));
  }
}

// A direction of any length in [kMinDirectionLength, kMaxDirectionLength] (normalised
// later; outside that range its normalisation under- or overflows).
void require_direction(const vec3& v, const std::string& path) {
  const double len = norm(v);
  require(len >= limits::kMinDirectionLength, path, "must not be zero-length");
  if (!(len <= limits::kMaxDirectionLength)) {
    ObjectReader::fail(path, "must have a length of at most " + num(limits::kMaxDirectionLength) +
                                 " (got " + num(len) + ")");
  }
}

// A radiance: >= 0, at most kMaxRadiance (scene_limits.h).
double check_radiance(double v, const std::string& path) {
  require(v >= 0, path, "must be >= 0");
  if (!(v <= limits::kMaxRadiance)) {
    ObjectReader::fail(path,
                       "must be at most " + num(limits::kMaxRadiance) + " (got " + num(v) + ")");
  }
  return v;
}

const std::string kNeeds2 = std::string("needs \"format\": \"") + kFormat2 + "\"";
const std::string kNeeds3 = std::string("needs \"format\": \"") + kFormat3 + "\"";

// A radiance (format /2): a number (grey: three equal channels) or [r, g, b], each finite
// in [0, kMaxRadiance]. Format /1 (version 1) has numbers only.
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
      c[k] = check_radiance(ObjectReader::as_number(v[k], pk), pk);
    }
    return c;
  }
  if (version >= 2 && !v.is_number()) ObjectReader::fail(p, shape);
  return Rgb(check_radiance(ObjectReader::as_number(v, p), p));
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

// A camera position: within kMaxCameraDistance of the origin, above the water at rest.
void check_position(const vec3& p, const std::string& path) {
  if (!(norm(p) <= limits::kMaxCameraDistance)) {
    ObjectReader::fail(path, "must be within " + num(limits::kMaxCameraDistance) +
                                 " m of the origin (got |position| = " + num(norm(p)) + " m)");
  }
  if (!(p.y >= limits::kMinCameraHeight)) {
    ObjectReader::fail(
        path, "must be above the water at rest (y >= " + num(limits::kMinCameraHeight) + " m)");
  }
}

void check_look_at(const vec3& a, const std::string& path) {
  if (!(norm(a) <= limits::kMaxLookAtDistance)) {
    ObjectReader::fail(path, "must be within " + num(limits::kMaxLookAtDistance) +
                                 " m of the origin (got |look_at| = " + num(norm(a)) + " m)");
  }
}

// The smallest value over s in [0, 1] of the quadratic q(s) = a s^2 + b s + c, and where.
double quadratic_min(double a, double b, double c, double& at) {
  at = 0;
  double best = c;
  if (a + b + c < best) {
    best = a + b + c;
    at = 1;
  }
  if (a > 0) {
    const double s = -b / (2 * a);
    if (s > 0 && s < 1 && a * s * s + b * s + c < best) {
      best = a * s * s + b * s + c;
      at = s;
    }
  }
  return best;
}

// The view vector D(s) = D0 + s (D1 - D0) of the segment between two keys (s in [0, 1];
// a single key has D1 = D0): where over s it comes closest to zero length and to `up`'s
// direction, as the squared margins |D|^2 - eps^2 and |D x u|^2 - eps^2 |D|^2 (u the unit
// up), each a quadratic in s. Negative: the rule fails there.
struct ViewMargins {
  double meet, meet_at, parallel, parallel_at;
};
ViewMargins view_margins(const vec3& d0, const vec3& d1, const vec3& u) {
  constexpr double eps = 1e-6;
  const vec3 e = d1 - d0;
  ViewMargins m{};
  m.meet = quadratic_min(dot(e, e), 2 * dot(d0, e), dot(d0, d0) - eps * eps, m.meet_at);
  const vec3 c0 = cross(d0, u), ce = cross(e, u);
  m.parallel =
      quadratic_min(dot(ce, ce) - eps * eps * dot(e, e), 2 * (dot(c0, ce) - eps * eps * dot(d0, e)),
                    dot(c0, c0) - eps * eps * dot(d0, d0), m.parallel_at);
  return m;
}

// `camera.keyframes` (format /3): at least two keys, times finite and strictly increasing,
// each position and look-at point as a fixed camera's; along every segment the position
// stays apart from the look-at point and the view apart from `up` (checked over the whole
// segment: linear interpolation can pass through either between two good keys).
std::vector<CameraKey> read_keyframes(ObjectReader& o, const vec3& up) {
  const std::string path = o.key_path("keyframes");
  const json& keys = o.get("keyframes");
  require(keys.is_array() && keys.size() >= 2, path,
          "must be an array of at least 2 keyframes {time, position, look_at}");
  const vec3 u = normalize(up);
  std::vector<CameraKey> out;
  for (size_t k = 0; k < keys.size(); ++k) {
    const std::string kp = path + "[" + std::to_string(k) + "]";
    ObjectReader r(keys[k], kp);
    CameraKey key;
    key.time = r.number("time");
    require_in(key.time, -limits::kMaxTime, limits::kMaxTime, r.key_path("time"), "s");
    if (k > 0 && !(key.time > out.back().time)) {
      ObjectReader::fail(r.key_path("time"), "must be greater than the previous keyframe's (" +
                                                 num(out.back().time) + " s), got " +
                                                 num(key.time) + " s");
    }
    key.position = r.vector<3>("position");
    check_position(key.position, r.key_path("position"));
    key.look_at = r.vector<3>("look_at");
    check_look_at(key.look_at, r.key_path("look_at"));
    r.finish();
    const vec3 d = key.look_at - key.position;
    const ViewMargins at_key = view_margins(d, d, u);
    require(at_key.meet > 0, r.key_path("look_at"), "must differ from " + r.key_path("position"));
    require(at_key.parallel > 0, kp,
            "the viewing direction is parallel to camera.up (the camera's basis is undefined)");
    if (k > 0) {
      const CameraKey& a = out.back();
      const ViewMargins m = view_margins(a.look_at - a.position, d, u);
      const std::string prev = path + "[" + std::to_string(k - 1) + "]";
      auto when = [&](double s) { return num(a.time + s * (key.time - a.time)); };
      require(m.meet > 0, prev,
              "the camera's position meets its look_at point between this keyframe and the "
              "next (at t = " +
                  when(m.meet_at) + " s)");
      require(m.parallel > 0, prev,
              "the viewing direction turns parallel to camera.up between this keyframe and "
              "the next (at t = " +
                  when(m.parallel_at) + " s)");
    }
    out.push_back(key);
  }
  return out;
}

CameraDesc read_camera(ObjectReader o, int version) {
  CameraDesc c;
  if (o.has("keyframes")) {
    require(version >= 3, o.key_path("keyframes"),
            std::string("needs \"format\": \"") + kFormat3 + "\"");
    for (const char* k : {"position", "look_at"}) {
      require(!o.has(k), o.key_path(k),
              "not allowed with camera.keyframes (a camera is fixed or keyframed)");
    }
    c.up = o.vector<3>("up");
    require_direction(c.up, o.key_path("up"));
    c.keyframes = read_keyframes(o, c.up);
    c.position = c.keyframes.front().position;
    c.look_at = c.keyframes.front().look_at;
    c.vfov_deg = o.number("vfov_deg");
    require_in(c.vfov_deg, limits::kMinVfov, limits::kMaxVfov, o.key_path("vfov_deg"), "degrees");
    o.finish();
    return c;
  }
  c.position = o.vector<3>("position");
  c.look_at = o.vector<3>("look_at");
  c.up = o.vector<3>("up");
  c.vfov_deg = o.number("vfov_deg");
  check_position(c.position, o.key_path("position"));
  check_look_at(c.look_at, o.key_path("look_at"));
  require(length(c.look_at - c.position) > 1e-6, o.key_path("look_at"),
          "must differ from camera.position");
  require_direction(c.up, o.key_path("up"));
  require(length(cross(normalize(c.look_at - c.position), normalize(c.up))) > 1e-6,
          o.key_path("up"), "must not be parallel to the viewing direction");
  require_in(c.vfov_deg, limits::kMinVfov, limits::kMaxVfov, o.key_path("vfov_deg"), "degrees");
  o.finish();
  return c;
}

LightDesc read_light(ObjectReader o, int version) {
  LightDesc l;
  l.direction = o.vector<3>("direction");
  require_direction(l.direction, o.key_path("direction"));
  l.angular_radius_deg = o.number("angular_radius_deg");
  require_in(l.angular_radius_deg, limits::kMinLightRadius, limits::kMaxLightRadius,
             o.key_path("angular_radius_deg"), "degrees");
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
  const double k = length(w.wave_vector);
  if (!(k >= kTwoPi / limits::kMaxWavelength && k <= kTwoPi / limits::kMinWavelength)) {
    ObjectReader::fail(o.key_path("wave_vector"),
                       "the wavelength 2 pi / |k| must be in [" + num(limits::kMinWavelength) +
                           ", " + num(limits::kMaxWavelength) + "] m (got " +
                           (k > 0 ? num(kTwoPi / k) + " m" : std::string("|k| = 0")) + ")");
  }
  if (!(w.amplitude * k <= limits::kMaxSteepness)) {
    ObjectReader::fail(o.key_path("amplitude"),
                       "the steepness amplitude * |wave_vector| must be at most " +
                           num(limits::kMaxSteepness) + " (Stokes' limit of breaking), got " +
                           num(w.amplitude * k));
  }
  w.angular_frequency = o.number("angular_frequency");
  require_in(w.angular_frequency, -limits::kMaxAngularFrequency, limits::kMaxAngularFrequency,
             o.key_path("angular_frequency"), "rad/s");
  w.phase = o.number_or("phase", 0.0);
  require_in(w.phase, -limits::kMaxPhase, limits::kMaxPhase, o.key_path("phase"), "rad");
  o.finish();
  return w;
}

// A cascade (format /3, scene/lattice.h): its patch, lattice and band, then its sidecar
// read from `dir` and checked against them.
CascadeDesc read_cascade(ObjectReader o, const std::string& dir) {
  CascadeDesc c;
  c.file = o.string("file");
  require(!c.file.empty(), o.key_path("file"), "must name a .npy file");
  c.lattice = o.integer("lattice");
  const int n = c.lattice;
  require(n >= kMinLattice && n <= kMaxLattice && (n & (n - 1)) == 0, o.key_path("lattice"),
          "must be a power of two in [" + std::to_string(kMinLattice) + ", " +
              std::to_string(kMaxLattice) + "] (got " + std::to_string(n) + ")");
  c.patch_size = o.number("patch_size");
  // Its longest wave (L) and its shortest (L / (N/2 sqrt 2), the lattice's corner) within
  // the scene's wavelengths.
  require_in(c.patch_size, limits::kMinWavelength * n, limits::kMaxWavelength,
             o.key_path("patch_size"), "m");
  const std::string bpath = o.key_path("band");
  const json& band = o.get("band");
  require(band.is_array() && band.size() == 2 && band[0].is_number() && band[1].is_number(), bpath,
          "must be [min, max], |k| in rad/m");
  c.band_min = band[0].get<double>();
  c.band_max = band[1].get<double>();
  const double corner = kTwoPi / c.patch_size * (n / 2) * std::sqrt(2.0);
  require(std::isfinite(c.band_min) && std::isfinite(c.band_max) && c.band_min >= 0 &&
              c.band_min < c.band_max,
          bpath,
          "must be [min, max] with 0 <= min < max (got [" + num(c.band_min) + ", " +
              num(c.band_max) + "])");
  require(c.band_max <= corner * (1 + 1e-12), bpath,
          "max must be at most the lattice's largest |k|, 2 pi / patch_size * N / 2 * sqrt 2 = " +
              num(corner) + " rad/m (got " + num(c.band_max) + ")");
  o.finish();
  const std::filesystem::path f(c.file);
  const std::string path =
      f.is_absolute() || dir.empty() ? c.file : (std::filesystem::path(dir) / f).string();
  c.data = read_lattice(path, c, o.key_path("file"));
  return c;
}

SurfaceDesc read_surface(ObjectReader o, int version, const std::string& dir) {
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
  double slope_sum = 0;
  for (size_t k = 0; k < waves.size(); ++k) {
    s.waves.push_back(read_wave(ObjectReader(waves[k], wpath + "[" + std::to_string(k) + "]")));
    slope_sum += s.waves.back().amplitude * length(s.waves.back().wave_vector);
  }
  if (o.has("depth")) {
    require(version >= 3, o.key_path("depth"), kNeeds3);
    s.depth = o.number("depth");
    require_in(s.depth, 0.01, 1e5, o.key_path("depth"), "m");
  }
  if (o.has("cascades")) {
    const std::string cpath = o.key_path("cascades");
    require(version >= 3, cpath, kNeeds3);
    const json& cs = o.get("cascades");
    require(cs.is_array(), cpath, "must be an array of cascade objects");
    for (size_t k = 0; k < cs.size(); ++k) {
      const std::string key = cpath + "[" + std::to_string(k) + "]";
      s.cascades.push_back(read_cascade(ObjectReader(cs[k], key), dir));
      const CascadeDesc& c = s.cascades.back();
      for (size_t q = 0; q < k; ++q) {
        const CascadeDesc& p = s.cascades[q];
        if (c.band_min < p.band_max && p.band_min < c.band_max) {
          ObjectReader::fail(key + ".band", "overlaps the band of " + cpath + "[" +
                                                std::to_string(q) + "]: a wavelength " +
                                                "would be counted twice");
        }
      }
      for (size_t e = 0; e < c.data->amplitude.size(); ++e) {
        const int i = static_cast<int>(e % c.lattice), j = static_cast<int>(e / c.lattice);
        slope_sum +=
            c.data->amplitude[e] * length(lattice_wave_vector(c.patch_size, c.lattice, i, j));
      }
    }
  }
  if (!(slope_sum <= limits::kMaxSlopeSum)) {
    ObjectReader::fail(wpath,
                       "the sum of the steepnesses amplitude * |wave_vector| must be at most " +
                           num(limits::kMaxSlopeSum) + " (got " + num(slope_sum) +
                           (s.cascades.empty() ? "" : ", the cascades' included") + ")");
  }
  o.finish();
  return s;
}

AnimationDesc read_animation(ObjectReader o) {
  AnimationDesc a;
  const double T = limits::kMaxTime;
  a.t0 = o.number("t0");
  require_in(a.t0, -T, T, o.key_path("t0"), "s");
  a.fps = o.number("fps");
  require_in(a.fps, limits::kMinFps, limits::kMaxFps, o.key_path("fps"), "frames per second");
  a.frames = o.integer("frames");
  require(a.frames >= 1, o.key_path("frames"), "must be >= 1");
  a.shutter = o.number("shutter");
  require_in(a.shutter, 0, limits::kMaxShutter, o.key_path("shutter"), "of the frame interval");
  // Every time the animation reaches, from frame 0's shutter opening to the last frame.
  const double first = a.t0 - a.shutter / a.fps, last = a.t0 + (a.frames - 1) / a.fps;
  if (!(first >= -T)) {
    ObjectReader::fail(o.key_path("t0"), "frame 0's shutter opens at t0 - shutter / fps = " +
                                             num(first) + " s, before -" + num(T) + " s");
  }
  if (!(last <= T)) {
    ObjectReader::fail(o.key_path("frames"), "the last frame is at t0 + (frames - 1) / fps = " +
                                                 num(last) + " s, after " + num(T) + " s");
  }
  o.finish();
  return a;
}

// The JSON reader: builds the document (nlohmann's DOM builder, driven through its SAX
// interface, in one pass) and on the way finds where a text fails to parse (the key path
// of the value being read and the byte position; the DOM parser reports neither for a
// number overflow) and the first duplicate key (the DOM parser would keep the last value
// silently).
class JsonReader {
 public:
  using number_integer_t = json::number_integer_t;
  using number_unsigned_t = json::number_unsigned_t;
  using number_float_t = json::number_float_t;
  using string_t = json::string_t;
  using binary_t = json::binary_t;

  explicit JsonReader(json& out) : dom_(out, false) {}

  std::string path() const {
    std::string p;
    for (const Frame& f : stack_) {
      if (f.array) {
        p.append("[").append(std::to_string(f.index)).append("]");
      } else if (!f.key.empty()) {
        if (!p.empty()) p.push_back('.');
        p.append(f.key);
      }
    }
    return p;
  }
  size_t position = 0;
  bool out_of_range = false;  // a number too large for a double (the key path names it)
  std::string detail;         // the parser's words for a syntax error
  std::string duplicate;      // the key path of the first duplicate key, if any

  bool null() { return value() && dom_.null(); }
  bool boolean(bool v) { return value() && dom_.boolean(v); }
  bool number_integer(number_integer_t v) { return value() && dom_.number_integer(v); }
  bool number_unsigned(number_unsigned_t v) { return value() && dom_.number_unsigned(v); }
  bool number_float(number_float_t v, const string_t& s) {
    return value() && dom_.number_float(v, s);
  }
  bool string(string_t& v) { return value() && dom_.string(v); }
  bool binary(binary_t& v) { return value() && dom_.binary(v); }
  bool start_object(std::size_t n) {
    stack_.push_back({false, 0, "", {}});
    return dom_.start_object(n);
  }
  bool key(string_t& k) {
    stack_.back().key = k;
    if (!stack_.back().keys.insert(k).second) {
      duplicate = path();
      return false;
    }
    return dom_.key(k);
  }
  bool end_object() { return end() && dom_.end_object(); }
  bool start_array(std::size_t n) {
    stack_.push_back({true, 0, "", {}});
    return dom_.start_array(n);
  }
  bool end_array() { return end() && dom_.end_array(); }
  bool parse_error(std::size_t pos, const std::string&, const nlohmann::detail::exception& e) {
    position = pos;
    out_of_range = e.id == 406;
    // "... syntax error while parsing object key - unexpected end of input; expected string
    // literal": what the parser met and wanted.
    const std::string what = e.what();
    const size_t dash = what.find(" - ");
    detail = dash == std::string::npos ? "" : what.substr(dash + 3);
    return false;
  }

 private:
  struct Frame {
    bool array;
    size_t index;
    std::string key;
    std::set<std::string> keys;  // of an object: the keys read so far
  };
  bool value() {
    if (!stack_.empty() && stack_.back().array) ++stack_.back().index;
    return true;
  }
  bool end() {
    stack_.pop_back();
    return value();
  }
  nlohmann::detail::json_sax_dom_parser<json> dom_;
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

Scene parse_scene(const std::string& text, const std::string& name, const std::string& dir) {
  json j;
  JsonReader check(j);
  if (!json::sax_parse(text, &check)) {
    if (!check.duplicate.empty()) {
      throw Error(name + ": " + check.duplicate +
                  ": duplicate key (JSON object keys must be unique)");
    }
    const std::string at = line_col(text, check.position > 0 ? check.position - 1 : 0);
    const std::string path = check.path();
    if (check.out_of_range) {
      throw Error(name + ": " + (path.empty() ? "" : path + ": ") + "number out of range at " + at);
    }
    // A syntax error: where it is, not a key (the text there may not be the key's at all).
    throw Error(name + ": " + at + ": invalid JSON" +
                (check.detail.empty() ? "" : " (" + check.detail + ")"));
  }
  try {
    ObjectReader top(j, "");
    const std::string format = top.string("format");
    require(format == kFormat || format == kFormat2 || format == kFormat3, "format",
            std::string("must be \"") + kFormat + "\", \"" + kFormat2 + "\" or \"" + kFormat3 +
                "\" (got \"" + format + "\")");
    const int version = format == kFormat ? 1 : format == kFormat2 ? 2 : 3;
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
    s.camera = read_camera(top.object("camera"), version);
    s.light = read_light(top.object("light"), version);
    if (top.has("sky")) s.sky = read_sky(top.object("sky"), version);
    s.source_dir = dir;
    s.surface = read_surface(top.object("surface"), version, dir);
    s.animation = read_animation(top.object("animation"));
    top.finish();
    return s;
  } catch (const Error& e) {
    throw Error(name + ": " + e.what());
  }
}

Scene load_scene(const std::string& path) {
  return parse_scene(read_file(path, limits::kMaxSceneFileBytes), path,
                     std::filesystem::path(path).parent_path().string());
}

bool Scene::grey() const {
  auto g = [](const Rgb& c) { return c.x == c.y && c.y == c.z; };
  return g(light.radiance) && g(sky.zenith) && g(sky.horizon) && g(surface.sea_radiance);
}

int Scene::format_version() const {
  if (camera.moving() || !surface.cascades.empty() || std::isfinite(surface.depth)) return 3;
  return grey() && !sky.gradient ? 1 : 2;
}

void write_scene(const std::string& path, const Scene& scene) {
  Scene s = scene;
  const std::filesystem::path out(path);
  for (size_t c = 0; c < s.surface.cascades.size(); ++c) {
    CascadeDesc& d = s.surface.cascades[c];
    if (!d.data) throw Error(path + ": surface.cascades[" + std::to_string(c) + "] has no data");
    d.file = out.stem().string() + ".cascade" + std::to_string(c) + ".npy";
    write_lattice((out.parent_path() / d.file).string(), *d.data);
  }
  write_file_atomic(path, scene_to_json(s) + "\n");
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
  const int version = s.format_version();
  json surface = {{"geometry", s.surface.geometry == Geometry::flat ? "flat" : "displaced"},
                  {"fresnel", s.surface.fresnel == FresnelMode::none ? "none" : "schlick"},
                  {"sea_radiance", radiance(s.surface.sea_radiance)},
                  {"waves", waves}};
  if (std::isfinite(s.surface.depth)) surface["depth"] = s.surface.depth;
  if (!s.surface.cascades.empty()) {
    json cs = json::array();
    for (const CascadeDesc& c : s.surface.cascades) {
      cs.push_back({{"file", c.file},
                    {"patch_size", c.patch_size},
                    {"lattice", c.lattice},
                    {"band", {c.band_min, c.band_max}}});
    }
    surface["cascades"] = cs;
  }
  json camera = {{"position", v3(s.camera.position)},
                 {"look_at", v3(s.camera.look_at)},
                 {"up", v3(s.camera.up)},
                 {"vfov_deg", s.camera.vfov_deg}};
  if (s.camera.moving()) {
    // A moving camera: its keys (format /3); position and look_at are not written.
    json keys = json::array();
    for (const CameraKey& k : s.camera.keyframes) {
      keys.push_back({{"time", k.time}, {"position", v3(k.position)}, {"look_at", v3(k.look_at)}});
    }
    camera = {{"up", v3(s.camera.up)}, {"vfov_deg", s.camera.vfov_deg}, {"keyframes", keys}};
  }
  json j = {
      {"format", version == 1   ? kFormat
                 : version == 2 ? kFormat2
                                : kFormat3},
      {"name", s.name},
      {"image", {{"width", s.width}, {"height", s.height}}},
      {"camera", camera},
      {"light",
       {{"direction", v3(s.light.direction)},
        {"angular_radius_deg", s.light.angular_radius_deg},
        {"radiance", radiance(s.light.radiance)},
        {"visible", s.light.visible}}},
      {"sky", sky},
      {"surface", surface},
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
