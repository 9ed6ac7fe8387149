// Bruneton et al.'s per-wave terms (bruneton.glsl, Sec. 3.2), lane-generic: the CPU engine
// compiles this file over its SIMD lanes too (kernel/cpu/lane_passes.inc), so the filtered
// sums over the waves are one text on both engines.

// w(a, b, x) of Sec. 3.2: the smoothstep 3 x'^2 - 2 x'^3, x' = clamp((x - a) / (b - a), 0, 1).
SG_FN real lod_weight(real a, real b, real x) {
  real t = clamp((x - a) / (b - a), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// w(n_min, n_max, lambda / l) of wave vector k for a pixel whose footprint maps image-plane
// offsets to horizontal offsets by J: lambda / l = 1 / f, f the projected frequency (max
// norm, aliasing.glsl). A wave with no phase change across the pixel (f = 0) keeps 1: 1 / f
// is then past any n_max (f taken at least 1e-30, without a branch for the lanes).
SG_FN real wave_lod_weight(vec2 k, mat2 J, real n_min, real n_max) {
  return lod_weight(n_min, n_max, 1.0 / max(projected_frequency(k, J, true), 1e-30));
}

// Wave w with its amplitude (and slope bound) at its filter weight.
SG_FN Wave filtered_wave_of(IN(Wave) w, mat2 J, real n_min, real n_max) {
  Wave r = w;
  real weight = wave_lod_weight(vec2(w.a, w.b), J, n_min, n_max);
  r.A *= weight;
  r.slope *= weight;
  return r;
}

// The filtered surface's sums over a block of waves at one point (display time): its
// height and slope along horizontal u, and the sums of |A|, |A| |k| and |A| |k|^2 of the
// filtered amplitudes (the displaced march's bounds).
struct FilteredSums {
  vec2 hs;
  vec3 bounds;
};

SG_FN FilteredSums filtered_sums_zero() {
  FilteredSums s;
  s.hs = vec2(0.0);
  s.bounds = vec3(0.0);
  return s;
}

// |A|, |A| |k| and |A| |k|^2 of wave w.
SG_FN vec3 wave_march_bounds(IN(Wave) w) {
  real ak = abs(w.A) * w.k;
  return vec3(abs(w.A), ak, ak * w.k);
}

SG_FN void filtered_sums_add(INOUT(FilteredSums) s, IN(Wave) w, real x, real z, vec2 u) {
  s.hs += wave_height_slope_of(w, x, z, 0.0, u.x, u.y);
  s.bounds += wave_march_bounds(w);
}

// A pixel's filtered slopes at one point (display time): the gradient of the waves at
// their weights w (Eq. 3) and the slope covariance of their filtered-out parts, (1 - w) A
// (Eq. 4 for sines, ndf.glsl's uniform term).
struct FilteredSlopes {
  vec2 g;
  NdfMoments m;
};

SG_FN FilteredSlopes filtered_slopes_zero() {
  FilteredSlopes s;
  s.g = vec2(0.0);
  s.m = ndf_zero();
  return s;
}

SG_FN void filtered_slopes_add(INOUT(FilteredSlopes) s, IN(Wave) w, mat2 J, real n_min, real n_max,
                               real x, real z) {
  Wave f = w;
  real weight = wave_lod_weight(vec2(w.a, w.b), J, n_min, n_max);
  ndf_add_uniform(s.m, (1.0 - weight) * w.A, vec2(w.a, w.b));
  f.A *= weight;
  s.g += wave_gradient_of(f, x, z, 0.0);
}
