// One wave's terms in the gradients along the reflection path (reflection_path.glsl, the
// temporal method of Podee et al. 2021 Sec. 3.3) and in the reference's path with its time
// derivatives (reference_path.glsl). Lane-generic (wave_terms.glsl): the GPU's loops and
// the CPU engine's SIMD lanes (kernel/cpu/lane_passes.inc) run this same text.

// A wave's term, of resolved amplitude A and phase theta (sine s, cosine c) at the display
// time, in the gradients of every instant (a fixed camera: theta_k = theta - c (end - t_k)
// by angle subtraction).
SG_FN void path_gradients_add(INOUT(PathGradients) p, IN(PathInstants) inst, IN(WaveBuffer) waves,
                              int i, IN(Wave) w, real A, real s, real c) {
  vec2 k = vec2(w.a, w.b);
  p.g[inst.segments] += (A * c) * k;
  for (int q = 0; q < inst.segments; ++q) {
    vec2 cs = rotated_cos_sin(wave_rotation_of(waves, inst.wave_stride, i, q), s, c);
    p.g[q] += (A * cs.x) * k;
  }
}

// The same under a moving camera: the phase at the display time's point (cosine c) for
// instant K, and at p_k and t_k for the others.
SG_FN void path_gradients_add_moving(INOUT(PathGradients) p, IN(PathInstants) inst, IN(Wave) w,
                                     real A, real c) {
  vec2 k = vec2(w.a, w.b);
  p.g[inst.segments] += (A * c) * k;
  for (int q = 0; q < inst.segments; ++q) {
    real theta = wave_phase(w, inst.points[q].x, inst.points[q].y, inst.dts[q]);
    p.g[q] += (A * cos(theta)) * k;
  }
}

// A wave's term in the reference's path, its phase theta (sine s, cosine c) at the window's
// end: with theta_k = theta - c (end - t_k), g = sum A cos(theta_k) (a, b) and
// dg/dt = -sum A c sin(theta_k) (a, b).
SG_FN void path_derivatives_add(INOUT(PathDerivatives) p, IN(PathInstants) inst,
                                IN(WaveBuffer) waves, int i, IN(Wave) w, real s, real c) {
  vec2 k = vec2(w.a, w.b);
  int K = inst.segments;
  p.g[K] += (w.A * c) * k;
  p.dg[K] -= (w.A * w.c * s) * k;
  for (int q = 0; q < K; ++q) {
    vec2 cs = rotated_cos_sin(wave_rotation_of(waves, inst.wave_stride, i, q), s, c);
    p.g[q] += (w.A * cs.x) * k;
    p.dg[q] -= (w.A * w.c * cs.y) * k;
  }
}
