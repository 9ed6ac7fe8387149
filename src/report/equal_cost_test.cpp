// Equal-cost interpolation on synthetic curves whose answers are known in closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "report/equal_cost.h"

namespace sg {
namespace {

// A power law in both: ms = 2 spp, rmse = 0.1 / sqrt(spp). Log-log interpolation is then
// exact between any two budgets.
std::vector<CurvePoint> power_curve() {
  std::vector<CurvePoint> c;
  for (double spp : {1.0, 4.0, 8.0, 18.0, 32.0, 64.0})
    c.push_back({spp, 2 * spp, 0.1 / std::sqrt(spp)});
  return c;
}

TEST(EqualCost, InterpolatesAPowerLawExactly) {
  const auto c = power_curve();
  const SameCost sc = same_cost(c, 20.0);  // 10 spp
  ASSERT_EQ(sc.status, CurveStatus::interpolated);
  EXPECT_NEAR(sc.spp, 10.0, 1e-9);
  EXPECT_NEAR(sc.rmse, 0.1 / std::sqrt(10.0), 1e-12);
  const SameRmse sr = same_rmse(c, 0.1 / std::sqrt(25.0));  // 25 spp
  ASSERT_EQ(sr.status, CurveStatus::interpolated);
  EXPECT_NEAR(sr.spp, 25.0, 1e-9);
  EXPECT_NEAR(sr.ms, 50.0, 1e-9);
  // On a budget itself.
  EXPECT_NEAR(same_cost(c, 36.0).spp, 18.0, 1e-9);
  EXPECT_NEAR(same_rmse(c, 0.1 / 8).spp, 64.0, 1e-9);
}

TEST(EqualCost, BoundsOutsideTheCurve) {
  const auto c = power_curve();
  EXPECT_EQ(same_cost(c, 1.0).status, CurveStatus::below);    // cheaper than 1 spp
  EXPECT_EQ(same_cost(c, 500.0).status, CurveStatus::above);  // dearer than 64 spp
  EXPECT_EQ(same_rmse(c, 0.2).status, CurveStatus::below);    // 1 spp already does
  EXPECT_EQ(same_rmse(c, 0.001).status, CurveStatus::above);  // 64 spp does not
  EXPECT_EQ(same_cost({}, 5.0).status, CurveStatus::above);
}

TEST(EqualCost, NoisyCurveUsesTheFirstBudgetThatReachesTheTarget) {
  // RMSE not monotone (noise): 0.05 is first reached between 4 and 8 spp.
  std::vector<CurvePoint> c = {
      {1, 1, 0.1}, {4, 4, 0.06}, {8, 8, 0.04}, {16, 16, 0.045}, {32, 32, 0.02}};
  const SameRmse r = same_rmse(c, 0.05);
  ASSERT_EQ(r.status, CurveStatus::interpolated);
  const double f = std::log(0.05 / 0.06) / std::log(0.04 / 0.06);
  EXPECT_NEAR(r.spp, std::exp(std::log(4.0) + f * std::log(2.0)), 1e-9);
  EXPECT_GT(r.spp, 4.0);
  EXPECT_LT(r.spp, 8.0);
  EXPECT_EQ(to_string(CurveStatus::below), "below");
  EXPECT_EQ(curve_status_from_string("interpolated"), CurveStatus::interpolated);
}

}  // namespace
}  // namespace sg
