// The reflection path of a pixel (Podee et al. 2021, Sec. 3.3, Fig. 1 and 4): the water
// point seen through the pixel centre, and the reflection of the view about the normal of
// the resolved waves at K + 1 instants of the shutter, t_k = start + k (end - start) / K
// (K sub-arcs, "dividing the frame time into subintervals", Sec. 3.5; K = 1 is the paper's
// path from the previous frame to the current one). The point is the one at the display
// time; on displaced water its horizontal position is kept for the whole interval (the
// paper samples "a single point on the water surface corresponding to the pixel centre").
//
// The gradients at the instants come from the phases at the display time by angle
// subtraction, cos(theta - c dt) = cos(theta) cos(c dt) + sin(theta) sin(c dt), with the
// rotations of the wave buffer (waves.glsl).
//
// The temporal method (Sec. 3.3) on a path: for each sub-arc, the fractions of time in the
// light disk and below the horizon (arc.glsl, exact for a constant-speed great-circle
// arc), combined into weights with the sub-arc's mean Fresnel factor (the sky at the
// height of the sub-arc's middle), averaged over the sub-arcs.

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

// Wave i's term, of resolved amplitude A and phase theta (sine s, cosine c) at the display
// time, in the gradients of every instant.
SG_FN void path_gradients_add(INOUT(PathGradients) p, IN(WaveBuffer) waves, IN(Frame) f, int i,
                              IN(Wave) w, real A, real s, real c) {
  vec2 k = vec2(w.a, w.b);
  p.g[f.segments] += (A * c) * k;
  for (int q = 0; q < f.segments; ++q) {
    vec2 rot = wave_rotation(waves, f, i, q);
    p.g[q] += (A * (c * rot.x + s * rot.y)) * k;
  }
}

// Every wave at full amplitude: the path of staa-temporal (the definition; the CPU engine's
// vectorised equivalent under SG_CPU_WAVE_SUMS).
SG_FN PathGradients wave_sum_path(IN(WaveBuffer) waves, IN(Frame) f, vec3 point) {
  PathGradients p = path_gradients_zero(f.segments);
  for (int i = 0; i < f.wave_count; ++i) {
    Wave w = wave_at(waves, f, i);
    real theta = wave_phase(w, point.x, point.z, 0.0);
    path_gradients_add(p, waves, f, i, w, w.A, sin(theta), cos(theta));
  }
  return p;
}

#ifdef SG_CPU_WAVE_SUMS
PathGradients path_gradients(IN(WaveBuffer) waves, IN(Frame) f, vec3 point);
#else
SG_FN PathGradients path_gradients(IN(WaveBuffer) waves, IN(Frame) f, vec3 point) {
  return wave_sum_path(waves, f, point);
}
#endif

struct PathShares {
  vec4 weights;   // the temporal method's weights (sub-arcs combined one by one)
  real in_light;  // fractions of the interval in the light and below the horizon
  real below;
  real fresnel;  // the mean Fresnel factor
};

SG_FN PathShares temporal_shares(IN(Frame) f, IN(PathGradients) p, vec3 view) {
  PathShares s;
  s.weights = vec4(0.0);
  s.in_light = 0.0;
  s.below = 0.0;
  s.fresnel = 0.0;
  int K = f.segments;
  real inv_k = 1.0 / real(K);
  vec3 n0 = normalize(normal_direction(p.g[0]));
  vec3 r0 = reflect_view(n0, view);
  real F0 = fresnel_factor(f.fresnel, dot(n0, view));
  for (int k = 0; k < K; ++k) {
    vec3 n1 = normalize(normal_direction(p.g[k + 1]));
    vec3 r1 = reflect_view(n1, view);
    real F1 = fresnel_factor(f.fresnel, dot(n1, view));
    real F = 0.5 * (F0 + F1);
    ArcFractions a = arc_fractions(r0, r1, f.light);
    vec3 mid = r0 + r1;
    real sky_y = mid.y / max(length(mid), 1e-30);
    s.in_light += a.in_light * inv_k;
    s.below += a.below * inv_k;
    s.fresnel += F * inv_k;
    s.weights += combine_weights(f, F, a.in_light, a.below, sky_y) * inv_k;
    r0 = r1;
    F0 = F1;
  }
  return s;
}
