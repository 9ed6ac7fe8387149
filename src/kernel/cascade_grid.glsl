// Lattice cascades shaded from their FFT fields, part one: the fields in the wave buffer
// and their point reads (slope, Hessian, height), before the intersection that reads the
// height (intersect.glsl); cascade_fields.glsl filters them over a pixel's footprint. A
// per-pixel cost fixed by the number of cascades, not of their waves (scene/lattice.h
// defines a cascade; docs/ocean.md, "Shading from the cascades", the design and its
// measured errors).
//
// The host transforms each cascade once per frame at the path's K + 1 instants
// (scene/cascade_fft.h: slopes and second derivatives on the N x N grid) and builds the
// LEAN chain of every instant (Olano and Baker 2010, "LEAN Mapping", Sec. 3): level l holds
// the means over aligned 2^l x 2^l blocks of the slope s, of s s^T and of the curvatures,
// down to one texel (shading/cascade_fields.h). The texels follow the waves' sums in the
// wave buffer, so every engine reads them as it reads the waves:
//   - at Frame.cascade_base, two texels per cascade: (L, N, o_x, o_z) with o the camera's
//     world (x, z) modulo L (grid coordinates are then camera-relative and small), and
//     (the cascade's whole slope covariance sum A^2/2 k k^T as xx, xz, zz; the levels);
//     then one texel per cascade c, the sum over cascades 0..c of bounds on the interpolated
//     height, on its slope along any horizontal direction and on its second derivative
//     along one (the displaced intersection's, cascade_interpolant_bounds: the last texel
//     bounds them all; the others bound the first cascades, which a far ray marches alone
//     when the rest fits its tolerance, intersect.glsl);
//   - then each cascade's data, instant by instant, level by level, two texels per texel:
//     a = (E[s_x], E[s_z], E[h_xx], E[h_zz]), b = (E[h_xz], E[s_x^2], E[s_x s_z], E[s_z^2]);
//     level 0 holds no spread (a grid point's second moments are its mean's square, and
//     are not read), so at the display time its b.y holds the height h instead, and so
//     at the other instants on displaced water (their texels' other entries than the
//     slopes' means are 0: only the display time's chain is whole); at the display time
//     its b.zw hold instant 0's slopes on flat water (0 on displaced water, and where a
//     method reads the display time alone).
// Level l's texel i averages samples i 2^l .. i 2^l + 2^l - 1 of the grid, whose sample p
// lies at world x = p L / N.
//
// What a pixel reads (cascade_filtered): the level whose texel spans the footprint's
// smaller axis scaled so that the filter passes half of a wave at the middle of Eq. 20's
// ramp (cascade_fields.glsl, cascade_resolving_scale: the waves a pixel resolves stay in
// the mean, those it aliases go to the second moments), the two levels about it blended
// (trilinear), and along the footprint's longer axis up
// to kCascadeMaxTaps such boxes side by side (anisotropic filtering; past that the boxes
// widen). Level 0 is interpolated by Catmull-Rom's cubic (a bilinear blend of a sine
// sampled four times per period is off by up to 29%; the cubic's error is measured in
// docs/ocean.md); the others bilinearly.

// A cascade's header and where its data starts in the wave buffer.
struct Cascade {
  real size;    // L, m
  int n;        // N
  vec2 origin;  // the camera's world (x, z) modulo L
  vec3 cov;     // sum A^2 / 2 k k^T (xx, xz, zz)
  int levels;   // log2 N + 1
  int data;     // the first texel of instant 0, level 0
};

const int kCascadeMaxTaps = 4;

// Texels of one instant's chain: 2 per texel over levels N^2, (N/2)^2, ..., 1.
SG_FN int cascade_instant_texels(int n) {
  return 2 * ((4 * n * n - 1) / 3);
}
// The first texel of level l within an instant's chain.
SG_FN int cascade_level_offset(int n, int l) {
  int nl = n >> l;
  return 2 * ((4 * n * n - 4 * nl * nl) / 3);
}

// Cascade c's header, its data starting at texel `data`. The loops over the cascades walk
// the data with cascade_data_start and cascade_data_end, two header texels a cascade;
// cascade_at finds one cascade alone by walking the headers before it.
SG_FN Cascade cascade_header(IN(WaveBuffer) waves, IN(Frame) f, int c, int data) {
  Cascade r;
  vec4 h0 = wave_texel(waves, f.cascade_base + 2 * c);
  vec4 h1 = wave_texel(waves, f.cascade_base + 2 * c + 1);
  r.size = h0.x;
  r.n = int(h0.y + 0.5);
  r.origin = vec2(h0.z, h0.w);
  r.cov = vec3(h1.x, h1.y, h1.z);
  r.levels = int(h1.w + 0.5);
  r.data = data;
  return r;
}
// Where cascade 0's data starts: after the headers and the bounds.
SG_FN int cascade_data_start(IN(Frame) f) {
  return f.cascade_base + 3 * f.cascade_count;
}
// Where the data of the cascade after `c` starts.
SG_FN int cascade_data_end(IN(Frame) f, IN(Cascade) c) {
  return c.data + (frame_segments(f) + 1) * cascade_instant_texels(c.n);
}

SG_FN Cascade cascade_at(IN(WaveBuffer) waves, IN(Frame) f, int c) {
  int data = cascade_data_start(f);
  for (int q = 0; q < c; ++q)
    data = cascade_data_end(f, cascade_header(waves, f, q, data));
  return cascade_header(waves, f, c, data);
}

// A texel's (or a filtered sample's) two vec4s, and the shutter start's slope where a read
// takes it along (cascade_read).
struct CascadeTexel {
  vec4 a;      // E[s_x], E[s_z], E[h_xx], E[h_zz]
  vec4 b;      // E[h_xz], E[s_x^2], E[s_x s_z], E[s_z^2]
  vec2 start;  // E[s_x], E[s_z] at instant 0, at the same points (else 0)
};

SG_FN CascadeTexel cascade_texel_zero() {
  CascadeTexel t;
  t.a = vec4(0.0);
  t.b = vec4(0.0);
  t.start = vec2(0.0);
  return t;
}

SG_FN void cascade_texel_add(INOUT(CascadeTexel) acc, IN(CascadeTexel) t, real w) {
  acc.a += w * t.a;
  acc.b += w * t.b;
  acc.start += w * t.start;
}

// What a filtered read takes: instant k's chain, with its second texels (`moments`; else
// b = 0: the slope and h_xx, h_zz alone) and, `start`, instant 0's slopes at the same
// points and weights (a camera that holds still reads the path's two ends at one water
// point: one pass over the filter's texels serves both, cascade_fields.glsl).
struct CascadeRead {
  int k;
  bool moments;
  bool start;
};

SG_FN CascadeRead cascade_read(int k, bool moments, bool start) {
  CascadeRead r;
  r.k = k;
  r.moments = moments;
  r.start = start && k > 0;
  return r;
}

// Where level l of a read's instant starts in the wave buffer (and instant 0's, where the
// read takes it along from a texel of its own: -1 where not), and the level's side n_l.
// At level 0 the display time's second texels hold instant 0's slopes in b.zw
// (cascade_chain.glsl, cascade_chain_level0): a read of the display time's moments takes
// them there (`start_in_moments`), two fetches a texel instead of three.
struct CascadeLevel {
  int base;
  int start;
  int n;
  bool moments;
  bool start_in_moments;
};

SG_FN CascadeLevel cascade_level(IN(Cascade) c, IN(CascadeRead) r, int l) {
  CascadeLevel v;
  int level = c.data + cascade_level_offset(c.n, l);
  v.base = level + r.k * cascade_instant_texels(c.n);
  v.start_in_moments = r.start && r.moments && l == 0;
  v.start = r.start && !v.start_in_moments ? level : -1;
  v.n = c.n >> l;
  v.moments = r.moments;
  return v;
}

// Texel (x, y) of a level, the indices wrapped to its n_l x n_l (a power of two: the two's-
// complement mask is the modulo), added to `acc` with weight w.
SG_FN void cascade_texel_add_at(INOUT(CascadeTexel) acc, IN(WaveBuffer) waves, IN(CascadeLevel) lv,
                                int x, int y, real w) {
  int i = 2 * ((y & (lv.n - 1)) * lv.n + (x & (lv.n - 1)));
  acc.a += w * wave_texel(waves, lv.base + i);
  if (lv.moments) {
    vec4 b = wave_texel(waves, lv.base + i + 1);
    acc.b += w * b;
    if (lv.start_in_moments) acc.start += w * vec2(b.z, b.w);
  }
  if (lv.start >= 0) {
    vec4 s = wave_texel(waves, lv.start + i);
    acc.start += w * vec2(s.x, s.y);
  }
}

// Camera-relative (x, z) in level-0 sample units, reduced to [0, N).
SG_FN vec2 cascade_grid_coord(IN(Cascade) c, vec2 xz) {
  real n = real(c.n);
  vec2 u = (xz + c.origin) * (n / c.size);
  return u - n * floor(u / n);
}

// Catmull-Rom's weights for the four samples about fraction t.
SG_FN vec4 catmull_rom_weights(real t) {
  real t2 = t * t;
  real t3 = t2 * t;
  return vec4(0.5 * (-t3 + 2.0 * t2 - t), 0.5 * (3.0 * t3 - 5.0 * t2 + 2.0),
              0.5 * (-3.0 * t3 + 4.0 * t2 + t), 0.5 * (t3 - t2));
}

// Level l at grid coordinate u: Catmull-Rom's bicubic at level 0 (16 texels), bilinear
// above (4 texels; texel i's centre is sample i 2^l + (2^l - 1) / 2). One loop serves
// both, its side (4 or 2) set by the level, rather than a branch for each: a SIMD group
// of pixels that all read levels above 0 runs 4 texels' code, where two branches would
// run both reads' 20 (llvmpipe runs every branch's code, taken or not; docs/gpu.md) and
// a GPU's warp both where its pixels straddle level 0's edge.
SG_FN CascadeTexel cascade_level_read(IN(WaveBuffer) waves, IN(Cascade) c, IN(CascadeRead) rd,
                                      int l, vec2 u) {
  bool cubic = l == 0;
  real s = real(1 << l);
  vec2 t = (u - 0.5 * (s - 1.0)) / s;
  vec2 i0 = floor(t);
  vec2 w = t - i0;
  vec4 wx = cubic ? catmull_rom_weights(w.x) : vec4(1.0 - w.x, w.x, 0.0, 0.0);
  vec4 wy = cubic ? catmull_rom_weights(w.y) : vec4(1.0 - w.y, w.y, 0.0, 0.0);
  int side = cubic ? 4 : 2;
  int x = int(i0.x) - (cubic ? 1 : 0);
  int y = int(i0.y) - (cubic ? 1 : 0);
  CascadeLevel lv = cascade_level(c, rd, l);
  CascadeTexel r = cascade_texel_zero();
  for (int b = 0; b < side; ++b) {
    for (int a = 0; a < side; ++a)
      cascade_texel_add_at(r, waves, lv, x + a, y + b, wx[a] * wy[b]);
  }
  return r;
}

// Level 0 at grid coordinate u, by Catmull-Rom's bicubic (16 texels).
SG_FN CascadeTexel cascade_bicubic(IN(WaveBuffer) waves, IN(Cascade) c, IN(CascadeRead) rd,
                                   vec2 u) {
  return cascade_level_read(waves, c, rd, 0, u);
}

// The chain at fractional level `level` (0 to levels - 1) and grid coordinate u: the two
// levels about it blended.
SG_FN CascadeTexel cascade_filtered(IN(WaveBuffer) waves, IN(Cascade) c, IN(CascadeRead) rd,
                                    real level, vec2 u) {
  int l0 = int(floor(level));
  real t = level - real(l0);
  CascadeTexel r = cascade_level_read(waves, c, rd, l0, u);
  // A grid point has no spread of its own: level 0's second moments are its mean's
  // square (an interpolated s s^T would add the blend's spread between samples).
  if (l0 == 0) r.b = vec4(r.b.x, r.a.x * r.a.x, r.a.x * r.a.y, r.a.y * r.a.y);
  if (t > 0.0 && l0 + 1 < c.levels) {
    CascadeTexel r1 = cascade_level_read(waves, c, rd, l0 + 1, u);
    r.a = mix(r.a, r1.a, t);
    r.b = mix(r.b, r1.b, t);
    r.start = mix(r.start, r1.start, t);
  }
  return r;
}

// Every cascade's slope at camera-relative (x, z) at instant k (K: the display time),
// point-sampled (level 0): the cascade share of the normal of `point`, `supersample` (T = 1),
// `staa-temporal` and `specaa`.
SG_FN vec2 cascade_gradient(IN(WaveBuffer) waves, IN(Frame) f, int k, real x, real z) {
  vec2 g = vec2(0.0);
  int data = cascade_data_start(f);
  for (int c = 0; c < f.cascade_count; ++c) {
    Cascade cc = cascade_header(waves, f, c, data);
    data = cascade_data_end(f, cc);
    vec4 a = cascade_bicubic(waves, cc, cascade_read(k, false, false),
                             cascade_grid_coord(cc, vec2(x, z)))
                 .a;
    g += vec2(a.x, a.y);
  }
  return g;
}

// Every cascade's height Hessian at camera-relative (x, z) at the display time, point-
// sampled (level 0, Catmull-Rom): (h_xx, h_xz, h_zz), the `specaa` kernel's curvature.
SG_FN vec3 cascade_hessian(IN(WaveBuffer) waves, IN(Frame) f, real x, real z) {
  vec3 h = vec3(0.0);
  int data = cascade_data_start(f);
  for (int c = 0; c < f.cascade_count; ++c) {
    Cascade cc = cascade_header(waves, f, c, data);
    data = cascade_data_end(f, cc);
    CascadeTexel t = cascade_bicubic(waves, cc, cascade_read(frame_segments(f), true, false),
                                     cascade_grid_coord(cc, vec2(x, z)));
    h += vec3(t.a.z, t.b.x, t.a.w);
  }
  return h;
}

// Catmull-Rom's weights' derivatives d w / d t (the interpolated height's slope).
SG_FN vec4 catmull_rom_derivative_weights(real t) {
  real t2 = t * t;
  return vec4(0.5 * (-3.0 * t2 + 4.0 * t - 1.0), 0.5 * (9.0 * t2 - 10.0 * t),
              0.5 * (-9.0 * t2 + 8.0 * t + 1.0), 0.5 * (3.0 * t2 - 2.0 * t));
}

// The first `count` cascades' height at camera-relative (x, z) at path instant k,
// Catmull-Rom's bicubic of level 0's heights, and that interpolant's own gradient (its
// weights' derivatives): (h, dh/dx, dh/dz). The displaced intersection marches this
// surface at the display time (the shading's slope, cascade_gradient, interpolates the
// slope grid instead: the two differ by the cubic's error, docs/ocean.md). The instants
// other than the display time hold their heights on displaced water only (level 0's b.y;
// shading/cascade_fields.h), where the path's points follow the water (reflection_path.glsl,
// path_views).
SG_FN vec3 cascade_height_gradient_of(IN(WaveBuffer) waves, IN(Frame) f, int count, int k, real x,
                                      real z) {
  vec3 r = vec3(0.0);
  int data = cascade_data_start(f);
  for (int c = 0; c < count; ++c) {
    Cascade cc = cascade_header(waves, f, c, data);
    data = cascade_data_end(f, cc);
    vec2 u = cascade_grid_coord(cc, vec2(x, z));
    vec2 i0 = floor(u);
    vec4 wx = catmull_rom_weights(u.x - i0.x);
    vec4 wz = catmull_rom_weights(u.y - i0.y);
    vec4 dx = catmull_rom_derivative_weights(u.x - i0.x);
    vec4 dz = catmull_rom_derivative_weights(u.y - i0.y);
    int nl = cc.n;
    int first = cc.data + k * cascade_instant_texels(cc.n);
    real per_texel = real(cc.n) / cc.size;
    for (int b = 0; b < 4; ++b) {
      for (int a = 0; a < 4; ++a) {
        int x0 = (int(i0.x) + a - 1) & (nl - 1);
        int y0 = (int(i0.y) + b - 1) & (nl - 1);
        real h = wave_texel(waves, first + 2 * (y0 * nl + x0) + 1).y;
        r += h * vec3(wx[a] * wz[b], per_texel * dx[a] * wz[b], per_texel * wx[a] * dz[b]);
      }
    }
  }
  return r;
}
SG_FN vec3 cascade_height_gradient_first(IN(WaveBuffer) waves, IN(Frame) f, int count, real x,
                                         real z) {
  return cascade_height_gradient_of(waves, f, count, frame_segments(f), x, z);
}
SG_FN vec3 cascade_height_gradient(IN(WaveBuffer) waves, IN(Frame) f, real x, real z) {
  return cascade_height_gradient_first(waves, f, f.cascade_count, x, z);
}

// Bounds on one cascade's interpolated height field (the bicubic above), from its grid's
// maxima m = (max |h|, max |forward difference of h| along x and z, the larger of the
// second differences along x and along z, the mixed difference) and its texel tau:
// Catmull-Rom's weights sum to at most 1.25 in absolute value, its slope is a combination
// of the three first differences about it with coefficients summing to at most 1.5 (the
// maxima over the fraction, tested), and its second derivative is D0 (2 - 3t) + D1 (3t - 1)
// of two second differences, at most 3 max |D|. So |h| <= 1.25^2 m0; along any horizontal
// unit direction |dh/du| <= 1.25 1.5 sqrt(mx^2 + mz^2) / tau; and the second derivative
// along it, u_x^2 h_xx + 2 u_x u_z h_xz + u_z^2 h_zz, at most 1.25 3 max(m_xx, m_zz) /
// tau^2 + 1.5^2 m_xz / tau^2. Returns (height, slope, curvature) bounds.
SG_FN vec3 cascade_interpolant_bounds(real max_h, vec2 max_d1, real max_d2, real max_dxz,
                                      real tau) {
  return vec3(1.5625 * max_h, 1.875 * length(max_d1) / tau,
              (3.75 * max_d2 + 2.25 * max_dxz) / (tau * tau));
}

// The sum of the first `count` cascades' bounds (texel c after the headers holds the sum
// over cascades 0..c): (height, slope along a horizontal direction, second derivative
// along one); zero for none.
SG_FN vec3 cascade_bounds_first(IN(WaveBuffer) waves, IN(Frame) f, int count) {
  if (count <= 0) return vec3(0.0);
  vec4 b = wave_texel(waves, f.cascade_base + 2 * f.cascade_count + count - 1);
  return vec3(b.x, b.y, b.z);
}
// Every cascade's.
SG_FN vec3 cascade_bounds(IN(WaveBuffer) waves, IN(Frame) f) {
  return cascade_bounds_first(waves, f, f.cascade_count);
}

// The fewest first cascades whose left-out rest (the last ones, in the scene's order: the
// generator writes them coarse to fine) bounds the height by at most `budget`.
SG_FN int first_cascade_below(IN(WaveBuffer) waves, IN(Frame) f, real budget) {
  real all = cascade_bounds(waves, f).x;
  int n = f.cascade_count;
  while (n > 0 && all - cascade_bounds_first(waves, f, n - 1).x <= budget)
    --n;
  return n;
}
