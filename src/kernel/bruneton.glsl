// Ocean lighting with seamless transitions from geometry to BRDF, `bruneton` (a baseline,
// methods/bruneton.h): Bruneton, Neyret, Holzschuch 2010 (docs/references.md), Sec. 3-5
// and Algorithm 5.1 in Fig. 9, on the sum of sines of the scene spec, per pixel at the
// display time.
//
// 1. Filter weights (Sec. 3.2, N_min = 1, N_max = 2.5 as Sec. 7.1). Each wave keeps a
//    weight w(N_min, N_max, lambda / l) of its amplitude in the geometry and the normals,
//    with the smoothstep w(a, b, x) = 3 x'^2 - 2 x'^3, x' = clamp((x - a) / (b - a), 0, 1).
//    The paper projects a screen-space grid on the water at rest; here the grid cell is the
//    pixel, so the projected cell size L and the projected pixel size l are one footprint
//    on the plane y = 0 (pixel_footprint at rest), and l is measured along the wave: the
//    larger of the phase steps between neighbouring pixel centres, the projected frequency
//    f of aliasing.glsl (max norm), lambda / l = 1 / f.
//    Sec. 7.1 restricts the sums to the waves whose weights can be non-zero; the wave
//    buffer is sorted by |k| (waves.glsl), and for a footprint J with smallest singular
//    value sigma a wave of wavenumber kappa has f >= kappa sigma / (2 pi sqrt 2) (|J^T k| >=
//    sigma |k|, and the larger axis frequency is at least the norm over sqrt 2), so every
//    wave with kappa >= 2 pi sqrt 2 / (N_min sigma) has w = 0 exactly: the pixel sums the
//    waves before it (first_wave_from) and takes the rest's slope covariance from the
//    buffer's suffix sums (Eq. 4 as the total less the resolved waves', without the
//    cancellation).
// 2. Position. Eq. 2 displaces the grid by trochoids; a sine wave has no horizontal
//    displacement, so the position filter scales the waves' heights: on displaced water the
//    camera ray meets the field of amplitudes w_i A_i (bruneton_intersect). Flat water: the
//    plane y = 0, as the spec says.
// 3. Normal (Eq. 3): from the gradient of the waves weighted by w_i; a normal facing away
//    from the viewer is mirrored, n <- n - 2 (n . v) v (Sec. 3.2).
// 4. BRDF variance (Eq. 4 for sines). The filtered-out part 1 - w_i of a sine wave of
//    amplitude A and wave vector k has slope covariance ((1 - w_i) A)^2 / 2 k k^T (the
//    trochoid's 1 - sqrt(1 - k^2 h^2) tends to k^2 h^2 / 2 for small steepness), summed over
//    the waves (ndf.glsl, ndf_add_uniform). The paper uses the wind and cross-wind axes, the
//    principal axes of the Cox-Munk ellipse; these scenes have no wind, so the axes are
//    the principal axes of this covariance: sigma_x^2, sigma_y^2 its eigenvalues, and no
//    correlation is dropped (the Ross BRDF takes axis-aligned variances). As the paper does
//    (Sec. 5.1), the world-space variances are used in the tangent frame of n, t_x the major
//    axis projected on the tangent plane.
// 5. Sun (Eq. 15, ocean_brdf.glsl), with Omega_sun = 2 pi (1 - cos(rho)) and F the spec's
//    Fresnel at the half vector. For a sun smaller than the lobe the paper clamps the
//    variances "to a minimum value" (Sec. 5.1) without printing it; the authors' released
//    shader uses max(sigmaSq, 2e-5), the default of --bruneton-min-variance. The sun hides
//    the sky behind it (scene spec): the sun term adds F (L_sun - L_sky) x for Eq. 15's x.
// 6. Sky and sea. Sec. 5.2 writes the reflected environment as F-bar L-bar and the
//    refracted light as L_sea (1 - F-bar) (Eq. 28), with L-bar the environment filtered by
//    the slope kernel (Eq. 22) and, as in Sec. 6, the sea's radiance below the horizon: with
//    the stereographic map of Sec. 5.2 the horizon is the unit circle, so L-bar =
//    (1 - b) L_sky + b L_sea, b the kernel's mass beyond it (below_horizon_fraction), and
//    F-bar L-bar + (1 - F-bar) L_sea is combine_weights(F-bar, 0, b). F-bar is 1 for
//    `fresnel: none`; for `schlick`, the fit of Eq. 26 (default) or the integral of Eq. 24.
// A pixel whose ray misses the water (the rest plane, or the filtered surface) sees the
// sky. Lattice cascades shaded from their fields (flat water; cascade_fields.glsl): the
// filtered normal takes each cascade's mean slope over the pixel's footprint and the
// variance its covariance there (LEAN's box filter of the FFT chain, in the place of the
// per-wave weights), the explicit waves as above.
// Where the camera is under the filtered surface (the hit is the camera: no view
// direction) or the shading is not finite, the pixel takes the centre ray's radiance
// (point_pixel) and says so.

// The wavenumber from which every wave has w = 0 for footprint J and N_min, 1.001 for the
// bound's rounding (the largest real when none is certain; smallest_singular_value:
// staa.glsl, whose fully aliasing waves are cut the same way).
SG_FN real lod_cutoff_wavenumber(mat2 J, real n_min) {
  real sigma = smallest_singular_value(J);
  if (!(sigma > 0.0)) return kRealMax;
  return 1.001 * kTwoPi * kSqrtTwo / (n_min * sigma);
}

// The first position from which every wave has w = 0 (the count when none is certain).
SG_FN int lod_filtered_from(IN(WaveBuffer) waves, IN(Frame) f, mat2 J, real n_min) {
  real k = lod_cutoff_wavenumber(J, n_min);
  if (!(k < kRealMax)) return f.wave_count;
  return first_wave_from(waves, f, k);
}

// Wave i at its filter weight.
SG_FN Wave filtered_wave(IN(WaveBuffer) waves, IN(Frame) f, IN(BrunetonParams) p, mat2 J, int i) {
  return filtered_wave_of(wave_at(waves, f, i), J, p.n_min, p.n_max);
}

// The filtered sums (bruneton_waves.glsl) over waves lo <= i < hi, hi - lo <= kMarchBlock,
// at camera-relative (x, z) at the display time; and a pixel's filtered slopes over its
// first n waves, eight an iteration (llvmpipe ends an invocation's loops after 65535
// iterations, waves.glsl). The CPU engine sums the same terms in SIMD lanes
// (SG_CPU_WAVE_SUMS, kernel/cpu/lane_passes.inc).
SG_FN FilteredSums wave_sum_filtered(IN(WaveBuffer) waves, IN(Frame) f, IN(BrunetonParams) p,
                                     mat2 J, int lo, int hi, real x, real z, vec2 u) {
  FilteredSums s = filtered_sums_zero();
  for (int j = 0; j < kMarchBlock; ++j) {
    if (lo + j < hi) filtered_sums_add(s, filtered_wave(waves, f, p, J, lo + j), x, z, u);
  }
  return s;
}

SG_FN FilteredSlopes wave_sum_filtered_slopes(IN(WaveBuffer) waves, IN(Frame) f,
                                              IN(BrunetonParams) p, mat2 J, int n, real x, real z) {
  FilteredSlopes s = filtered_slopes_zero();
  for (int i = 0; i < n; i += kHeightUnroll) {
    for (int j = 0; j < kHeightUnroll; ++j) {
      if (i + j < n) filtered_slopes_add(s, wave_at(waves, f, i + j), J, p.n_min, p.n_max, x, z);
    }
  }
  return s;
}

#ifdef SG_CPU_WAVE_SUMS
FilteredSums filtered_sums(IN(WaveBuffer) waves, IN(Frame) f, IN(BrunetonParams) p, mat2 J, int lo,
                           int hi, real x, real z, vec2 u);
FilteredSlopes filtered_slopes(IN(WaveBuffer) waves, IN(Frame) f, IN(BrunetonParams) p, mat2 J,
                               int n, real x, real z);
#else
SG_FN FilteredSums filtered_sums(IN(WaveBuffer) waves, IN(Frame) f, IN(BrunetonParams) p, mat2 J,
                                 int lo, int hi, real x, real z, vec2 u) {
  return wave_sum_filtered(waves, f, p, J, lo, hi, x, z, u);
}
SG_FN FilteredSlopes filtered_slopes(IN(WaveBuffer) waves, IN(Frame) f, IN(BrunetonParams) p,
                                     mat2 J, int n, real x, real z) {
  return wave_sum_filtered_slopes(waves, f, p, J, n, x, z);
}
#endif

// The filtered surface's height and its slope along horizontal u at camera-relative
// (x, z), the display time: the first n waves, each at its weight.
SG_FN vec2 filtered_height_slope(IN(WaveBuffer) waves, IN(Frame) f, IN(BrunetonParams) p, mat2 J,
                                 int n, real x, real z, vec2 u) {
  vec2 r = vec2(0.0);
  for (int lo = 0; lo < n; lo += kMarchBlock)
    r += filtered_sums(waves, f, p, J, lo, min(lo + kMarchBlock, n), x, z, u).hs;
  return r;
}

// The filtered surface's point below o + s d: the hit at s.
SG_FN RayHit filtered_surface_hit(IN(WaveBuffer) waves, IN(Frame) f, IN(BrunetonParams) p, mat2 J,
                                  int n, vec3 o, vec3 d, real s) {
  RayHit r = no_hit();
  r.hit = true;
  r.s = s;
  r.point = o + s * d;
  r.point.y = filtered_height_slope(waves, f, p, J, n, r.point.x, r.point.z, vec2(d.x, d.z)).x;
  return r;
}

// One look at the filtered f(s) = y(s) - h(s) from s, as intersect.glsl's march_probe: the
// first n waves summed kMarchBlock at a time in |k| order with the height's slope along the
// ray and their filtered bounds. After the first hi waves, f >= f_hi - e_hi (e_hi the
// filtered amplitude of waves hi..n, the whole's less the waves summed) and f_hi changes at
// most at the rate and curvature of the waves summed, so no zero lies within the larger of
// the first- and second-order steps from f_hi - e_hi; the sum stops once that step is at
// least what every wave's first-order step could be, (f_hi + e_hi) / Lip. b.x, b.y, b.z:
// the filtered sums of |A|, |A| |k| and |A| |k|^2 over the n waves.
struct FilteredProbe {
  real step;  // f has no zero in [s, s + step)
  bool full;  // every one of the n waves summed: f is f(s)
  real f;
};

SG_FN FilteredProbe filtered_probe(IN(WaveBuffer) waves, IN(Frame) f, IN(BrunetonParams) p, mat2 J,
                                   int n, vec3 o, vec3 d, real s, vec3 b, real lip, real min_step) {
  FilteredProbe r;
  vec3 q = o + s * d;
  r.step = 0.0;
  r.full = n == 0;
  r.f = q.y;
  real dxz = length(vec2(d.x, d.z));
  vec2 hs = vec2(0.0);
  vec3 summed = vec3(0.0);  // the filtered sums of |A|, |A| |k|, |A| |k|^2 so far
  for (int lo = 0; lo < n; lo += kMarchBlock) {
    int hi = min(n, lo + kMarchBlock);
    FilteredSums bs = filtered_sums(waves, f, p, J, lo, hi, q.x, q.z, vec2(d.x, d.z));
    hs += bs.hs;
    summed += bs.bounds;
    real fn = q.y - hs.x;
    real e = hi < n ? max(b.x - summed.x, 0.0) + graze_depth() : 0.0;
    real g = fn - e;
    if (g > 0.0) {
      real lip_hi = abs(d.y) + summed.y * dxz;
      r.step = max(r.step,
                   max(g / lip_hi, march_second_order_step(g, d.y - hs.y, summed.z * dxz * dxz)));
    }
    if (hi == n) {
      r.full = true;
      r.f = fn;
      break;
    }
    if (r.step >= max((fn + e) / lip, min_step)) break;
  }
  if (r.full) r.step = max(r.step, max(r.f / lip, min_step));
  return r;
}

// The first hit of the unit ray o + s d with the filtered surface y = sum_{i<n} w_i A_i
// sin(theta_i): the march of intersect.glsl (filtered_probe's steps; the slab
// |y| <= sum w |A| and the rate Lip = |d.y| + (sum w |A| |k|) |d.xz| of the filtered
// amplitudes), refined by Illinois to root_tolerance (RootBracket). hit.s = 0 where the camera is
// under the filtered surface.
SG_FN RayHit filtered_intersect(IN(WaveBuffer) waves, IN(Frame) f, IN(BrunetonParams) p, mat2 J,
                                int n, vec3 o, vec3 d) {
  RayHit r = no_hit();
  vec3 b = vec3(0.0);  // the filtered sums of |A|, |A| |k|, |A| |k|^2
  for (int i = 0; i < n; ++i)
    b += wave_march_bounds(filtered_wave(waves, f, p, J, i));
  real amax = b.x;
  real lip = abs(d.y) + b.y * length(vec2(d.x, d.z));
  real s_enter = 0.0;
  real s_exit = kRealMax;
  if (d.y < 0.0) {
    s_enter = max(0.0, (o.y - amax) / -d.y);
    s_exit = (o.y + amax) / -d.y;
  } else if (d.y > 0.0) {
    if (o.y > amax) return r;
    s_exit = (amax - o.y) / d.y;
  } else if (abs(o.y) > amax) {
    return r;
  }
  if (!(s_exit >= s_enter)) return r;
  vec2 u = vec2(d.x, d.z);
  real min_step = graze_depth() / max(lip, 1e-30);
  real s = s_enter;
  real s_prev = s;
  real f_prev = 0.0;  // f(s_prev) when prev_full
  bool prev_full = false;
  for (int step = 0; step < kMaxMarchSteps; ++step) {
    SG_COUNT(march_steps, 1);
    FilteredProbe q = filtered_probe(waves, f, p, J, n, o, d, s, b, lip, min_step);
    if (q.full && q.f <= 0.0) {
      if (step == 0) {
        // The ray starts at or below the surface (the camera inside the slab).
        r.hit = true;
        r.s = s;
        r.point = o + s * d;
        return r;
      }
      vec3 qa = o + s_prev * d;
      real fa =
          prev_full ? f_prev : qa.y - filtered_height_slope(waves, f, p, J, n, qa.x, qa.z, u).x;
      RootBracket br = root_bracket(s_prev, fa, s, q.f);
      if (!(fa > 0.0)) br = root_bracket(s_prev, fa, s_prev, fa);  // a zero there by rounding
      for (int it = 0; it < kMaxRefineSteps && root_bracket_open(br); ++it) {
        real c = root_bracket_next(br);
        vec3 qc = o + c * d;
        real fc = qc.y - filtered_height_slope(waves, f, p, J, n, qc.x, qc.z, u).x;
        if (root_bracket_take(br, c, fc)) break;
      }
      return filtered_surface_hit(waves, f, p, J, n, o, d, br.b);
    }
    if (s >= s_exit) break;
    s_prev = s;
    f_prev = q.f;
    prev_full = q.full;
    real next = min(s_exit, s + max(q.step, 2.0 * kRealEpsilon * abs(s)));
    if (!(next < kRealMax)) break;
    s = next;
  }
  // The slab's floor going down: f <= 0 there but for rounding (intersect.glsl).
  if (d.y < 0.0 && s >= s_exit) return filtered_surface_hit(waves, f, p, J, n, o, d, s_exit);
  return r;
}

SG_FN FallbackResult bruneton_fallback(IN(WaveBuffer) waves, IN(Frame) f, int i, int j) {
  FallbackResult r;
  r.weights = point_pixel(waves, f, i, j);
  r.fallback = true;
  return r;
}

SG_FN FallbackResult bruneton_pixel(IN(WaveBuffer) waves, IN(Frame) f, IN(BrunetonParams) p, int i,
                                    int j) {
  FallbackResult r;
  r.fallback = false;
  real px = real(i) + 0.5;
  real py = real(j) + 0.5;
  vec3 o = f.camera.position;
  vec3 d = normalize(camera_direction(f.camera, px, py));
  Footprint rest = pixel_footprint(waves, f, px, py, 0.0, false);
  if (!rest.hit) {
    r.weights = miss_pixel_weights(f, i, j);
    return r;
  }
  // 1. The waves that can have a weight: the first n.
  mat2 J = footprint_xz_jacobian(rest);
  int n = lod_filtered_from(waves, f, J, p.n_min);

  // 2. Position: the rest plane, or the filtered height field.
  vec3 P = rest.point;
  if (f.displaced) {
    RayHit hit = filtered_intersect(waves, f, p, J, n, o, d);
    if (!hit.hit) {
      r.weights = miss_pixel_weights(f, i, j);
      return r;
    }
    if (!(hit.s > 0.0)) return bruneton_fallback(waves, f, i, j);
    P = hit.point;
  }
  vec3 v = normalize(o - P);

  // 3-4. The filtered gradient and the filtered-out waves' slope covariance: the first n
  // waves' shares 1 - w, every wave past them (the suffix sums) and the cascades' moments
  // over the footprint.
  vec2 g = vec2(0.0);
  vec3 cov = vec3(0.0);
  if (f.cascade_count > 0) {
    CascadeMoments cm = cascade_footprint_moments(waves, f, vec2(P.x, P.z), J);
    g = cm.mean;
    cov = cm.cov;
  }
  FilteredSlopes sl = filtered_slopes(waves, f, p, J, n, P.x, P.z);
  NdfMoments m = sl.m;
  g += sl.g;
  vec3 n_dir = normalize(normal_direction(g));
  if (dot(n_dir, v) < 0.0) n_dir = normalize(n_dir - 2.0 * dot(n_dir, v) * v);
  vec4 suffix = wave_suffix_moments(waves, f, n);
  PrincipalAxes axes = principal_axes(sym2(m.cov + vec3(suffix.x, suffix.y, suffix.z) + cov));
  vec2 sigma2 =
      vec2(max(axes.s1 * axes.s1, p.min_variance), max(axes.s2 * axes.s2, p.min_variance));
  vec3 major = vec3(axes.u.x, 0.0, axes.u.y);
  vec3 tx = major - dot(major, n_dir) * n_dir;
  if (dot(tx, tx) < 1e-12) tx = vec3(0.0, 0.0, 1.0) - n_dir.z * n_dir;  // n along the axis
  tx = normalize(tx);
  vec3 ty = cross(n_dir, tx);
  vec3 v_ts = vec3(dot(v, tx), dot(v, ty), dot(v, n_dir));
  vec3 l_ts = vec3(dot(f.light.L, tx), dot(f.light.L, ty), dot(f.light.L, n_dir));

  // 5. Sun (Eq. 15).
  real x = sun_reflectance(v_ts, l_ts, sigma2, kTwoPi * (1.0 - f.light.cos_radius));
  real F_sun = fresnel_factor(f.fresnel, dot(v, normalize(v + f.light.L)));

  // 6. Sky and sea (Eqs. 22-28).
  real F_bar = 1.0;
  if (f.fresnel != 0) {
    F_bar = p.fresnel_integral
                ? effective_fresnel_integral(v_ts, sigma2)
                : effective_fresnel_fit(v_ts.z, sqrt(slope_variance_toward(v_ts, sigma2)));
  }
  real below = below_horizon_fraction(v, n_dir, tx, ty, sigma2);
  real sky_y = reflect_view(n_dir, v).y;
  r.weights = combine_weights(f, F_bar, 0.0, below, sky_y) +
              F_sun * x * (light_weights() - sky_weights(f, f.light.L.y));
  if (!finite_weights(r.weights)) return bruneton_fallback(waves, f, i, j);
  return r;
}
