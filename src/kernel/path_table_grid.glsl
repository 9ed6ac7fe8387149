// The radial grid of the path-integral tables (kernel/path_table.glsl; shading/path_table.h):
// where the nodes of d (the 2D table F) and of v (the 3D table S) lie in a slice of extent R.
// Its own file because the tables' makers read it too: the host (shading/path_table.cpp) and
// the web page's table passes (src/web/shaders/tables.glsl).
//
// A slice of extent R >= 1: node y in [0, 1] (y = i / (n - 1)) lies at r(y) = 1 - (1 - y /
// y1)^2 for y <= y1 and 1 + (R - 1) ((y - y1) / (1 - y1))^2 above, with y1 = 1 / (1 + 0.35
// sqrt(R - 1)) (0.35 measured best of 0.1 to 1: docs/path-tables.md, "Size"). The nodes
// crowd quadratically about the edge r = 1 from both sides, so the chord sqrt(1 - v^2) of
// sigma = 0 (a square root at v = 1) is linear in y there and F's step at d = 1 falls on a
// node; the narrower the slice's Gaussian, the more nodes lie inside [0, 1].
SG_FN real table_radial_split(real R) {
  return 1.0 / (1.0 + 0.35 * sqrt(max(R - 1.0, 0.0)));
}

SG_FN real table_radial_node(real R, real y) {
  real y1 = table_radial_split(R);
  if (y <= y1) {
    real s = 1.0 - y / y1;
    return 1.0 - s * s;
  }
  real s = (y - y1) / (1.0 - y1);
  return 1.0 + (R - 1.0) * s * s;
}

// The inverse of table_radial_node for 0 <= r <= R.
SG_FN real table_radial(real R, real r) {
  real y1 = table_radial_split(R);
  if (r <= 1.0) return y1 * (1.0 - sqrt(max(1.0 - r, 0.0)));
  return y1 + (1.0 - y1) * sqrt(min((r - 1.0) / max(R - 1.0, 1e-30), 1.0));
}
