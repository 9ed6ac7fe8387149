// Lattice cascades shaded from their FFT fields, part two: the fields filtered over a
// pixel's footprint (cascade_grid.glsl holds the layout and the point reads): what they
// give a `staa` pixel and the LEAN-style baselines.

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

// The scale that matches the chain's filter to Eq. 20's ramp (aliasing.glsl): a wave of f
// cycles per pixel is resolved in full below alias_start, aliased in full past alias_end,
// half at f_mid = (alias_start + alias_end) / 2. The chain passes a wave of f_m cycles per
// metre as a box of width w (a texel of the level read) and the bilinear tent between
// texel centres (w each side): sinc(f_m w) sinc(f_m w)^2, which is 1/2 at f_m w =
// kChainHalfPass. Half at f_mid for a footprint axis of sigma metres per pixel, w =
// kChainHalfPass sigma / f_mid: boxes sigma / scale wide with scale = f_mid /
// kChainHalfPass (1.50 with the defaults 0.3 and 0.8). Between levels the trilinear blend
// moves the response either way; over the levels' fractions the chain keeps 0.48 of a
// wave at f_mid, 0.80 at alias_start and 0.24 at alias_end
// (`CascadeFields.ChainResolvesAWaveAsEq20sRamp`). The scale alias_end (boxes 1.9 times
// as wide, before 2026-12-05) kept 0.47 at alias_start and 0.10 at f_mid, the rest going
// to the aliasing NDF: docs/ocean.md, "The chain's filter matched to Eq. 20".
const real kChainHalfPass = 0.36606325663820;
SG_FN real cascade_resolving_scale(IN(StaaParams) p) {
  return 0.5 * (p.alias_start + p.alias_end) / kChainHalfPass;
}

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

// The mean of the chain over the filter's boxes about `centre` (camera-relative x, z), what
// the read `rd` takes (cascade_grid.glsl, CascadeRead).
SG_FN CascadeTexel cascade_box_mean(IN(WaveBuffer) waves, IN(Cascade) c, IN(CascadeRead) rd,
                                    IN(CascadeFilter) b, vec2 centre) {
  real inv_taps = 1.0 / real(b.taps);
  CascadeTexel acc = cascade_texel_zero();
  for (int q = 0; q < b.taps; ++q) {
    vec2 at = centre + ((real(q) + 0.5) * inv_taps - 0.5) * b.major * b.axis;
    cascade_texel_add(acc, cascade_filtered(waves, c, rd, b.level, cascade_grid_coord(c, at)),
                      inv_taps);
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
  int K = frame_segments(f);
  CascadeShare s;
  for (int k = 0; k <= K; ++k) {
    s.g[k] = vec2(0.0);
    s.hess[k] = vec3(0.0);
  }
  CascadeFilter b = cascade_filter(c, footprint_xz_jacobian(fp), cascade_resolving_scale(p));
  if (b.whole) {
    s.cov = c.cov;
    return s;
  }
  // Where the instants' points coincide (the camera holds still on flat water), the display
  // time's pass over the filter's texels takes the shutter start's slopes along (the same
  // weights: the same values as a pass of its own).
  bool start_along = !v.moving;
  CascadeTexel now = cascade_texel_zero();
  for (int k = K; k >= (start_along ? 1 : 0); --k) {
    vec2 centre = v.moving ? v.point[k] : vec2(fp.point.x, fp.point.z);
    CascadeTexel acc =
        cascade_box_mean(waves, c, cascade_read(k, k == K, start_along && k == K), b, centre);
    s.g[k] = vec2(acc.a.x, acc.a.y);
    if (k == K) {
      now = acc;
      s.hess[k] = vec3(acc.a.z, acc.b.x, acc.a.w);
    } else {
      s.hess[k] = s.hess[K];
    }
  }
  if (start_along) {
    s.g[0] = now.start;
    s.hess[0] = s.hess[K];
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
  int data = cascade_data_start(f);
  for (int c = 0; c < f.cascade_count; ++c) {
    Cascade cc = cascade_header(waves, f, c, data);
    data = cascade_data_end(f, cc);
    CascadeFilter b = cascade_filter(cc, J, 1.0);
    if (b.whole) {
      r.cov += cc.cov;
      continue;
    }
    CascadeTexel t =
        cascade_box_mean(waves, cc, cascade_read(frame_segments(f), true, false), b, centre);
    vec2 g = vec2(t.a.x, t.a.y);
    r.mean += g;
    r.cov += cascade_psd(sym2(vec3(t.b.y, t.b.z, t.b.w)) - outerProduct(g, g));
  }
  return r;
}
