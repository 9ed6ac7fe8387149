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

namespace {

// Edit distance with transpositions (optimal string alignment).
size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i)
    d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j)
    d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    for (size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min(
          {d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[a.size()][b.size()];
}

}  // namespace

std::string closest_name(const std::string& word, const std::vector<std::string>& names) {
  std::string best;
  size_t best_d = 3;
  for (const std::string& n : names) {
    const size_t d = edit_distance(word, n);
    if (d < best_d && 3 * d < std::max(word.size(), n.size())) {
      best = n;
      best_d = d;
    }
  }
  return best;
}

std::vector<std::string> flag_names(const CLI::App* app) {
  std::vector<std::string> names;
  for (; app != nullptr; app = app->get_parent()) {
    for (const CLI::Option* o : app->get_options()) {
      for (const std::string& l : o->get_lnames())
        names.push_back("--" + l);
      for (const std::string& s : o->get_snames())
        names.push_back("-" + s);
    }
  }
  return names;
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
