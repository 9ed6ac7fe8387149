// The GLSL ES 3.00 side of the kernel's two-language pattern (kernel/cpp_prelude.h,
// kernel/glsl_prelude.glsl): the same names mapped to the most restricted target the
// kernel runs on, WebGL 2 (`sunglint web`, src/web/). A fragment shader is
// `#version 300 es`, this prelude, the interface, the kernel's files in order and a main()
// per method (src/web/shaders/). What ES 3.00 lacks, and how this prelude stands in:
//  - buffer textures: a buffer (the wave buffer, the path tables' fine grids) is a 2D
//    texture 1024 texels wide filled row by row, texel i at (i mod 1024, i / 1024) (a
//    constant power of two: shifts and masks, where a division by the texture's width costs
//    a scalar division per pixel on a CPU rasteriser such as SwiftShader);
//  - umulExtended (ES 3.10): the 64-bit product of two 32-bit words from four 16-bit
//    products, exact (the sampling streams stay bit for bit the host's, kernel/rng.glsl);
//  - brace initialisers: SG_ARRAY(T, N, (items)) is the array constructor T[N](items);
//  - a default float precision in fragment shaders: everything is highp (32-bit float and
//    int; WebGL 2 guarantees highp in fragment shaders).
precision highp float;
precision highp int;
precision highp sampler2D;
precision highp sampler2DArray;

#define real float
// The page renders fixed cameras only (camera.glsl: camera_at is the frame's camera).
#define SG_FIXED_CAMERA
#define IN(T) in T
#define OUT(T) out T
#define INOUT(T) inout T
#define SG_FN
// The kernel's work counters count in its C++ counting build only (kernel/cpp_types.h).
#define SG_COUNT(what, n)
// The page's programs have no loop budget (glsl_prelude.glsl).
#define loop_budget_spent(work) false
#ifndef SG_MAX_SEGMENTS
#define SG_MAX_SEGMENTS 8
#endif
#define SG_ARRAY(T, N, ITEMS) T[N] ITEMS
#define WaveBuffer sampler2D
#define R32Texture2D sampler2D
#define R32Texture3D sampler2DArray
#define TableLine sampler2D
#define MapTexels sampler2D
#define ImagePlanes sampler2D
#define plane_value(img, x, y, c) texelFetch(img, ivec2(x, y), 0)[c]

const real kRealEpsilon = 1.1920928955078125e-07;
const real kRealMax = 3.4028234663852886e+38;
const bool kDoublePrecision = false;
// The lane-generic subset's choice and branch test (kernel/wave_terms.glsl): on one real,
// the ternary and the condition itself.
real select(bool c, real a, real b) {
  return c ? a : b;
}
bool any_lane(bool c) {
  return c;
}

// Texel i >= 0 of a buffer held in a 2D texture 1024 texels wide, row by row.
vec4 sg_buffer_texel(sampler2D t, int i) {
  return texelFetch(t, ivec2(i & 1023, i >> 10), 0);
}
#define wave_texel(waves, i) sg_buffer_texel(waves, i)
#define line_value(line, i) sg_buffer_texel(line, i).x
#define map_value(map, i) sg_buffer_texel(map, i).x

// umulExtended(a, b, hi, lo): a * b = hi 2^32 + lo, by 16-bit halves (each partial product
// and the middle sum fit in 32 bits).
void sg_umul_extended(uint a, uint b, out uint hi, out uint lo) {
  uint a0 = a & 0xFFFFu;
  uint a1 = a >> 16u;
  uint b0 = b & 0xFFFFu;
  uint b1 = b >> 16u;
  uint p00 = a0 * b0;
  uint p01 = a0 * b1;
  uint p10 = a1 * b0;
  uint mid = (p00 >> 16u) + (p01 & 0xFFFFu) + (p10 & 0xFFFFu);
  lo = (mid << 16u) | (p00 & 0xFFFFu);
  hi = a1 * b1 + (p01 >> 16u) + (p10 >> 16u) + (mid >> 16u);
}
#define umulExtended sg_umul_extended
