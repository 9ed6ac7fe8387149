#include "math/simd_trig.h"

#include <cmath>

// Highway's per-target compilation: this file is included once per instruction set. The
// order of these lines matters, so they are kept out of clang-format's include sorting.
// clang-format off
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "math/simd_trig.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>
// clang-format on

HWY_BEFORE_NAMESPACE();
namespace sg {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void SinCosArray(const double* HWY_RESTRICT x, double* HWY_RESTRICT s, double* HWY_RESTRICT c,
                 size_t n) {
  const hn::ScalableTag<double> d;
  const size_t lanes = hn::Lanes(d);
  const auto inv_two_pi = hn::Set(d, 0.15915494309189533577);
  // 2 pi split in two parts (Cody-Waite) so that x - k * 2pi is exact for moderate k.
  const auto two_pi_hi = hn::Set(d, 6.28318530717958623200);
  const auto two_pi_lo = hn::Set(d, 2.44929359829470635445e-16);
  size_t k = 0;
  for (; k + lanes <= n; k += lanes) {
    auto v = hn::LoadU(d, x + k);
    auto q = hn::Round(hn::Mul(v, inv_two_pi));
    v = hn::NegMulAdd(q, two_pi_lo, hn::NegMulAdd(q, two_pi_hi, v));
    hn::StoreU(hn::Sin(d, v), d, s + k);
    hn::StoreU(hn::Cos(d, v), d, c + k);
  }
  for (; k < n; ++k) {
    s[k] = std::sin(x[k]);
    c[k] = std::cos(x[k]);
  }
}

void ShiftedCosineSums(const double* HWY_RESTRICT ac, const double* HWY_RESTRICT as,
                       const double* HWY_RESTRICT bc, const double* HWY_RESTRICT bs,
                       const double* HWY_RESTRICT cos_t, const double* HWY_RESTRICT sin_t,
                       size_t nk, size_t nt, double* HWY_RESTRICT gx, double* HWY_RESTRICT gz) {
  const hn::ScalableTag<double> d;
  const size_t lanes = hn::Lanes(d);
  size_t q = 0;
  for (; q + lanes <= nt; q += lanes) {
    auto x = hn::Zero(d), z = hn::Zero(d);
    for (size_t k = 0; k < nk; ++k) {
      const auto c = hn::LoadU(d, cos_t + k * nt + q), s = hn::LoadU(d, sin_t + k * nt + q);
      x = hn::NegMulAdd(hn::Set(d, as[k]), s, hn::MulAdd(hn::Set(d, ac[k]), c, x));
      z = hn::NegMulAdd(hn::Set(d, bs[k]), s, hn::MulAdd(hn::Set(d, bc[k]), c, z));
    }
    hn::StoreU(x, d, gx + q);
    hn::StoreU(z, d, gz + q);
  }
  for (; q < nt; ++q) {
    double x = 0, z = 0;
    for (size_t k = 0; k < nk; ++k) {
      x += ac[k] * cos_t[k * nt + q] - as[k] * sin_t[k * nt + q];
      z += bc[k] * cos_t[k * nt + q] - bs[k] * sin_t[k * nt + q];
    }
    gx[q] = x;
    gz[q] = z;
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace sg
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace sg {
HWY_EXPORT(SinCosArray);
HWY_EXPORT(ShiftedCosineSums);

void shifted_cosine_sums(const double* ac, const double* as, const double* bc, const double* bs,
                         const double* cos_t, const double* sin_t, size_t nk, size_t nt, double* gx,
                         double* gz) {
  HWY_DYNAMIC_DISPATCH(ShiftedCosineSums)(ac, as, bc, bs, cos_t, sin_t, nk, nt, gx, gz);
}

void sincos_array(const double* x, double* s, double* c, size_t n) {
  HWY_DYNAMIC_DISPATCH(SinCosArray)(x, s, c, n);
}
const char* simd_trig_target() {
  const int64_t targets = hwy::SupportedTargets() & HWY_TARGETS;
  return targets ? hwy::TargetName(targets & -targets) : "none";  // lowest bit: the best
}
}  // namespace sg
#endif
