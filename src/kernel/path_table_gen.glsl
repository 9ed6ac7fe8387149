// Making the path-integral table S(u, v, sigma) (Podee et al. 2021, Eq. 18; what the tables
// hold, their grid and every choice: shading/path_table.h). Each row (v, sigma) of S is a
// running sum along u of the cells' integrals of F(sqrt(u^2 + v^2), sigma). F is the host's:
// evaluated once per slice in double on a fine uniform grid (shading/disk_gaussian.h,
// Boost's non-central chi-squared), read here with cubic Lagrange interpolation; a cell is
// integrated with 4-point Gauss-Legendre on sub-panels of at most sigma, so that the rule
// resolves F's edge of width sigma. The host (shading/path_table.cpp) runs these functions
// in double and sums the cells in double; `sunglint web` runs them in float, one fragment
// per cell, and sums the cells with a parallel prefix sum (src/web/shaders/tables.glsl).

// The 4-point Gauss-Legendre rule on [-1, 1]: the 2 positive nodes and their weights (from
// Boost.Math's gauss<double, 4>, to the last bit: path_table_test).
const real kGl4X[2] = SG_ARRAY(real, 2, (0.33998104358485631, 0.86113631159405257));
const real kGl4W[2] = SG_ARRAY(real, 2, (0.65214515486254609, 0.34785484513745385));

// F at distance d from the fine grid g[offset .. offset + count) of spacing `step` (node j
// at d = j step): the cubic through nodes j - 1 .. j + 2 in Newton form; F is even in d, so
// the node before 0 mirrors the one after it. 0 past the grid (beyond sqrt(2) R: F < 1e-9).
SG_FN real fine_f(IN(TableLine) g, int offset, int count, real step, real d) {
  real x = d / step;
  int j = int(x);
  if (j + 2 >= count) return 0.0;
  real t = x - real(j);
  real gm = j == 0 ? line_value(g, offset + 1) : line_value(g, offset + j - 1);
  real g0 = line_value(g, offset + j);
  real g1 = line_value(g, offset + j + 1);
  real g2 = line_value(g, offset + j + 2);
  return g0 + t * ((g1 - g0) + (t - 1.0) * (0.5 * (g1 - 2.0 * g0 + gm) +
                                            (t + 1.0) * (g2 - 3.0 * g1 + 3.0 * g0 - gm) / 6.0));
}

// The integral of F(sqrt(u^2 + v2)) over the panel [c - r, c + r] of u: 4-point
// Gauss-Legendre on the fine grid's F.
SG_FN real path_cell_panel(IN(TableLine) g, int offset, int count, real step, real c, real r,
                           real v2) {
  real cell = 0.0;
  for (int q = 0; q < 2; ++q) {
    real dx = r * kGl4X[q];
    real f = fine_f(g, offset, count, step, sqrt((c - dx) * (c - dx) + v2)) +
             fine_f(g, offset, count, step, sqrt((c + dx) * (c + dx) + v2));
    cell += kGl4W[q] * f;
  }
  return r * cell;
}

// S of slice 0 (sigma = 0, F the disk's indicator): the length of the chord at distance v
// from the centre that lies left of u.
SG_FN real path_table_chord(real u, real v) {
  real c = sqrt(max(0.0, 1.0 - v * v));
  return clamp(u, -c, c) + c;
}
