#include "scene/footprint.h"

#include "scene/intersect.h"

namespace sg {

namespace {

PixelFootprint footprint(const SceneModel& m, double px, double py, double t, bool displaced) {
  PixelFootprint f;
  const vec3 d = m.camera.direction(px, py);  // unnormalised: linear in (px, py)
  const vec3 o = m.camera.position();
  RayHit hit = displaced ? intersect_displaced(m.waves, o, normalize(d), t) : intersect_flat(o, d);
  if (!hit.hit) return f;
  // intersect_displaced works on the unit direction: convert its parameter to d's.
  const double s = displaced ? hit.s / length(d) : hit.s;
  vec3 normal(0, 1, 0);
  if (displaced) {
    vec2 g = m.waves.gradient(hit.point.x, hit.point.z, t);
    normal = vec3(-g.x, 1, -g.y);
  }
  f.hit = true;
  f.point = hit.point;
  f.distance = length(o - hit.point);
  f.at_camera = !(f.distance > 0);
  f.view = f.at_camera ? -normalize(d) : normalize(o - hit.point);
  f.dp_dpx = transfer_differential(d, s, m.camera.ddir_dpx(), normal);
  f.dp_dpy = transfer_differential(d, s, m.camera.ddir_dpy(), normal);
  return f;
}

}  // namespace

PixelFootprint pixel_footprint(const SceneModel& m, double px, double py, double t) {
  return footprint(m, px, py, t, m.displaced());
}

PixelFootprint rest_plane_footprint(const SceneModel& m, double px, double py) {
  return footprint(m, px, py, 0.0, false);
}

}  // namespace sg
