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

}  // namespace HWY_NAMESPACE
}  // namespace sg
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace sg {
HWY_EXPORT(SinCosArray);

void sincos_array(const double* x, double* s, double* c, size_t n) {
  HWY_DYNAMIC_DISPATCH(SinCosArray)(x, s, c, n);
}
const char* simd_trig_target() {
  const int64_t targets = hwy::SupportedTargets() & HWY_TARGETS;
  return targets ? hwy::TargetName(targets & -targets) : "none";  // lowest bit: the best
}
}  // namespace sg
#endif
