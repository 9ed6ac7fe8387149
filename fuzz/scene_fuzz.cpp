// libFuzzer target of the scene loader (`make fuzz`): any bytes given to parse_scene either
// are rejected with sg::Error (a message naming the key) or load as a scene on which the
// loader's promises hold:
//  - the canonical JSON of the scene loads again, to the same canonical JSON;
//  - its models (camera frame, light frame, wave bounds) are finite;
//  - a few camera rays meet the flat and the displaced water in bounded time (the kernel's
//    march and its step budget, kernel/intersect.glsl, through shading/water_geometry.h)
//    at finite points with finite normals.
// Anything else (another exception, a crash, a sanitizer report, a NaN, a slow unit) is a
// finding: libFuzzer writes the input to the artifact folder.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "base/error.h"
#include "scene/model.h"
#include "scene/scene.h"
#include "shading/water_geometry.h"

namespace {

void require(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "scene_fuzz: %s\n", what);
    std::abort();
  }
}

bool finite(const sg::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  sg::Scene s;
  try {
    s = sg::parse_scene(text, "fuzz.json");
  } catch (const sg::Error& e) {
    require(std::string(e.what()).rfind("fuzz.json: ", 0) == 0, "an error without the file name");
    return 0;
  }
  const std::string canonical = sg::scene_to_json(s);
  sg::Scene again;
  try {
    again = sg::parse_scene(canonical, "canonical.json");
  } catch (const sg::Error& e) {
    std::fprintf(stderr, "scene_fuzz: canonical JSON rejected: %s\n", e.what());
    std::abort();
  }
  require(sg::scene_to_json(again) == canonical, "canonical JSON does not round-trip");

  const sg::SceneModel m(s);
  require(finite(m.camera.forward()) && finite(m.camera.right()) && finite(m.camera.up()),
          "camera frame not finite");
  require(finite(m.light.L) && finite(m.light.e1) && finite(m.light.e2) &&
              std::isfinite(m.light.tan_radius),
          "light frame not finite");
  require(std::isfinite(m.waves.amplitude_bound()) && std::isfinite(m.waves.slope_bound()),
          "wave bounds not finite");
  const sg::FrameTime ft = sg::frame_time(s, s.animation.frames - 1);
  const double t = ft.end;
  require(std::isfinite(t) && std::isfinite(s.shutter_start(0)), "frame times not finite");
  const sg::WaterGeometry water(m, ft);
  const double W = s.width, H = s.height;
  for (const sg::vec2 p : {sg::vec2(W / 2, H / 2), sg::vec2(0, H), sg::vec2(W, 0)}) {
    const sg::vec3 d = m.camera.direction(p.x, p.y);
    require(finite(d), "camera ray not finite");
    const sg::vec3 o = m.camera.position();
    for (const sg::RayHit& h : {sg::intersect_flat(o, d), water.intersect_displaced(o, d, t)}) {
      if (!h.hit) continue;
      require(finite(h.point), "hit point not finite");
      const sg::vec2 g = water.gradient(h.point.x, h.point.z, t);
      require(finite(sg::water_normal(g)), "normal not finite");
    }
  }
  return 0;
}
