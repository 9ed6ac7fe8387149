// The reference's path (step 1 of kernel/reference.glsl): on flat water a spatial sample's
// hit point does not move, and its radiance over the shutter depends only on the gradient
// g(t) = grad h(x, z, t) there. Here: g and dg/dt at the instants t_k = end - duration
// (K - k) / K, k = 0..K (one sine and cosine per wave, the other instants by angle addition
// with the wave buffer's rotations), and the cubic Hermite interpolant H(s), s in [0, 1],
// of one sub-interval between two instants, whose error the host bounds when it picks K
// (methods/reference.h, reference_time_split).

// The definition (the CPU engine runs the same terms in SIMD lanes under
// SG_CPU_WAVE_SUMS): path_terms.glsl, path_derivatives_add, over every wave; the window
// ending dt (<= 0) after the display time.
SG_FN PathDerivatives wave_sum_path_derivatives(IN(WaveBuffer) waves, IN(Frame) f, vec3 point,
                                                real dt) {
  PathDerivatives p;
  for (int k = 0; k <= frame_segments(f); ++k) {
    p.g[k] = vec2(0.0);
    p.dg[k] = vec2(0.0);
  }
  PathInstants inst = path_instants_fixed(f);
  for (int i = 0; i < f.wave_count; ++i) {
    Wave w = wave_at(waves, f, i);
    real theta = wave_phase(w, point.x, point.z, dt);
    path_derivatives_add(p, inst, waves, i, w, sin(theta), cos(theta));
  }
  return p;
}

#ifdef SG_CPU_WAVE_SUMS
PathDerivatives path_derivatives(IN(WaveBuffer) waves, IN(Frame) f, vec3 point, real dt);
#else
SG_FN PathDerivatives path_derivatives(IN(WaveBuffer) waves, IN(Frame) f, vec3 point, real dt) {
  return wave_sum_path_derivatives(waves, f, point, dt);
}
#endif

// The cubic Hermite interpolant of one sub-interval.
struct HermitePath {
  vec2 c0;
  vec2 c1;
  vec2 c2;
  vec2 c3;
};

SG_FN HermitePath hermite_path(vec2 g0, vec2 d0, vec2 g1, vec2 d1, real h) {
  HermitePath H;
  H.c0 = g0;
  H.c1 = h * d0;
  H.c2 = 3.0 * (g1 - g0) - (2.0 * h) * d0 - h * d1;
  H.c3 = 2.0 * (g0 - g1) + h * d0 + h * d1;
  return H;
}

SG_FN vec2 hermite_at(IN(HermitePath) H, real s) {
  return H.c0 + s * (H.c1 + s * (H.c2 + s * H.c3));
}
