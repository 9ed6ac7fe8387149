// Sine and cosine of many angles at once, vectorised with Highway (its contrib math
// Sin/Cos: at most 3 ULP on [-39000, 39000]) and dispatched at run time to the best
// instruction set of the machine (SSE4, AVX2, AVX-512, ...). Angles are first reduced to
// [-pi, pi] in double precision, so any finite angle is accepted; the reduction adds an
// absolute error of about |x| * 1e-16 rad, the rounding that x itself already carries.
//
// The reference renderer evaluates hundreds of millions of wave phases per frame; this
// is where its time goes (docs/benchmarks.md).
#pragma once

#include <cstddef>

namespace sg {

// s[k] = sin(x[k]), c[k] = cos(x[k]) for k < n. The arrays may not overlap.
void sincos_array(const double* x, double* s, double* c, size_t n);

// The instruction set sincos_array runs on, as Highway names it ("AVX3", "AVX2",
// ...). Their last bits may differ between instruction sets.
const char* simd_trig_target();

}  // namespace sg
