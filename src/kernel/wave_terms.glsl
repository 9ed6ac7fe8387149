// The per-wave arithmetic that the sums over the waves share, written so that it also
// compiles with `real` a vector of waves in SIMD lanes (kernel/cpu/lane_types.h): the CPU
// engine's vectorised passes run this text, one wave per lane, where a GPU thread runs it
// one wave per iteration (Podee et al. 2021 Sec. 3: the pixel's one pass over the waves).
//
// The lane-generic rules, on top of the kernel's subset (kernel/cpp_prelude.h), for this
// file and the others the lanes compile (aliasing.glsl, ndf.glsl, staa_waves.glsl):
//  - a comparison of reals goes only to select(c, a, b) (GLSL's c ? a : b on one real) or
//    to any_lane(c) (a branch around work that adds nothing in the lanes where c fails);
//  - `bool` and `int` are pixel-wide (the same in every lane): branches and loops on them
//    are free;
//  - no reads of the wave buffer but wave_rotation_of (waves.glsl; each build reads its own
//    layout), no Frame, no constants of its own (constants.glsl's are scalars in every
//    build).

// x reduced to [-pi, pi]: x - 2 pi k, k = round(x / 2 pi). GPUs' sin and cos lose
// accuracy away from [-pi, pi]. 2 pi is split Cody-Waite style into 6.28125 (8 bits, so
// that k 6.28125 is exact for |k| < 2^16 in float) and the rest, so the reduction adds
// about |k| 2e-3 times the precision's rounding, well below what x itself carries.
SG_FN real wrap_angle(real x) {
  real k = floor(x * kInvTwoPi + 0.5);
  return (x - k * 6.28125) - k * 0.0019353071795864769252867665590;
}

// sin(x) / x from x and its sine sin_x (which a caller may have from a reduced angle or
// an angle addition), accurate near 0: 1 - x^2 / 6 below 1e-4.
SG_FN real sinc_from(real x, real sin_x) {
  return select(abs(x) < 1e-4, 1.0 - x * x / 6.0, sin_x / select(abs(x) < 1e-4, 1.0, x));
}

// One wave of the frame (waves.glsl: wave_at reads it from the wave buffer).
struct Wave {
  real A;
  real a;
  real b;
  real theta0;
  real c;
  real k;
  real slope;
};

// Wave w's phase at (x, z) and dt, reduced to [-pi, pi] for sin and cos.
SG_FN real wave_phase(IN(Wave) w, real x, real z, real dt) {
  return wrap_angle(w.a * x + w.b * z + w.theta0 + w.c * dt);
}

// (cos, sin) of a wave's phase at instant k < K, theta_k = theta - c (end - t_k), from the
// sine s and cosine c of its display-time phase theta and the rotation (cos, sin) of
// c (end - t_k) (waves.glsl, wave_rotation), by angle subtraction.
SG_FN vec2 rotated_cos_sin(vec2 rot, real s, real c) {
  return vec2(c * rot.x + s * rot.y, s * rot.x - c * rot.y);
}

// The gradients of the resolved waves at the path's instants (reflection_path.glsl).
struct PathGradients {
  vec2 g[kMaxSegments + 1];  // (dh/dx, dh/dz) of the resolved waves at t_0 .. t_K
};

// Zero gradients for the instants of K sub-arcs (the rest of the array is not read).
SG_FN PathGradients path_gradients_zero(int K) {
  PathGradients p;
  for (int k = 0; k <= K; ++k)
    p.g[k] = vec2(0.0);
  return p;
}

// One wave's height at (x, z) and dt.
SG_FN real wave_height_of(IN(Wave) w, real x, real z, real dt) {
  return w.A * sin(wave_phase(w, x, z, dt));
}

// One wave's height and its derivative along the horizontal direction u = (ux, uz):
// (A sin(theta), A cos(theta) (a ux + b uz)).
SG_FN vec2 wave_height_slope_of(IN(Wave) w, real x, real z, real dt, real ux, real uz) {
  real th = wave_phase(w, x, z, dt);
  return w.A * vec2(sin(th), cos(th) * (w.a * ux + w.b * uz));
}

// One wave's curvature factors (a^2, a b, b^2): its Hessian (h_xx, h_xz, h_zz) is
// -A sin(theta) times them.
SG_FN vec3 wave_curvature_of(IN(Wave) w) {
  return vec3(w.a * w.a, w.a * w.b, w.b * w.b);
}

// One wave's Hessian (h_xx, h_xz, h_zz) = -A sin(theta) (a^2, a b, b^2).
SG_FN vec3 wave_hessian_of(IN(Wave) w, real x, real z, real dt) {
  return -(w.A * sin(wave_phase(w, x, z, dt))) * wave_curvature_of(w);
}

// One wave's gradient (dh/dx, dh/dz) = A cos(theta) (a, b).
SG_FN vec2 wave_gradient_of(IN(Wave) w, real x, real z, real dt) {
  real k = w.A * cos(wave_phase(w, x, z, dt));
  return k * vec2(w.a, w.b);
}

// The path's instants t_k = end - duration (K - k) / K, k = 0..K, as the sums over the
// waves take them (reflection_path.glsl, path_instants): each wave's display-time phase
// turned back by the wave buffer's rotations (waves `wave_stride` texels apart) and, where
// the instants' points move, on to each instant's own water point p_k (k < K; p_K is the
// display time's point; path_terms.glsl, path_instant_cos_sin).
struct PathInstants {
  int segments;  // K
  int wave_stride;
  bool moving;
  vec2 points[kMaxSegments + 1];
};

// K as the per-wave terms take it. A GLSL program compiled for its frames' K
// (SG_EXACT_SEGMENTS, gl_engine/kernel_program.h: every entry but the reference) takes the
// constant: the pixel's arrays that the terms index by K (the gradients and Hessians at the
// instants) then stay in registers, where an index known only at run time sends them
// through memory on every wave (on llvmpipe a third of `staa`'s frame on `smooth`,
// docs/benchmarks.md; a GPU's local arrays behave alike). Elsewhere, the frame's K.
SG_FN int path_segments(IN(PathInstants) inst) {
#ifndef SG_EXACT_SEGMENTS
  return inst.segments;
#else
  return kMaxSegments;
#endif
}

// The gradient and its time derivative at the path's instants t_0 .. t_K (the reference's
// path, reference_path.glsl).
struct PathDerivatives {
  vec2 g[kMaxSegments + 1];
  vec2 dg[kMaxSegments + 1];
};
