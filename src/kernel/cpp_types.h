// The per-precision half of the C++ prelude (kernel/cpp_prelude.h): GLSL's type names
// over glm at the precision SG_KERNEL_REAL, the built-in functions the kernel may call,
// and texelFetch on the table views. Included inside a namespace, once per precision, so
// it has no include guard.
//
// #define SG_KERNEL_REAL double   (or float)
// namespace sg::kd {
// #include "kernel/cpp_types.h"
// #include "kernel/kernel.glsl"
// }

using real = SG_KERNEL_REAL;
using vec2 = glm::vec<2, real>;
using vec3 = glm::vec<3, real>;
using vec4 = glm::vec<4, real>;
using mat2 = glm::mat<2, 2, real>;
using mat3 = glm::mat<3, 3, real>;
using mat3x2 = glm::mat<3, 2, real>;  // 3 columns of 2 rows, as in GLSL
using mat2x3 = glm::mat<2, 3, real>;  // 2 columns of 3 rows
using ivec2 = glm::ivec2;
using ivec3 = glm::ivec3;
using uint = unsigned int;
using uvec2 = glm::uvec2;

// The kernel's work counters (sg::KernelCounters, kernel/cpp_prelude.h): SG_COUNT(what, n)
// adds n to counter `what` in the counting build (SG_KERNEL_COUNTING:
// kernel/kernel_counting.h), nothing in the others, nothing in GLSL.
#undef SG_COUNT
#ifdef SG_KERNEL_COUNTING
#define SG_COUNT(what, n) (::sg::kernel_counters().what += uint64_t(n))
#else
#define SG_COUNT(what, n) ((void)0)
#endif

using glm::abs;
using glm::ceil;
using glm::clamp;
using glm::cross;
using glm::determinant;
using glm::dot;
using glm::floor;
using glm::fma;
using glm::fract;
using glm::inverse;
using glm::inversesqrt;
using glm::length;
using glm::max;
using glm::min;
using glm::mix;
using glm::mod;
using glm::normalize;
using glm::outerProduct;
using glm::sign;
using glm::sqrt;
#ifdef SG_KERNEL_COUNTING
// The transcendental built-ins, each call counted per component (exact matches beat glm's
// templates for the kernel's real and vector arguments).
#define SG_COUNTED_1(fn)          \
  inline real fn(real x) {        \
    SG_COUNT(transcendentals, 1); \
    return glm::fn(x);            \
  }                               \
  inline vec2 fn(const vec2& x) { \
    SG_COUNT(transcendentals, 2); \
    return glm::fn(x);            \
  }                               \
  inline vec3 fn(const vec3& x) { \
    SG_COUNT(transcendentals, 3); \
    return glm::fn(x);            \
  }                               \
  inline vec4 fn(const vec4& x) { \
    SG_COUNT(transcendentals, 4); \
    return glm::fn(x);            \
  }
SG_COUNTED_1(sin)
SG_COUNTED_1(cos)
SG_COUNTED_1(tan)
SG_COUNTED_1(asin)
SG_COUNTED_1(acos)
SG_COUNTED_1(atan)
SG_COUNTED_1(exp)
SG_COUNTED_1(log)
SG_COUNTED_1(log2)
#undef SG_COUNTED_1
inline real atan(real y, real x) {
  SG_COUNT(transcendentals, 1);
  return glm::atan(y, x);
}
inline real pow(real x, real y) {
  SG_COUNT(transcendentals, 1);
  return glm::pow(x, y);
}
#else
using glm::acos;
using glm::asin;
using glm::atan;
using glm::cos;
using glm::exp;
using glm::log;
using glm::log2;
using glm::pow;
using glm::sin;
using glm::tan;
#endif
using glm::transpose;
using glm::umulExtended;
using sg::kernel_tables::ImagePlanes;
using sg::kernel_tables::MapTexels;
using sg::kernel_tables::R32Texture2D;
using sg::kernel_tables::R32Texture3D;
using sg::kernel_tables::TableLine;

// GLSL's isnan / isinf on scalars.
inline bool isnan(real x) {
  return std::isnan(x);
}
inline bool isinf(real x) {
  return std::isinf(x);
}
// GLSL's round-half-away? No: GLSL's round() may go either way at .5; the kernel uses
// floor(x + 0.5) where it needs a rule.

// The lane-generic subset's choice and branch test (kernel/wave_terms.glsl): on one real,
// the ternary and the condition itself (kernel/cpu/lane_types.h: lane by lane).
inline real select(bool c, real a, real b) {
  return c ? a : b;
}
inline bool any_lane(bool c) {
  return c;
}

// texelFetch of GLSL for R32F textures: the value in .x.
inline vec4 texelFetch(const R32Texture2D& t, const ivec2& p, int) {
  SG_COUNT(table_fetches, 1);
  return vec4(real(t.data[size_t(p.y) * size_t(t.width) + size_t(p.x)]), 0, 0, 1);
}
inline vec4 texelFetch(const R32Texture3D& t, const ivec3& p, int) {
  SG_COUNT(table_fetches, 1);
  return vec4(
      real(t.data[(size_t(p.z) * size_t(t.height) + size_t(p.y)) * size_t(t.width) + size_t(p.x)]),
      0, 0, 1);
}

// Value i of a 1-D table (GLSL: texelFetch of an R32F buffer).
inline real line_value(const TableLine& t, int i) {
  SG_COUNT(table_fetches, 1);
  return real(t.data[i]);
}
// Float i of a map (GLSL: texelFetch of an R32F buffer).
inline real map_value(const MapTexels& t, int i) {
  SG_COUNT(table_fetches, 1);
  return real(t.data[i]);
}
// Channel c of texel (x, y) of an image (GLSL: texelFetch of an RGBA32F sampler2D).
inline real plane_value(const ImagePlanes& t, int x, int y, int c) {
  SG_COUNT(table_fetches, 1);
  return real(t.data[(size_t(y) * size_t(t.width) + size_t(x)) * size_t(t.channels) + size_t(c)]);
}

// The precision's constants (the GLSL prelude defines the float ones).
const real kRealEpsilon = std::numeric_limits<real>::epsilon();
const real kRealMax = std::numeric_limits<real>::max();
const bool kDoublePrecision = sizeof(real) == sizeof(double);

// The per-wave data of a frame (kernel/waves.glsl), vec4 texels: GLSL's samplerBuffer
// (RGBA32F) over an array the host fills in begin_frame. In C++ it also carries the same
// waves as arrays for the CPU engine's vectorised sums (none: the kernel's own loops).
struct WaveBuffer {
  const vec4* data = nullptr;
  int size = 0;  // texels
  sg::wave_simd::Arrays<real> arrays;
};
// Texel i of the wave buffer (GLSL 4.50: texelFetch of the samplerBuffer; GLSL ES: of a
// 2D texture, row by row).
inline vec4 wave_texel(const WaveBuffer& b, int i) {
  SG_COUNT(buffer_fetches, 1);
  return b.data[i];
}
