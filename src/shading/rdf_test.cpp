// The NDF-to-RDF map: its Jacobian against finite differences, and the linearised RDF's
// mass in the light disk against Monte Carlo with exact reflections.
#include "shading/rdf.h"

#include <gtest/gtest.h>

#include <cmath>

#include "math/rng.h"
#include "shading/gaussian_disk.h"

namespace sg {
namespace {

TEST(Rdf, ReflectionIsTheMirrorOfTheView) {
  const vec3 v = normalize(vec3(0.1, 0.2, 1));
  const vec2 n(0.05, -0.1);
  vec3 r = reflect_about_ndf_point(n, v);
  vec3 nh = normalize(vec3(n.x, 1, n.y));
  EXPECT_LT(length(r - (2 * dot(nh, v) * nh - v)), 1e-15);
}

TEST(Rdf, JacobianMatchesFiniteDifferences) {
  LightModel light(LightDesc{{0.0, 0.207912, -0.978148}, 0.27, Rgb(1.0), false});
  Pcg32 rng(4, 4);
  for (int k = 0; k < 200; ++k) {
    const vec3 v = normalize(vec3(rng.uniform() - 0.5, 0.02 + 0.3 * rng.uniform(), 1.0));
    const vec2 n(0.3 * (rng.uniform() - 0.5), 0.3 * (rng.uniform() - 0.5));
    if (dot(reflect_about_ndf_point(n, v), light.L) < 0.3) continue;
    const mat2 J = ndf_to_light_plane_jacobian(n, v, light);
    const double h = 1e-6;
    vec2 dx = (ndf_to_light_plane(n + vec2(h, 0), v, light) -
               ndf_to_light_plane(n - vec2(h, 0), v, light)) /
              (2 * h);
    vec2 dz = (ndf_to_light_plane(n + vec2(0, h), v, light) -
               ndf_to_light_plane(n - vec2(0, h), v, light)) /
              (2 * h);
    const double scale = std::max(length(dx), length(dz));
    EXPECT_LT(length(J[0] - dx), 1e-7 * scale);
    EXPECT_LT(length(J[1] - dz), 1e-7 * scale);
  }
}

TEST(Rdf, ViewJacobianMatchesFiniteDifferences) {
  LightModel light(LightDesc{{0.0, 0.207912, -0.978148}, 0.27, Rgb(1.0), false});
  const vec3 m(0.05, 1.0, -0.12);
  auto plane_of = [&](const vec3& v) {
    return light.to_plane((2.0 * dot(m, v) / dot(m, m)) * m - v);
  };
  const vec3 v = normalize(vec3(0.02, 0.1, 1.0));
  const vec3 r = (2.0 * dot(m, v) / dot(m, m)) * m - v;
  const glm::dmat3x2 J = light_plane_jacobian(r, light) * reflection_jacobian_view(m);
  for (int c = 0; c < 3; ++c) {
    vec3 h(0.0);
    h[c] = 1e-6;
    vec2 fd = (plane_of(v + h) - plane_of(v - h)) / 2e-6;
    EXPECT_LT(length(J[c] - fd), 1e-6 * (1 + length(fd))) << c;
  }
}

TEST(Rdf, MassInTheDiskMatchesMonteCarloForModerateVariances) {
  // The shared scenes' light (radius 0.27 degrees), a grazing view, and slope
  // distributions whose reflections spread from 0.3 to 3 disk radii. Normals are sampled
  // from the NDF, reflected exactly and tested against the cone; the linearised RDF
  // (Eqs. 11-16) must agree within 4 Monte-Carlo standard errors plus a linearisation
  // allowance of 3% of the mass (Appendix B's error grows with the variance; at these
  // spreads it stays below that).
  LightModel light(LightDesc{{0.0, 0.207912, -0.978148}, 0.27, Rgb(1.0), false});
  const vec3 v = normalize(vec3(0.01, 0.06, 1.0));
  // A centre normal that reflects v close to the light.
  vec2 nc(0, 0);
  for (int it = 0; it < 50; ++it) {
    vec2 p = ndf_to_light_plane(nc, v, light);
    nc -= glm::inverse(ndf_to_light_plane_jacobian(nc, v, light)) * (p - vec2(0.002, -0.001));
  }
  Pcg32 rng(77, 1);
  for (double spread : {0.3, 1.0, 3.0}) {
    const mat2 J = ndf_to_light_plane_jacobian(nc, v, light);
    // NDF covariance chosen so that the RDF's larger std is `spread` disk radii.
    const mat2 Jinv = glm::inverse(J);
    const double sr = spread * light.tan_radius;
    const mat2 cov_r(vec2(sr * sr, 0.3 * sr * sr), vec2(0.3 * sr * sr, 0.5 * sr * sr));
    const mat2 cov = Jinv * cov_r * glm::transpose(Jinv);
    const double predicted = gaussian_disk_mass(ndf_to_light_plane(nc, v, light),
                                                rdf_covariance(J, cov), light.tan_radius);
    // Sample N(nc, cov) via its Cholesky factor.
    const double l11 = std::sqrt(cov[0][0]), l21 = cov[0][1] / l11;
    const double l22 = std::sqrt(cov[1][1] - l21 * l21);
    const int n = 400000;
    int hits = 0;
    for (int k = 0; k < n; ++k) {
      double u1 = std::max(rng.uniform(), 1e-300), u2 = rng.uniform();
      double g1 = std::sqrt(-2 * std::log(u1)) * std::cos(kTwoPi * u2);
      double g2 = std::sqrt(-2 * std::log(u1)) * std::sin(kTwoPi * u2);
      vec2 nn = nc + vec2(l11 * g1, l21 * g1 + l22 * g2);
      hits += light.contains(normalize(reflect_about_ndf_point(nn, v)));
    }
    const double mc = double(hits) / n, se = std::sqrt(mc * (1 - mc) / n);
    EXPECT_NEAR(predicted, mc, 4 * se + 0.03 * mc) << "spread " << spread;
    EXPECT_GT(mc, 0.005);
  }
}

}  // namespace
}  // namespace sg
