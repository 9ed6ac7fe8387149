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
struct Wave {
  real A;
  real a;
  real b;
  real theta0;
  real c;
  real k;
  real slope;
};

SG_FN Wave wave_at(IN(WaveBuffer) waves, IN(Frame) f, int i) {
  vec4 t0 = texelFetch(waves, i * f.wave_stride);
  vec4 t1 = texelFetch(waves, i * f.wave_stride + 1);
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

// (cos, sin) of c (end - t_k): the rotation from the display time back to instant k < K.
SG_FN vec2 wave_rotation(IN(WaveBuffer) waves, IN(Frame) f, int i, int k) {
  vec4 t = texelFetch(waves, i * f.wave_stride + 2 + k / 2);
  return (k % 2) == 0 ? vec2(t.x, t.y) : vec2(t.z, t.w);
}

// Wave i's phase at (x, z) and dt, reduced to [-pi, pi] for sin and cos.
SG_FN real wave_phase(IN(Wave) w, real x, real z, real dt) {
  return wrap_angle(w.a * x + w.b * z + w.theta0 + w.c * dt);
}

// The sums over the waves at one point and time: the definitions. The CPU engine replaces
// the two that every method calls by vectorised equivalents (SG_CPU_WAVE_SUMS below;
// kernel/cpu/wave_sums.h), tested equal to these.
SG_FN real wave_sum_height(IN(WaveBuffer) waves, IN(Frame) f, real x, real z, real dt) {
  real h = 0.0;
  for (int i = 0; i < f.wave_count; ++i) {
    Wave w = wave_at(waves, f, i);
    h += w.A * sin(wave_phase(w, x, z, dt));
  }
  return h;
}

// (dh/dx, dh/dz)
SG_FN vec2 wave_sum_gradient(IN(WaveBuffer) waves, IN(Frame) f, real x, real z, real dt) {
  vec2 g = vec2(0.0);
  for (int i = 0; i < f.wave_count; ++i) {
    Wave w = wave_at(waves, f, i);
    real k = w.A * cos(wave_phase(w, x, z, dt));
    g += k * vec2(w.a, w.b);
  }
  return g;
}

#ifdef SG_CPU_WAVE_SUMS
real water_height(IN(WaveBuffer) waves, IN(Frame) f, real x, real z, real dt);
vec2 water_gradient(IN(WaveBuffer) waves, IN(Frame) f, real x, real z, real dt);
#else
SG_FN real water_height(IN(WaveBuffer) waves, IN(Frame) f, real x, real z, real dt) {
  return wave_sum_height(waves, f, x, z, dt);
}
SG_FN vec2 water_gradient(IN(WaveBuffer) waves, IN(Frame) f, real x, real z, real dt) {
  return wave_sum_gradient(waves, f, x, z, dt);
}
#endif

// The unnormalised normal (-dh/dx, 1, -dh/dz) of the scene spec for gradient g.
SG_FN vec3 normal_direction(vec2 g) {
  return vec3(-g.x, 1.0, -g.y);
}
