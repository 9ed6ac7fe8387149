// One wave's terms in the gradients along the reflection path (reflection_path.glsl, the
// temporal method of Podee et al. 2021 Sec. 3.3) and in the reference's path with its time
// derivatives (reference_path.glsl). Lane-generic (wave_terms.glsl): the GPU's loops and
// the CPU engine's SIMD lanes (kernel/cpu/lane_passes.inc) run this same text.

// (cos, sin) of wave i's phase at instant q < K, theta_q = theta - c (end - t_q) + k . (p_q -
// p_K), from the sine s and cosine c of its phase theta at the display time and point p_K:
// the turn back in time by angle subtraction (rotated_cos_sin, the wave buffer's rotations)
// and, where the instants' points move (inst.moving: a moving camera, displaced water), the
// turn k . (p_q - p_K) on top. Both turns are small angles, so float carries each instant's
// phase to the display time's rounding; the phase taken whole at p_q and t_q, k . p_q +
// theta0 + c dt_q, rounds on its own at each instant (at 1 km from the camera, 6e-5 rad
// apart in float: enough to move a path tangent to a small light's disk; docs/gpu.md).
SG_FN vec2 path_instant_cos_sin(IN(PathInstants) inst, IN(WaveBuffer) waves, int i, IN(Wave) w,
                                real s, real c, int q) {
  vec2 cs = rotated_cos_sin(wave_rotation_of(waves, inst.wave_stride, i, q), s, c);
  if (inst.moving) {
    vec2 dp = inst.points[q] - inst.points[path_segments(inst)];
    real d = w.a * dp.x + w.b * dp.y;
    cs = rotated_cos_sin(vec2(cos(d), -sin(d)), cs.y, cs.x);
  }
  return cs;
}

// A wave's term, of resolved amplitude A and phase theta (sine s, cosine c) at the display
// time and point, in the gradients of every instant (path_instant_cos_sin).
SG_FN void path_gradients_add(INOUT(PathGradients) p, IN(PathInstants) inst, IN(WaveBuffer) waves,
                              int i, IN(Wave) w, real A, real s, real c) {
  vec2 k = vec2(w.a, w.b);
  int K = path_segments(inst);
  p.g[K] += (A * c) * k;
  for (int q = 0; q < K; ++q)
    p.g[q] += (A * path_instant_cos_sin(inst, waves, i, w, s, c, q).x) * k;
}

// A wave's term in the reference's path, its phase theta (sine s, cosine c) at the window's
// end: with theta_k = theta - c (end - t_k), g = sum A cos(theta_k) (a, b) and
// dg/dt = -sum A c sin(theta_k) (a, b).
SG_FN void path_derivatives_add(INOUT(PathDerivatives) p, IN(PathInstants) inst,
                                IN(WaveBuffer) waves, int i, IN(Wave) w, real s, real c) {
  vec2 k = vec2(w.a, w.b);
  int K = path_segments(inst);
  p.g[K] += (w.A * c) * k;
  p.dg[K] -= (w.A * w.c * s) * k;
  for (int q = 0; q < K; ++q) {
    vec2 cs = rotated_cos_sin(wave_rotation_of(waves, inst.wave_stride, i, q), s, c);
    p.g[q] += (w.A * cs.x) * k;
    p.dg[q] -= (w.A * w.c * cs.y) * k;
  }
}
