// One level of a cascade's moment chain (gl_engine/cascade_fft_gl.h; the CPU's is
// scene/cascade_fft.h's moment_chain): level 0 from the FFT's field (dh/dx, h, dh/dz, .)
// per grid point, each later level the mean of 2 x 2 texels of the one before. A texel is
// two vec4s: (E[s_x], E[s_z], E[s_x^2], E[s_x s_z]) and (E[s_z^2], E[h], 0, 0).
layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = 0) readonly buffer Field {
  vec4 field[];
};
layout(std430, binding = 1) buffer Moments {
  vec4 moments[];
};

uniform int size;         // this level's side
uniform int from_field;   // 1: level 0, read the field
uniform int source_base;  // the previous level's first vec4 in `moments`
uniform int target_base;  // this level's first vec4

void main() {
  ivec2 id = ivec2(gl_GlobalInvocationID.xy);
  if (id.x >= size || id.y >= size) return;
  vec4 a, b;
  if (from_field != 0) {
    vec4 f = field[id.y * size + id.x];
    a = vec4(f.x, f.z, f.x * f.x, f.x * f.z);
    b = vec4(f.z * f.z, f.y, 0.0, 0.0);
  } else {
    int fine = 2 * size;
    a = vec4(0.0);
    b = vec4(0.0);
    for (int dy = 0; dy < 2; ++dy) {
      for (int dx = 0; dx < 2; ++dx) {
        int e = source_base + 2 * ((2 * id.y + dy) * fine + 2 * id.x + dx);
        a += moments[e];
        b += moments[e + 1];
      }
    }
    a *= 0.25;
    b *= 0.25;
  }
  int t = target_base + 2 * (id.y * size + id.x);
  moments[t] = a;
  moments[t + 1] = b;
}
