#include "scene/intersect.h"

#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <limits>

namespace sg {

RayHit intersect_flat(const vec3& o, const vec3& d) {
  RayHit r;
  if (o.y > 0 ? d.y >= 0 : d.y <= 0) return r;
  r.s = -o.y / d.y;
  r.point = o + r.s * d;
  r.point.y = 0;
  r.hit = true;
  return r;
}

RayHit intersect_displaced(const WaveField& waves, const vec3& o, const vec3& d, double t,
                           long* evaluations) {
  long evals = 0;
  auto f = [&](double s) {
    ++evals;
    vec3 p = o + s * d;
    return p.y - waves.height(p.x, p.z, t);
  };
  RayHit r;
  const double amax = waves.amplitude_bound();
  // The part of the ray inside the slab |y| <= amax.
  double s0 = 0, s1 = 0;
  if (d.y < 0) {
    s0 = std::max(0.0, (o.y - amax) / -d.y);
    s1 = (o.y + amax) / -d.y;
  } else if (d.y > 0) {
    if (o.y > amax) return r;
    s1 = (amax - o.y) / d.y;
  } else {
    if (std::fabs(o.y) > amax) return r;
    s1 = std::numeric_limits<double>::infinity();
  }
  if (!(s1 >= s0)) return r;
  const double lip = std::fabs(d.y) + waves.slope_bound() * std::hypot(d.x, d.z);
  const double min_step = kGrazeDepth / std::max(lip, 1e-300);

  double s = s0, fs = f(s);
  if (fs <= 0) {
    // The ray starts at or below the surface (only when the camera is inside the slab).
    r.hit = true;
    r.s = s;
    r.point = o + s * d;
    if (evaluations) *evaluations += evals;
    return r;
  }
  long step = 0;
  for (; step < kMaxMarchSteps && s < s1; ++step) {
    double next = std::min(s1, s + std::max(fs / lip, min_step));
    if (!std::isfinite(next)) break;
    double fn = f(next);
    if (fn <= 0) {
      // Root bracketed in [s, next]: refine.
      std::uintmax_t iters = 100;
      auto tol = [](double a, double b) {
        return std::fabs(b - a) <= std::ldexp(std::fabs(a) + std::fabs(b), -50);
      };
      double root = next;
      if (fn < -kRootTolerance) {
        auto br = boost::math::tools::toms748_solve(f, s, next, fs, fn, tol, iters);
        root = 0.5 * (br.first + br.second);
      }
      r.hit = true;
      r.s = root;
      r.point = o + root * d;
      r.point.y = waves.height(r.point.x, r.point.z, t);
      ++evals;
      break;
    }
    s = next;
    fs = fn;
    if (s >= s1) break;
  }
  r.exhausted = !r.hit && step >= kMaxMarchSteps;
  if (evaluations) *evaluations += evals;
  return r;
}

}  // namespace sg
