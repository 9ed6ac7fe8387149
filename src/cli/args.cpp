#include "cli/args.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "base/error.h"

namespace sg {
namespace {

bool parse_int(const std::string& s, int& out) {
  auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return !s.empty() && ec == std::errc() && p == s.data() + s.size();
}

// The whole of `s` as a finite double.
bool parse_finite(const std::string& s, double& out) {
  if (s.empty()) return false;
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && std::isfinite(out);
}

std::string show(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

}  // namespace

CLI::Validator finite_number() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        double v;
        return parse_finite(s, v) ? "" : "must be a finite number (got '" + s + "')";
      },
      "NUMBER", "finite");
}

CLI::Validator number_in(double lo, double hi) {
  const std::string range = "[" + show(lo) + ", " + show(hi) + "]";
  return CLI::Validator(
      [lo, hi, range](std::string& s) -> std::string {
        double v;
        if (!parse_finite(s, v) || v < lo || v > hi) {
          return "must be a number in " + range + " (got '" + s + "')";
        }
        return "";
      },
      "NUMBER in " + range, "number_in");
}

CLI::Validator integer_in(long long lo, long long hi) {
  const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  return CLI::Validator(
      [lo, hi, range](std::string& s) -> std::string {
        long long v = 0;
        auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
        if (s.empty() || ec != std::errc() || p != s.data() + s.size() || v < lo || v > hi) {
          return "must be an integer in " + range + " (got '" + s + "')";
        }
        return "";
      },
      "INT in " + range, "integer_in");
}

FrameRange parse_frame_range(const std::string& text, const std::string& flag) {
  FrameRange r;
  size_t dash = text.find('-', 1);
  bool ok = dash == std::string::npos ? parse_int(text, r.first) && (r.last = r.first, true)
                                      : parse_int(text.substr(0, dash), r.first) &&
                                            parse_int(text.substr(dash + 1), r.last);
  if (!ok || r.first < 0 || r.last < r.first) {
    throw Error(flag + ": expected a frame range A-B with 0 <= A <= B (got '" + text + "')");
  }
  return r;
}

void check_frame(int frame, const Scene& scene, const std::string& flag) {
  if (frame < 0 || frame >= scene.animation.frames) {
    throw Error(flag + ": frame " + std::to_string(frame) + " is outside the animation [0, " +
                std::to_string(scene.animation.frames - 1) + "] (animation.frames is " +
                std::to_string(scene.animation.frames) + ")");
  }
}

void apply_image_size(Scene& scene, int width, int height) {
  if (width <= 0 && height <= 0) return;
  int w = width, h = height;
  if (w <= 0)
    w = std::max(1, static_cast<int>(std::lround(double(h) * scene.width / scene.height)));
  if (h <= 0)
    h = std::max(1, static_cast<int>(std::lround(double(w) * scene.height / scene.width)));
  set_image_size(scene, w, h);
}

}  // namespace sg
