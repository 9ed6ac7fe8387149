// Lattice cascades shaded from their FFT fields: a per-pixel cost fixed by the number of
// cascades, not of their waves (scene/lattice.h defines a cascade; docs/ocean.md, "Shading
// from the cascades", the design and its measured errors).
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
//   - then each cascade's data, instant by instant, level by level, two texels per texel:
//     a = (E[s_x], E[s_z], E[h_xx], E[h_zz]), b = (E[h_xz], E[s_x^2], E[s_x s_z], E[s_z^2]).
// Level l's texel i averages samples i 2^l .. i 2^l + 2^l - 1 of the grid, whose sample p
// lies at world x = p L / N.
//
// What a pixel reads (cascade_filtered): the level whose texel spans the footprint's
// smaller axis scaled to Eq. 20's end of aliasing (a box of width w passes waves longer
// than about 3 w and removes those of length w or less: with w = sigma_min / alias_end the
// waves a pixel resolves stay in the mean, those it aliases go to the second moments),
// the two levels about it blended (trilinear), and along the footprint's longer axis up
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

SG_FN Cascade cascade_at(IN(WaveBuffer) waves, IN(Frame) f, int c) {
  Cascade r;
  int data = f.cascade_base + 2 * f.cascade_count;
  for (int q = 0; q < c; ++q) {
    int nq = int(wave_texel(waves, f.cascade_base + 2 * q).y + 0.5);
    data += (f.segments + 1) * cascade_instant_texels(nq);
  }
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

// A texel's (or a filtered sample's) two vec4s.
struct CascadeTexel {
  vec4 a;  // E[s_x], E[s_z], E[h_xx], E[h_zz]
  vec4 b;  // E[h_xz], E[s_x^2], E[s_x s_z], E[s_z^2]
};

SG_FN CascadeTexel cascade_texel_zero() {
  CascadeTexel t;
  t.a = vec4(0.0);
  t.b = vec4(0.0);
  return t;
}

SG_FN void cascade_texel_add(INOUT(CascadeTexel) acc, IN(CascadeTexel) t, real w) {
  acc.a += w * t.a;
  acc.b += w * t.b;
}

// Texel (x, y) of level l at instant k, the indices wrapped to the level's n_l x n_l (a
// power of two: the two's-complement mask is the modulo); `moments`: with its second
// texel (else b = 0: the slope and h_xx, h_zz alone).
SG_FN CascadeTexel cascade_texel(IN(WaveBuffer) waves, IN(Cascade) c, int k, int l, int x, int y,
                                 bool moments) {
  int nl = c.n >> l;
  int i = c.data + k * cascade_instant_texels(c.n) + cascade_level_offset(c.n, l) +
          2 * ((y & (nl - 1)) * nl + (x & (nl - 1)));
  CascadeTexel t;
  t.a = wave_texel(waves, i);
  t.b = moments ? wave_texel(waves, i + 1) : vec4(0.0);
  return t;
}

// Camera-relative (x, z) in level-0 sample units, reduced to [0, N).
SG_FN vec2 cascade_grid_coord(IN(Cascade) c, vec2 xz) {
  real n = real(c.n);
  vec2 u = (xz + c.origin) * (n / c.size);
  return u - n * floor(u / n);
}

// Level l >= 1 at grid coordinate u, bilinearly (texel i's centre is sample
// i 2^l + (2^l - 1) / 2).
SG_FN CascadeTexel cascade_bilinear(IN(WaveBuffer) waves, IN(Cascade) c, int k, int l, vec2 u,
                                    bool moments) {
  real s = real(1 << l);
  vec2 t = (u - 0.5 * (s - 1.0)) / s;
  vec2 i0 = floor(t);
  vec2 w = t - i0;
  int x = int(i0.x);
  int y = int(i0.y);
  CascadeTexel r = cascade_texel_zero();
  cascade_texel_add(r, cascade_texel(waves, c, k, l, x, y, moments), (1.0 - w.x) * (1.0 - w.y));
  cascade_texel_add(r, cascade_texel(waves, c, k, l, x + 1, y, moments), w.x * (1.0 - w.y));
  cascade_texel_add(r, cascade_texel(waves, c, k, l, x, y + 1, moments), (1.0 - w.x) * w.y);
  cascade_texel_add(r, cascade_texel(waves, c, k, l, x + 1, y + 1, moments), w.x * w.y);
  return r;
}

// Catmull-Rom's weights for the four samples about fraction t.
SG_FN vec4 catmull_rom_weights(real t) {
  real t2 = t * t;
  real t3 = t2 * t;
  return vec4(0.5 * (-t3 + 2.0 * t2 - t), 0.5 * (3.0 * t3 - 5.0 * t2 + 2.0),
              0.5 * (-3.0 * t3 + 4.0 * t2 + t), 0.5 * (t3 - t2));
}

// Level 0 at grid coordinate u, by Catmull-Rom's bicubic (16 texels).
SG_FN CascadeTexel cascade_bicubic(IN(WaveBuffer) waves, IN(Cascade) c, int k, vec2 u,
                                   bool moments) {
  vec2 i0 = floor(u);
  vec4 wx = catmull_rom_weights(u.x - i0.x);
  vec4 wy = catmull_rom_weights(u.y - i0.y);
  int x = int(i0.x);
  int y = int(i0.y);
  CascadeTexel r = cascade_texel_zero();
  for (int b = 0; b < 4; ++b) {
    for (int a = 0; a < 4; ++a) {
      cascade_texel_add(r, cascade_texel(waves, c, k, 0, x + a - 1, y + b - 1, moments),
                        wx[a] * wy[b]);
    }
  }
  return r;
}

// The chain at fractional level `level` (0 to levels - 1) and grid coordinate u: the two
// levels about it blended.
SG_FN CascadeTexel cascade_filtered(IN(WaveBuffer) waves, IN(Cascade) c, int k, real level, vec2 u,
                                    bool moments) {
  int l0 = int(floor(level));
  real t = level - real(l0);
  CascadeTexel r;
  if (l0 == 0) {
    r = cascade_bicubic(waves, c, k, u, moments);
    // A grid point has no spread of its own: level 0's second moments are its mean's
    // square (an interpolated s s^T would add the blend's spread between samples).
    r.b = vec4(r.b.x, r.a.x * r.a.x, r.a.x * r.a.y, r.a.y * r.a.y);
  } else {
    r = cascade_bilinear(waves, c, k, l0, u, moments);
  }
  if (t > 0.0 && l0 + 1 < c.levels) {
    CascadeTexel r1 = cascade_bilinear(waves, c, k, l0 + 1, u, moments);
    r.a = mix(r.a, r1.a, t);
    r.b = mix(r.b, r1.b, t);
  }
  return r;
}

// Every cascade's slope at camera-relative (x, z) at instant k (K: the display time),
// point-sampled (level 0): the cascade share of the normal of `point`, `supersample` (T = 1),
// `staa-temporal` and `specaa`.
SG_FN vec2 cascade_gradient(IN(WaveBuffer) waves, IN(Frame) f, int k, real x, real z) {
  vec2 g = vec2(0.0);
  for (int c = 0; c < f.cascade_count; ++c) {
    Cascade cc = cascade_at(waves, f, c);
    vec4 a = cascade_bicubic(waves, cc, k, cascade_grid_coord(cc, vec2(x, z)), false).a;
    g += vec2(a.x, a.y);
  }
  return g;
}

// What the cascades give a `staa` pixel (kernel/staa.glsl, StaaSums): at each instant
// the filtered mean slope (the resolved gradient); the filtered curvature (the resolved
// Hessian, for the pixel-footprint term) the display time's at every instant (one texel
// per fetch at the other instants, as a moving camera holds the waves' Hessians); at the
// display time the slopes' covariance over
// the filter's boxes (the aliasing NDF, Eq. 3's role), less what the resolved curvature
// spreads across the boxes (the footprint term's role: H Sigma_box H^T), clamped to be
// positive semi-definite.
struct CascadeShare {
  vec2 g[kMaxSegments + 1];
  vec3 hess[kMaxSegments + 1];
  vec3 cov;
};

// The footprint's axes: x the larger singular value of J (metres per pixel), y the
// smaller; zw the unit direction of the larger.
SG_FN vec4 footprint_axes(mat2 J) {
  mat2 M = J * transpose(J);
  real tr = M[0][0] + M[1][1];
  real det = M[0][0] * M[1][1] - M[0][1] * M[1][0];
  real disc = sqrt(max(0.25 * tr * tr - det, 0.0));
  real l1 = 0.5 * tr + disc;
  real l2 = max(0.5 * tr - disc, 0.0);
  vec2 u = vec2(l1 - M[1][1], M[0][1]);
  if (!(dot(u, u) > 0.0)) u = M[0][0] >= M[1][1] ? vec2(1.0, 0.0) : vec2(0.0, 1.0);
  u = normalize(u);
  return vec4(sqrt(l1), sqrt(l2), u.x, u.y);
}

// The footprint's filter on one cascade's chain (as GL's anisotropic filtering places its
// probes; EXT_texture_filter_anisotropic): boxes of width w = max(minor, major / taps)
// across, `taps` of them side by side along the major axis, read at the level whose texel
// is w wide; the axes are those of J scaled by 1 / scale. `whole`: the boxes span the
// patch (every wave averages out: the mean is 0, the covariance the cascade's whole).
struct CascadeFilter {
  real major;  // the boxes' span along `axis`, m
  real w;      // a box's width, m
  real level;
  int taps;
  vec2 axis;
  bool whole;
};

SG_FN CascadeFilter cascade_filter(IN(Cascade) c, mat2 J, real scale) {
  vec4 ax = footprint_axes(J);
  real h = c.size / real(c.n);
  CascadeFilter b;
  b.major = ax.x / scale;
  b.w = max(ax.y / scale, b.major / real(kCascadeMaxTaps));
  b.level = log2(max(b.w / h, 1.0));
  b.whole = !(b.level < real(c.levels - 1));
  b.taps = clamp(int(ceil(b.major / b.w - 1e-6)), 1, kCascadeMaxTaps);
  b.axis = vec2(ax.z, ax.w);
  return b;
}

// The mean of the chain over the filter's boxes about `centre` (camera-relative x, z) at
// instant k.
SG_FN CascadeTexel cascade_box_mean(IN(WaveBuffer) waves, IN(Cascade) c, int k, IN(CascadeFilter) b,
                                    vec2 centre, bool moments) {
  real inv_taps = 1.0 / real(b.taps);
  CascadeTexel acc = cascade_texel_zero();
  for (int q = 0; q < b.taps; ++q) {
    vec2 at = centre + ((real(q) + 0.5) * inv_taps - 0.5) * b.major * b.axis;
    cascade_texel_add(
        acc, cascade_filtered(waves, c, k, b.level, cascade_grid_coord(c, at), moments), inv_taps);
  }
  return acc;
}

// A symmetric 2 x 2 matrix clamped to positive semi-definite (the cubic's overshoot and the
// subtractions of a covariance can leave a small negative eigenvalue): (xx, xz, zz).
SG_FN vec3 cascade_psd(mat2 m2) {
  real tr = m2[0][0] + m2[1][1];
  real det = m2[0][0] * m2[1][1] - m2[0][1] * m2[1][0];
  real disc = sqrt(max(0.25 * tr * tr - det, 0.0));
  real e1 = max(0.5 * tr + disc, 0.0);
  real e2 = max(0.5 * tr - disc, 0.0);
  if (e2 <= 0.0) {
    // Rank one (or zero): the larger eigenvalue's direction.
    vec2 d = vec2(e1 - m2[1][1], m2[0][1]);
    if (!(dot(d, d) > 0.0)) d = m2[0][0] >= m2[1][1] ? vec2(1.0, 0.0) : vec2(0.0, 1.0);
    d = normalize(d);
    m2 = e1 * outerProduct(d, d);
  }
  return vec3(m2[0][0], m2[0][1], m2[1][1]);
}

SG_FN CascadeShare cascade_staa_share(IN(WaveBuffer) waves, IN(Frame) f, IN(StaaParams) p,
                                      IN(Footprint) fp, IN(PathViews) v, IN(Cascade) c) {
  int K = f.segments;
  CascadeShare s;
  for (int k = 0; k <= K; ++k) {
    s.g[k] = vec2(0.0);
    s.hess[k] = vec3(0.0);
  }
  CascadeFilter b = cascade_filter(c, footprint_xz_jacobian(fp), p.alias_end);
  if (b.whole) {
    s.cov = c.cov;
    return s;
  }
  CascadeTexel now = cascade_texel_zero();
  for (int k = K; k >= 0; --k) {
    vec2 centre = v.moving ? v.point[k] : vec2(fp.point.x, fp.point.z);
    CascadeTexel acc = cascade_box_mean(waves, c, k, b, centre, k == K);
    s.g[k] = vec2(acc.a.x, acc.a.y);
    if (k == K) {
      now = acc;
      s.hess[k] = vec3(acc.a.z, acc.b.x, acc.a.w);
    } else {
      s.hess[k] = s.hess[K];
    }
  }
  // The covariance over the boxes, less the resolved curvature's spread over them (the
  // boxes' positions: w^2 / 12 across, the taps' span along the axis).
  vec2 g = s.g[K];
  mat2 m2 = sym2(vec3(now.b.y, now.b.z, now.b.w)) - outerProduct(g, g);
  real along = max(b.major, b.w);
  mat2 box = (b.w * b.w / 12.0) * mat2(1.0) +
             ((along * along - b.w * b.w) / 12.0) * outerProduct(b.axis, b.axis);
  mat2 H = sym2(s.hess[K]);
  m2 -= H * box * H;
  s.cov = cascade_psd(m2);
  return s;
}

// What the cascades give the LEAN-style baselines (`lean`, `bruneton`), at the display
// time: the slopes' mean and covariance over the pixel's footprint J at camera-relative
// `centre` (Olano and Baker 2010, Sec. 3: B and M - B B^T of the filtered chain), summed
// over the cascades. Each cascade holds its own band with independent phases, so the cross
// terms between cascades are left out: over a box that holds many wavelengths of both they
// average to zero, and one that holds less than a wavelength of either sees it constant.
struct CascadeMoments {
  vec2 mean;
  vec3 cov;  // xx, xz, zz
};

SG_FN CascadeMoments cascade_footprint_moments(IN(WaveBuffer) waves, IN(Frame) f, vec2 centre,
                                               mat2 J) {
  CascadeMoments r;
  r.mean = vec2(0.0);
  r.cov = vec3(0.0);
  for (int c = 0; c < f.cascade_count; ++c) {
    Cascade cc = cascade_at(waves, f, c);
    CascadeFilter b = cascade_filter(cc, J, 1.0);
    if (b.whole) {
      r.cov += cc.cov;
      continue;
    }
    CascadeTexel t = cascade_box_mean(waves, cc, f.segments, b, centre, true);
    vec2 g = vec2(t.a.x, t.a.y);
    r.mean += g;
    r.cov += cascade_psd(sym2(vec3(t.b.y, t.b.z, t.b.w)) - outerProduct(g, g));
  }
  return r;
}

// Every cascade's height Hessian at camera-relative (x, z) at the display time, point-
// sampled (level 0, Catmull-Rom): (h_xx, h_xz, h_zz), the `specaa` kernel's curvature.
SG_FN vec3 cascade_hessian(IN(WaveBuffer) waves, IN(Frame) f, real x, real z) {
  vec3 h = vec3(0.0);
  for (int c = 0; c < f.cascade_count; ++c) {
    Cascade cc = cascade_at(waves, f, c);
    CascadeTexel t =
        cascade_bicubic(waves, cc, f.segments, cascade_grid_coord(cc, vec2(x, z)), true);
    h += vec3(t.a.z, t.b.x, t.a.w);
  }
  return h;
}
