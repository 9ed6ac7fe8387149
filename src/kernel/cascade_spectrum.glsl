// A lattice cascade's spectra at one lattice point, what its inverse FFT takes (the
// evaluation and its derivation: scene/cascade_fft.h; the cascade: scene/lattice.h). Not
// part of the shading kernel (kernel.glsl does not list it): the CPU's CascadeFft and the GL
// engine's cascade FFT (gl_engine/shaders/cascade_spectrum_main.glsl) include it, so the
// two engines build the same spectra from one text.

// Z = A e^{i theta} of a lattice point whose phase at the frame's time is theta =
// omega t + phi (Tessendorf 2001, "Simulating Ocean Water", Eq. 43, in the scene's sine
// form); complex numbers are vec2 (re, im).
SG_FN vec2 cascade_z(real amplitude, real theta) {
  return amplitude * vec2(cos(theta), sin(theta));
}

// The spectra of (dh/dx + i h) and of dh/dz at lattice point k, from Z there and Z at the
// mirrored index -k (modulo N) with its wave vector k_m: with E(Y)_k = (Y_k + conj Y_-k)/2
// and O(Y)_k = (Y_k - conj Y_-k)/2i, the result is (E(k_x Z) + i O(Z), E(k_z Z)) as
// (re, im, re, im). At the Nyquist index, its own mirror, k_m is its own k.
SG_FN vec4 cascade_spectra(vec2 z, vec2 z_mirror, vec2 k, vec2 k_mirror) {
  vec2 zc = vec2(z_mirror.x, -z_mirror.y);
  vec2 even_x = 0.5 * (k.x * z + k_mirror.x * zc);
  vec2 d = z - zc;
  // O(Z) = -i d / 2 = (d.y / 2, -d.x / 2); i O(Z) = (d.x / 2, d.y / 2).
  vec2 a = even_x + 0.5 * d;
  vec2 b = 0.5 * (k.y * z + k_mirror.y * zc);
  return vec4(a.x, a.y, b.x, b.y);
}

// The curvatures' spectra at lattice point k, for a second pass of transforms beside
// cascade_spectra's: h's second derivatives are Im IDFT[-k_i k_j Z], so with
// O(w Z)_k = (w(k) Z_k - w(k_m) conj Z_-k) / 2i (w(k_m) the mirror's own factor: at a
// Nyquist row k_m is not -k) the result is
//   xy: i O(-k_x k_z Z), to add to cascade_spectra's second spectrum (dh/dz + i d2h/dxdz);
//   zw: O(-k_x^2 Z) + i O(-k_z^2 Z) (d2h/dx2 + i d2h/dz2).
SG_FN vec4 cascade_curvature_spectra(vec2 z, vec2 z_mirror, vec2 k, vec2 k_mirror) {
  vec2 zc = vec2(z_mirror.x, -z_mirror.y);
  // (w z - w_m zc) for each factor; O = that / 2i = (d.y / 2, -d.x / 2); i O = (d.x / 2, d.y / 2).
  vec2 dxz = -k.x * k.y * z + k_mirror.x * k_mirror.y * zc;
  vec2 dxx = -k.x * k.x * z + k_mirror.x * k_mirror.x * zc;
  vec2 dzz = -k.y * k.y * z + k_mirror.y * k_mirror.y * zc;
  vec2 b = 0.5 * dxz;
  vec2 c = vec2(0.5 * dxx.y, -0.5 * dxx.x) + 0.5 * dzz;
  return vec4(b.x, b.y, c.x, c.y);
}

// The slopes' spectrum alone, E(k_x Z) + i E(k_z Z), whose inverse FFT is dh/dx + i dh/dz:
// one transform where a path instant needs the slope only.
SG_FN vec2 cascade_slope_spectrum(vec2 z, vec2 z_mirror, vec2 k, vec2 k_mirror) {
  vec2 zc = vec2(z_mirror.x, -z_mirror.y);
  vec2 ex = 0.5 * (k.x * z + k_mirror.x * zc);
  vec2 ez = 0.5 * (k.y * z + k_mirror.y * zc);
  return vec2(ex.x - ez.y, ex.y + ez.x);
}
