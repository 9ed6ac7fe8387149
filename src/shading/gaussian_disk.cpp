#include "shading/gaussian_disk.h"

#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>

namespace sg {

PrincipalAxes principal_axes(const mat2& c) {
  const double a = c[0][0], b = 0.5 * (c[1][0] + c[0][1]), d = c[1][1];
  const double mean = 0.5 * (a + d), diff = 0.5 * (a - d);
  const double rad = std::sqrt(diff * diff + b * b);
  PrincipalAxes p;
  const double l1 = mean + rad, l2 = mean - rad;
  p.s1 = std::sqrt(std::max(0.0, l1));
  p.s2 = std::sqrt(std::max(0.0, l2));
  // Eigenvector of l1: (b, l1 - a) or (l1 - d, b), whichever is longer (better conditioned);
  // both vanish for an isotropic covariance, where any axis will do.
  const vec2 u1(b, l1 - a), u2(l1 - d, b);
  vec2 u = dot(u1, u1) > dot(u2, u2) ? u1 : u2;
  if (dot(u, u) < 1e-300) u = vec2(1, 0);
  p.u = normalize(u);
  return p;
}

namespace {

// P(lo <= X <= hi) for X ~ N(0, s^2), s >= 0.
double normal_interval(double lo, double hi, double s) {
  if (hi <= lo) return 0.0;
  if (s <= 0) return (lo <= 0 && 0 <= hi) ? 1.0 : 0.0;
  const double k = 1.0 / (s * std::sqrt(2.0));
  // erfc keeps precision in the tails.
  if (lo >= 0) return 0.5 * (std::erfc(lo * k) - std::erfc(hi * k));
  if (hi <= 0) return 0.5 * (std::erfc(-hi * k) - std::erfc(-lo * k));
  return 1.0 - 0.5 * (std::erfc(hi * k) + std::erfc(-lo * k));
}

}  // namespace

double gaussian_disk_mass(const vec2& mean, const mat2& cov, double R) {
  const PrincipalAxes p = principal_axes(cov);
  const vec2 w(-p.u.y, p.u.x);
  const vec2 c = -mean;  // the disk centre relative to the mean
  const double cs = dot(c, p.u), cw = dot(c, w);
  if (p.s1 <= 0) return dot(mean, mean) <= R * R ? 1.0 : 0.0;
  // Beyond 9 major standard deviations the mass is below 3e-18 (the chi distribution's tail
  // with 2 degrees of freedom, exp(-81/2)): a disk that far away holds nothing, one that
  // holds that whole ball holds everything.
  const double dm = length(mean);
  if (dm >= R + 9 * p.s1) return 0.0;
  if (dm + 9 * p.s1 <= R) return 1.0;
  // Likewise along the minor axis: a disk whose nearest point is 9 minor standard
  // deviations off the major axis holds at most the tail P(|W| >= 9 s2) ~ 2e-19.
  if (std::fabs(cw) >= R + 9 * p.s2) return 0.0;
  // s range: the disk's extent along u, clipped to +-9 s1 about the mean.
  const double lo = std::max(cs - R, -9 * p.s1), hi = std::min(cs + R, 9 * p.s1);
  if (hi <= lo) return 0.0;
  double ulo = std::asin(std::clamp((lo - cs) / R, -1.0, 1.0));
  double uhi = std::asin(std::clamp((hi - cs) / R, -1.0, 1.0));
  // Where the chord's half-length h = R cos(u) is below |c_w| - 9 s2 the chord lies beyond
  // 9 minor standard deviations: nothing there (the same 2e-19 tail). Trim those ends.
  if (std::fabs(cw) - 9 * p.s2 > 0) {
    const double umax = std::acos(std::min(1.0, (std::fabs(cw) - 9 * p.s2) / R));
    ulo = std::max(ulo, -umax);
    uhi = std::min(uhi, umax);
    if (uhi <= ulo) return 0.0;
  }
  auto f = [&](double u) {
    const double s = cs + R * std::sin(u), h = R * std::cos(u);
    const double dens = std::exp(-0.5 * sqr(s / p.s1)) / (p.s1 * std::sqrt(kTwoPi));
    return dens * normal_interval(cw - h, cw + h, p.s2) * R * std::cos(u);
  };
  // The minor conditional's probability steps (over a width ~ s2) where the chord's
  // half-length h = R cos(u) equals |c_w|: split there so that each piece is smooth.
  double cuts[4] = {ulo, uhi, ulo, ulo};
  int ncuts = 2;
  if (std::fabs(cw) < R) {
    const double us = std::acos(std::fabs(cw) / R);
    for (double c : {-us, us}) {
      if (c > ulo && c < uhi) cuts[ncuts++] = c;
    }
  }
  std::sort(cuts, cuts + ncuts);
  double mass = 0;
  for (int k = 0; k + 1 < ncuts; ++k) {
    mass += boost::math::quadrature::gauss<double, 30>::integrate(f, cuts[k], cuts[k + 1]);
  }
  return mass;
}

double gaussian_disk_mass_riemann(const vec2& mean, const mat2& cov, double R, int n) {
  const mat2 inv = glm::inverse(cov);
  const double det = glm::determinant(cov);
  if (!(det > 0)) return gaussian_disk_mass(mean, cov, R);  // no density to sample
  const double norm = 1.0 / (kTwoPi * std::sqrt(det)), cell = 2 * R / n;
  double sum = 0;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const vec2 q(-R + (i + 0.5) * cell, -R + (j + 0.5) * cell);
      if (dot(q, q) > R * R) continue;
      const vec2 d = q - mean;
      sum += std::exp(-0.5 * dot(d, inv * d));
    }
  }
  return sum * norm * cell * cell;
}

double gaussian_half_plane_mass(const vec2& mean, const mat2& cov, const vec2& a, double c) {
  const double m = dot(a, mean) + c, var = dot(a, cov * a);
  if (!(var > 0)) return m <= 0 ? 1.0 : 0.0;
  return 0.5 * std::erfc(m / std::sqrt(2 * var));
}

}  // namespace sg
