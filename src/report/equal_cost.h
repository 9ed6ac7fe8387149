// Equal-cost comparison: where a method stands on the quality-cost curve of
// supersampling. The curve is a list of budgets (samples per pixel, measured time per
// frame, RMSE), in increasing samples. For a target method (time T, RMSE R) it answers
//   - same cost: the budget that costs T, and the RMSE supersampling reaches at that cost;
//   - same RMSE: the budget that reaches R, and what it costs (also as a ratio to T).
// Between two budgets the curve is interpolated linearly in log-log coordinates (RMSE
// of Monte Carlo supersampling falls as a power of the samples; time grows about
// linearly with them), walking from the cheapest budget to the first bracketing pair.
// Outside the curve the answer is a bound, not a number: `below` (the cheapest budget
// already costs more than T, or already reaches R) or `above` (the largest budget costs
// less than T, or does not reach R).
#pragma once

#include <string>
#include <vector>

namespace sg {

struct CurvePoint {
  double spp = 0;  // samples per pixel
  double ms = 0;   // time per frame
  double rmse = 0;
};

enum class CurveStatus { interpolated, below, above };
std::string to_string(CurveStatus s);
CurveStatus curve_status_from_string(const std::string& s);  // throws sg::Error

struct SameCost {
  CurveStatus status = CurveStatus::above;
  double spp = 0, rmse = 0;  // when interpolated
};
struct SameRmse {
  CurveStatus status = CurveStatus::above;
  double spp = 0, ms = 0;  // when interpolated
};

// `curve` in increasing spp, every value > 0.
SameCost same_cost(const std::vector<CurvePoint>& curve, double target_ms);
SameRmse same_rmse(const std::vector<CurvePoint>& curve, double target_rmse);

}  // namespace sg
