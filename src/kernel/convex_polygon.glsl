// Small convex polygons in the plane: the reflection space of the micro-specular highlight
// (Podee, Max, Iwasaki, Dobashi, "Micro-specular-highlight real-time rendering", Sec. 3.1;
// microspec.glsl): the four corner reflections of a pixel projected on the light plane,
// and the area the light disk shares with them (Sec. 3.2).
//
// The four projected corners need not form a convex quad: across a wave crest the corner
// reflections can fold (a dart) or cross (a bow tie). Every reflection the paper's bilinear
// model interpolates is a convex combination of the four corner vectors, and the gnomonic
// projection maps a convex combination of directions with r . L > 0 to a convex combination
// of their images (Phi(sum w_k r_k) = sum [w_k (r_k . L) / sum_j w_j (r_j . L)] Phi(r_k)), so
// the reflection space always lies in the convex hull of the projected corners. The method
// therefore works on that hull: for a convex quad it is the quad itself; for a fold or a
// crossing it is the smallest convex set that holds every interpolated reflection.
//
// Vertices are counter-clockwise, without repeats or collinear points; a polygon of fewer
// than three vertices (coincident or collinear corners) has zero area, and
// polygon_closest_point then works on its segment or point. At most kPolygonCapacity
// vertices: a quad's hull clipped by two lines has at most 6.
//
// circle_polygon_area: the disk's area inside a polygon, from disk_triangle_area
// (disk_coverage.glsl): the polygon split into the triangles (c, a_k, a_{k+1}) fanned from
// the disk's centre, each meeting the disk exactly; the signed pieces sum to the
// intersection's area (winding-weighted for a self-intersecting polygon, which is why
// microspec passes the hull). disk_half_plane_area: the disk's area on one side of a line.

const int kPolygonCapacity = 8;

struct ConvexPolygon {
  vec2 v[kPolygonCapacity];
  int n;
};

SG_FN ConvexPolygon polygon_none() {
  ConvexPolygon p;
  for (int k = 0; k < kPolygonCapacity; ++k)
    p.v[k] = vec2(0.0);
  p.n = 0;
  return p;
}

// The convex hull of the points pts.v[0 .. pts.n) (Andrew's monotone chain).
SG_FN ConvexPolygon convex_hull(IN(ConvexPolygon) pts) {
  vec2 p[kPolygonCapacity];
  for (int k = 0; k < kPolygonCapacity; ++k)
    p[k] = vec2(0.0);
  // Insertion sort by (x, y), dropping exact repeats.
  int n = 0;
  for (int q = 0; q < pts.n; ++q) {
    vec2 a = pts.v[q];
    int k = n;
    while (k > 0 && (p[k - 1].x > a.x || (p[k - 1].x == a.x && p[k - 1].y > a.y))) {
      p[k] = p[k - 1];
      k -= 1;
    }
    if (k > 0 && p[k - 1].x == a.x && p[k - 1].y == a.y) {  // a repeat: undo the shift
      for (int m = k; m < n; ++m)
        p[m] = p[m + 1];
      continue;
    }
    p[k] = a;
    n += 1;
  }
  // Lower hull left to right, then upper hull right to left; a turn that is not strictly
  // counter-clockwise is popped, which drops repeats and collinear points.
  vec2 h[2 * kPolygonCapacity];
  for (int k = 0; k < 2 * kPolygonCapacity; ++k)
    h[k] = vec2(0.0);
  int k = 0;
  for (int i = 0; i < n; ++i) {
    while (k >= 2 && cross2(h[k - 1] - h[k - 2], p[i] - h[k - 2]) <= 0.0)
      k -= 1;
    h[k] = p[i];
    k += 1;
  }
  int lower = k + 1;
  for (int i = n - 2; i >= 0; --i) {
    while (k >= lower && cross2(h[k - 1] - h[k - 2], p[i] - h[k - 2]) <= 0.0)
      k -= 1;
    h[k] = p[i];
    k += 1;
  }
  ConvexPolygon res = polygon_none();
  // The chain ends where it started (k - 1 vertices); a single point gives k = 1.
  res.n = n <= 1 ? n : k - 1;
  for (int i = 0; i < res.n; ++i)
    res.v[i] = h[i];
  return res;
}

// Signed area (shoelace): positive when counter-clockwise.
SG_FN real polygon_area(IN(ConvexPolygon) poly) {
  real s = 0.0;
  for (int i = 0; i < poly.n; ++i)
    s += cross2(poly.v[i], poly.v[(i + 1) % poly.n]);
  return 0.5 * s;
}

// Whether p lies in the polygon or on its boundary (false for fewer than 3 vertices).
SG_FN bool polygon_contains(IN(ConvexPolygon) poly, vec2 p) {
  if (poly.n < 3) return false;
  for (int i = 0; i < poly.n; ++i) {
    vec2 a = poly.v[i];
    vec2 b = poly.v[(i + 1) % poly.n];
    if (cross2(b - a, p - a) < 0.0) return false;
  }
  return true;
}

// The point of the segment [a, b] nearest to p.
SG_FN vec2 closest_on_segment(vec2 a, vec2 b, vec2 p) {
  vec2 d = b - a;
  real dd = dot(d, d);
  if (dd <= 0.0) return a;
  return a + clamp(dot(p - a, d) / dd, 0.0, 1.0) * d;
}

// The point of the polygon's boundary (its edges; its segment or point when degenerate)
// nearest to p (n >= 1).
SG_FN vec2 polygon_closest_boundary_point(IN(ConvexPolygon) poly, vec2 p) {
  if (poly.n == 1) return poly.v[0];
  vec2 best = poly.v[0];
  real best_d2 = -1.0;
  int edges = poly.n == 2 ? 1 : poly.n;
  for (int i = 0; i < edges; ++i) {
    vec2 q = closest_on_segment(poly.v[i], poly.v[(i + 1) % poly.n], p);
    real d2 = dot(q - p, q - p);
    if (best_d2 < 0.0 || d2 < best_d2) {
      best_d2 = d2;
      best = q;
    }
  }
  return best;
}

// The point of the polygon nearest to p: p itself when inside (Sec. 3.1: "If the center is
// in the reflection space, the closest point is the center. Otherwise, the closest point is
// the point on the reflection space edge with the closest distance to the center").
SG_FN vec2 polygon_closest_point(IN(ConvexPolygon) poly, vec2 p) {
  return polygon_contains(poly, p) ? p : polygon_closest_boundary_point(poly, p);
}

// The part of the polygon where dot(a, p) + c >= 0 (Sutherland-Hodgman against one line).
SG_FN ConvexPolygon polygon_clip_half_plane(IN(ConvexPolygon) poly, vec2 a, real c) {
  ConvexPolygon res = polygon_none();
  for (int i = 0; i < poly.n; ++i) {
    vec2 p = poly.v[i];
    vec2 q = poly.v[(i + 1) % poly.n];
    real fp = dot(a, p) + c;
    real fq = dot(a, q) + c;
    if (fp >= 0.0 && res.n < kPolygonCapacity) {
      res.v[res.n] = p;
      res.n += 1;
    }
    if ((fp >= 0.0) != (fq >= 0.0) && res.n < kPolygonCapacity) {
      res.v[res.n] = p + (fp / (fp - fq)) * (q - p);
      res.n += 1;
    }
  }
  return res;
}

// The area of the disk |p - centre| <= R inside the polygon (signed by orientation).
SG_FN real circle_polygon_area(vec2 centre, real R, IN(ConvexPolygon) poly) {
  if (poly.n < 3 || !(R > 0.0)) return 0.0;
  real area = 0.0;
  for (int k = 0; k < poly.n; ++k)
    area += disk_triangle_area(poly.v[k] - centre, poly.v[(k + 1) % poly.n] - centre, R);
  return area;
}

// The area of the disk of radius R whose centre lies at signed distance d inside a
// half-plane (d > 0: centre inside; d < 0: outside): R^2 acos(-d/R) + d sqrt(R^2 - d^2),
// clamped to [0, pi R^2].
SG_FN real disk_half_plane_area(real R, real d) {
  if (d >= R) return kPi * R * R;
  if (d <= -R) return 0.0;
  return clamp(R * R * acos(-d / R) + d * sqrt(R * R - d * d), 0.0, kPi * R * R);
}
