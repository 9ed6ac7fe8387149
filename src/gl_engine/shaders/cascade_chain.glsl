// One level of a cascade's LEAN chain at one path instant, written into the wave buffer in
// the kernel's layout (kernel/cascade_grid.glsl; the host's twin: shading/cascade_fields.h,
// CascadeFields::append, whose texels these are to float rounding). Level 0 from the
// FFT's fields (gl_engine/cascade_fft_gl.h), each later level the mean of 2 x 2 texels of
// the one before (Olano and Baker 2010, "LEAN Mapping", Sec. 3). A texel is two vec4s:
//   a = (E[s_x], E[s_z], E[h_xx], E[h_zz]), b = (E[h_xz], E[s_x^2], E[s_x s_z], E[s_z^2]);
// at the display time (`full`) from field_a = (dh/dx, h, dh/dz, d2h/dxdz) and field_b =
// (d2h/dx2, d2h/dz2, ., .), level 0's b.y holding the height h in the place of s_x^2 (a
// grid point has no spread: level 1 takes its slope's square instead); at the path's other
// instants the slopes alone, (dh/dx, dh/dz) from field_a's xy or zw (`slot`), the rest 0.
// A method that reads level 0 alone (shading/cascade_fields.h, CascadeReads) takes the
// display time's level 0 as (s_x, s_z, 0, 0), (0, h, 0, 0) (`full` 2) and no later level.
layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = 0) readonly buffer FieldA {
  vec4 field_a[];
};
layout(std430, binding = 1) readonly buffer FieldB {
  vec4 field_b[];
};
layout(std430, binding = 2) buffer Waves {
  vec4 waves[];
};

uniform int size;    // this level's side
uniform int level;   // 0: from the fields
uniform int full;    // 1: the display time's chain; 0: slopes alone; 2: the display time's
                     // slopes and height alone
uniform int slot;    // slopes alone, level 0: 0 field_a.xy, 1 field_a.zw
uniform int source;  // the previous level's first texel in `waves`
uniform int target;  // this level's first texel

void main() {
  ivec2 id = ivec2(gl_GlobalInvocationID.xy);
  if (id.x >= size || id.y >= size) return;
  int i = id.y * size + id.x;
  vec4 a = vec4(0.0), b = vec4(0.0);
  if (level == 0) {
    vec4 f = field_a[i];
    if (full == 1) {
      vec4 g = field_b[i];
      a = vec4(f.x, f.z, g.x, g.y);
      b = vec4(f.w, f.y, f.x * f.z, f.z * f.z);
    } else if (full == 2) {
      a.xy = f.xz;
      b.y = f.y;
    } else {
      a.xy = slot == 0 ? f.xy : f.zw;
    }
  } else {
    int fine = 2 * size;
    for (int dy = 0; dy < 2; ++dy) {
      for (int dx = 0; dx < 2; ++dx) {
        int e = source + 2 * ((2 * id.y + dy) * fine + 2 * id.x + dx);
        vec4 ta = waves[e], tb = waves[e + 1];
        if (level == 1) tb.y = ta.x * ta.x;
        a += ta;
        b += tb;
      }
    }
    a *= 0.25;
    b = full != 0 ? 0.25 * b : vec4(0.0);
  }
  waves[target + 2 * i] = a;
  waves[target + 2 * i + 1] = b;
}
