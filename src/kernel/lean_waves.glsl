// The LEAN map's per-wave terms (lean.glsl; Olano and Baker 2010, "LEAN Mapping"),
// lane-generic: the CPU engine fills the map's level 0 over its SIMD lanes, a block of
// texels a lane each (kernel/cpu/lane_passes.inc, LeanBlockPass), where a GPU thread runs
// the same terms over a block of 4 x 4 texels (lean.glsl, lean_level0_block).
//
// A texel holds the slope of the waves its grid samples, point-sampled at its centre (a
// normal map generated from sine data, as Podee et al. 2021 generated theirs, Sec. 5). A
// wave's phase there splits into a part along the texel's column and one along its row,
//     theta(x, z) = a x + (b z + theta0),
// so that a block's tables of cos and sin of each part give every texel's wave by angle
// addition, cos(theta) = cos(row) cos(column) - sin(row) sin(column): four products a
// wave and texel instead of a sine.

// Wave w's share in a map of `texel` metres: its slope's amplitude A (a, b) where the grid
// samples it (at most 0.5 cycles per texel along x and along z: aliasing.glsl's projected
// frequency over the texel grid), else 0 (the map leaves it to its uniform covariance,
// Podee Eq. 3: point samples would alias it into a false pattern).
SG_FN vec2 lean_wave_amplitude(IN(Wave) w, real texel) {
  mat2 grid = mat2(vec2(texel, 0.0), vec2(0.0, texel));
  real mapped =
      select(projected_frequency(vec2(w.a, w.b), grid, true) <= 0.5, real(1.0), real(0.0));
  return (mapped * w.A) * vec2(w.a, w.b);
}

// The phase's part along a column (x) and along a row (z, with the display time's phase),
// each reduced to [-pi, pi].
SG_FN real lean_column_phase(IN(Wave) w, real x) {
  return wrap_angle(w.a * x);
}
SG_FN real lean_row_phase(IN(Wave) w, real z) {
  return wrap_angle(w.b * z + w.theta0);
}

// One wave's slope (dh/dx, dh/dz) = A cos(theta) (a, b) at a texel from its amplitude
// (lean_wave_amplitude) and the (cos, sin) of its row's and column's phases.
SG_FN vec2 lean_wave_slope(vec2 amplitude, vec2 row, vec2 column) {
  return amplitude * (row.x * column.x - row.y * column.y);
}
