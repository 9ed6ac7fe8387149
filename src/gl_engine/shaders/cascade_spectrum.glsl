// A cascade's spectra at one or two times (gl_engine/cascade_fft_gl.h): one invocation per
// lattice point builds what one inverse FFT of two complex fields takes, by the same text
// as the CPU (kernel/cascade_spectrum.glsl). The lattice holds (A, phi + omega t0 modulo
// 2 pi, omega, 0) per point, phases set in double on the host at the time origin t0, so
// that the float phase here, omega (t - t0) + that, stays accurate over the frames.
// `mode` (uniform across the dispatch) picks the pair, whose transform is then
//   0: (dh/dx + i h, dh/dz + i d2h/dxdz) at t0 + dt0;
//   1: (d2h/dx2 + i d2h/dz2 at t0 + dt0, dh/dx + i dh/dz at t0 + dt1);
//   2: (dh/dx + i dh/dz at t0 + dt0, the same at t0 + dt1);
// in modes 1 and 2 the second field is zero where `second` is 0.
layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = 0) readonly buffer Lattice {
  vec4 lattice[];
};
layout(std430, binding = 1) writeonly buffer Spectra {
  vec4 spectra[];
};

uniform int n;       // the lattice N
uniform float dk;    // 2 pi / L
uniform float dt0;   // the first field's t - t0, s
uniform float dt1;   // the second's
uniform int mode;    // see above
uniform int second;  // modes 1, 2: 1 where the second field is wanted

int lattice_frequency(int i) {
  return i < n / 2 ? i : i - n;
}

void main() {
  ivec2 id = ivec2(gl_GlobalInvocationID.xy);
  if (id.x >= n || id.y >= n) return;
  int im = (n - id.x) % n, jm = (n - id.y) % n;
  vec4 p = lattice[id.y * n + id.x];
  vec4 q = lattice[jm * n + im];
  vec2 z = cascade_z(p.x, p.z * dt0 + p.y);
  vec2 zm = cascade_z(q.x, q.z * dt0 + q.y);
  vec2 k = dk * vec2(float(lattice_frequency(id.x)), float(lattice_frequency(id.y)));
  vec2 km = dk * vec2(float(lattice_frequency(im)), float(lattice_frequency(jm)));
  vec4 r;
  if (mode == 0) {
    vec4 s = cascade_spectra(z, zm, k, km);
    r = vec4(s.xy, s.zw + cascade_curvature_spectra(z, zm, k, km).xy);
  } else {
    vec2 first = mode == 1 ? cascade_curvature_spectra(z, zm, k, km).zw
                           : cascade_slope_spectrum(z, zm, k, km);
    vec2 other = vec2(0.0);
    if (second != 0) {
      other = cascade_slope_spectrum(cascade_z(p.x, p.z * dt1 + p.y),
                                     cascade_z(q.x, q.z * dt1 + q.y), k, km);
    }
    r = vec4(first, other);
  }
  spectra[id.y * n + id.x] = r;
}
