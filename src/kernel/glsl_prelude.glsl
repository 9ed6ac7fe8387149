// The GLSL side of the kernel's two-language pattern (see kernel/cpp_prelude.h): the
// names the kernel's sources use, mapped to GLSL 4.50. The GL engine's shaders are
// `#version 450`, this prelude, the kernel's files in order (kernel/kernel.glsl lists
// them) and a main() per method (src/gl_engine/).
#define real float
#define IN(T) in T
#define OUT(T) out T
#define INOUT(T) inout T
#define SG_FN
// The kernel's work counters count in its C++ counting build only (kernel/cpp_types.h).
#define SG_COUNT(what, n)
// Whether a pass of samples has spent its budget of estimated loop iterations, `work`
// (kernel/sampling.glsl): in a program compiled with SG_LOOP_GUARD (the sampling methods',
// gl_engine/shaders/main.glsl), so that an invocation ends its pass before llvmpipe's limit
// of 65535 loop iterations and the next pass goes on from there; never elsewhere.
#ifdef SG_LOOP_GUARD
#define loop_budget_spent(work) ((work) >= real(SG_LOOP_GUARD))
#else
#define loop_budget_spent(work) false
#endif
#ifndef SG_MAX_SEGMENTS
#define SG_MAX_SEGMENTS 8
#endif
#define SG_ARRAY(T, N, ITEMS) T[N] ITEMS
#define WaveBuffer samplerBuffer
#define wave_texel(waves, i) texelFetch(waves, i)
#define R32Texture2D sampler2D
#define R32Texture3D sampler2DArray
#define TableLine samplerBuffer
#define line_value(line, i) texelFetch(line, i).x
#define MapTexels samplerBuffer
#define map_value(map, i) texelFetch(map, i).x
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
