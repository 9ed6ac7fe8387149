// A cascade's spectra at the frame's time (gl_engine/cascade_fft_gl.h): one invocation per
// lattice point builds what the inverse FFT of (dh/dx + i h, dh/dz) takes, by the same
// text as the CPU (kernel/cascade_spectrum.glsl). The lattice holds (A, phi + omega t0
// modulo 2 pi, omega, 0) per point, phases set in double on the host at the time origin t0,
// so that the float phase here, omega (t - t0) + that, stays accurate over the frames.
layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = 0) readonly buffer Lattice {
  vec4 lattice[];
};
layout(std430, binding = 1) writeonly buffer Spectra {
  vec4 spectra[];
};

uniform int n;     // the lattice N
uniform float dk;  // 2 pi / L
uniform float dt;  // t - t0, s

int lattice_frequency(int i) {
  return i < n / 2 ? i : i - n;
}

void main() {
  ivec2 id = ivec2(gl_GlobalInvocationID.xy);
  if (id.x >= n || id.y >= n) return;
  int im = (n - id.x) % n, jm = (n - id.y) % n;
  vec4 p = lattice[id.y * n + id.x];
  vec4 q = lattice[jm * n + im];
  vec2 z = cascade_z(p.x, p.z * dt + p.y);
  vec2 zm = cascade_z(q.x, q.z * dt + q.y);
  vec2 k = dk * vec2(float(lattice_frequency(id.x)), float(lattice_frequency(id.y)));
  vec2 km = dk * vec2(float(lattice_frequency(im)), float(lattice_frequency(jm)));
  spectra[id.y * n + id.x] = cascade_spectra(z, zm, k, km);
}
