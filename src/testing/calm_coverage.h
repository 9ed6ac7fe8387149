// The exact answer for calm water (all amplitudes 0), shared by the tests of every method
// that claims to approximate the pixel mean there: the fraction of a pixel covered by the
// mirrored light's image.
#pragma once

#include <algorithm>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <cmath>
#include <vector>

#include "scene/model.h"

namespace sg::testing {

// The fraction of pixel (i, j) whose camera rays, mirrored by calm water, fall in the
// light's cone. With d = d(px, py) linear in (px, py) and L' = L mirrored, a ray is inside
// when g = (d . L')^2 - cos^2(rho) |d|^2 >= 0 (on the nappe d . L' > 0). For each column
// px the rows inside form the interval between the two roots of g in py; its length,
// clipped to [j, j+1], is integrated over px. The integrand has square-root kinks where
// the roots merge (discriminant zero) or cross j or j + 1; those points are roots of
// quadratics in px, so [i, i+1] is split there and each piece integrated by tanh-sinh.
inline double analytic_calm_coverage(const SceneModel& m, int i, int j) {
  const vec3 Lm(m.light.L.x, -m.light.L.y, m.light.L.z);
  const double c2 = m.light.cos_radius * m.light.cos_radius;
  const vec3 Dx = m.camera.ddir_dpx(), Dy = m.camera.ddir_dpy();
  auto g_coeffs = [&](const vec3& P, const vec3& D, double& a, double& b, double& c) {
    a = sqr(dot(D, Lm)) - c2 * dot(D, D);
    b = 2 * (dot(P, Lm) * dot(D, Lm) - c2 * dot(P, D));
    c = sqr(dot(P, Lm)) - c2 * dot(P, P);
  };
  auto chord = [&](double px) {
    double a, b, c;
    g_coeffs(m.camera.direction(px, 0.0), Dy, a, b, c);
    const double disc = b * b - 4 * a * c;
    if (!(a < 0) || disc <= 0) return 0.0;
    const double r1 = (-b + std::sqrt(disc)) / (2 * a), r2 = (-b - std::sqrt(disc)) / (2 * a);
    const double lo = std::max<double>(j, std::min(r1, r2));
    const double hi = std::min<double>(j + 1, std::max(r1, r2));
    return std::max(0.0, hi - lo);
  };
  // Breakpoints: roots in px of g(px, j) and g(px, j + 1), and of the discriminant of g in
  // py (a quadratic in px, recovered exactly from three values).
  std::vector<double> cuts = {double(i), double(i + 1)};
  auto add_roots = [&](double a, double b, double c) {
    double disc = b * b - 4 * a * c;
    if (a == 0 || disc < 0) return;
    for (double r : {(-b + std::sqrt(disc)) / (2 * a), (-b - std::sqrt(disc)) / (2 * a)}) {
      if (r > i && r < i + 1) cuts.push_back(r);
    }
  };
  for (double py : {double(j), double(j + 1)}) {
    double a, b, c;
    g_coeffs(m.camera.direction(0.0, py), Dx, a, b, c);
    add_roots(a, b, c);
  }
  auto disc_at = [&](double px) {
    double a, b, c;
    g_coeffs(m.camera.direction(px, 0.0), Dy, a, b, c);
    return b * b - 4 * a * c;
  };
  const double d0 = disc_at(i), dh = disc_at(i + 0.5), d1 = disc_at(i + 1.0);
  // q(s) = d0 + s (4 dh - 3 d0 - d1) + s^2 (2 d0 + 2 d1 - 4 dh), s = px - i.
  {
    double qa = 2 * d0 + 2 * d1 - 4 * dh, qb = 4 * dh - 3 * d0 - d1, qc = d0;
    double disc = qb * qb - 4 * qa * qc;
    if (qa != 0 && disc >= 0) {
      for (double r : {(-qb + std::sqrt(disc)) / (2 * qa), (-qb - std::sqrt(disc)) / (2 * qa)}) {
        if (r > 0 && r < 1) cuts.push_back(i + r);
      }
    }
  }
  std::sort(cuts.begin(), cuts.end());
  boost::math::quadrature::tanh_sinh<double> integrator;
  double total = 0;
  for (size_t k = 0; k + 1 < cuts.size(); ++k) {
    if (cuts[k + 1] - cuts[k] > 1e-15)
      total += integrator.integrate(chord, cuts[k], cuts[k + 1], 1e-11);
  }
  return total;
}

}  // namespace sg::testing
