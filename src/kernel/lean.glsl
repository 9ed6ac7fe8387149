// LEAN mapping, the baseline `lean` (methods/lean.h; Olano and Baker 2010, "LEAN Mapping",
// I3D, as Podee et al. 2021 compared it, Sec. 5, Table 1): the map of the slope's first and
// second moments, its MIP chain, its filtered lookups and the pixel shaded from them.
//
// The map. Each texel holds, as a GPU's textures do, in single precision,
//     B = (b_x, b_z)                  the slope (dh/dx, dh/dz): LEAN's first-moment texture
//     M = (b_x^2, b_z^2, b_x b_z)     its second moments: LEAN's second-moment texture
// five floats a texel, level after level (MapTexels: an R32F buffer). Level 0 is N x N
// texels over the square [0, N]^2 of texel coordinates (texel (i, j) covers [i, i+1] x
// [j, j+1], its centre at origin + (i + 1/2, j + 1/2) texel metres); level l is N / 2^l a
// side, each texel the mean of its 2 x 2 children (the GPU MIP chain), down to 1 x 1.
// Outside the map a lookup reads the border (GL's CLAMP_TO_BORDER): mean slope 0 and the
// second moments of the mapped waves averaged over the unbounded plane (Podee Eq. 3; the
// cross terms of two waves average to zero), the limit the coarsest level approaches as the
// map grows, so a footprint straddling the edge blends into the uniform NDF at the scale of
// its level instead of showing a seam.
//
// Moments filter linearly, so any linear filter of B and M (box levels, bilinear,
// trilinear, a sum of probes) gives the mean and second moments of the slopes under it,
// and the filtered slope distribution is LEAN's Gaussian of covariance
//     Sigma = M - B B^T
// with its correlation M_xz - B_x B_z (Chermain et al. 2021, Sec. 5.1, Eq. 16; Podee Eq. 4).
// Filters (positions and footprints in level-0 texel units):
//   bilinear(l, s)   the four level-l texels around s, bilinear weights.
//   trilinear(s, lambda)  lambda clamped to [0, L]; bilinear at floor(lambda) and the next
//                    level, blended by the fraction (GL's LINEAR_MIPMAP_LINEAR).
//   lookup, trilinear: lambda = log2(max(|ds/dpx|, |ds/dpy|)) (GL's level of detail).
//   lookup, aniso:   GL EXT_texture_filter_anisotropic: P_max, P_min the longer and shorter
//                    of |ds/dpx|, |ds/dpy|; N = min(ceil(P_max / P_min), max_aniso)
//                    trilinear probes at lambda = log2(P_max / N), equally spaced along the
//                    longer derivative at offsets ((k + 1/2) / N - 1/2) of it, equally
//                    weighted (the footprint parallelogram cut into N strips; Feline,
//                    McCormack et al. 1999, places probes the same way).
//
// The pixel, at the display time: the water point through its centre and its footprint
// (footprint.glsl), the map filtered there; the map's moments plus the cascades' own over
// the footprint (cascade_fields.glsl: a lattice cascade's FFT chain is already a LEAN map of
// it) and the covariance of the waves the map leaves out (the place of LEAN's base
// roughness) make the Gaussian NDF N(-B, Sigma), shaded at its centre (ndf_lobe.glsl). A
// camera under the surface (no footprint to filter) or weights that are not finite fall
// back to the centre ray's radiance (`point`'s), counted by the host.

struct LeanMoments {
  vec2 B;
  vec3 M;  // (xx, zz, xz)
};

SG_FN LeanMoments lean_moments_zero() {
  LeanMoments m;
  m.B = vec2(0.0);
  m.M = vec3(0.0);
  return m;
}

// A single slope: M = g g^T.
SG_FN LeanMoments lean_moments_of_slope(vec2 g) {
  LeanMoments m;
  m.B = g;
  m.M = vec3(g.x * g.x, g.y * g.y, g.x * g.y);
  return m;
}

SG_FN void lean_moments_add(INOUT(LeanMoments) acc, IN(LeanMoments) m, real w) {
  acc.B += w * m.B;
  acc.M += w * m.M;
}

// Sigma = M - B B^T, made positive semi-definite (single-precision texels can leave a
// variance of -1e-8 where the true one is 0).
SG_FN mat2 lean_covariance(IN(LeanMoments) m) {
  real xx = max(0.0, m.M.x - m.B.x * m.B.x);
  real zz = max(0.0, m.M.y - m.B.y * m.B.y);
  real lim = sqrt(xx * zz);
  real xz = clamp(m.M.z - m.B.x * m.B.y, -lim, lim);
  return mat2(vec2(xx, xz), vec2(xz, zz));
}

// The floats a texel takes in the map.
const int kLeanTexelFloats = 5;

// The levels of a map of N = size texels a side (a power of two): N, N/2, ..., 1.
SG_FN int lean_level_count(int size) {
  int levels = 1;
  while ((size >> levels) >= 1)
    ++levels;
  return levels;
}

// The first texel of level `level` in a map of N = size texels a side (a power of two):
// the levels before it hold N^2 + (N/2)^2 + ... + (2 N_l)^2 = (4 N^2 - 4 N_l^2) / 3 texels,
// N_l = N >> level (a geometric series; exact in integers, 4 N^2 - 4 N_l^2 being a
// multiple of 3, and past the last level, N_l = 0, the floor of the whole chain's
// (4 N^2 - 1) / 3: its size). One expression a lookup, where a loop over the levels ran.
SG_FN int lean_level_offset(int size, int level) {
  int nl = size >> level;
  return (4 * size * size - 4 * nl * nl) / 3;
}

// The floats of texel `index` (counted over every level): B, then M.
SG_FN LeanMoments lean_map_texel(IN(MapTexels) map, int index) {
  int at = kLeanTexelFloats * index;
  LeanMoments m;
  m.B = vec2(map_value(map, at), map_value(map, at + 1));
  m.M = vec3(map_value(map, at + 2), map_value(map, at + 3), map_value(map, at + 4));
  return m;
}

SG_FN LeanMoments lean_border(IN(LeanParams) p) {
  LeanMoments m;
  m.B = vec2(0.0);
  m.M = p.border;
  return m;
}

// Texel (i, j) of level `level`, the border outside it.
SG_FN LeanMoments lean_texel(IN(MapTexels) map, IN(LeanParams) p, int level, int i, int j) {
  int n = p.size >> level;
  if (i < 0 || j < 0 || i >= n || j >= n) return lean_border(p);
  return lean_map_texel(map, lean_level_offset(p.size, level) + j * n + i);
}

// Level `level` at s (level-0 texel coordinates): its texel centres sit at (i + 1/2) 2^l.
SG_FN LeanMoments lean_bilinear(IN(MapTexels) map, IN(LeanParams) p, int level, vec2 s) {
  real scale = 1.0 / real(1 << level);
  vec2 uv = s * scale - vec2(0.5);
  vec2 fl = floor(uv);
  int i0 = int(fl.x);
  int j0 = int(fl.y);
  real a = uv.x - fl.x;
  real b = uv.y - fl.y;
  LeanMoments acc = lean_moments_zero();
  lean_moments_add(acc, lean_texel(map, p, level, i0, j0), (1.0 - a) * (1.0 - b));
  lean_moments_add(acc, lean_texel(map, p, level, i0 + 1, j0), a * (1.0 - b));
  lean_moments_add(acc, lean_texel(map, p, level, i0, j0 + 1), (1.0 - a) * b);
  lean_moments_add(acc, lean_texel(map, p, level, i0 + 1, j0 + 1), a * b);
  return acc;
}

SG_FN LeanMoments lean_trilinear(IN(MapTexels) map, IN(LeanParams) p, vec2 s, real lambda) {
  int top = p.levels - 1;
  if (!(lambda > 0.0)) return lean_bilinear(map, p, 0, s);  // also NaN (a zero footprint)
  if (lambda >= real(top)) return lean_bilinear(map, p, top, s);
  int l0 = int(lambda);
  real t = lambda - real(l0);
  LeanMoments acc = lean_moments_zero();
  lean_moments_add(acc, lean_bilinear(map, p, l0, s), 1.0 - t);
  lean_moments_add(acc, lean_bilinear(map, p, l0 + 1, s), t);
  return acc;
}

// The map filtered at s with the footprint's derivatives ds/dpx, ds/dpy (level-0 texels
// per pixel).
SG_FN LeanMoments lean_lookup(IN(MapTexels) map, IN(LeanParams) p, vec2 s, vec2 ds_dpx,
                              vec2 ds_dpy) {
  real px = length(ds_dpx);
  real py = length(ds_dpy);
  real pmax = max(px, py);
  real pmin = min(px, py);
  if (!p.aniso || !(pmax > 0.0)) return lean_trilinear(map, p, s, log2(pmax));
  real ratio = pmin > 0.0 ? ceil(pmax / pmin) : real(p.max_aniso);
  int n = int(clamp(ratio, 1.0, real(max(1, p.max_aniso))));
  real lambda = log2(pmax / real(n));
  vec2 major = px >= py ? ds_dpx : ds_dpy;
  LeanMoments acc = lean_moments_zero();
  for (int k = 0; k < n; ++k) {
    vec2 at = s + ((real(k) + 0.5) / real(n) - 0.5) * major;
    lean_moments_add(acc, lean_trilinear(map, p, at, lambda), 1.0 / real(n));
  }
  return acc;
}

// The centre of level-0 texel (i, j), camera-relative (x, z).
SG_FN vec2 lean_texel_centre(IN(LeanParams) p, int i, int j) {
  return p.origin + (vec2(real(i), real(j)) + vec2(0.5)) * p.texel;
}

// Level 0's texels in a block of kLeanBlock x kLeanBlock from texel (i0, j0), from the
// frame's waves at the display time: the GL engine's map program, a block an invocation
// (the CPU fills the same terms in SIMD lanes, methods/lean.cpp). Each wave's row and
// column phases are taken once a row and once a column of the block, and every texel's
// slope by angle addition from them (lean_wave_slope), as the CPU's lanes take them from a
// block's tables: 2 kLeanBlock sines and cosines a wave for kLeanBlock^2 texels, where a
// texel alone took two (a quarter of them at kLeanBlock = 4), without the workgroup's
// shared memory and barriers that llvmpipe pays for (docs/benchmarks.md, "`lean`'s map on
// the GPU with a workgroup's shared rows and columns"). A wave the grid cannot sample
// (lean_wave_amplitude 0) is skipped, alike for every invocation. Texel (i0 + c, j0 + r)
// is g[r * kLeanBlock + c]; those past the map's side are computed and not stored.
const int kLeanBlock = 4;
struct LeanBlock {
  vec2 g[kLeanBlock * kLeanBlock];
};

SG_FN LeanBlock lean_level0_block(IN(WaveBuffer) waves, IN(Frame) f, IN(LeanParams) p, int i0,
                                  int j0) {
  LeanBlock b;
  for (int e = 0; e < kLeanBlock * kLeanBlock; ++e)
    b.g[e] = vec2(0.0);
  for (int k = 0; k < f.wave_count; ++k) {
    Wave w = wave_at(waves, f, k);
    vec2 amplitude = lean_wave_amplitude(w, p.texel);
    if (amplitude.x == 0.0 && amplitude.y == 0.0) continue;
    vec2 row[kLeanBlock];
    vec2 column[kLeanBlock];
    for (int q = 0; q < kLeanBlock; ++q) {
      vec2 xz = lean_texel_centre(p, i0 + q, j0 + q);
      real r = lean_row_phase(w, xz.y);
      real c = lean_column_phase(w, xz.x);
      row[q] = vec2(cos(r), sin(r));
      column[q] = vec2(cos(c), sin(c));
    }
    for (int r = 0; r < kLeanBlock; ++r) {
      for (int c = 0; c < kLeanBlock; ++c)
        b.g[r * kLeanBlock + c] += lean_wave_slope(amplitude, row[r], column[c]);
    }
  }
  return b;
}

// A texel of level l + 1 from its four children in level l.
SG_FN LeanMoments lean_parent(IN(LeanMoments) c00, IN(LeanMoments) c10, IN(LeanMoments) c01,
                              IN(LeanMoments) c11) {
  LeanMoments acc = lean_moments_zero();
  lean_moments_add(acc, c00, 0.25);
  lean_moments_add(acc, c10, 0.25);
  lean_moments_add(acc, c01, 0.25);
  lean_moments_add(acc, c11, 0.25);
  return acc;
}

// The map's filtered moments at a footprint: texel coordinates and their derivatives.
SG_FN LeanMoments lean_footprint_moments(IN(MapTexels) map, IN(LeanParams) p, IN(Footprint) fp) {
  if (p.empty) return lean_border(p);
  vec2 s = (vec2(fp.point.x, fp.point.z) - p.origin) / p.texel;
  vec2 ds_dpx = vec2(fp.dp_dpx.x, fp.dp_dpx.z) / p.texel;
  vec2 ds_dpy = vec2(fp.dp_dpy.x, fp.dp_dpy.z) / p.texel;
  return lean_lookup(map, p, s, ds_dpx, ds_dpy);
}

SG_FN FallbackResult lean_pixel(IN(WaveBuffer) waves, IN(Frame) f, IN(MapTexels) map,
                                IN(LeanParams) p, int i, int j) {
  FallbackResult r;
  r.fallback = false;
  Footprint fp = pixel_footprint(waves, f, real(i) + 0.5, real(j) + 0.5, 0.0, f.displaced);
  if (!fp.hit) {
    r.weights = miss_pixel_weights(f, i, j);
    return r;
  }
  if (fp.distance > 0.0) {
    LeanMoments mo = lean_footprint_moments(map, p, fp);
    vec2 mean = mo.B;
    mat2 cov = lean_covariance(mo) + sym2(p.base);
    if (f.cascade_count > 0) {
      CascadeMoments cm = cascade_footprint_moments(waves, f, vec2(fp.point.x, fp.point.z),
                                                    footprint_xz_jacobian(fp));
      mean += cm.mean;
      cov += sym2(cm.cov);
    }
    r.weights = ndf_lobe_weights(f, fp.view, -mean, cov);
    if (finite_weights(r.weights)) return r;
  }
  r.weights = point_pixel(waves, f, i, j);
  r.fallback = true;
  return r;
}
