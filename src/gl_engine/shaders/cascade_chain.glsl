// One level of a cascade's LEAN chain at one path instant, written into the wave buffer in
// the kernel's layout (kernel/cascade_grid.glsl) by the chain's own text
// (kernel/cascade_chain.glsl, which the host's CascadeFields::append writes through too:
// the same texels to float rounding). Level 0 from the FFT's fields
// (gl_engine/cascade_fft_gl.h), each later level the mean of 2 x 2 texels of the one
// before (Olano and Baker 2010, "LEAN Mapping", Sec. 3). At the display time (`full` 1,
// kCascadeChainFull) from field_a = (dh/dx, h, dh/dz, d2h/dxdz) and field_b = (d2h/dx2,
// d2h/dz2, and instant 0's dh/dx, dh/dz: level 0 keeps them, or 0 where not transformed); at the
// path's other instants the slopes alone (kCascadeChainSlopes), (dh/dx, dh/dz) from field_a's xy or
// zw (`slot`). A method that reads level 0 alone (shading/cascade_fields.h, CascadeReads) takes the
// display time's slopes and height (kCascadeChainSlopesHeight) and no later level.
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
uniform int full;    // the chain's mode (kernel/cascade_chain.glsl): kCascadeChainFull,
                     // kCascadeChainSlopes or kCascadeChainSlopesHeight
uniform int slot;    // slopes alone, level 0: 0 field_a.xy, 1 field_a.zw
uniform int source;  // the previous level's first texel in `waves`
uniform int target;  // this level's first texel

// Texel (x, y) of the previous level, of side 2 size.
CascadeChainTexel child(int x, int y) {
  int e = source + 2 * (y * 2 * size + x);
  CascadeChainTexel t;
  t.a = waves[e];
  t.b = waves[e + 1];
  return t;
}

void main() {
  ivec2 id = ivec2(gl_GlobalInvocationID.xy);
  if (id.x >= size || id.y >= size) return;
  int i = id.y * size + id.x;
  CascadeChainTexel t;
  if (level == 0) {
    vec4 f = field_a[i];
    vec2 slope = full != kCascadeChainSlopes ? f.xz : (slot == 0 ? f.xy : f.zw);
    vec4 g = full == kCascadeChainFull ? field_b[i] : vec4(0.0);
    t = cascade_chain_level0(slope, f.y, vec3(g.x, f.w, g.y), vec2(g.z, g.w), full);
  } else {
    int x = 2 * id.x, y = 2 * id.y;
    t = cascade_chain_parent(child(x, y), child(x + 1, y), child(x, y + 1), child(x + 1, y + 1),
                             level - 1, full);
  }
  waves[target + 2 * i] = t.a;
  waves[target + 2 * i + 1] = t.b;
}
