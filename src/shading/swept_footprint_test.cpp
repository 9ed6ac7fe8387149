// The swept parallelogram's light share against Monte Carlo: uniform times along the
// path and uniform points in the parallelogram, counted inside the disk.
#include "shading/swept_footprint.h"

#include <gtest/gtest.h>

#include <cmath>

#include "math/rng.h"

namespace sg {
namespace {

double monte_carlo(const std::vector<vec2>& c, const mat2& D, double R, int n, Pcg32& rng) {
  const int K = static_cast<int>(c.size()) - 1;
  int hits = 0;
  for (int q = 0; q < n; ++q) {
    const double t = rng.uniform() * K;
    const int k = std::min(K - 1, static_cast<int>(t));
    const vec2 p = mix(c[k], c[k + 1], t - k) + D * vec2(rng.uniform() - 0.5, rng.uniform() - 0.5);
    hits += dot(p, p) <= R * R;
  }
  return double(hits) / n;
}

TEST(SweptFootprint, MatchesMonteCarlo) {
  Pcg32 rng(31, 2);
  const double R = 1.0;
  int partial = 0;
  for (int trial = 0; trial < 40; ++trial) {
    // Parallelograms from 0.1 to 5 disk radii, skewed; paths of 1-3 segments that cross,
    // graze or miss the disk, or stand still.
    const mat2 D(vec2(0.1 + 3 * rng.uniform(), rng.uniform() - 0.5),
                 vec2(2 * rng.uniform() - 1, 0.1 + 3 * rng.uniform()));
    const int K = 1 + trial % 3;
    std::vector<vec2> c(K + 1);
    for (auto& p : c)
      p = vec2(6 * rng.uniform() - 3, 6 * rng.uniform() - 3);
    if (trial % 7 == 0) c.assign(K + 1, c[0]);  // no motion
    std::vector<char> valid(K + 1, 1);
    const double exact = swept_parallelogram_share(c, valid, D, R);
    const int n = 400000;
    const double mc = monte_carlo(c, D, R, n, rng);
    const double se = std::sqrt(std::max(mc * (1 - mc), 1e-4) / n);
    // 4.5 standard errors (40 trials) plus 1e-4 for the quadrature in time.
    EXPECT_NEAR(exact, mc, 4.5 * se + 1e-4) << trial;
    partial += exact > 0.01 && exact < 0.99;
  }
  EXPECT_GT(partial, 15);
}

TEST(SweptFootprint, LimitsAndInvalidSegments) {
  const double R = 0.5;
  // A tiny parallelogram standing inside / outside the disk.
  std::vector<char> valid = {1, 1};
  EXPECT_NEAR(swept_parallelogram_share({vec2(0.1, 0), vec2(0.1, 0)}, valid, mat2(1e-3), R), 1.0,
              1e-12);
  EXPECT_NEAR(swept_parallelogram_share({vec2(2, 0), vec2(2, 0)}, valid, mat2(1e-3), R), 0.0,
              1e-12);
  // A point crossing the disk's diameter from -1 to 1 spends half its time inside.
  EXPECT_NEAR(swept_parallelogram_share({vec2(-1, 0), vec2(1, 0)}, valid, mat2(0.0), R), 0.5, 1e-3);
  // A sub-segment with an invalid end contributes nothing.
  std::vector<char> half = {1, 1, 0};
  EXPECT_NEAR(swept_parallelogram_share({vec2(0, 0), vec2(0, 0), vec2(0, 0)}, half, mat2(0.1), R),
              0.5, 1e-12);
}

}  // namespace
}  // namespace sg
