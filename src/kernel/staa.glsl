// `staa`: the spatio-temporal anti-aliasing of Podee, Max, Iwasaki and Dobashi 2021,
// "Temporal and spatial anti-aliasing for rendering reflections on water waves", per
// pixel (Fig. 2 and 5), with sunglint's pixel-footprint term (docs/method.md):
//  1. The water point seen through the pixel centre and its footprint (footprint.glsl).
//  2. One pass over the waves (staa_wave_pass): each wave's projected frequency splits it
//     into a resolved share (1 - alpha) and an aliasing share alpha (Eq. 20,
//     aliasing.glsl); the resolved shares give the gradients at the path's instants
//     (reflection_path.glsl) and the Hessians there; the aliasing shares the NDF's moments
//     (Eq. 3 or Eqs. 4-7 with Appendix A, ndf.glsl). Nothing is stored per wave. The pass
//     visits the waves one by one only up to the remainder (staa_remainder_start): the
//     waves, sorted by |k|, that certainly alias fully in this pixel (and, for the
//     per-pixel NDF, span many cycles of it) add their summed covariance in O(1).
//  3. No aliasing share and no footprint term: the temporal method exactly (Sec. 3.3).
//  4. Otherwise (staa_finish) the NDF, centred on the resolved normal, maps to a Gaussian
//     RDF of covariance J Sigma J^T on the light plane (Eqs. 8-16, rdf.glsl; J taken at
//     the light with `--rdf-at light`, at the NDF's centre as the paper), plus the
//     footprint term D V D^T (the pixel square as a Gaussian, reflection_footprint.glsl)
//     averaged over the instants
//     (staa_footprint_covariance; docs/method.md, "The footprint along the path"); its
//     centre moves along the resolved reflection path (K straight sub-segments on the light plane).
//     Its time-averaged mass in the light disk (Eq. 17) is the light's share: the RDF as 1, 3, 5 or
//     9 circular Gaussians along its major axis (Sec. 3.5, 3.6, Appendix C; kernel_fit.glsl), each
//     integrated along the path offset by its centre (Fig. 10) with the path tables (Eqs. 18-19,
//     path_table.glsl); past the elongation threshold the fallback, the RDF's mass in the disk by
//     quadrature or the paper's Riemann sum (gaussian.glsl), at the display time or averaged along
//     the path. J and Sigma are those of the display time.
//  5. The weights. The light's share takes the Fresnel factor of the centre normal. The
//     smooth terms, Fresnel times the sky and the sea, and the share below the horizon
//     are integrated over the normals' Gaussian in the NDF plane (smooth_terms.glsl):
//     the NDF, the footprint's spread of the resolved normals and their path over the
//     shutter (`--smooth-terms ndf`, the default). With `--smooth-terms mean` they are
//     taken at the centre normal and the horizon's share is the RDF's mass beyond the
//     horizon's line on the light plane (radiance.glsl, combine_weights).
// As the aliasing shares fall to 0 so does the NDF's covariance, and the path integral
// tends to the fraction of the path inside the disk: the transition to step 3 is
// continuous (Fig. 11).
// A camera that moves over the shutter (docs/method.md, "A moving camera"): the path's
// instant k takes the pixel's ray from camera_at(t_k), its water point p_k and view
// (reflection_path.glsl, PathViews): the resolved waves' gradient at p_k and the reflection
// of that view. Eq. 20's split and Appendix A's half-width are taken over the footprint
// swept by the point's motion p_K - p_0 (aliasing.glsl, swept_frequency; ndf.glsl,
// swept_half_width). The pixel-footprint term stays the display time's: the motion is the
// path's. On displaced water the points move too, along the pixel's one ray as the water
// rises and falls (path_views), and take the same branches, but for the footprint term,
// taken along the path at each instant's Hessian as under a still camera. A still camera
// over flat water takes none of these branches.

// Reflections further than this from the light (r . L / |r| below it) are not projected
// on the light plane: the gnomonic projection diverges at 90 degrees, and an RDF would
// need a spread of more than tan(84 deg) ~ 10 plane units to reach the disk from there.
const real kMinCosToLight = 0.1;

// The fully aliasing remainder (Bruneton et al. 2010, Sec. 3.2: with the waves sorted by
// wavelength, the variance of what a pixel does not resolve is a difference of sums).
// For a footprint Jacobian J with smallest singular value sigma (metres per pixel along
// the footprint's shortest direction), a wave of wavenumber kappa has
//   - projected frequency f >= kappa sigma / (2 pi) (norm; / sqrt 2 for max, as
//     max(|fx|, |fy|) >= |(fx, fy)| / sqrt 2), since |J^T k| >= sigma |k|; so it aliases
//     fully (alpha = 1, Eq. 20; the curvature limit only raises alpha) once
//     kappa >= 2 pi alias_end (sqrt 2) / sigma;
//   - phase half-width D >= kappa sigma / 2 (ndf.glsl: D = |k|^2 / (2 |J^-1 k|_max) and
//     |J^-1 k|_max <= |J^-1 k| <= |k| / sigma).
// Past the first of these the uniform NDF (Eq. 3) of the remaining waves is their summed
// covariance sum A^2 / 2 k k^T exactly: the wave buffer's suffix sums (waves.glsl).
// The per-pixel NDF (Appendix A) is not: a wave adds the mean slope K k and the
// covariance (J - K^2) k k^T, K = A cos(theta) sin(D) / D and
// J = A^2 / 2 (1 + cos(2 theta) sin(2D) / (2D)), whose limit as D grows is no mean and
// the full A^2 / 2. The remainder adds that limit once D >= kFarHalfWidth is certain too
// (kappa >= 2 kFarHalfWidth / sigma), so that each remaining wave's error is at most
//     |K| <= A / D <= A / 8,   |(J - K^2) - A^2 / 2| <= A^2 / (4D) + A^2 / D^2 <= 0.047 A^2
// (mean slope within 1/8 of the wave's slope amplitude A |k|, variance within 9.4% of
// its own A^2 |k|^2 / 2; summed over the remainder, the mean within
// sum A |k| / 8 and each covariance entry within 9.4% of the remainder's trace). These are
// bounds: cos(theta) and cos(2 theta) take every sign across the remainder's waves, and
// kernel/resolved_waves_test.cpp measures the actual departures. Everything below the remainder is
// visited one by one (resolved, transition, and fully aliasing waves closer than the
// bound), so the cost per pixel follows the waves it resolves; the 1.001 guards the
// bound's rounding. `wave_remainder` off: every wave one by one.
const real kFarHalfWidth = 8.0;

// The smaller singular value of a 2x2 matrix: |det| / sigma_max.
SG_FN real smallest_singular_value(mat2 J) {
  real t = dot(J[0], J[0]) + dot(J[1], J[1]);
  real det = abs(determinant(J));
  real smax = sqrt(0.5 * (t + sqrt(max(t * t - 4.0 * det * det, 0.0))));
  return smax > 0.0 ? det / smax : 0.0;
}

// For footprint Jacobian J: the wavenumber from which every wave aliases fully (x), and
// the remainder's (y, at least x); kRealMax for a singular J.
SG_FN vec2 staa_remainder_wavenumbers(IN(StaaParams) p, mat2 J) {
  real sigma = smallest_singular_value(J);
  if (!(sigma > 0.0)) return vec2(kRealMax);
  real k_alias = 1.001 * kTwoPi * p.alias_end * (p.nyquist_max ? kSqrtTwo : 1.0) / sigma;
  real k_far = p.per_pixel_ndf ? 1.001 * 2.0 * kFarHalfWidth / sigma : 0.0;
  return vec2(k_alias, max(k_alias, k_far));
}

// The first wave of the remainder for footprint Jacobian J (N: none).
SG_FN int staa_remainder_start(IN(WaveBuffer) waves, IN(Frame) f, IN(StaaParams) p, mat2 J) {
  if (!p.wave_remainder) return f.wave_count;
  vec2 k = staa_remainder_wavenumbers(p, J);
  return k.y < kRealMax ? first_wave_from(waves, f, k.y) : f.wave_count;
}

// The remainder's share of the sums: the covariance of waves c..N-1, and whether any has
// an amplitude.
SG_FN void staa_add_remainder(INOUT(StaaSums) sums, IN(WaveBuffer) waves, IN(Frame) f, int c) {
  vec4 m = wave_suffix_moments(waves, f, c);
  sums.ndf.cov += vec3(m.x, m.y, m.z);
  sums.remainder = vec3(m.x, m.y, m.z);
  sums.any_alias = sums.any_alias || m.w > 0.0;
}

// The RDF's kernels (--kernels) as the kernel takes it: the constant in a GLSL program
// compiled for one count (SG_STAA_KERNELS, gl_engine/kernel_program.h), so that the
// kernels' arrays stay in registers (as K: frame_segments, interface.glsl); else the
// parameter.
SG_FN int staa_kernel_count(IN(StaaParams) p) {
#ifndef SG_STAA_KERNELS
  return p.kernels;
#else
  return SG_STAA_KERNELS;
#endif
}

// The option's cells per side (--smooth-cells) as the kernel takes it: the constant in a
// GLSL program compiled for one value (SG_SMOOTH_CELLS, gl_engine/kernel_program.h), so
// that the cells' arrays indexed by it stay in registers (as K: frame_segments,
// interface.glsl); else the parameter.
SG_FN int staa_smooth_cells(IN(StaaParams) p) {
#ifndef SG_SMOOTH_CELLS
  return p.smooth_cells;
#else
  return SG_SMOOTH_CELLS;
#endif
}

// Whether the frame's water needs the smooth terms: F != 1 or a sky gradient (where F = 1
// and the sky is constant the water is the sky or the sea, and only the horizon's share is
// at stake: the RDF's mass beyond the horizon's line on the light plane serves, at no
// cost). A GLSL program may be compiled for one answer (SG_SMOOTH_TERMS 0 or 1,
// gl_engine/kernel_program.h), which the engine runs on the frames that give it: the terms'
// code (the cells' sums in every wave's terms, the cells' evaluations per pixel) then
// leaves the programs of scenes without them. Code that never runs still costs a shader:
// llvmpipe runs both sides of every branch, taken or not (docs/gpu.md).
SG_FN bool staa_frame_terms(IN(Frame) f) {
#ifndef SG_SMOOTH_TERMS
  return f.fresnel != 0 || f.sky_gradient;
#else
  return SG_SMOOTH_TERMS != 0;
#endif
}

// Whether the frame's light is lower than its radius, so that part of its disk lies below
// the horizon and comes off the light's share (staa_light_below_horizon). Compiled in
// like staa_frame_terms (SG_LIGHT_SETS 0 or 1, gl_engine/kernel_program.h): the segment's
// quadrature leaves the programs of the frames whose disk clears the horizon.
SG_FN bool staa_frame_light_sets(IN(Frame) f) {
#ifndef SG_LIGHT_SETS
  return f.light.L.y < f.light.tan_radius * length(light_horizon_normal(f.light));
#else
  return SG_LIGHT_SETS != 0;
#endif
}

// Whether the frame's camera moves through a shutter: the smooth terms' cells then take
// the waves that the path does not follow averaged over it (staa_waves.glsl,
// staa_wave_add). The GL engine compiles staa's program for the answer (SG_SWEPT_CELLS 0
// or 1, gl_engine/kernel_program.h; the pass reads it through staa_swept_cells): the swept
// cells' code leaves the programs of fixed cameras, which llvmpipe would otherwise run (a
// fifth of fresnel-sky's frame, docs/benchmarks.md).
SG_FN bool staa_frame_swept_cells(IN(Frame) f) {
  return f.camera_keys.count > 0 && f.duration > 0.0;
}

// The smooth terms' cells per side for this frame: none with --smooth-terms mean, and
// none where the frame needs no terms (staa_frame_terms); else the option's.
SG_FN int staa_smooth_side(IN(Frame) f, IN(StaaParams) p) {
  if (staa_smooth_cells(p) <= 0 || !staa_frame_terms(f)) return 0;
  return staa_smooth_cells(p);
}

// The pass's pixel-wide inputs (staa_waves.glsl): the footprint's Jacobian and its
// inverse, Eq. 20's band, the curvature limit, the smooth terms' cells, and under a moving
// camera the instants' points and times and the motion.
SG_FN StaaWavePixel staa_wave_pixel(IN(Frame) f, IN(StaaParams) p, IN(Footprint) fp,
                                    IN(PathViews) v) {
  StaaWavePixel px;
  px.point = vec2(fp.point.x, fp.point.z);
  px.J = footprint_xz_jacobian(fp);
  real det = determinant(px.J);
  px.invertible = det != 0.0;
  px.Jinv = px.invertible ? inverse(px.J) : mat2(0.0);
  px.max_norm = p.nyquist_max;
  px.alias_start = p.alias_start;
  px.alias_end = p.alias_end;
  px.curvature = p.footprint != 0 && p.curvature_limit > 0.0;
  px.limit = p.curvature_limit * f.light.radius;
  px.per_pixel_ndf = p.per_pixel_ndf;
  px.cells = staa_smooth_side(f, p);
  path_instants_into(f, v, px.inst);
  px.instant_hessians = !v.camera_moves && f.duration > 0.0;
  px.sweep = v.point[frame_segments(f)] - v.point[0];
  px.swept_cells = staa_frame_swept_cells(f);
  px.duration = f.duration;
  return px;
}

// Waves 0 <= i < n, one by one (staa_waves.glsl): the definition; the CPU engine runs the
// same text over the waves in SIMD lanes under SG_CPU_WAVE_SUMS (kernel/cpu/wave_sums.h).
SG_FN void staa_waves_loop(INOUT(StaaSums) sums, IN(WaveBuffer) waves, IN(Frame) f,
                           IN(StaaWavePixel) px, int n) {
  for (int i = 0; i < n; ++i)
    staa_wave_add(sums, px, waves, i, wave_at(waves, f, i));
}

#ifdef SG_CPU_WAVE_SUMS
void staa_waves_add(INOUT(StaaSums) sums, IN(WaveBuffer) waves, IN(Frame) f, IN(StaaWavePixel) px,
                    int n);
#else
SG_FN void staa_waves_add(INOUT(StaaSums) sums, IN(WaveBuffer) waves, IN(Frame) f,
                          IN(StaaWavePixel) px, int n) {
  staa_waves_loop(sums, waves, f, px, n);
}
#endif

// The one pass over the waves (step 2): the waves below the remainder one by one, then the
// remainder's sums.
SG_FN StaaSums staa_wave_pass(IN(WaveBuffer) waves, IN(Frame) f, IN(StaaParams) p, IN(Footprint) fp,
                              IN(PathViews) v) {
  StaaSums sums = staa_sums_zero(frame_segments(f));
  StaaWavePixel px = staa_wave_pixel(f, p, fp, v);
  int c = staa_remainder_start(waves, f, p, px.J);
  staa_waves_add(sums, waves, f, px, c);
  staa_add_remainder(sums, waves, f, c);
  return sums;
}

// The lattice cascades' share (cascade_fields.glsl), after the pass over the waves: their
// filtered slopes and curvatures in the path's gradients and Hessians, their sub-footprint
// covariance in the aliasing NDF and, as the remainder's, in every smooth-terms cell; the
// cells' means move by the display time's filtered slope (NDF-plane coordinates: minus).
SG_FN void staa_cascades_add(INOUT(StaaSums) sums, IN(WaveBuffer) waves, IN(Frame) f,
                             IN(StaaParams) p, IN(Footprint) fp, IN(PathViews) v) {
  int side = staa_smooth_side(f, p);
  int data = cascade_data_start(f);
  for (int c = 0; c < f.cascade_count; ++c) {
    Cascade cc = cascade_header(waves, f, c, data);
    data = cascade_data_end(f, cc);
    CascadeShare s = cascade_staa_share(waves, f, p, fp, v, cc);
    for (int k = 0; k <= frame_segments(f); ++k) {
      sums.path.g[k] += s.g[k];
      sums.hess[k] += s.hess[k];
    }
    sums.ndf.cov += s.cov;
    sums.remainder += s.cov;
    sums.any_alias = sums.any_alias || s.cov.x + s.cov.z > 0.0;
    for (int q = 0; q < side * side; ++q)
      sums.cells.m[q].mean -= s.g[frame_segments(f)];
  }
}

SG_FN StaaResult staa_result_miss() {
  StaaResult r;
  r.weights = vec4(0.0);
  r.hit = false;
  r.aliasing = false;
  r.temporal = false;
  r.fallback = false;
  r.exact_pending = false;
  r.in_light = 0.0;
  r.below = 0.0;
  r.fresnel = 1.0;
  r.sky_y = 1.0;
  r.exact_D = mat2(0.0);
  r.terms_valid = false;
  r.terms.f_above = 0.0;
  r.terms.f_zenith = 0.0;
  r.terms.f_horizon = 0.0;
  r.terms.above = 0.0;
  return r;
}

// The weights of a finished pixel: the light's share at the Fresnel factor of the centre
// normal, and the sky and sea from the smooth terms over the normals when they were taken
// (smooth_terms.glsl), else at the centre normal (combine_weights).
SG_FN vec4 staa_weights(IN(Frame) f, IN(StaaResult) r) {
  if (r.terms_valid) return smooth_weights(f, r.terms, r.fresnel, r.in_light);
  return combine_weights(f, r.fresnel, r.in_light, r.below, r.sky_y);
}

// The group of a smooth-terms cell whose mean slope along the view lies `a` from the
// cells' mean (staa_smooth_terms): below -cut, within, above.
SG_FN int smooth_cell_group(real a, real cut) {
  return a < -cut ? 0 : (a > cut ? 2 : 1);
}

// The smooth terms over the pixel and the shutter (smooth_terms.glsl): over the mixture of
// the pixel's n x n cells' Gaussians of normals, taken as one moment-matched Gaussian or
// three, the cells grouped by their mean slope along the view. A cell's Gaussian has every
// wave's moments over the cell at the display time (ndf.glsl, box_cells_add: all the waves
// at their full amplitude, so that a wave of the transition band is neither linearised
// across the pixel nor split), plus the remainder's covariance, moved along the resolved
// waves' path over the shutter: the time-mean of the path's offset from the display
// time, and its spread, uniform in time along each sub-segment (the segments' midpoints'
// spread plus d d^T / 12 within each).
SG_FN SmoothTerms staa_smooth_terms(IN(Frame) f, IN(StaaParams) p, IN(StaaSums) sums, vec3 view) {
  int K = frame_segments(f);
  real inv_k = 1.0 / real(K);
  vec2 g_mean = vec2(0.0);
  for (int k = 0; k < K; ++k)
    g_mean += 0.5 * (sums.path.g[k] + sums.path.g[k + 1]) * inv_k;
  mat2 shared_cov = sym2(sums.remainder);
  for (int k = 0; k < K; ++k) {
    vec2 mid = 0.5 * (sums.path.g[k] + sums.path.g[k + 1]) - g_mean;
    vec2 d = sums.path.g[k + 1] - sums.path.g[k];
    shared_cov += (outerProduct(mid, mid) + outerProduct(d, d) / 12.0) * inv_k;
  }
  // NDF-plane coordinates are minus the slope: the shutter's mean offset is -(g_mean - g_K).
  vec2 shift = sums.path.g[K] - g_mean;
  int n = staa_smooth_cells(p);  // on (staa_centre_terms): the side is the option's
  real inv_cells = 1.0 / real(n * n);
  // The cells' mixture as one Gaussian (its mean and covariance): where the cells' means
  // spread by less than a tenth of their own covariance (by trace), or the whole spread is
  // below 0.02 in slope, F and the sky are near enough to quadratic over it that the
  // mixture and its moment-matched Gaussian give the same terms; one evaluation then.
  vec2 m_bar = vec2(0.0);
  mat2 w_bar = mat2(0.0);
  for (int c = 0; c < n * n; ++c) {
    m_bar += sums.cells.m[c].mean * inv_cells;
    w_bar += sym2(sums.cells.m[c].cov) * inv_cells;
  }
  mat2 b_bar = mat2(0.0);
  for (int c = 0; c < n * n; ++c) {
    vec2 dm = sums.cells.m[c].mean - m_bar;
    b_bar += outerProduct(dm, dm) * inv_cells;
  }
  real tw = w_bar[0][0] + w_bar[1][1] + shared_cov[0][0] + shared_cov[1][1];
  real tb = b_bar[0][0] + b_bar[1][1];
  bool one = n == 1 || tb <= 0.1 * tw || tb + tw < 0.02 * 0.02;
  // Otherwise the cells in three groups by their mean slope along the view's horizontal
  // direction e, each group's mixture moment-matched. F and the reflection's height see
  // the slope across the view only through its square beside 1 + a^2 (smooth_terms.glsl),
  // which a group's moment-matched covariance keeps, so the mixture's shape that matters
  // is its spread along e: the groups cut it at -+0.43 of its deviation (a normal's
  // terciles). Three evaluations at most, one where the cells agree (every cell then in
  // group 0, whose moments are the mixture's); `staa`'s images moved by about 0.1% of
  // their RMSE against the reference when the nine cells' evaluations became the groups'
  // (docs/method.md, "The smooth terms").
  vec2 vh = vec2(view.x, view.z);
  real vh2 = dot(vh, vh);
  vec2 e = vh2 > 0.0 ? vh * inversesqrt(vh2) : vec2(1.0, 0.0);
  real cut = 0.43 * sqrt(max(dot(e, b_bar * e), 0.0));
  int group[kMaxBoxCells];
  real count[3];
  vec2 g_m[3];
  mat2 g_w[3];
  mat2 g_b[3];
  for (int g = 0; g < 3; ++g) {
    count[g] = 0.0;
    g_m[g] = vec2(0.0);
    g_w[g] = mat2(0.0);
    g_b[g] = mat2(0.0);
  }
  for (int c = 0; c < n * n; ++c) {
    int g = one ? 0 : smooth_cell_group(dot(sums.cells.m[c].mean - m_bar, e), cut);
    group[c] = g;
    count[g] += 1.0;
    g_m[g] += sums.cells.m[c].mean;
    g_w[g] += sym2(sums.cells.m[c].cov);
  }
  for (int g = 0; g < 3; ++g) {
    real inv = count[g] > 0.0 ? 1.0 / count[g] : 0.0;
    g_m[g] *= inv;
    g_w[g] *= inv;
  }
  for (int c = 0; c < n * n; ++c) {
    int g = group[c];
    vec2 dm = sums.cells.m[c].mean - g_m[g];
    g_b[g] += outerProduct(dm, dm) / count[g];
  }
  // One evaluation a group: one call in a loop (a GL program then holds smooth_terms' code
  // once; llvmpipe runs every copy, taken or not: docs/gpu.md).
  SmoothTerms res;
  res.f_above = 0.0;
  res.f_zenith = 0.0;
  res.f_horizon = 0.0;
  res.above = 0.0;
  for (int g = 0; g < (one ? 1 : 3); ++g) {
    if (count[g] == 0.0) continue;
    real weight = count[g] * inv_cells;
    vec2 mean = g_m[g] + shift;
    mat2 cov = g_w[g] + shared_cov;
    // On displaced water the normals within a cell as the view sees them
    // (visible_normals.glsl), before the spread of the group's means is added. The cells
    // themselves stay equal shares: they are the pixel square mapped through the tangent
    // plane at the centre's hit, which already places the pixel's rays on the water to
    // first order (weighting them by their projected area as well moved `staa`'s far water
    // away from the reference: docs/method.md).
    if (f.displaced) {
      VisibleNormals vn = visible_normals(mean, cov, view);
      mean = vn.mean;
      cov = vn.cov;
    }
    cov += g_b[g];
    SmoothTerms t = smooth_terms(f, mean, cov, view);
    res.f_above += t.f_above * weight;
    res.f_zenith += t.f_zenith * weight;
    res.f_horizon += t.f_horizon * weight;
    res.above += t.above * weight;
  }
  return res;
}

// The least |p . axis| over the path's centres p(t): its valid sub-segments (p moves
// linearly along each) and its last instant.
SG_FN real path_min_abs_projection(IN(StaaPath) path, int K, vec2 axis) {
  real m = abs(dot(path.centre[K], axis));
  for (int k = 0; k < K; ++k) {
    if (!(path.valid[k] && path.valid[k + 1])) continue;
    real a = dot(path.centre[k], axis);
    real b = dot(path.centre[k + 1], axis);
    m = min(m, a * b <= 0.0 ? 0.0 : min(abs(a), abs(b)));
  }
  return m;
}

// The pixel-footprint term's covariance on the light plane (the unit box as the Gaussian
// D V D^T, V = diag(box_var) the display time's, footprint_box_variances; added to the
// RDF's), averaged along the path. The resolved waves'
// curvature changes over the shutter as they travel (a wave of period T turns its Hessian
// by 2 pi / T per second), and the path crosses the light's disk at some instant: each
// instant's footprint is taken at its own gradient and Hessian, and the average over the
// shutter is the trapezoid rule's over the K + 1 instants. `display`: the display time's.
// Under a moving camera (whose instants' footprints are not formed) and with a zero
// shutter, the display time's alone. On displaced water under a still camera the instants'
// points move along the one ray (path_views) and the view stays: their own Hessians.
SG_FN mat2 staa_footprint_covariance(IN(Frame) f, IN(Footprint) fp, IN(PathViews) v,
                                     IN(StaaSums) sums, vec2 mean, mat2 display, vec2 box_var,
                                     IN(LightAnchor) a, IN(ReflectionChain) chain) {
  int K = frame_segments(f);
  mat2 cov = display;
  if (!v.camera_moves && f.duration > 0.0) {
    mat2 sum = 0.5 * display;
    // At the light's anchor the chain rule's factors are the display time's at every
    // instant (the view and n_L do not move): `chain`, the display time's (staa_rdf); only
    // the Hessian changes.
    for (int k = 0; k < K; ++k) {
      mat2 ck = display;
      if (a.valid) {
        mat2 Dk = reflection_chain_d(chain, fp, sums.hess[k]);
        ck = footprint_box_covariance(Dk, box_var);
      } else {
        ReflectionFootprint rk =
            reflection_footprint(f.light, fp, sums.path.g[k], sums.hess[k], mean);
        if (rk.valid) ck = footprint_box_covariance(rk.D, box_var);
      }
      sum += (k == 0 ? 0.5 : 1.0) * ck;
    }
    cov = sum / real(K);
  }
  return cov;
}

// Steps 3 to 5 from the sums, as stages. Each stage is one function with one exit; the
// stages run in this order, and a pixel leaves the chain where a stage has decided it:
//  a. the temporal method, exactly, when nothing aliases and there is no footprint term
//     (staa_temporal_result);
//  b. the NDF's centre along the path on the light plane (staa_ndf_along_path), and b'. the
//     path that the light's share integrates (staa_light_path: the same, or linearised at
//     the light);
//  c. the terms at the centre normal: Fresnel, the sky's split, the smooth terms
//     (staa_centre_terms); a reflection turned away from the light ends here;
//  d. the RDF's covariance on the light plane with the footprint term (staa_rdf), or the
//     host's exact footprint (`--footprint exact`);
//  e. the share below the horizon (staa_below_share);
//  f. the light's share: the cull, then one integrator chosen once (staa_light_share).

// Stage a: no aliasing share and no footprint term: the temporal method, exactly (Sec. 3.3).
SG_FN StaaResult staa_temporal_result(IN(Frame) f, IN(StaaSums) sums, IN(PathViews) v) {
  PathShares ps = temporal_shares_along(f, sums.path, v);
  StaaResult res = staa_result_miss();
  res.hit = true;
  res.temporal = true;
  res.weights = ps.weights;
  res.in_light = ps.in_light;
  res.below = ps.below;
  res.fresnel = ps.fresnel;
  return res;
}

// Stage b: the aliasing waves' NDF (none: a point at the resolved normal), and its centre
// at each instant mapped to the light plane: minus the resolved slope plus the mean
// shift, reflected about the view of that instant. Instants whose reflection points away
// from the light (r . L / |r| below kMinCosToLight) are not valid.
struct StaaNdf {
  vec2 mean;  // the NDF's mean shift (Appendix A), 0 without the per-pixel NDF
  mat2 cov;   // the NDF's covariance
  vec2 now;   // the NDF's centre at the display time
};

SG_FN StaaNdf staa_ndf_along_path(IN(Frame) f, IN(StaaParams) p, IN(PathViews) v, IN(StaaSums) sums,
                                  INOUT(StaaPath) path) {
  int K = frame_segments(f);
  StaaNdf ndf;
  ndf.mean = (sums.any_alias && p.per_pixel_ndf && p.ndf_mean_shift) ? sums.ndf.mean : vec2(0.0);
  ndf.cov = sums.any_alias ? sym2(sums.ndf.cov) : mat2(0.0);
  if (f.displaced && sums.any_alias) {
    // On displaced water the aliasing normals as the view sees them at the display time
    // (visible_normals.glsl, Heitz 2014 Eq. 3): the slopes (m . v)+ weights, about the
    // pixel's resolved slope -g[K]. Its mean shift moves the whole path, as the per-pixel
    // NDF's mean does (every instant's view is near the display time's).
    vec2 centre = -sums.path.g[K] + ndf.mean;
    VisibleNormals vn = visible_normals(centre, ndf.cov, v.view[K]);
    ndf.mean += vn.mean - centre;
    ndf.cov = vn.cov;
  }
  for (int k = 0; k <= K; ++k) {
    vec3 r = reflect_about_ndf_point(-sums.path.g[k] + ndf.mean, v.view[k]);
    path.valid[k] = dot(r, f.light.L) > kMinCosToLight * length(r);
    path.centre[k] = path.valid[k] ? light_to_plane(f.light, r) : vec2(0.0);
  }
  ndf.now = -sums.path.g[K] + ndf.mean;
  return ndf;
}

// Stage b': the centres on the light plane that the light's share integrates. With
// `--rdf-at light` (rdf.glsl, light_anchor) the NDF's centre at each instant maps through
// Phi linearised at the light for that instant's view, J_L (n_k - n_L): defined at every
// instant, also where the centre reflects away from the light, since a wide NDF may
// still reach it from there. The returned anchor is the display time's; where it is not
// valid, or with `--rdf-at centre` (Eqs. 11-16), the light's path is stage b's, exactly
// mapped. The pixel-footprint term's `exact` integration (no aliasing share) keeps stage
// b's path: it integrates the exact parallelogram around the exact centre.
SG_FN LightAnchor staa_light_path(IN(Frame) f, IN(StaaParams) p, IN(PathViews) v, IN(StaaSums) sums,
                                  IN(StaaNdf) ndf, INOUT(StaaPath) path) {
  int K = frame_segments(f);
  LightAnchor a = light_anchor(v.view[K], f.light);
  a.valid = a.valid && p.rdf_at_light && !(p.footprint == 2 && !sums.any_alias);
  if (!a.valid) return a;
  for (int k = 0; k <= K; ++k) {
    LightAnchor ak = a;
    if (v.moving) ak = light_anchor(v.view[k], f.light);
    path.valid[k] = ak.valid;
    path.centre[k] = ak.valid ? anchored_light_plane(ak, -sums.path.g[k] + ndf.mean) : vec2(0.0);
  }
  return a;
}

// The share of the pixel's normals that reflect the view below the horizon, in the NDF
// plane (rdf.glsl, ndf_below_horizon_share), for a pixel whose reflection turns away from
// the light (no light plane to take it on, staa_below_share): N(n_k, Sigma) with
// n_k = -g_k + shift the resolved normal at instant k and Sigma the aliasing waves'
// covariance plus, with a footprint, the resolved normals' spread over the pixel square,
// (dn/dpx dn/dpx^T + dn/dpy dn/dpy^T) / 12 with dn/dp = -(H dX/dp)
// (reflection_footprint.glsl). Averaged over the path's instants, as the light's share is.
SG_FN real staa_below_share_ndf(IN(Frame) f, IN(StaaParams) p, IN(Footprint) fp, IN(PathViews) v,
                                IN(StaaSums) sums, IN(StaaNdf) ndf) {
  int K = frame_segments(f);
  mat2 cov = ndf.cov;
  if (p.footprint != 0) {
    vec3 ax = reflection_footprint_dm(sums.hess[K], fp.dp_dpx);
    vec3 ay = reflection_footprint_dm(sums.hess[K], fp.dp_dpy);
    vec2 a = vec2(ax.x, ax.z);
    vec2 b = vec2(ay.x, ay.z);
    cov += (1.0 / 12.0) * mat2(a.x * a.x + b.x * b.x, a.x * a.y + b.x * b.y, a.x * a.y + b.x * b.y,
                               a.y * a.y + b.y * b.y);
  }
  real below = 0.0;
  for (int k = 0; k <= K; ++k)
    below += ndf_below_horizon_share(v.view[k], -sums.path.g[k] + ndf.mean, cov);
  return below / real(K + 1);
}

// Stage c: the Fresnel factor and the sky's split at the centre normal; the smooth terms
// over the normals (smooth_terms.glsl) when they are on, which also give the share below
// the horizon; without them, the share below the horizon of a reflection turned away from
// the light from the NDF plane (staa_below_share_ndf; one turned towards it takes it on
// the light plane in staa_finish).
SG_FN void staa_centre_terms(IN(Frame) f, IN(StaaParams) p, IN(StaaSums) sums, IN(Footprint) fp,
                             IN(PathViews) v, IN(StaaNdf) ndf, bool toward_light,
                             INOUT(StaaResult) res) {
  vec3 view = fp.view;
  vec3 n_now = normalize(vec3(ndf.now.x, 1.0, ndf.now.y));
  res.fresnel = fresnel_factor(f.fresnel, dot(n_now, view));
  res.sky_y = reflect_view(n_now, view).y;
  if (staa_smooth_side(f, p) > 0 && view.y > 0.0) {
    res.terms = staa_smooth_terms(f, p, sums, view);
    res.terms_valid = true;
    res.below = 1.0 - res.terms.above;
  } else if (!toward_light) {
    res.below = staa_below_share_ndf(f, p, fp, v, sums, ndf);
  }
}

// Stage d: the RDF's covariance on the light plane, J Sigma J^T (Eqs. 8-16), plus the
// pixel-footprint term, the pixel square mapped to the light plane by the resolved
// reflection's derivatives D, averaged along the path (staa_footprint_covariance). J and
// D are taken at the NDF's centre, or at the light where the anchor `a` is valid (stage
// b'). With `--footprint exact` and no aliasing share the host integrates the swept
// parallelogram instead: `exact` is set and D returned.
struct StaaRdf {
  mat2 cov;
  bool exact;  // handed to the host with D
  mat2 D;
};

SG_FN StaaRdf staa_rdf(IN(Frame) f, IN(StaaParams) p, IN(Footprint) fp, IN(PathViews) v,
                       IN(StaaSums) sums, IN(StaaNdf) ndf, IN(LightAnchor) a) {
  int K = frame_segments(f);
  StaaRdf rdf;
  mat2 J = a.valid ? a.J : ndf_to_light_plane_jacobian(ndf.now, fp.view, f.light);
  rdf.cov = rdf_covariance(J, ndf.cov);
  rdf.exact = false;
  rdf.D = mat2(0.0);
  if (p.footprint != 0) {
    // The chain rule's factors once: the display time's D, and at the light's anchor every
    // instant's along the shutter (staa_footprint_covariance).
    ReflectionChain chain =
        reflection_chain(f.light, fp, reflection_footprint_normal(sums.path.g[K], ndf.mean, a));
    ReflectionFootprint rf =
        reflection_footprint_at(f.light, fp, chain, sums.path.g[K], sums.hess[K], ndf.mean, a);
    if (rf.valid && p.footprint == 2 && !sums.any_alias) {
      rdf.exact = true;
      rdf.D = rf.D;
    } else if (rf.valid) {
      // The pixel square's Gaussian, its variance along each pixel axis the least-squares
      // fit to the box's response against the rest of the light's spread, the disk's and
      // the aliasing RDF's (reflection_footprint.glsl, footprint_box_variances).
      vec2 box_var = footprint_box_variances(
          rf.D, rdf.cov + (0.25 * f.light.tan_radius * f.light.tan_radius) * mat2(1.0));
      rdf.cov += staa_footprint_covariance(
          f, fp, v, sums, ndf.mean, footprint_box_covariance(rf.D, box_var), box_var, a, chain);
    }
  }
  return rdf;
}

// Stage e: the RDF's share below the horizon, averaged over the path's valid instants
// (radiance.glsl, horizon_share).
SG_FN real staa_below_share(IN(Frame) f, IN(StaaPath) path, mat2 cov_r) {
  real below = 0.0;
  int counted = 0;
  for (int k = 0; k <= frame_segments(f); ++k) {
    if (!path.valid[k]) continue;
    below += horizon_share(f.light, path.centre[k], cov_r);
    counted += 1;
  }
  return below / real(counted);
}

// The least |W p| over the path of the RDF's centres p(t) (its valid sub-segments, along
// which p moves linearly, and its last instant): with W the identity the least distance
// from the disk's centre; with W the whitening of the RDF's covariance
// (staa_whitening) the least Mahalanobis distance.
SG_FN real path_min_distance(IN(StaaPath) path, int K, mat2 W) {
  real nearest = kRealMax;
  for (int k = 0; k < K; ++k) {
    if (!(path.valid[k] && path.valid[k + 1])) continue;
    vec2 a = W * path.centre[k];
    vec2 d = W * (path.centre[k + 1] - path.centre[k]);
    real dd = dot(d, d);
    real t = dd > 0.0 ? clamp(-dot(a, d) / dd, 0.0, 1.0) : 0.0;
    nearest = min(nearest, length(a + t * d));
  }
  return min(nearest, length(W * path.centre[K]));
}

// W with W^T W = cov^-1 for the principal axes `ax` of cov (s2 > 0): the coordinates along
// the major and the minor axis in their deviations.
SG_FN mat2 staa_whitening(IN(PrincipalAxes) ax) {
  return mat2(ax.u.x / ax.s1, -ax.u.y / ax.s2, ax.u.y / ax.s1, ax.u.x / ax.s2);
}

// The Mahalanobis cull's margin in deviations (staa_light_share): a mass below
// exp(-8^2 / 2) = 1.3e-14 of the light's radiance is left out.
const real kStaaCullTail = 8.0;

// Stage f's integrators: the RDF's time-averaged mass in the light's disk (Eq. 17).
const int kStaaVanishing = 0;  // a point RDF: the fraction of the path in the disk
const int kStaaFallback = 1;   // past the elongation threshold (Sec. 3.6)
const int kStaaKernels = 2;    // circular kernels along the major axis (Sec. 3.5, App. C)

// Which integrator an RDF of principal axes `ax` takes: a vanishing RDF is a point; a
// degenerate one (a line at the precision's resolution) or one more elongated than the
// threshold (`--elongation`, else the number of kernels) takes the fallback.
SG_FN int staa_integrator(IN(StaaParams) p, IN(PrincipalAxes) ax, real R) {
  real threshold = p.elongation_threshold > 0.0 ? p.elongation_threshold
                   : p.kernels > 1              ? real(p.kernels)
                                                : kRealMax;
  real point_sigma = kDoublePrecision ? 1e-9 : 1e-5;
  real line_sigma = kDoublePrecision ? 1e-12 : 1e-6;
  bool degenerate = !(ax.s2 > line_sigma * R);
  return ax.s1 <= point_sigma * R                    ? kStaaVanishing
         : (degenerate || ax.s1 / ax.s2 > threshold) ? kStaaFallback
                                                     : kStaaKernels;
}

// The fallback (Sec. 3.6): the RDF's mass in the disk at the display time, or averaged
// along the path. `--fallback quadrature` takes each sub-segment's time average in closed
// form in time (gaussian.glsl, gaussian_disk_mass_along): the cost of one instant's mass
// whatever the path's length, so that neighbouring pixels with short and long paths take
// the same work. The paper's Riemann sum has no such form: it is averaged by the midpoint
// rule with samples closer than a third of the width of the mass-versus-position bump
// (disk radius + RDF spread along the path), at most 32 per sub-segment.
//
// A GLSL program may fix the two options at compile time (SG_STAA_FALLBACK_RIEMANN and
// SG_STAA_FALLBACK_ALONG_PATH, 0 or 1, in the header that gl_engine/kernel_program.cpp
// writes): the other integrators' code then leaves the program. Code that never runs
// still costs a shader: on llvmpipe the program with all four took 56 s to compile and
// twice the time a frame of the one with its own integrator alone (docs/benchmarks.md).
SG_FN real staa_fallback_share(IN(StaaParams) p, IN(StaaPath) path, int K, mat2 cov_r, real R) {
#ifndef SG_STAA_FALLBACK_RIEMANN
  bool riemann = p.fallback_riemann;
  bool along_path = p.fallback_along_path;
#else
  bool riemann = SG_STAA_FALLBACK_RIEMANN != 0;
  bool along_path = SG_STAA_FALLBACK_ALONG_PATH != 0;
#endif
  real in_light = 0.0;
  if (!along_path) {
    in_light = riemann ? gaussian_disk_mass_riemann(path.centre[K], cov_r, R, p.riemann_cells)
                       : gaussian_disk_mass(path.centre[K], cov_r, R);
  } else if (!riemann) {
    for (int k = 0; k < K; ++k) {
      if (!(path.valid[k] && path.valid[k + 1])) continue;
      in_light += gaussian_disk_mass_along(path.centre[k], path.centre[k + 1], cov_r, R);
    }
    in_light *= 1.0 / real(K);
  } else {
    for (int k = 0; k < K; ++k) {
      if (!(path.valid[k] && path.valid[k + 1])) continue;
      vec2 d = path.centre[k + 1] - path.centre[k];
      real len = length(d);
      vec2 dir = len > 0.0 ? d / len : vec2(1.0, 0.0);
      real width = R + sqrt(max(0.0, dot(dir, cov_r * dir)));
      int n = clamp(int(ceil(3.0 * len / width)), 1, 32);
      real seg = 0.0;
      for (int q = 0; q < n; ++q) {
        vec2 c = path.centre[k] + ((real(q) + 0.5) / real(n)) * d;
        seg += gaussian_disk_mass_riemann(c, cov_r, R, p.riemann_cells);
      }
      in_light += seg / real(n);
    }
    in_light *= 1.0 / real(K);
  }
  return in_light;
}

// The kernels (Sec. 3.5, 3.6, Appendix C; kernel_fit.glsl): the RDF as circular Gaussians
// along its major axis, each integrated along the path offset by its centre (Fig. 10) with
// the path tables (Eqs. 18-19). The principal-frame cull of staa_light_share, for circles
// of at most the largest kernel's deviation offset by at most the largest offset.
// A vanishing RDF is one kernel of deviation 0 at the centre, uncut: the fraction of the
// path inside the disk (the path tables at sigma 0). Both integrators share this one call
// of path_average: a GL program holds its code once (llvmpipe runs every copy of a
// function's code, taken or not: docs/gpu.md).
SG_FN real staa_kernels_share(IN(R32Texture2D) table_f, IN(R32Texture3D) table_s,
                              IN(PathTableInfo) tinfo, IN(R32Texture2D) fits,
                              IN(KernelFitInfo) finfo, IN(StaaParams) p, IN(StaaPath) path, int K,
                              IN(PrincipalAxes) ax, real R, real min_minor, real min_major,
                              bool vanishing) {
  KernelSet ks;
  if (vanishing) {
    ks = point_kernel();
  } else {
    ks = elliptical_kernels(fits, finfo, staa_kernel_count(p), ax.s2, ax.s1);
  }
  real sigma_max = 0.0;
  real offset_max = 0.0;
  for (int q = 0; q < ks.count; ++q) {
    sigma_max = max(sigma_max, ks.sigma[q]);
    offset_max = max(offset_max, abs(ks.offset[q]));
  }
  bool culled = !vanishing &&
                (min_minor > R + 12.0 * sigma_max || min_major > R + offset_max + 12.0 * sigma_max);
  real in_light = 0.0;
  real inv_k = 1.0 / real(K);
  for (int q = 0; q < ks.count && !culled; ++q) {
    vec2 offset = ks.offset[q] * ax.u;
    real along = 0.0;
    for (int k = 0; k < K; ++k) {
      if (!(path.valid[k] && path.valid[k + 1])) continue;
      along += path_average(table_f, table_s, tinfo, path.centre[k] + offset,
                            path.centre[k + 1] + offset, ks.sigma[q], R);
    }
    in_light += ks.weight[q] * along * inv_k;
  }
  return in_light;
}

// The part of stage f's mass in the disk that lies below the horizon, where the light has
// set behind the sea (a low sun or moon wider than its height): reflections there meet
// the water, not the light, and the spec gives them the sea. On the light plane the
// horizon is the line L.y + p . (e1.y, e2.y) = 0 (reflection_footprint.glsl,
// horizon_share), which cuts the disk where the light is lower than its radius; the RDF's
// mass in that segment (gaussian.glsl, gaussian_disk_segment_mass), averaged over the
// path's valid instants as the below share is, comes off the light's share. Called only in
// frames whose disk reaches below the horizon (staa_frame_light_sets).
SG_FN real staa_light_below_horizon(IN(Frame) f, IN(StaaPath) path, mat2 cov_r) {
  vec2 g = light_horizon_normal(f.light);
  real R = f.light.tan_radius;
  real below = 0.0;
  int counted = 0;
  for (int k = 0; k <= frame_segments(f); ++k) {
    if (!path.valid[k]) continue;
    below += gaussian_disk_segment_mass(path.centre[k], cov_r, R, g, f.light.L.y);
    counted += 1;
  }
  return counted > 0 ? below / real(counted) : 0.0;
}

// Stage f: the light's share, the RDF's time-averaged mass in the disk, before the clamp
// to what the horizon leaves. Culls first: when every point of the centres' path is
// further from the disk than its radius plus 12 major standard deviations, the mass is
// below exp(-144 / 2) ~ 1e-31 (most pixels never reflect the light); in the RDF's
// principal frame, when the disk's extent along the minor (major) axis stays further than
// 12 minor (major) deviations from the centre along the whole path, the mass is at most
// the 1D tail beyond 12 deviations, 1.8e-33 (an elongated RDF, one dominant aliasing wave
// or the footprint term alone, is culled there where the round bound cannot).
// Then the Mahalanobis cull: with d the least Mahalanobis distance of the path from the
// disk's centre, every point of the disk lies at least d - R / s2 from the RDF's centre
// in the whitened frame (the disk is within R / s2 of its centre there), so each
// instant's mass is at most the 2D normal's radial tail beyond it, exp(-(d - R / s2)^2 /
// 2); culled where d - R / s2 > kStaaCullTail = 8, a mass below 1.3e-14 (in the frames
// that the fallback met on medium and high at 640x360, 32% of its calls, whose masses
// were all below 1.1e-17). The axis-wise culls see an elongated RDF's reach along its
// axes only; this one its reach in every direction. A line (s2 = 0) is not whitened.
// `culled`: a cull before the integrators decided (the share is 0); `fallback`: the
// fallback integrator was chosen.
struct StaaLightShare {
  real in_light;
  bool culled;
  bool fallback;
};

SG_FN StaaLightShare staa_light_share(IN(R32Texture2D) table_f, IN(R32Texture3D) table_s,
                                      IN(PathTableInfo) tinfo, IN(R32Texture2D) fits,
                                      IN(KernelFitInfo) finfo, IN(Frame) f, IN(StaaParams) p,
                                      IN(StaaPath) path, mat2 cov_r) {
  int K = frame_segments(f);
  real R = f.light.tan_radius;
  PrincipalAxes ax = principal_axes(cov_r);
  StaaLightShare s;
  s.in_light = 0.0;
  s.culled = path_min_distance(path, K, mat2(1.0)) > R + 12.0 * ax.s1;
  if (!s.culled && ax.s2 > 0.0)
    s.culled = path_min_distance(path, K, staa_whitening(ax)) - R / ax.s2 > kStaaCullTail;
  s.fallback = false;
  if (!s.culled) {
    int integrator = staa_integrator(p, ax, R);
    real min_minor = path_min_abs_projection(path, K, vec2(-ax.u.y, ax.u.x));
    real min_major = path_min_abs_projection(path, K, ax.u);
    s.fallback = integrator == kStaaFallback;
    if (integrator == kStaaFallback) {
      bool culled = min_minor > R + 12.0 * ax.s2 || min_major > R + 12.0 * ax.s1;
      if (!culled) s.in_light = staa_fallback_share(p, path, K, cov_r, R);
    } else {
      s.in_light = staa_kernels_share(table_f, table_s, tinfo, fits, finfo, p, path, K, ax, R,
                                      min_minor, min_major, integrator == kStaaVanishing);
    }
  }
  return s;
}

// A path's instants 0..K into another: what the stages read of the fixed-size arrays
// (copying the whole struct moved kMaxSegments + 1 entries a pixel on the CPU).
SG_FN void staa_path_copy(IN(StaaPath) from, int K, INOUT(StaaPath) to) {
  for (int k = 0; k <= K; ++k) {
    to.centre[k] = from.centre[k];
    to.valid[k] = from.valid[k];
  }
}

// Steps 3 to 5 from the sums: the stages above in order.
SG_FN StaaResult staa_finish(IN(R32Texture2D) table_f, IN(R32Texture3D) table_s,
                             IN(PathTableInfo) tinfo, IN(R32Texture2D) fits,
                             IN(KernelFitInfo) finfo, IN(Frame) f, IN(StaaParams) p,
                             IN(Footprint) fp, IN(PathViews) v, IN(StaaSums) sums,
                             OUT(StaaPath) path) {
  int K = frame_segments(f);
  for (int k = 0; k <= K; ++k) {
    path.centre[k] = vec2(0.0);
    path.valid[k] = false;
  }
  StaaResult res;
  if (!sums.any_alias && p.footprint == 0) {
    res = staa_temporal_result(f, sums, v);
  } else {
    res = staa_result_miss();
    res.hit = true;
    res.aliasing = sums.any_alias;
    StaaNdf ndf = staa_ndf_along_path(f, p, v, sums, path);
    staa_centre_terms(f, p, sums, fp, v, ndf, path.valid[K], res);
    StaaPath light_path;
    staa_path_copy(path, K, light_path);
    LightAnchor a = staa_light_path(f, p, v, sums, ndf, light_path);
    StaaRdf rdf;
    rdf.cov = mat2(0.0);
    rdf.exact = false;
    rdf.D = mat2(0.0);
    if (light_path.valid[K]) rdf = staa_rdf(f, p, fp, v, sums, ndf, a);
    if (rdf.exact) {
      // The host integrates the light's share and ends with staa_exact_result.
      res.exact_pending = true;
      res.exact_D = rdf.D;
    } else {
      if (path.valid[K] && !res.terms_valid) {
        // The horizon is a line of the exactly mapped light plane: stage b's path, and the
        // covariance linearised at the NDF's centre. From the light's, through
        // M = J_c J_L^-1: exact for the NDF and the resolved normals' spread, which both
        // map through dPhi/dn; the footprint's share from the view's change across the
        // pixel (~1e-3 rad, far below the normals' spread) is carried by the same M.
        mat2 cov_h = rdf.cov;
        if (a.valid) {
          mat2 M = ndf_to_light_plane_jacobian(ndf.now, fp.view, f.light) * inverse(a.J);
          cov_h = M * rdf.cov * transpose(M);
        }
        res.below = staa_below_share(f, path, cov_h);
      }
      if (light_path.valid[K]) {
        StaaLightShare s =
            staa_light_share(table_f, table_s, tinfo, fits, finfo, f, p, light_path, rdf.cov);
        res.fallback = s.fallback;
        real in_light = s.culled ? 0.0 : s.in_light;
        if (!s.culled && staa_frame_light_sets(f))
          in_light -= staa_light_below_horizon(f, light_path, rdf.cov);
        res.in_light = clamp(in_light, 0.0, 1.0 - res.below);
      }
      res.weights = staa_weights(f, res);
    }
    staa_path_copy(light_path, K, path);
  }
  return res;
}

// A `--footprint exact` pixel that staa_finish handed to the host (res.exact_pending): with
// the light's share in_light of the swept parallelogram D (shading/swept_footprint.h, which
// the host integrates), the share below the horizon over the parallelogram's moment-matched
// Gaussian D D^T / 12 unless the smooth terms gave it, the cap, and the weights, as
// staa_finish ends its other pixels.
SG_FN StaaResult staa_exact_result(IN(Frame) f, IN(StaaPath) path, IN(StaaResult) r,
                                   real in_light) {
  StaaResult res = r;
  if (!res.terms_valid) {
    res.below = staa_below_share(f, path, res.exact_D * transpose(res.exact_D) / 12.0);
  }
  res.in_light = clamp(in_light, 0.0, 1.0 - res.below);
  res.weights = staa_weights(f, res);
  res.exact_pending = false;
  return res;
}

// Whether a lit pixel may be cut into quarters where its resolved waves fold (`--fold-cells
// X`, staa_pixel): the constant of a GLSL program compiled for it (SG_FOLD_CELLS,
// gl_engine/kernel_program.h), so that a program without it holds no second wave pass;
// elsewhere the parameter's.
SG_FN bool staa_fold_cells_on(IN(StaaParams) p) {
#ifndef SG_FOLD_CELLS
  return p.fold_cells > 0.0;
#else
  return SG_FOLD_CELLS != 0 && p.fold_cells > 0.0;
#endif
}

// Steps 1 to 5 over one square of the image plane about `at` whose water point and
// footprint are `fp`: the pixel, or a quarter of it. `fold`: the pass's largest departure of
// a resolved wave's slope from its tangent across the square (staa_waves.glsl, StaaSums).
SG_FN StaaResult staa_square(IN(WaveBuffer) waves, IN(R32Texture2D) table_f,
                             IN(R32Texture3D) table_s, IN(PathTableInfo) tinfo,
                             IN(R32Texture2D) fits, IN(KernelFitInfo) finfo, IN(Frame) f,
                             IN(StaaParams) q, vec2 at, IN(Footprint) fp, OUT(StaaPath) path,
                             OUT(real) fold) {
  PathViews v = path_views(waves, f, fp, at.x, at.y);
  StaaSums sums = staa_wave_pass(waves, f, q, fp, v);
  staa_cascades_add(sums, waves, f, q, fp, v);
  fold = sums.fold;
  return staa_finish(table_f, table_s, tinfo, fits, finfo, f, q, fp, v, sums, path);
}

// The whole pixel (i, j).
SG_FN StaaResult staa_pixel(IN(WaveBuffer) waves, IN(R32Texture2D) table_f,
                            IN(R32Texture3D) table_s, IN(PathTableInfo) tinfo,
                            IN(R32Texture2D) fits, IN(KernelFitInfo) finfo, IN(Frame) f,
                            IN(StaaParams) p, int i, int j, OUT(StaaPath) path) {
  // A pixel that the horizon crosses: the water's part at its centroid (with the Gaussian
  // footprint term where `exact` would hand it to the host), the sky over the rest
  // (horizon_coverage.glsl).
  PixelWater pw = pixel_water(f.camera, i, j);
  Footprint fp = pixel_footprint(waves, f, pw.centre.x, pw.centre.y, 0.0, f.displaced);
  if (!(pw.share > 0.0) || !fp.hit) {
    StaaResult r = staa_result_miss();
    r.weights = miss_pixel_weights(f, i, j);
    for (int k = 0; k <= frame_segments(f); ++k) {
      path.centre[k] = vec2(0.0);
      path.valid[k] = false;
    }
    return r;
  }
  StaaParams q = p;
  if (pw.share < 1.0 && q.footprint == 2) q.footprint = 1;
  real fold;
  StaaResult r =
      staa_square(waves, table_f, table_s, tinfo, fits, finfo, f, q, pw.centre, fp, path, fold);
  if (staa_fold_cells_on(q) && pw.share >= 1.0 && q.footprint == 1 && r.in_light > 0.0 &&
      fold > q.fold_cells * f.light.radius) {
    // A lit pixel where a resolved wave's slope turns across it: the mean of its quarters,
    // each a pixel of half the size about its own centre (the footprint's derivatives
    // halved), as a render at twice the resolution shades them; the whole pixel's where a
    // quarter's ray misses the water.
    vec4 quarters = vec4(0.0);
    bool cut = true;
    for (int c = 0; c < 4; ++c) {
      vec2 at = pw.centre + vec2((c & 1) != 0 ? 0.25 : -0.25, (c & 2) != 0 ? 0.25 : -0.25);
      Footprint fc = pixel_footprint(waves, f, at.x, at.y, 0.0, f.displaced);
      if (!fc.hit) {
        cut = false;
        break;
      }
      fc.dp_dpx *= 0.5;
      fc.dp_dpy *= 0.5;
      StaaPath pc;
      real fold_c;
      quarters +=
          0.25 * staa_square(waves, table_f, table_s, tinfo, fits, finfo, f, q, at, fc, pc, fold_c)
                     .weights;
    }
    if (cut) r.weights = quarters;
  }
  r.weights = with_sky_part(f, pw, i, j, r.weights);
  return r;
}
