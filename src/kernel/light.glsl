// The light disk and the light plane (Podee et al. 2021, Fig. 6 and Eq. 8; scene/light.h).
//
// A unit direction r lies in the disk when its angle to L is at most the radius. The test
// is written as |r - L|^2 <= 4 sin^2(radius / 2), not r . L >= cos(radius): the sun's
// radius, 0.27 degrees, makes cos(radius) = 1 - 1.1e-5, and in float the dot product's
// rounding would move the rim by half a percent of the radius; the chord is well
// conditioned in both precisions.
//
// The light plane is perpendicular to L at unit distance along it; r with r . L > 0 maps
// to (r . e1, r . e2) / (r . L), the gnomonic projection: great circles map to lines and
// the light's cone to the disk of radius tan(radius) about the origin.

SG_FN bool light_contains(IN(Light) l, vec3 unit_dir) {
  vec3 d = unit_dir - l.L;
  return dot(d, d) <= l.chord2;
}

// Light-plane coordinates of direction r (any length, r . L > 0).
SG_FN vec2 light_to_plane(IN(Light) l, vec3 r) {
  real inv = 1.0 / dot(r, l.L);
  return vec2(dot(r, l.e1) * inv, dot(r, l.e2) * inv);
}

// The height (y) of L + p.x e1 + p.y e2: the direction through light-plane point p scaled
// to r . L = 1. Its sign is that of r.y, so the horizon is the straight line
// elevation_on_plane(p) = 0 of the light plane.
SG_FN real elevation_on_plane(IN(Light) l, vec2 p) {
  return l.L.y + p.x * l.e1.y + p.y * l.e2.y;
}

// The horizon's line on the light plane, elevation_on_plane(p) = L.y + p . a = 0: its
// normal a = (e1.y, e2.y) (zero for a light at the zenith, whose plane the horizon never
// meets).
SG_FN vec2 light_horizon_normal(IN(Light) l) {
  return vec2(l.e1.y, l.e2.y);
}
