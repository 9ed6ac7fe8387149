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

// The instruction set the two functions here run on, as Highway names it ("AVX3", "AVX2",
// ...). Their last bits may differ between instruction sets.
const char* simd_trig_target();

// Sums of shifted cosines by angle addition, for the gradient of a sum of sines at many
// times: for q < nt,
//   gx[q] = sum_k (ac[k] cos_t[k*nt + q] - as[k] sin_t[k*nt + q])
//   gz[q] = sum_k (bc[k] cos_t[k*nt + q] - bs[k] sin_t[k*nt + q])
// With ac = A a cos(theta), as = A a sin(theta) (and b for z), and cos_t, sin_t of c t,
// gx = sum A a cos(theta + c t) = dh/dx (Podee et al. 2021, Eq. 1 differentiated).
void shifted_cosine_sums(const double* ac, const double* as, const double* bc, const double* bs,
                         const double* cos_t, const double* sin_t, size_t nk, size_t nt, double* gx,
                         double* gz);

}  // namespace sg
