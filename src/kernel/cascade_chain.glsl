// A lattice cascade's texels in the wave buffer, from its FFT fields on the grid (the
// layout the kernel reads: kernel/cascade_grid.glsl), and the differences of its height
// grid whose maxima bound the displaced march's interpolant. The LEAN chain (Olano and
// Baker 2010, "LEAN Mapping", Sec. 3: a filtered normal is the mean of the slopes and of
// their second moments over the footprint): level 0 holds each grid point's slope s, its
// curvatures and s s^T; level l + 1 the mean of 2 x 2 texels of level l, down to one texel.
// Not part of the shading kernel (kernel.glsl does not list it): the host's fields
// (shading/cascade_fields.cpp, CascadeFields::append) and the GL engine's passes
// (gl_engine/shaders/cascade_chain.glsl and cascade_bounds.glsl) include it, so the two
// engines write the same texels from one text.

// What an instant's chain holds, the GL pass's `full` (shading/cascade_fields.h,
// CascadeReads): the slopes alone, the rest 0 (the path's instants other than the display
// time); the display time's whole chain; the display time's slopes and height alone, at
// level 0 (what the reads other than `all` build).
const int kCascadeChainSlopes = 0;
const int kCascadeChainFull = 1;
const int kCascadeChainSlopesHeight = 2;

// A texel's two vec4s as the chain writes them: a = (E[s_x], E[s_z], E[h_xx], E[h_zz]),
// b = (E[h_xz], E[s_x^2], E[s_x s_z], E[s_z^2]).
struct CascadeChainTexel {
  vec4 a;
  vec4 b;
};

// Level 0's texel of a grid point from its slope (dh/dx, dh/dz), height and curvatures
// (d2h/dx2, d2h/dxdz, d2h/dz2). A grid point has no spread (its second moments are its
// slope's square, and are not read), so b.y holds the height instead, and in the whole
// chain b.zw the slope at the path's first instant (`start`: the shutter start's, on flat
// water; 0 where the engines leave it out), which a still camera's pass over the display
// time's texels takes along (cascade_grid.glsl, cascade_level) without a third texel a
// point; what `mode` leaves out is 0 (the height and curvatures are not read then).
SG_FN CascadeChainTexel cascade_chain_level0(vec2 slope, real height, vec3 curvature, vec2 start,
                                             int mode) {
  CascadeChainTexel t;
  t.a = vec4(slope.x, slope.y, 0.0, 0.0);
  t.b = vec4(0.0);
  if (mode == kCascadeChainFull) {
    t.a = vec4(slope.x, slope.y, curvature.x, curvature.z);
    t.b = vec4(curvature.y, height, start.x, start.y);
  } else if (mode == kCascadeChainSlopesHeight) {
    t.b = vec4(0.0, height, 0.0, 0.0);
  }
  return t;
}

// A child's second texel as its parent averages it: at level 0 the products of its slope
// in place of the height and the first instant's slope.
SG_FN vec4 cascade_chain_moments(IN(CascadeChainTexel) t, int level) {
  if (level == 0) return vec4(t.b.x, t.a.x * t.a.x, t.a.x * t.a.y, t.a.y * t.a.y);
  return t.b;
}

// The texel of level `child_level` + 1 over four texels of level `child_level`, (x, y) at
// (2i, 2j), (2i + 1, 2j), (2i, 2j + 1) and (2i + 1, 2j + 1): their mean, the second texel
// 0 unless `mode` is the whole chain.
SG_FN CascadeChainTexel cascade_chain_parent(IN(CascadeChainTexel) c00, IN(CascadeChainTexel) c10,
                                             IN(CascadeChainTexel) c01, IN(CascadeChainTexel) c11,
                                             int child_level, int mode) {
  CascadeChainTexel t;
  t.a = 0.25 * (c00.a + c10.a + c01.a + c11.a);
  t.b = vec4(0.0);
  if (mode == kCascadeChainFull) {
    t.b =
        0.25 * (cascade_chain_moments(c00, child_level) + cascade_chain_moments(c10, child_level) +
                cascade_chain_moments(c01, child_level) + cascade_chain_moments(c11, child_level));
  }
  return t;
}

// The height grid's differences at point (i, j) whose maxima over the grid bound its
// bicubic interpolant (shading/cascade_fields.h, cascade_bounds_from_maxima, in this
// order), from the heights at (i, j), (i + 1, j), (i - 1, j), (i, j + 1), (i, j - 1) and
// (i + 1, j + 1) (the indices wrapping around the periodic patch).
struct CascadeHeightDifferences {
  real height;  // |h(i, j)|
  real step_x;  // |h(i + 1, j) - h(i, j)|
  real step_z;  // |h(i, j + 1) - h(i, j)|
  real second;  // the larger second difference, along x or z
  real mixed;   // |h(i + 1, j + 1) - h(i + 1, j) - h(i, j + 1) + h(i, j)|
};

SG_FN CascadeHeightDifferences cascade_height_differences(real h, real h_xp, real h_xm, real h_zp,
                                                          real h_zm, real h_xpzp) {
  CascadeHeightDifferences d;
  d.height = abs(h);
  d.step_x = abs(h_xp - h);
  d.step_z = abs(h_zp - h);
  d.second = max(abs(h_xm - 2.0 * h + h_xp), abs(h_zm - 2.0 * h + h_zp));
  d.mixed = abs(h_xpzp - h_xp - h_zp + h);
  return d;
}
