// One pass of a cascade's inverse 2-D FFT (gl_engine/cascade_fft_gl.h): a workgroup of
// N / 4 invocations transforms one row of N elements in shared memory, Stockham autosort (no
// bit reversal: Stockham 1966; the radix-R form of Bainville's OpenCL FFT notes), radix 4
// while four sub-transforms fit and one radix-2 pass where log2 N is odd, and writes the row
// as a column of the output. Two passes are the 2-D transform, in the input's orientation.
// Radix 4 halves the passes, and with them the workgroup's barriers and shared-memory round
// trips, of the radix-2 form (docs/benchmarks.md, "The GL transforms in radix 4"). Each
// element is a vec4 of two complex numbers, transformed together. The twiddles e^{i pi k / p}
// are the host's, in double rounded to float, at index p + k (p = 1, 2, ..., N / 2).
layout(local_size_x = SG_FFT_QUARTER) in;

layout(std430, binding = 0) readonly buffer Source {
  vec4 source[];
};
layout(std430, binding = 1) writeonly buffer Target {
  vec4 target[];
};
layout(std430, binding = 2) readonly buffer Twiddles {
  vec2 twiddles[];
};

shared vec4 line[2][4 * SG_FFT_QUARTER];

vec2 cmul(vec2 a, vec2 b) {
  return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x);
}
vec4 cmul2(vec4 u, vec2 w) {
  return vec4(cmul(u.xy, w), cmul(u.zw, w));
}
// i u, for both complex numbers.
vec4 times_i(vec4 u) {
  return vec4(-u.y, u.x, -u.w, u.z);
}

void main() {
  const uint q = uint(SG_FFT_QUARTER), n = 4u * q;
  uint row = gl_WorkGroupID.x, i = gl_LocalInvocationID.x;
  for (uint r = 0u; r < 4u; ++r)
    line[0][i + r * q] = source[row * n + i + r * q];
  barrier();
  uint s = 0u, p = 1u;
  // Radix 4: sub-transforms of length p into 4 p. Element r of invocation i is twiddled by
  // e^{i pi r k / (2 p)} (k = i mod p; at index 2 p + k for r = 1, p + k for r = 2), then
  // the inverse 4-point DFT, sum_r a_r i^{r m}, goes to j + m p.
  for (; 4u * p <= n; p <<= 2u) {
    uint k = i & (p - 1u);
    vec2 w1 = twiddles[2u * p + k], w2 = twiddles[p + k];
    vec4 a0 = line[s][i];
    vec4 a1 = cmul2(line[s][i + q], w1);
    vec4 a2 = cmul2(line[s][i + 2u * q], w2);
    vec4 a3 = cmul2(line[s][i + 3u * q], cmul(w1, w2));
    vec4 e0 = a0 + a2, e1 = a0 - a2, o0 = a1 + a3, o1 = times_i(a1 - a3);
    uint j = ((i - k) << 2u) + k;
    line[1u - s][j] = e0 + o0;
    line[1u - s][j + p] = e1 + o1;
    line[1u - s][j + 2u * p] = e0 - o0;
    line[1u - s][j + 3u * p] = e1 - o1;
    s = 1u - s;
    barrier();
  }
  if (p < n) {
    // One radix-2 pass (p = N / 2): invocation i takes elements i and i + N / 4, each with
    // its partner N / 2 on; k is the element itself.
    for (uint r = 0u; r < 2u; ++r) {
      uint e = i + r * q;
      vec4 u0 = line[s][e], u1 = cmul2(line[s][e + p], twiddles[p + e]);
      line[1u - s][e] = u0 + u1;
      line[1u - s][e + p] = u0 - u1;
    }
    s = 1u - s;
    barrier();
  }
  for (uint r = 0u; r < 4u; ++r)
    target[(i + r * q) * n + row] = line[s][i + r * q];
}
