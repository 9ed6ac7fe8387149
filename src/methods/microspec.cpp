#include "methods/microspec.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "shading/circle_polygon.h"
#include "shading/convex_polygon.h"
#include "shading/radiance.h"
#include "shading/water_geometry.h"

namespace sg {
namespace {

// Corners further than acos(kMinLightCos) from the light are clipped away (no image on
// the light plane; their images would lie beyond tan(87 deg) = 19 there).
constexpr double kMinLightCos = 0.05;
// Reflection spaces smaller than this times tan^2(rho) have no meaningful area ratio.
constexpr double kDegenerateArea = 1e-9;

}  // namespace

CornerReflection corner_reflection(const WaterGeometry& water, double px, double py, double t) {
  CornerReflection c;
  const SceneModel& m = water.model();
  const vec3 o = m.camera.position();
  const vec3 d = normalize(m.camera.direction(px, py));
  const RayHit hit = water.intersect(o, d, t);
  if (!hit.hit) return c;
  const vec3 n = normal_from_gradient(water.gradient(hit.point.x, hit.point.z, t));
  c.hit = true;
  c.at_camera = !(hit.s > 0);
  c.v = -d;
  c.r = normalize(reflect_view(n, c.v));
  return c;
}

MicrospecFractions microspec_fractions(const LightModel& light,
                                       const std::array<CornerReflection, 4>& c,
                                       MicrospecArea area_mode) {
  MicrospecFractions f;
  // Images on the light plane: the corners with r . L >= kMinLightCos, plus, for every pair
  // (edge or diagonal) that crosses r . L = kMinLightCos, the crossing point. Their hull is
  // the part of the corners' hull that the light plane can represent.
  std::array<vec2, ConvexPolygon::kCapacity> pts{};
  int np = 0;
  std::array<double, 4> rl{};
  for (int k = 0; k < 4; ++k) {
    rl[k] = dot(c[k].r, light.L);
    if (rl[k] >= kMinLightCos) pts[np++] = light.to_plane(c[k].r);
  }
  if (np < 4) {
    for (int a = 0; a < 4; ++a) {
      for (int b = a + 1; b < 4; ++b) {
        if ((rl[a] >= kMinLightCos) == (rl[b] >= kMinLightCos)) continue;
        const double s = (kMinLightCos - rl[a]) / (rl[b] - rl[a]);
        pts[np++] = light.to_plane(c[a].r + s * (c[b].r - c[a].r));
      }
    }
  }
  if (np == 0) {
    vec3 sum(0.0);
    for (const auto& k : c) {
      f.below += k.r.y <= 0 ? 0.25 : 0.0;
      sum += k.r;
    }
    f.brightest = normalize(sum);
    return f;
  }
  const ConvexPolygon hull = convex_hull({pts.data(), static_cast<size_t>(np)});
  const double R = light.tan_radius;
  const double hull_area = polygon_area(hull.vertices());
  const vec2 horizon_a(light.e1.y, light.e2.y);  // elevation_on_plane(p) = a . p + L.y
  if (hull_area <= kDegenerateArea * R * R) {
    // All corners reflect (nearly) one direction: the spec's point test at the nearest point.
    const vec2 p = closest_point(hull, vec2(0.0));
    const bool above = light.elevation_on_plane(p) > 0;
    f.degenerate = true;
    f.below = above ? 0.0 : 1.0;
    f.in_light = above && dot(p, p) <= R * R ? 1.0 : 0.0;
    f.brightest = light.from_plane(p);
    return f;
  }
  const ConvexPolygon above = clip_half_plane(hull, horizon_a, light.L.y);
  const double above_area = above.n >= 3 ? polygon_area(above.vertices()) : 0.0;
  f.below = std::clamp(1.0 - above_area / hull_area, 0.0, 1.0);
  // The brightest reflection: the point of the reflection space (above the horizon, where
  // the light can be seen) nearest the light centre.
  const vec2 p = closest_point(above.n > 0 ? above : hull, vec2(0.0));
  f.brightest = light.from_plane(p);
  if (above_area <= 0 || dot(p, p) > R * R) return f;  // the light is not seen
  double shared = 0;
  if (area_mode == MicrospecArea::exact) {
    shared = circle_polygon_area(vec2(0.0), R, above.vertices());
  } else {
    // Each shape cut by a line where it meets the other (see microspec.h): the disk by the
    // supporting line of the polygon nearest the light centre (the nearest edge's line when
    // the centre is inside), the polygon by the disk's tangent line facing it.
    const vec2 q = closest_boundary_point(above, vec2(0.0));
    const double d = contains(above, vec2(0.0)) ? length(q) : -length(q);
    vec2 mean(0.0);
    for (const vec2& p : above.vertices())
      mean += p / double(above.n);
    const vec2 u = dot(mean, mean) > 0 ? normalize(mean) : vec2(1, 0);
    const ConvexPolygon cut = clip_half_plane(above, -u, R);  // u . x <= R
    const double by_disk = cut.n >= 3 ? polygon_area(cut.vertices()) : 0.0;
    shared = std::min(disk_half_plane_area(R, d), by_disk);
  }
  f.in_light = std::clamp(shared / hull_area, 0.0, 1.0);
  return f;
}

RadianceWeights microspec_weights(const SceneModel& m, const std::array<CornerReflection, 4>& c,
                                  MicrospecArea area) {
  const MicrospecFractions f = microspec_fractions(m.light, c, area);
  const vec3 v = normalize(c[0].v + c[1].v + c[2].v + c[3].v);
  const double nv = std::sqrt(std::max(0.0, 0.5 * (1.0 + dot(f.brightest, v))));
  return combine_weights(m, fresnel(m.scene.surface.fresnel, nv), f.in_light, f.below,
                         reflect_view(normalize(f.brightest), v).y);
}

RadianceWeights MicrospecMethod::shade_corners(const FrameContext& ctx, int i, int j,
                                               const std::array<CornerReflection, 4>& c) const {
  for (const auto& k : c) {
    if (!k.hit) return centre_ray_weights(ctx, water(ctx), i, j);  // as `point` (microspec.h)
    if (k.at_camera) return fallback(ctx, i, j);
  }
  return finite_or_fallback(microspec_weights(ctx.model, c, options_.area), ctx, i, j);
}

RadianceWeights MicrospecMethod::weights(const FrameContext& ctx, int i, int j) const {
  const double t = ctx.time.end;
  const WaterGeometry& g = water(ctx);
  const std::array<CornerReflection, 4> c = {
      corner_reflection(g, i, j, t), corner_reflection(g, i + 1, j, t),
      corner_reflection(g, i + 1, j + 1, t), corner_reflection(g, i, j + 1, t)};
  return shade_corners(ctx, i, j, c);
}

void MicrospecMethod::shade_tile(const FrameContext& ctx, int x0, int y0, int x1, int y1,
                                 Image& out) const {
  thread_local std::vector<CornerReflection> grid;
  const int w = x1 - x0 + 1;
  grid.resize(static_cast<size_t>(w) * (y1 - y0 + 1));
  const WaterGeometry& g = water(ctx);
  for (int j = y0; j <= y1; ++j) {
    for (int i = x0; i <= x1; ++i)
      grid[(j - y0) * w + (i - x0)] = corner_reflection(g, i, j, ctx.time.end);
  }
  for (int j = y0; j < y1; ++j) {
    for (int i = x0; i < x1; ++i) {
      const CornerReflection* row = &grid[(j - y0) * w + (i - x0)];
      const std::array<CornerReflection, 4> c = {row[0], row[1], row[w + 1], row[w]};
      store_pixel(ctx, out, i, j, shade_corners(ctx, i, j, c));
    }
  }
}

}  // namespace sg
