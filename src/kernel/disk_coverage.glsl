// The visible light disk over a pixel square: the fraction of pixel (i, j) that sees the
// disk, for the methods that integrate over the pixel (staa, staa-temporal, the
// baselines); the sampling estimators (point, supersample, reference) test their rays.
//
// The camera's image plane and the light plane (perpendicular to L at unit distance,
// light.glsl) are both central projections from the camera's centre, so the map between
// them is a homography: it takes the pixel square to a convex quadrilateral whose edges are
// exactly the images of the square's edges, and the light's cone to the disk of radius
// tan(radius) about the origin. The coverage is the disk's area inside that quadrilateral
// over the quadrilateral's area. It weights the light plane's area, not the image plane's:
// the two differ by the homography's Jacobian, whose relative change across one pixel near
// the disk is about 3 theta dtheta (theta the angle to L, at most the radius plus a pixel,
// dtheta a pixel's angle): below 1e-5 for the sun at any usual image size. Small and well
// conditioned in float: the corners are of the size of the disk, no cancellation.
//
// disk_triangle_area is also the CPU's circle-polygon area (shading/circle_polygon.h):
// the polygon split into triangles (0, a, b) fanned from the disk's centre; each triangle
// meets the circle in at most two points of its far edge; pieces inside contribute
// triangles, pieces outside circular sectors.

SG_FN real cross2(vec2 a, vec2 b) {
  return a.x * b.y - a.y * b.x;
}

// Signed area of the sector of radius R from direction a to direction b (|angle| < pi).
SG_FN real disk_sector_area(vec2 a, vec2 b, real R) {
  return 0.5 * R * R * atan(cross2(a, b), dot(a, b));
}

// Signed area of the disk |p| <= R inside the triangle (0, a, b).
SG_FN real disk_triangle_area(vec2 a, vec2 b, real R) {
  vec2 d = b - a;
  real A = dot(d, d);
  if (!(A > 0.0)) return 0.0;
  // |a + s d|^2 = R^2:  A s^2 + B s + C = 0.
  real B = 2.0 * dot(a, d);
  real C = dot(a, a) - R * R;
  real disc = B * B - 4.0 * A * C;
  if (disc <= 0.0) return disk_sector_area(a, b, R);  // the edge's line misses the circle
  real sq = sqrt(disc);
  // Stable roots (no cancellation between -B and sq).
  real q = -0.5 * (B + (B >= 0.0 ? sq : -sq));
  real s1 = q / A;
  real s2 = q != 0.0 ? C / q : -s1;
  if (s1 > s2) {
    real tmp = s1;
    s1 = s2;
    s2 = tmp;
  }
  if (s2 <= 0.0 || s1 >= 1.0) return disk_sector_area(a, b, R);  // the chord lies beyond
  real t1 = max(s1, 0.0);
  real t2 = min(s2, 1.0);
  vec2 p1 = a + t1 * d;
  vec2 p2 = a + t2 * d;
  // a..p1 outside (a sector), p1..p2 inside (a triangle), p2..b outside (a sector); the
  // triangle as cross(p1, p2 - p1) / 2, with no cancellation of terms of size |p1| |p2|.
  real area = 0.5 * cross2(p1, (t2 - t1) * d);
  if (t1 > 0.0) area += disk_sector_area(a, p1, R);
  if (t2 < 1.0) area += disk_sector_area(p2, b, R);
  return area;
}

// The fraction of pixel (i, j), the square [i, i+1] x [j, j+1] of the image plane, whose
// rays see the light disk (0 when the light is not visible).
SG_FN real light_pixel_coverage(IN(Camera) c, IN(Light) l, int i, int j) {
  if (!l.visible) return 0.0;
  real px = real(i) + 0.5;
  real py = real(j) + 0.5;
  vec3 d = camera_direction(c, px, py);
  real len = length(d);
  // Far from the disk: the pixel's half-diagonal as an angle, bounded by the larger
  // differential (the direction is not unit), plus the radius.
  real reach = 0.5 * (length(camera_ddir_dpx(c)) + length(camera_ddir_dpy(c))) / len;
  vec3 u = d / len - l.L;
  real lim = l.radius + reach * 1.5;
  if (dot(u, u) > lim * lim) return 0.0;
  // The quadrilateral on the light plane, counter-clockwise there or not: the signed sums
  // share the sign of its area.
  vec2 q0 = light_to_plane(l, camera_direction(c, px - 0.5, py - 0.5));
  vec2 q1 = light_to_plane(l, camera_direction(c, px + 0.5, py - 0.5));
  vec2 q2 = light_to_plane(l, camera_direction(c, px + 0.5, py + 0.5));
  vec2 q3 = light_to_plane(l, camera_direction(c, px - 0.5, py + 0.5));
  real quad = 0.5 * (cross2(q0, q1) + cross2(q1, q2) + cross2(q2, q3) + cross2(q3, q0));
  if (!(abs(quad) > 0.0)) return light_contains(l, d / len) ? 1.0 : 0.0;
  real R = l.tan_radius;
  real in_disk = disk_triangle_area(q0, q1, R) + disk_triangle_area(q1, q2, R) +
                 disk_triangle_area(q2, q3, R) + disk_triangle_area(q3, q0, R);
  return clamp(in_disk / quad, 0.0, 1.0);
}

// A pixel whose centre ray hits no water: the sky at the centre, and the light over the
// part of the pixel that sees it.
SG_FN vec4 miss_pixel_weights(IN(Frame) f, int i, int j) {
  real px = real(i) + 0.5;
  real py = real(j) + 0.5;
  vec3 d = normalize(camera_direction(f.camera, px, py));
  real cover = light_pixel_coverage(f.camera, f.light, i, j);
  return cover * light_weights() + (1.0 - cover) * sky_weights(f, d.y);
}
