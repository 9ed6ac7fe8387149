// `staa`'s pass over the waves, one wave's terms (Podee et al. 2021 Sec. 3.2-3.4, with
// sunglint's footprint term; staa.glsl step 2): its projected frequency splits it into a
// resolved share (1 - alpha) A and an aliasing share alpha A (Eq. 20, aliasing.glsl); the
// resolved share adds to the gradients and Hessians at the path's instants, the aliasing
// share to the NDF's moments (Eq. 3, or Eqs. 4-7 with Appendix A: ndf.glsl), and with the
// smooth terms on, the whole wave to the pixel's cells (ndf.glsl, box_cells_add).
// Lane-generic (wave_terms.glsl): the GPU's loop (staa.glsl, staa_waves_loop) and the CPU
// engine's SIMD lanes (kernel/cpu/wave_sums.cpp) run this same text.

// What the pass over the waves gathers for one pixel.
struct StaaSums {
  PathGradients path;  // the resolved waves' gradients at the instants
  // The resolved waves' Hessian (xx, xz, zz) at the instants; under a moving camera the
  // display time's at every instant.
  vec3 hess[kMaxSegments + 1];
  NdfMoments ndf;  // the aliasing waves' NDF
  bool any_alias;  // some wave with A > 0 has alpha > 0
  // The largest departure of a resolved share's slope from its tangent across the pixel,
  // (1 - alpha) A |k| D^2 (reflection units; staa_wave_add).
  real fold;
  // The smooth terms (--smooth-cells n > 0): every wave's moments at its full amplitude
  // (not split by Eq. 20) over n x n cells of the pixel (ndf.glsl, box_cells_add), and the
  // remainder's covariance, which every cell shares.
  BoxCells cells;
  vec3 remainder;
};

// Zero sums for the instants of K sub-arcs (the rest of the arrays is not read), in place:
// the sums are large (in the CPU's SIMD lanes, kilobytes), and no copy is made of them.
SG_FN StaaSums staa_sums_zero(int K) {
  StaaSums s;
  for (int k = 0; k <= K; ++k) {
    s.path.g[k] = vec2(0.0);
    s.hess[k] = vec3(0.0);
  }
  s.ndf.mean = vec2(0.0);
  s.ndf.cov = vec3(0.0);
  s.any_alias = false;
  s.fold = 0.0;
  for (int c = 0; c < kMaxBoxCells; ++c) {
    s.cells.m[c].mean = vec2(0.0);
    s.cells.m[c].cov = vec3(0.0);
  }
  s.remainder = vec3(0.0);
  return s;
}

// The pass's pixel-wide inputs (staa.glsl, staa_wave_pixel fills them).
struct StaaWavePixel {
  vec2 point;       // (x, z) of the water point at the display time, camera-relative
  mat2 J;           // the footprint's Jacobian (footprint.glsl: columns dX/dpx, dX/dpy)
  mat2 Jinv;        // its inverse, 0 where J is singular
  bool invertible;  // det J != 0
  bool max_norm;    // Eq. 20's frequency: the larger axis (else the norm)
  real alias_start;
  real alias_end;
  bool curvature;      // the curvature limit is on
  real limit;          // the curvature limit times the light's radius
  bool per_pixel_ndf;  // Appendix A's moments (else Eq. 3)
  int cells;           // the smooth terms' cells per side (0: none)
  PathInstants inst;   // the path's instants (wave_terms.glsl)
  // The instants' Hessians are read (a still camera and a shutter: the footprint term at
  // each instant, staa.glsl, staa_footprint_covariance); else the display time's alone.
  bool instant_hessians;
  vec2 sweep;  // a moving camera's motion p_K - p_0 over the shutter
  // The camera moves through a shutter of this length (s): the smooth terms' cells take the
  // waves the path does not follow averaged over it (staa_wave_add).
  bool swept_cells;
  real duration;
};

// The smooth terms' cells per side where they are on (px.cells > 0). A GLSL program compiled
// for one value of the option (SG_SMOOTH_CELLS, gl_engine/kernel_program.h) takes the
// constant: the cells' array indexed by it stays in registers, as K does (frame_segments,
// interface.glsl). Elsewhere, the pixel's.
SG_FN int staa_cells_side(IN(StaaWavePixel) px) {
#ifndef SG_SMOOTH_CELLS
  return px.cells;
#else
  return SG_SMOOTH_CELLS;
#endif
}

// Whether the cells sweep over the shutter (a moving camera): the constant in a GLSL
// program compiled for it (SG_SWEPT_CELLS, gl_engine/kernel_program.h) and in the web
// page's, whose cameras are fixed (SG_FIXED_CAMERA); else the pixel's.
SG_FN bool staa_swept_cells(IN(StaaWavePixel) px) {
#ifndef SG_SWEPT_CELLS
#ifndef SG_FIXED_CAMERA
  return px.swept_cells;
#else
  return false;
#endif
#else
  return SG_SWEPT_CELLS != 0;
#endif
}

// Wave i's resolved share A (sine s and cosine c of its display-time phase) in the
// gradients and Hessians of the path's instants: instant k's phase by
// path_instant_cos_sin (path_terms.glsl), the gradient A cos k, the Hessian -A sin k k^T
// (the instants' other than the display time's only where `hessians`: nothing reads them
// under a moving camera or a zero shutter).
SG_FN void staa_path_add(INOUT(StaaSums) sums, IN(PathInstants) inst, bool hessians,
                         IN(WaveBuffer) waves, int i, IN(Wave) w, real A, real s, real c) {
  vec2 k = vec2(w.a, w.b);
  vec3 kk = wave_curvature_of(w);
  int K = path_segments(inst);
  sums.path.g[K] += (A * c) * k;
  sums.hess[K] -= (A * s) * kk;
  for (int q = 0; q < K; ++q) {
    vec2 cs = path_instant_cos_sin(inst, waves, i, w, s, c, q);
    sums.path.g[q] += (A * cs.x) * k;
    if (hessians) sums.hess[q] -= (A * cs.y) * kk;
  }
}

// Wave i's terms in the pixel's sums.
SG_FN void staa_wave_add(INOUT(StaaSums) sums, IN(StaaWavePixel) px, IN(WaveBuffer) waves, int i,
                         IN(Wave) w) {
  vec2 k = vec2(w.a, w.b);
  real theta = wave_phase(w, px.point.x, px.point.y, 0.0);
  real s = sin(theta);
  real c = cos(theta);
  real freq = px.inst.moving ? swept_frequency(k, px.J, px.sweep, px.max_norm)
                             : projected_frequency(k, px.J, px.max_norm);
  real alpha = alias_fraction(freq, px.alias_start, px.alias_end);
  real D = px.invertible ? footprint_half_width(k, px.Jinv) : 0.0;
  // Where the linearisation breaks: a resolved wave of phase half-width D has a slope
  // A |k| cos(theta) that departs from its tangent by up to A |k| D^2 / 2 across the
  // pixel; the reflection moves twice as far, dev.
  real dev = w.slope * D * D;
  if (px.curvature) {
    // Past `curvature_limit` disk radii the wave goes to the aliasing set, ramping over a
    // factor of two.
    alpha = max(alpha, clamp(dev / px.limit - 1.0, 0.0, 1.0));
  }
  real resolved = (1.0 - alpha) * w.A;
  sums.fold = max(sums.fold, (1.0 - alpha) * dev);
  // A share of 0 adds nothing: the branch skips the instants' terms of the fully aliasing
  // waves.
  if (any_lane(resolved != 0.0))
    staa_path_add(sums, px.inst, px.instant_hessians, waves, i, w, resolved, s, c);
  real aliasing = alpha * w.A;
  if (any_lane(aliasing > 0.0)) {
    sums.any_alias = true;
    if (px.per_pixel_ndf) {
      real Dn = px.inst.moving ? swept_half_width(D, k, px.sweep) : D;
      ndf_add_per_pixel(sums.ndf, aliasing, k, c, Dn, sin(Dn), cos(Dn));
    } else {
      ndf_add_uniform(sums.ndf, aliasing, k);
    }
  }
  if (px.cells > 0) {
    vec2 h = 0.5 * vec2(dot(k, px.J[0]), dot(k, px.J[1]));
    if (staa_swept_cells(px)) {
      // Under a moving camera the cells take the resolved share at the display time (the
      // path's instants move them over the shutter: staa_smooth_terms) and the aliasing
      // share averaged over the shutter, which the path does not follow: at the pixel's
      // sliding point its phase turns by c T + k . (p_K - p_0) (path_instant_cos_sin), a
      // third axis of each cell's box (box_cells_add_swept). Taken whole at the display
      // time, a wave the pixel slides across kept one phase's slope where the water shows
      // the pixel every phase (docs/method.md, "A moving camera").
      if (any_lane(resolved != 0.0))
        box_cells_add(sums.cells, staa_cells_side(px), resolved, k, s, c, h);
      if (any_lane(aliasing > 0.0)) {
        box_cells_add_swept(sums.cells, staa_cells_side(px), aliasing, k, s, c, h,
                            0.5 * (w.c * px.duration + dot(k, px.sweep)));
      }
    } else {
      box_cells_add(sums.cells, staa_cells_side(px), w.A, k, s, c, h);
    }
  }
}
