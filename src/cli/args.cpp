#include "cli/args.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "base/error.h"

namespace sg {
namespace {

bool parse_int(const std::string& s, int& out) {
  auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return !s.empty() && ec == std::errc() && p == s.data() + s.size();
}

}  // namespace

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
