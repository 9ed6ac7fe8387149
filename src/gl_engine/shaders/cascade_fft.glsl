// One pass of a cascade's inverse 2-D FFT (gl_engine/cascade_fft_gl.h): a workgroup of
// N / 2 invocations transforms one row of N elements in shared memory, radix-2 Stockham
// autosort (no bit reversal: Stockham 1966; the form of Bainville's OpenCL FFT notes), and
// writes it as a column of the output. Two passes are the 2-D transform, in the input's
// orientation. Each element is a vec4 of two complex numbers, transformed together. The
// twiddles e^{i pi k / p} are the host's, in double rounded to float, at index p + k.
layout(local_size_x = SG_FFT_HALF) in;

layout(std430, binding = 0) readonly buffer Source {
  vec4 source[];
};
layout(std430, binding = 1) writeonly buffer Target {
  vec4 target[];
};
layout(std430, binding = 2) readonly buffer Twiddles {
  vec2 twiddles[];
};

shared vec4 line[2][2 * SG_FFT_HALF];

vec2 cmul(vec2 a, vec2 b) {
  return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x);
}

void main() {
  const uint half_n = uint(SG_FFT_HALF), n = 2u * half_n;
  uint row = gl_WorkGroupID.x, i = gl_LocalInvocationID.x;
  line[0][i] = source[row * n + i];
  line[0][i + half_n] = source[row * n + i + half_n];
  barrier();
  uint s = 0u;
  for (uint p = 1u; p < n; p <<= 1u) {
    uint k = i & (p - 1u);
    vec2 w = twiddles[p + k];
    vec4 u0 = line[s][i], u1 = line[s][i + half_n];
    u1 = vec4(cmul(u1.xy, w), cmul(u1.zw, w));
    uint j = ((i - k) << 1u) + k;
    line[1u - s][j] = u0 + u1;
    line[1u - s][j + p] = u0 - u1;
    s = 1u - s;
    barrier();
  }
  target[i * n + row] = line[s][i];
  target[(i + half_n) * n + row] = line[s][i + half_n];
}
