// The water surface: a sum of sine waves (Podee et al. 2021, Eq. 1, with the scene spec's
// phase), h(x, z, t) = sum_i A_i sin(a_i x + b_i z + c_i t + phi_i), and its analytic
// derivatives. Positions are camera-relative and dt = t - display time (interface.glsl). The
// surface normal is normalize(-dh/dx, 1, -dh/dz) (scene spec).

// One wave of the frame, read from the wave buffer. Texels of wave i (stride S):
//   i S + 0: (A, a, b, theta0)   amplitude, wave vector, phase at (0, 0) and display time
//   i S + 1: (c, |k|, A |k|, 0)  angular frequency, wavenumber, slope amplitude
//   i S + 2 + k / 2: (cos, sin) of c (end - t_k) for the path's instants k = 0..K-1,
//                    two instants per texel (xy for even k, zw for odd k).
// Waves are sorted by |k| (ascending) on the host.
//
// After the N waves, at texel N S, the waves' sums from each position on (Bruneton et al.
// 2010, Sec. 3.2: with the waves sorted by wavelength, what a pixel leaves out is a
// suffix, and its variance is a difference of sums), N + 1 entries of two texels, entry
// i = 0..N holding the sums over the waves j >= i (suffix) or j < i (prefix):
//   N S + 2 i:     (sum_{j>=i} A_j^2 / 2 (a_j^2, a_j b_j, b_j^2), sum_{j>=i} A_j^2)
//                  the suffix's slope covariance (Eq. 3) and squared amplitudes;
//   N S + 2 i + 1: (sum_{j>=i} A_j, sum_{j<i} A_j, sum_{j<i} A_j |k_j|, sum_{j<i} A_j |k_j|^2)
//                  the suffix's amplitude (a bound on its height), the prefix's amplitude,
//                  slope and curvature bounds (its slab, and the bounds on the first and
//                  second derivatives of its height along a ray, intersect.glsl).
// The host sums in double; entry N is the empty suffix (zeros and the whole prefix).
//
// The layout is written once, here: the host packs the texels with the functions below
// (shading/kernel_frame.cpp) and the kernel reads them back at the same offsets.

// Texels per wave for K path segments.
SG_FN int wave_stride_for(int segments) {
  return 2 + (segments + 1) / 2;
}
// The first texel of wave i, of the rotation of its instant k, of the sums' entry i.
SG_FN int wave_texel_index(int stride, int i) {
  return i * stride;
}
SG_FN int wave_rotation_index(int stride, int i, int k) {
  return i * stride + 2 + k / 2;
}
SG_FN int wave_sums_index(int wave_count, int stride, int i) {
  return wave_count * stride + 2 * i;
}
// A wave's two texels.
SG_FN vec4 wave_pack_phase(IN(Wave) w) {
  return vec4(w.A, w.a, w.b, w.theta0);
}
SG_FN vec4 wave_pack_motion(IN(Wave) w) {
  return vec4(w.c, w.k, w.slope, 0.0);
}
// Texel t with instant k's rotation (cos, sin) = r put in its half.
SG_FN vec4 wave_pack_rotation(vec4 t, int k, vec2 r) {
  return (k % 2) == 0 ? vec4(r.x, r.y, t.z, t.w) : vec4(t.x, t.y, r.x, r.y);
}
// The sums' entry: the suffix's slope covariance and squared amplitude; the suffix's
// amplitude and the prefix's amplitude, slope and curvature bounds.
SG_FN vec4 wave_pack_suffix(vec3 cov, real amplitude2) {
  return vec4(cov, amplitude2);
}
SG_FN vec4 wave_pack_bounds(real suffix_amplitude, vec3 prefix) {
  return vec4(suffix_amplitude, prefix);
}

SG_FN Wave wave_at(IN(WaveBuffer) waves, IN(Frame) f, int i) {
  SG_COUNT(waves, 1);
  vec4 t0 = wave_texel(waves, wave_texel_index(f.wave_stride, i));
  vec4 t1 = wave_texel(waves, wave_texel_index(f.wave_stride, i) + 1);
  Wave w;
  w.A = t0.x;
  w.a = t0.y;
  w.b = t0.z;
  w.theta0 = t0.w;
  w.c = t1.x;
  w.k = t1.y;
  w.slope = t1.z;
  return w;
}

// (cos, sin) of c (end - t_k): the rotation from the display time back to instant k < K,
// for waves `stride` texels apart (Frame.wave_stride).
SG_FN vec2 wave_rotation_of(IN(WaveBuffer) waves, int stride, int i, int k) {
  vec4 t = wave_texel(waves, wave_rotation_index(stride, i, k));
  return (k % 2) == 0 ? vec2(t.x, t.y) : vec2(t.z, t.w);
}
SG_FN vec2 wave_rotation(IN(WaveBuffer) waves, IN(Frame) f, int i, int k) {
  return wave_rotation_of(waves, f.wave_stride, i, k);
}

// (cos, sin) of wave i's phase at instant k < K (wave_terms.glsl, rotated_cos_sin).
SG_FN vec2 wave_instant_cos_sin(IN(WaveBuffer) waves, IN(Frame) f, int i, int k, real s, real c) {
  return rotated_cos_sin(wave_rotation(waves, f, i, k), s, c);
}

// The sums of entry i (0 <= i <= N) of the table above.
SG_FN vec4 wave_suffix_moments(IN(WaveBuffer) waves, IN(Frame) f, int i) {
  return wave_texel(waves, wave_sums_index(f.wave_count, f.wave_stride, i));
}
SG_FN vec4 wave_bounds_at(IN(WaveBuffer) waves, IN(Frame) f, int i) {
  return wave_texel(waves, wave_sums_index(f.wave_count, f.wave_stride, i) + 1);
}

// The first position whose wavenumber is at least `k` (N when none is): a binary search
// over the sorted |k|.
SG_FN int first_wave_from(IN(WaveBuffer) waves, IN(Frame) f, real k) {
  int lo = 0;
  int hi = f.wave_count;
  while (lo < hi) {
    int mid = (lo + hi) / 2;
    if (wave_texel(waves, wave_texel_index(f.wave_stride, mid) + 1).y < k) {
      lo = mid + 1;
    } else {
      hi = mid;
    }
  }
  return lo;
}

// The first position i whose suffix's amplitude sum_{j>=i} A_j is at most `amplitude`
// (N when only the empty suffix is): a binary search, the suffix sums falling with i.
SG_FN int first_wave_below(IN(WaveBuffer) waves, IN(Frame) f, real amplitude) {
  int lo = 0;
  int hi = f.wave_count;
  while (lo < hi) {
    int mid = (lo + hi) / 2;
    if (wave_bounds_at(waves, f, mid).x > amplitude) {
      lo = mid + 1;
    } else {
      hi = mid;
    }
  }
  return lo;
}

// The sums over the waves at one point and time: the definitions, over wave_terms.glsl's
// terms. The CPU engine runs the same terms in SIMD lanes (SG_CPU_WAVE_SUMS below;
// kernel/cpu/lane_passes.inc), tested equal to these.
// The height of wave i.
SG_FN real wave_height_term(IN(WaveBuffer) waves, IN(Frame) f, int i, real x, real z, real dt) {
  return wave_height_of(wave_at(waves, f, i), x, z, dt);
}

// The height of the first n waves (in |k| order), summed in that order, eight waves an
// iteration (the last iteration's waves past n add nothing): the displaced march calls it
// at every step, and llvmpipe ends every loop of an invocation after 65535 iterations in
// all (docs/gpu.md), which a grazing ray over hundreds of waves passed within one sample.
// GPU compilers unroll such loops themselves.
const int kHeightUnroll = 8;
SG_FN real wave_sum_height_first(IN(WaveBuffer) waves, IN(Frame) f, int n, real x, real z,
                                 real dt) {
  real h = 0.0;
  for (int i = 0; i < n; i += kHeightUnroll) {
    for (int j = 0; j < kHeightUnroll; ++j) {
      if (i + j < n) h += wave_height_term(waves, f, i + j, x, z, dt);
    }
  }
  return h;
}

// The height of waves lo <= i < hi and its derivative along the horizontal direction
// u = (ux, uz), (sum A_i sin(theta_i), sum A_i cos(theta_i) (a_i ux + b_i uz)), summed in
// position order; hi - lo <= kMarchBlock (the displaced march's blocks, intersect.glsl).
const int kMarchBlock = 8;
SG_FN vec2 wave_sum_height_slope(IN(WaveBuffer) waves, IN(Frame) f, int lo, int hi, real x, real z,
                                 real dt, real ux, real uz) {
  vec2 r = vec2(0.0);
  for (int j = 0; j < kMarchBlock; ++j) {
    if (lo + j < hi) r += wave_height_slope_of(wave_at(waves, f, lo + j), x, z, dt, ux, uz);
  }
  return r;
}

SG_FN real wave_sum_height(IN(WaveBuffer) waves, IN(Frame) f, real x, real z, real dt) {
  return wave_sum_height_first(waves, f, f.wave_count, x, z, dt);
}

// (dh/dx, dh/dz)
SG_FN vec2 wave_sum_gradient(IN(WaveBuffer) waves, IN(Frame) f, real x, real z, real dt) {
  vec2 g = vec2(0.0);
  for (int i = 0; i < f.wave_count; ++i)
    g += wave_gradient_of(wave_at(waves, f, i), x, z, dt);
  return g;
}

// (h_xx, h_xz, h_zz) summed over the waves in position order: the host's baselines at a
// point (`staa` sums its Hessians in its own pass over the waves, staa_waves.glsl).
SG_FN vec3 water_hessian(IN(WaveBuffer) waves, IN(Frame) f, real x, real z, real dt) {
  vec3 h = vec3(0.0);
  for (int i = 0; i < f.wave_count; ++i)
    h += wave_hessian_of(wave_at(waves, f, i), x, z, dt);
  return h;
}

#ifdef SG_CPU_WAVE_SUMS
real water_height(IN(WaveBuffer) waves, IN(Frame) f, real x, real z, real dt);
real water_height_first(IN(WaveBuffer) waves, IN(Frame) f, int n, real x, real z, real dt);
vec2 water_height_slope(IN(WaveBuffer) waves, IN(Frame) f, int lo, int hi, real x, real z, real dt,
                        real ux, real uz);
vec2 water_gradient(IN(WaveBuffer) waves, IN(Frame) f, real x, real z, real dt);
#else
SG_FN real water_height_first(IN(WaveBuffer) waves, IN(Frame) f, int n, real x, real z, real dt) {
  return wave_sum_height_first(waves, f, n, x, z, dt);
}
SG_FN real water_height(IN(WaveBuffer) waves, IN(Frame) f, real x, real z, real dt) {
  return wave_sum_height(waves, f, x, z, dt);
}
SG_FN vec2 water_height_slope(IN(WaveBuffer) waves, IN(Frame) f, int lo, int hi, real x, real z,
                              real dt, real ux, real uz) {
  return wave_sum_height_slope(waves, f, lo, hi, x, z, dt, ux, uz);
}
SG_FN vec2 water_gradient(IN(WaveBuffer) waves, IN(Frame) f, real x, real z, real dt) {
  return wave_sum_gradient(waves, f, x, z, dt);
}
#endif

// The unnormalised normal (-dh/dx, 1, -dh/dz) of the scene spec for gradient g.
SG_FN vec3 normal_direction(vec2 g) {
  return vec3(-g.x, 1.0, -g.y);
}
