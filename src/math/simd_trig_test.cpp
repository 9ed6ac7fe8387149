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

}  // namespace
}  // namespace sg
