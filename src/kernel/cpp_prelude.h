// The C++ side of the shading kernel's two-language pattern (Bruneton and Neyret's
// precomputed atmospheric scattering, `functions.glsl` with its C++ `definitions.h`): the
// kernel's functions are written once, in the subset of GLSL 4.50 that is also C++20,
// in the .glsl files beside this one. This header makes those files compile as C++ over
// glm, in double or in float precision, for the CPU engine and the tests; glsl_prelude.glsl
// makes them a compute shader for the GL engine.
//
// What the subset allows (tests/kernel/check_subset.py holds the sources to it):
//  - types: real (double or float here, float in GLSL), int, uint, bool, vec2/3/4, mat2/3,
//    ivec2/3, uvec2, structs without member initialisers, fixed-size arrays;
//  - parameters as IN(T), OUT(T), INOUT(T); every function marked SG_FN;
//  - GLSL's built-ins that glm provides under the same name (dot, cross, length, normalize,
//    clamp, mix, min, max, abs, sign, floor, fract, mod, sqrt, inversesqrt, exp, log, pow,
//    sin, cos, tan, asin, acos, atan, transpose, inverse, determinant, outerProduct, fma,
//    umulExtended) and texelFetch on the table types below;
//  - float literals written with a decimal point (2.0, never 2 or 2.0f); a vector is never
//    mixed with an int. The float build compiles with -fsingle-precision-constant, so a
//    literal is a float there, as in GLSL;
//  - the wave buffer read through wave_texel(waves, i) only; constant arrays initialised as
//    SG_ARRAY(T, N, (v0, v1, ...)) (GLSL ES has no brace initialisers).
// Not allowed: pointers, references, std::, templates, exceptions, allocation, static or
// thread_local state, recursion, swizzles beyond .x/.y/.z/.w, struct constructors, and (for
// GLSL ES 3.00 and WebGL 2, kernel/glsl_es_prelude.glsl) the ternary operator on structs,
// names beginning with webgl_ or _webgl, and any name with two consecutive underscores.
//
// Include this file, then, inside a namespace of your own, kernel/cpp_types.h with
// SG_KERNEL_REAL defined as double or float (kernel/kernel_double.h does both).
#pragma once

#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <glm/gtc/type_precision.hpp>
#include <limits>

// Parameters: GLSL's in / out / inout.
#define IN(T) const T&
#define OUT(T) T&
#define INOUT(T) T&
// The cap on a reflection path's sub-arcs (kernel/interface.glsl).
#define SG_MAX_SEGMENTS 32
// Every kernel function: inline in C++ (the kernel is included by several translation
// units), nothing in GLSL.
#define SG_FN inline
// Whether a pass of samples has spent its loop budget (a GL program's sampling passes,
// kernel/glsl_prelude.glsl): a C++ caller has none.
#define loop_budget_spent(work) ((void)(work), false)
// A constant array's initialiser: `const real k[2] = SG_ARRAY(real, 2, (1.0, 2.0));` is
// `{1.0, 2.0}` in C++ and `real[2](1.0, 2.0)` in GLSL.
#define SG_ARRAY_ITEMS(...) __VA_ARGS__
#define SG_ARRAY(T, N, ITEMS) \
  { SG_ARRAY_ITEMS ITEMS }

namespace sg::kernel_tables {

// Views of the tables the kernel reads with texelFetch: R32F textures (float data, as a
// GPU holds them). The data stay with their owner (shading/path_table.h, the compiled-in
// kernel fits); a view is two words and a size.
struct R32Texture2D {  // GLSL sampler2D (R32F): texel (x, y) = data[y * width + x]
  const float* data = nullptr;
  int width = 0, height = 0;
};
struct R32Texture3D {  // GLSL sampler2DArray (R32F): texel (x, y, layer)
  const float* data = nullptr;
  int width = 0, height = 0, layers = 0;
};
// A 1-D table of the host's doubles (kernel/path_table_gen.glsl: the fine grids the path
// tables are integrated from); in GLSL an R32F buffer, read with line_value.
struct TableLine {
  const double* data = nullptr;
  int size = 0;
};
// A map of float texels (kernel/lean.glsl: the LEAN map's moments, five floats a texel);
// in GLSL an R32F buffer, read with map_value.
struct MapTexels {
  const float* data = nullptr;
  long size = 0;  // floats
};
// An image of float texels, its channels interleaved (kernel/taa.glsl: the current samples'
// radiances and the history): channel c of texel (x, y) = data[(y * width + x) * channels +
// c]. In GLSL an RGBA32F sampler2D, read with plane_value.
struct ImagePlanes {
  const float* data = nullptr;
  int width = 0, channels = 1;
};

}  // namespace sg::kernel_tables

namespace sg {

// The kernel's work, counted by its counting build (kernel/kernel_counting.h, namespace
// sg::kc: the kernel's own loops in double, each call below counted where the kernel
// text says SG_COUNT or reads a texel; the other builds count nothing): what a GPU
// invocation of the same text executes. One set per thread; the caller reads and resets
// it around a pixel (methods/kernel_counts.h).
struct KernelCounters {
  uint64_t waves = 0;            // explicit waves visited (wave_at: one wave's terms)
  uint64_t buffer_fetches = 0;   // wave-buffer texels read (waves, sums, cascade fields)
  uint64_t table_fetches = 0;    // table texels read (path tables, kernel fits)
  uint64_t nodes = 0;            // quadrature nodes evaluated
  uint64_t transcendentals = 0;  // sin, cos, tan, asin, acos, atan, exp, log, log2, pow
                                 // (per component)
  uint64_t march_steps = 0;      // steps of the displaced intersection's march
};
inline KernelCounters& kernel_counters() {
  thread_local KernelCounters c;
  return c;
}

}  // namespace sg

namespace sg::wave_simd {

// The frame's waves as structure-of-arrays, in the order of the wave buffer, for the CPU
// engine's vectorised sums (kernel/cpu/wave_sums.h): rot_c / rot_s hold the rotations to
// the path's instants, [instant k][wave].
template <class T>
struct Arrays {
  const T* A = nullptr;
  const T* a = nullptr;
  const T* b = nullptr;
  const T* theta0 = nullptr;
  const T* c = nullptr;
  const T* k = nullptr;
  const T* slope = nullptr;
  const T* rot_c = nullptr;
  const T* rot_s = nullptr;
  int count = 0;
};

}  // namespace sg::wave_simd
