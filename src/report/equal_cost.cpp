#include "report/equal_cost.h"

#include <cmath>

#include "base/error.h"

namespace sg {

std::string to_string(CurveStatus s) {
  switch (s) {
    case CurveStatus::interpolated:
      return "interpolated";
    case CurveStatus::below:
      return "below";
    case CurveStatus::above:
      return "above";
  }
  return "above";
}

CurveStatus curve_status_from_string(const std::string& s) {
  if (s == "interpolated") return CurveStatus::interpolated;
  if (s == "below") return CurveStatus::below;
  if (s == "above") return CurveStatus::above;
  throw Error("equal_cost.status: unknown value '" + s + "'");
}

namespace {

// Fraction of the way from a to b where x lies, in log coordinates.
double log_fraction(double x, double a, double b) {
  const double la = std::log(a), lb = std::log(b);
  return lb == la ? 0.0 : (std::log(x) - la) / (lb - la);
}
double log_lerp(double a, double b, double f) {
  return std::exp(std::log(a) + f * (std::log(b) - std::log(a)));
}

}  // namespace

SameCost same_cost(const std::vector<CurvePoint>& c, double target_ms) {
  SameCost r;
  if (c.empty() || !(target_ms > 0)) return r;
  if (target_ms < c.front().ms) {
    r.status = CurveStatus::below;
    return r;
  }
  for (size_t k = 0; k + 1 < c.size(); ++k) {
    const double lo = std::min(c[k].ms, c[k + 1].ms), hi = std::max(c[k].ms, c[k + 1].ms);
    if (target_ms < lo || target_ms > hi) continue;
    const double f = log_fraction(target_ms, c[k].ms, c[k + 1].ms);
    r.status = CurveStatus::interpolated;
    r.spp = log_lerp(c[k].spp, c[k + 1].spp, f);
    r.rmse = log_lerp(c[k].rmse, c[k + 1].rmse, f);
    return r;
  }
  if (target_ms == c.front().ms) {  // a one-point curve that costs exactly T
    r.status = CurveStatus::interpolated;
    r.spp = c.front().spp;
    r.rmse = c.front().rmse;
  }
  return r;
}

SameRmse same_rmse(const std::vector<CurvePoint>& c, double target_rmse) {
  SameRmse r;
  if (c.empty() || !(target_rmse > 0)) return r;
  if (c.front().rmse <= target_rmse) {
    r.status = CurveStatus::below;
    return r;
  }
  for (size_t k = 0; k + 1 < c.size(); ++k) {
    if (c[k + 1].rmse > target_rmse) continue;
    // c[k].rmse > target >= c[k+1].rmse: the first budget that reaches the target.
    const double f = log_fraction(target_rmse, c[k].rmse, c[k + 1].rmse);
    r.status = CurveStatus::interpolated;
    r.spp = log_lerp(c[k].spp, c[k + 1].spp, f);
    r.ms = log_lerp(c[k].ms, c[k + 1].ms, f);
    return r;
  }
  return r;
}

}  // namespace sg
