// The micro-specular highlight, `microspec` (a baseline, methods/microspec.h): Podee, Max,
// Iwasaki, Dobashi, "Micro-specular-highlight real-time rendering" (docs/references.md),
// Sec. 3, on the water of the scene spec.
//
// Reflection vector selection (Sec. 3.1). At the display time, the camera rays through the
// pixel's four corners meet the water (flat or displaced); each point's normal mirrors its
// view into a corner reflection r_k. Projected on the light plane (light.glsl: origin at
// the light's centre, the disk of radius tan(rho) about it) they bound the reflection space,
// the convex hull of the projected corners (convex_polygon.glsl says why the hull holds
// every interpolated reflection). The point of that space nearest the light centre gives the
// brightest reflection: the centre itself when inside, else the nearest point of its edges.
//
// Result weighting (Sec. 3.2). The light along the brightest reflection (the light when it
// lies in the disk, else the sky), weighted by area(disk and reflection space) /
// area(reflection space): with the paper's constant Jacobian of the bilinear map, the
// fraction of the pixel that mirrors the disk. `exact_area` computes the shared area
// exactly (circle_polygon_area); else the paper's cheaper approximation ("we approximate
// the projected light source by a circle, and the reflection space with a quad"): each
// shape replaced by a straight line where it meets the other: the disk cut by the polygon's
// supporting line nearest the light centre (one circular segment), the polygon by the
// disk's tangent line facing the polygon's vertex mean (one half-plane clip); both are upper
// bounds of the shared area, so their minimum is too (never less light than `exact`).
//
// Choices the paper leaves open (methods/microspec.h has the reasons):
// - Fresnel at the brightest reflection r*, whose normal is the half vector of r* and the
//   view: n . v = sqrt((1 + r* . v) / 2), v the mean of the corners' views.
// - Sky and sea: the horizon is a line of the light plane, so the below fraction is the
//   hull's area beyond it, exactly, and the disk meets the part above it.
// - Zero area (below 1e-9 tan^2(rho)): the spec's point test at the closest point.
// - Corners more than acos(0.05) = 87 degrees from the light have no image: the reflection
//   space is the part of the corners' hull with r . L >= 0.05 (edges and diagonals clipped
//   where they cross it); with no corner there, no light, and the below fraction is the
//   share of corners reflected below the horizon.
// - A pixel whose corner ray misses the water (it straddles the image's horizon line) is
//   point sampled at its centre, as `point` does; a corner with the camera under the
//   surface, or a value that is not finite, falls back to that value and is counted.

const real kMicrospecMinLightCos = 0.05;
const real kMicrospecDegenerateArea = 1e-9;

// The reflection at image-plane point (px, py), at the display time.
SG_FN CornerReflection microspec_corner(IN(WaveBuffer) waves, IN(Frame) f, real px, real py) {
  CornerReflection c;
  c.hit = false;
  c.at_camera = false;
  c.r = vec3(0.0, 1.0, 0.0);
  c.v = vec3(0.0, 1.0, 0.0);
  vec3 o = f.camera.position;
  vec3 d = normalize(camera_direction(f.camera, px, py));
  RayHit hit;
  if (f.displaced) {
    hit = intersect_displaced(waves, f, o, d, 0.0);
  } else {
    hit = intersect_flat(o, d);
  }
  if (!hit.hit) return c;
  vec2 g = water_gradient(waves, f, hit.point.x, hit.point.z, 0.0);
  c.hit = true;
  c.at_camera = !(hit.s > 0.0);
  c.v = -d;
  c.r = normalize(reflect_view(normal_direction(g), c.v));
  return c;
}

// What the reflection space sees: the fraction mirroring the light (gated by the brightest
// reflection lying in the disk), the fraction below the horizon, the brightest reflection.
struct MicrospecFractions {
  real in_light;
  real below;
  vec3 brightest;
  bool degenerate;  // zero area: the point test at the closest point
};

// The unit direction through light-plane point p.
SG_FN vec3 light_from_plane(IN(Light) l, vec2 p) {
  return normalize(l.L + p.x * l.e1 + p.y * l.e2);
}

SG_FN MicrospecFractions microspec_fractions(IN(Light) l, IN(PixelCorners) c, bool exact_area) {
  MicrospecFractions f;
  f.in_light = 0.0;
  f.below = 0.0;
  f.brightest = vec3(0.0, 1.0, 0.0);
  f.degenerate = false;
  // Images on the light plane: the corners with r . L >= the cut, plus, for every pair
  // (edge or diagonal) that crosses it, the crossing point. Their hull is the part of the
  // corners' hull that the light plane can represent.
  ConvexPolygon pts = polygon_none();
  real rl[4];
  for (int k = 0; k < 4; ++k) {
    rl[k] = dot(c.c[k].r, l.L);
    if (rl[k] >= kMicrospecMinLightCos) {
      pts.v[pts.n] = light_to_plane(l, c.c[k].r);
      pts.n += 1;
    }
  }
  if (pts.n < 4) {
    for (int a = 0; a < 4; ++a) {
      for (int b = a + 1; b < 4; ++b) {
        if ((rl[a] >= kMicrospecMinLightCos) == (rl[b] >= kMicrospecMinLightCos)) continue;
        real s = (kMicrospecMinLightCos - rl[a]) / (rl[b] - rl[a]);
        if (pts.n < kPolygonCapacity) {
          pts.v[pts.n] = light_to_plane(l, c.c[a].r + s * (c.c[b].r - c.c[a].r));
          pts.n += 1;
        }
      }
    }
  }
  if (pts.n == 0) {
    vec3 sum = vec3(0.0);
    for (int k = 0; k < 4; ++k) {
      f.below += c.c[k].r.y <= 0.0 ? 0.25 : 0.0;
      sum += c.c[k].r;
    }
    f.brightest = normalize(sum);
    return f;
  }
  ConvexPolygon hull = convex_hull(pts);
  real R = l.tan_radius;
  real hull_area = polygon_area(hull);
  if (hull_area <= kMicrospecDegenerateArea * R * R) {
    // All corners reflect (nearly) one direction: the spec's point test at the nearest point.
    vec2 p = polygon_closest_point(hull, vec2(0.0));
    bool above = elevation_on_plane(l, p) > 0.0;
    f.degenerate = true;
    f.below = above ? 0.0 : 1.0;
    f.in_light = above && dot(p, p) <= R * R ? 1.0 : 0.0;
    f.brightest = light_from_plane(l, p);
    return f;
  }
  ConvexPolygon above = polygon_clip_half_plane(hull, light_horizon_normal(l), l.L.y);
  real above_area = above.n >= 3 ? polygon_area(above) : 0.0;
  f.below = clamp(1.0 - above_area / hull_area, 0.0, 1.0);
  // The brightest reflection: the point of the reflection space (above the horizon, where
  // the light can be seen) nearest the light centre.
  vec2 p = above.n > 0 ? polygon_closest_point(above, vec2(0.0))
                       : polygon_closest_point(hull, vec2(0.0));
  f.brightest = light_from_plane(l, p);
  if (above_area <= 0.0 || dot(p, p) > R * R) return f;  // the light is not seen
  real shared_area = 0.0;
  if (exact_area) {
    shared_area = circle_polygon_area(vec2(0.0), R, above);
  } else {
    // Each shape cut by a line where it meets the other (above).
    vec2 q = polygon_closest_boundary_point(above, vec2(0.0));
    real d = polygon_contains(above, vec2(0.0)) ? length(q) : -length(q);
    vec2 mean = vec2(0.0);
    for (int k = 0; k < above.n; ++k)
      mean += above.v[k] / real(above.n);
    vec2 u = dot(mean, mean) > 0.0 ? normalize(mean) : vec2(1.0, 0.0);
    ConvexPolygon cut = polygon_clip_half_plane(above, -u, R);  // u . x <= R
    real by_disk = cut.n >= 3 ? polygon_area(cut) : 0.0;
    shared_area = min(disk_half_plane_area(R, d), by_disk);
  }
  f.in_light = clamp(shared_area / hull_area, 0.0, 1.0);
  return f;
}

// The pixel's weights from its four corners (all on the water, none at the camera).
SG_FN vec4 microspec_weights(IN(Frame) f, IN(PixelCorners) c, bool exact_area) {
  MicrospecFractions m = microspec_fractions(f.light, c, exact_area);
  vec3 v = normalize(c.c[0].v + c.c[1].v + c.c[2].v + c.c[3].v);
  real nv = sqrt(max(0.0, 0.5 * (1.0 + dot(m.brightest, v))));
  return combine_weights(f, fresnel_factor(f.fresnel, nv), m.in_light, m.below,
                         reflect_view(normalize(m.brightest), v).y);
}

// Pixel (i, j) from its four corners.
SG_FN FallbackResult microspec_shade(IN(WaveBuffer) waves, IN(Frame) f, IN(MicrospecParams) p,
                                     IN(PixelCorners) c, int i, int j) {
  FallbackResult r;
  r.fallback = false;
  // The corners in order: the first off the water (0) or at the camera (1) decides.
  int failed = -1;
  for (int k = 0; k < 4; ++k) {
    if (failed < 0 && !c.c[k].hit) failed = 0;
    if (failed < 0 && c.c[k].at_camera) failed = 1;
  }
  if (failed < 0) {
    r.weights = microspec_weights(f, c, p.exact_area);
    if (finite_weights(r.weights)) return r;
    failed = 1;
  }
  // A corner off the water: the centre ray, as `point`; a corner at the camera or a value
  // that is not finite: the same, counted by the host.
  r.weights = point_pixel(waves, f, i, j);
  r.fallback = failed == 1;
  return r;
}

// Pixel (i, j) alone: its four corners traced (a tile or a workgroup shares them instead:
// methods/microspec.cpp, gl_engine/shaders/main.glsl).
SG_FN FallbackResult microspec_pixel(IN(WaveBuffer) waves, IN(Frame) f, IN(MicrospecParams) p,
                                     int i, int j) {
  PixelCorners c;
  c.c[0] = microspec_corner(waves, f, real(i), real(j));
  c.c[1] = microspec_corner(waves, f, real(i + 1), real(j));
  c.c[2] = microspec_corner(waves, f, real(i + 1), real(j + 1));
  c.c[3] = microspec_corner(waves, f, real(i), real(j + 1));
  return microspec_shade(waves, f, p, c, i, j);
}
