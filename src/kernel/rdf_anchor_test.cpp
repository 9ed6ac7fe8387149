// The RDF linearised at the light (kernel/rdf.glsl, light_anchor) against direct
// integration: the light's share of a Gaussian NDF N(n_c, Sigma) is its mass over the
// normals that reflect the view into the disk, integrated here over the disk in
// light-plane coordinates p with the exact inverse map n(p) (the half vector of the
// view and the direction through p) and its Jacobian determinant by central differences,
// on a polar Gauss-Legendre grid. Views from grazing to steep, lights ahead, to the side
// and behind, the sun's and a large disk, NDFs from narrow to as wide as a rough sea's,
// with the light from their centre to deep in their tail. The linearisation at the light
// is exact to first order in the disk's radius; the paper's, at the NDF's centre (Eqs.
// 11-16), is measured beside it on the same cases.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "kernel/kernel_double.h"
#include "math/rng.h"
#include "math/vec.h"
#include "scene/light.h"
#include "shading/kernel_frame.h"

namespace sg {
namespace {

// Gauss-Legendre nodes and weights on [0, 1], n points, by Newton on P_n.
void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w) {
  x.resize(n);
  w.resize(n);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(kPi * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-15) break;
    }
    x[i] = 0.5 * (1 - z);
    w[i] = 1.0 / ((1 - z * z) * dp * dp);
  }
}

// The NDF-plane point whose normal reflects unit view v into the direction through
// light-plane point p.
kd::vec2 normal_of(const kd::Light& l, const kd::vec3& v, kd::vec2 p) {
  const kd::vec3 r = normalize(l.L + p.x * l.e1 + p.y * l.e2);
  const kd::vec3 h = r + v;
  return kd::vec2(h.x / h.y, h.z / h.y);
}

double gaussian_density(kd::vec2 d, const kd::mat2& cov) {
  const double det = kd::determinant(cov);
  const kd::vec2 s = kd::inverse(cov) * d;
  return std::exp(-0.5 * dot(d, s)) / (kTwoPi * std::sqrt(det));
}

// The NDF's exact mass over the normals that reflect v into the disk.
double direct_mass(const kd::Light& l, const kd::vec3& v, kd::vec2 nc, const kd::mat2& cov) {
  std::vector<double> xr, wr, xa, wa;
  gauss_legendre(24, xr, wr);
  gauss_legendre(48, xa, wa);
  const double R = l.tan_radius, h = 1e-4 * R;
  double mass = 0;
  for (size_t i = 0; i < xr.size(); ++i) {
    const double rho = R * xr[i];
    for (size_t j = 0; j < xa.size(); ++j) {
      const double phi = kTwoPi * xa[j];
      const kd::vec2 p = rho * kd::vec2(std::cos(phi), std::sin(phi));
      const kd::vec2 dx =
          (normal_of(l, v, p + kd::vec2(h, 0)) - normal_of(l, v, p - kd::vec2(h, 0))) / (2 * h);
      const kd::vec2 dy =
          (normal_of(l, v, p + kd::vec2(0, h)) - normal_of(l, v, p - kd::vec2(0, h))) / (2 * h);
      const double jac = std::abs(dx.x * dy.y - dx.y * dy.x);
      mass +=
          wr[i] * wa[j] * R * rho * kTwoPi * jac * gaussian_density(normal_of(l, v, p) - nc, cov);
    }
  }
  return mass;
}

kd::vec3 direction(double elev_deg, double azim_deg) {
  const double e = elev_deg * kPi / 180, a = azim_deg * kPi / 180;
  return kd::vec3(std::cos(e) * std::sin(a), std::sin(e), -std::cos(e) * std::cos(a));
}

TEST(RdfAnchor, LightShareMatchesDirectIntegration) {
  Pcg32 rng(2029, 3);
  std::vector<double> sun, large, sun_centre, large_centre;
  for (int c = 0; c < 400; ++c) {
    const double radius = c % 4 == 3 ? 2.0 : 0.27;
    const double light_el = 2 + 68 * rng.uniform(), light_az = -150 + 300 * rng.uniform();
    LightModel model(LightDesc{glm::dvec3(direction(light_el, light_az)), radius, Rgb(1.0), false});
    const kd::Light l = model.kernel_light();
    // The view: from the water point towards a camera above it, from grazing to steep.
    const kd::vec3 v = -direction(-(0.5 + 50 * rng.uniform()), 30 * (rng.uniform() - 0.5));
    const kd::LightAnchor a = kd::light_anchor(v, l);
    if (!a.valid) continue;
    EXPECT_LT(length(kd::reflect_about_ndf_point(a.n, v) - l.L), 1e-12);
    // An NDF from narrow to a rough sea's, elongated and turned.
    const double s1 = 0.01 + 0.3 * rng.uniform(), s2 = s1 * (0.2 + 0.8 * rng.uniform());
    const double th = kPi * rng.uniform();
    const kd::vec2 u(std::cos(th), std::sin(th)), w(-u.y, u.x);
    const kd::mat2 cov = s1 * s1 * kd::outerProduct(u, u) + s2 * s2 * kd::outerProduct(w, w);
    // The light 0 to 3.5 deviations from the centre, in the NDF's own metric.
    const double z = 3.5 * rng.uniform(), ph = kTwoPi * rng.uniform();
    const kd::vec2 nc = a.n - z * (std::cos(ph) * s1 * u + std::sin(ph) * s2 * w);
    const double exact = direct_mass(l, v, nc, cov);
    if (!(exact > 1e-12)) continue;
    const double at_light = kd::gaussian_disk_mass(kd::anchored_light_plane(a, nc),
                                                   kd::rdf_covariance(a.J, cov), l.tan_radius);
    const kd::vec3 r = kd::reflect_about_ndf_point(nc, v);
    double at_centre = 0;
    if (dot(r, l.L) > 0.1 * length(r)) {
      const kd::mat2 Jc = kd::ndf_to_light_plane_jacobian(nc, v, l);
      at_centre = kd::gaussian_disk_mass(kd::light_to_plane(l, r), kd::rdf_covariance(Jc, cov),
                                         l.tan_radius);
    }
    const double err_light = std::abs(at_light / exact - 1);
    const double err_centre = std::abs(at_centre / exact - 1);  // measured beside
    // First order in the disk's radius; the second order grows with the light's distance
    // from the NDF's centre over its width: measured, the sun's disk at most 2.4% (median
    // 0), a 2-degree disk at most 16% (median 0.8%). The linearisation at the centre on the
    // same cases: median 10% and 5%, 90th percentile 105% and 75%.
    EXPECT_LT(err_light, radius > 1 ? 0.2 : 0.03)
        << "case " << c << " light " << light_el << "/" << light_az << " view y " << v.y << " z "
        << z << " s1 " << s1 << " exact " << exact << " anchored " << at_light;
    (radius > 1 ? large : sun).push_back(err_light);
    (radius > 1 ? large_centre : sun_centre).push_back(err_centre);
  }
  auto median = [](std::vector<double> e) {
    std::nth_element(e.begin(), e.begin() + e.size() / 2, e.end());
    return e[e.size() / 2];
  };
  ASSERT_GT(sun.size(), 250u);
  ASSERT_GT(large.size(), 80u);
  std::printf(
      "relative error, median: sun %.2e at the light, %.2e at the centre; 2-degree disk "
      "%.2e, %.2e\n",
      median(sun), median(sun_centre), median(large), median(large_centre));
  EXPECT_LT(median(sun), 1e-3);
  EXPECT_LT(median(large), 0.02);
}

// Where the view ray passes close to a low, large light, J_L is nearly singular and the
// disk's first-order preimage reaches slopes whose reflections miss the disk. A scene met
// it (a 6.4 degree light 2.5 degrees up, water 9 degrees from it seen 4 degrees down, flat
// normals): the anchor, tilted 84 degrees, took in the NDF at the flat normal and gave the
// pixel half the light where no reflection meets it. Here, over views and lights near
// each other, disks of 0.27 to 15 degrees and NDFs centred anywhere from the light to the
// flat normal: wherever the anchor is valid, its mass agrees with the direct one within
// 0.05, or 35% where the mass is larger (measured: 0.035 at most, the rest of first order
// in a 3 to 7 degree disk; without the test at the preimage's ends 67 of 600 cases
// failed, by up to 1.0), and the case above is refused.
TEST(RdfAnchor, RefusedWhereTheDisksPreimageBends) {
  {
    LightModel model(LightDesc{glm::dvec3(direction(2.5, 9.0)), 6.43, Rgb(1.0), false});
    const kd::Light l = model.kernel_light();
    const kd::vec3 v = -direction(-4.08, 0.0);
    const kd::mat2 cov(0.0013, 0.0017, 0.0017, 0.0069);
    EXPECT_LT(direct_mass(l, v, kd::vec2(0.0), cov), 1e-6);
    EXPECT_FALSE(kd::light_anchor(v, l).valid);
  }
  Pcg32 rng(2031, 5);
  int valid = 0, refused = 0;
  double worst = 0;
  for (int c = 0; c < 600; ++c) {
    const double radius =
        std::exp(std::log(0.27) + (std::log(15.0) - std::log(0.27)) * rng.uniform());
    const double light_el = 0.5 + 20 * rng.uniform(), light_az = 40 * (rng.uniform() - 0.5);
    LightModel model(LightDesc{glm::dvec3(direction(light_el, light_az)), radius, Rgb(1.0), false});
    const kd::Light l = model.kernel_light();
    const kd::vec3 v = -direction(-(0.5 + 15 * rng.uniform()), 40 * (rng.uniform() - 0.5));
    const kd::LightAnchor a = kd::light_anchor(v, l);
    if (!a.valid) {
      ++refused;
      continue;
    }
    ++valid;
    const double s1 = 0.02 + 0.25 * rng.uniform(), s2 = s1 * (0.2 + 0.8 * rng.uniform());
    const double th = kPi * rng.uniform();
    const kd::vec2 u(std::cos(th), std::sin(th)), w(-u.y, u.x);
    const kd::mat2 cov = s1 * s1 * kd::outerProduct(u, u) + s2 * s2 * kd::outerProduct(w, w);
    // The NDF's centre between the flat normal and the light's anchor.
    const kd::vec2 nc =
        rng.uniform() * a.n + 0.3 * kd::vec2(rng.uniform() - 0.5, rng.uniform() - 0.5);
    const double exact = direct_mass(l, v, nc, cov);
    const double at_light = kd::gaussian_disk_mass(kd::anchored_light_plane(a, nc),
                                                   kd::rdf_covariance(a.J, cov), l.tan_radius);
    const double err = std::abs(at_light - exact);
    worst = std::max(worst, err / std::max(0.1, exact));
    EXPECT_LT(err, std::max(0.05, 0.35 * exact))
        << "case " << c << " radius " << radius << " light " << light_el << "/" << light_az
        << " view y " << v.y << " n_c " << nc.x << "," << nc.y << " n_L " << a.n.x << "," << a.n.y
        << " exact " << exact << " anchored " << at_light;
  }
  std::printf("anchor valid in %d cases, refused in %d; worst error %.3g (of max(0.1, mass))\n",
              valid, refused, worst);
  EXPECT_GT(valid, 300);
  EXPECT_GT(refused, 20);
}

}  // namespace
}  // namespace sg
