// The vectorised sine and cosine against the C library, over the angles the renderer
// meets (wave phases up to 1e5 rad) and beyond Highway's own range.
#include "math/simd_trig.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "math/rng.h"

namespace sg {
namespace {

TEST(SimdTrig, MatchesLibm) {
  Pcg32 rng(7, 7);
  for (double range : {3.2, 100.0, 4e4, 1e6}) {
    const size_t n = 10007;  // not a multiple of the vector width: the tail is used
    std::vector<double> x(n), s(n), c(n);
    for (auto& v : x)
      v = (2 * rng.uniform() - 1) * range;
    sincos_array(x.data(), s.data(), c.data(), n);
    double worst = 0;
    for (size_t k = 0; k < n; ++k) {
      worst = std::max(worst, std::fabs(s[k] - std::sin(x[k])));
      worst = std::max(worst, std::fabs(c[k] - std::cos(x[k])));
    }
    // A few ULP of the result plus the reduction's |x| * 2^-52 (see simd_trig.h).
    EXPECT_LT(worst, 4e-16 + range * 3e-16) << range;
  }
}

TEST(SimdTrig, ShiftedCosineSumsAreTheGradientByAngleAddition) {
  Pcg32 rng(8, 8);
  for (size_t nt : {1, 3, 8, 13}) {
    const size_t nk = 37;
    std::vector<double> A(nk), theta(nk), c(nk), t(nt);
    for (size_t k = 0; k < nk; ++k) {
      A[k] = rng.uniform();
      theta[k] = 100 * rng.uniform();
      c[k] = 10 * rng.uniform();
    }
    for (auto& v : t)
      v = rng.uniform();
    std::vector<double> ac(nk), as(nk), bc(nk), bs(nk), cos_t(nk * nt), sin_t(nk * nt);
    for (size_t k = 0; k < nk; ++k) {
      ac[k] = A[k] * std::cos(theta[k]);
      as[k] = A[k] * std::sin(theta[k]);
      bc[k] = 2 * ac[k];
      bs[k] = 2 * as[k];
      for (size_t q = 0; q < nt; ++q) {
        cos_t[k * nt + q] = std::cos(c[k] * t[q]);
        sin_t[k * nt + q] = std::sin(c[k] * t[q]);
      }
    }
    std::vector<double> gx(nt), gz(nt);
    shifted_cosine_sums(ac.data(), as.data(), bc.data(), bs.data(), cos_t.data(), sin_t.data(), nk,
                        nt, gx.data(), gz.data());
    for (size_t q = 0; q < nt; ++q) {
      double direct = 0;
      for (size_t k = 0; k < nk; ++k)
        direct += A[k] * std::cos(theta[k] + c[k] * t[q]);
      EXPECT_NEAR(gx[q], direct, 1e-13);
      EXPECT_NEAR(gz[q], 2 * direct, 2e-13);
    }
  }
}

}  // namespace
}  // namespace sg
