// The shading of a Gaussian NDF (kernel/ndf_lobe.glsl, `specaa`'s and `lean`'s lobes)
// against Monte Carlo: normals drawn from the Gaussian, each reflected exactly and shaded
// with the scene spec's rules (the light's cone, the horizon); and its weights against the
// spec's combination with Fresnel, the sky and the sea.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "kernel/kernel_double.h"
#include "math/rng.h"
#include "scene/model.h"
#include "shading/kernel_frame.h"
#include "testing/testing.h"

namespace sg {
namespace {

// Draws n ~ N(centre, cov) (Cholesky).
struct NdfSampler {
  vec2 centre;
  double l11, l21, l22;
  NdfSampler(const vec2& c, const mat2& cov) : centre(c) {
    l11 = std::sqrt(cov[0][0]);
    l21 = cov[0][1] / l11;
    l22 = std::sqrt(std::max(0.0, cov[1][1] - l21 * l21));
  }
  vec2 draw(Pcg32& rng) const {
    const double u1 = std::max(rng.uniform(), 1e-300), u2 = rng.uniform();
    const double g1 = std::sqrt(-2 * std::log(u1)) * std::cos(kTwoPi * u2);
    const double g2 = std::sqrt(-2 * std::log(u1)) * std::sin(kTwoPi * u2);
    return centre + vec2(l11 * g1, l21 * g1 + l22 * g2);
  }
};

kd::Frame frame_of(const Scene& s) {
  SceneModel m(s);
  KernelInputsD in;
  build_kernel_inputs(m, frame_time(s, 0), 1, 0, in);
  return in.frame;
}

TEST(NdfLobe, LightAndHorizonFractionsMatchMonteCarlo) {
  // No Fresnel: the weights are (in_light, sky..., below).
  const kd::Frame f = frame_of(testing::small_scene({}));
  ASSERT_EQ(f.fresnel, 0);
  // A grazing view; centre normals that mirror it inside the light disk and 3 disk radii
  // away from it. Inside: slope covariances of growing spread. Away: covariances whose
  // RDF (Eq. 16) has a chosen shape, elongated along or across the offset, so that the
  // light fraction depends on the RDF's orientation.
  const vec3 v = normalize(vec3(0.01, 0.06, 1.0));
  const double R = f.light.tan_radius;
  Pcg32 rng(5, 9);
  struct Case {
    vec2 target;   // light-plane point of the centre reflection
    double sd;     // slope standard deviation (0: the RDF's below)
    double c;      // correlation
    double ratio;  // variance of n_z relative to n_x (of the RDF's e2 to e1 when sd = 0)
  };
  const Case cases[] = {
      {{0.4 * R, -0.2 * R}, 0.001, 0.3, 0.6}, {{0.4 * R, -0.2 * R}, 0.003, 0.3, 0.6},
      {{0.4 * R, -0.2 * R}, 0.02, 0.3, 0.6},  {{0.4 * R, -0.2 * R}, 0.05, 0.3, 0.6},
      {{0.4 * R, -0.2 * R}, 0.1, 0.3, 0.6},   {{3 * R, 0.0}, 0.0, 0.0, 0.1},
      {{3 * R, 0.0}, 0.0, 0.0, 10.0},         {{0.0, 3 * R}, 0.0, 0.6, 0.1},
      {{0.0, 3 * R}, 0.0, 0.6, 10.0},
  };
  for (const Case& cs : cases) {
    vec2 nc(0, 0);
    for (int it = 0; it < 50; ++it) {
      const vec2 p = kd::light_to_plane(f.light, kd::reflect_about_ndf_point(nc, v));
      nc -= glm::inverse(kd::ndf_to_light_plane_jacobian(nc, v, f.light)) * (p - cs.target);
    }
    const double sd = cs.sd;
    mat2 cov;
    if (sd > 0) {
      const double vx = sd * sd, vz = cs.ratio * sd * sd, cxz = cs.c * std::sqrt(vx * vz);
      cov = mat2(vec2(vx, cxz), vec2(cxz, vz));
    } else {
      // RDF: 2 R along the larger axis, `ratio` the variance of e2 over e1.
      const double v1 = sqr(2 * R) * std::min(1.0, 1 / cs.ratio), v2 = v1 * cs.ratio;
      const double c12 = cs.c * std::sqrt(v1 * v2);
      const mat2 Jinv = glm::inverse(kd::ndf_to_light_plane_jacobian(nc, v, f.light));
      cov = Jinv * mat2(vec2(v1, c12), vec2(c12, v2)) * glm::transpose(Jinv);
    }
    const kd::vec4 w = kd::ndf_lobe_weights(f, v, nc, cov);
    NdfSampler sampler(nc, cov);
    const int n = 200000;
    int light = 0, below = 0;
    for (int k = 0; k < n; ++k) {
      const vec3 r = normalize(kd::reflect_about_ndf_point(sampler.draw(rng), v));
      if (r.y <= 0) {
        ++below;
      } else {
        light += kd::light_contains(f.light, r);
      }
    }
    const double pl = double(light) / n, pb = double(below) / n;
    std::printf(
        "centre (%.1f, %.1f) R, slope sd %g, ratio %g: light %.5f (MC %.5f), "
        "below %.5f (MC %.5f)\n",
        cs.target.x / R, cs.target.y / R, sd, cs.ratio, w.x, pl, w.w, pb);
    // 4 standard errors plus a linearisation allowance: 3% of the value (as rdf_test) up to
    // slope deviations of 0.02, 10% beyond, where the first-order maps (Podee Eq. 11 and
    // the horizon's line on the light plane) bend over the spread.
    const double lin = sd <= 0.02 ? 0.03 : 0.1;
    EXPECT_NEAR(w.x, pl, 4 * std::sqrt(pl * (1 - pl) / n) + lin * pl + 1e-4) << sd;
    EXPECT_NEAR(w.w, pb, 4 * std::sqrt(pb * (1 - pb) / n) + lin * pb + 1e-4) << sd;
    if (sd == 0.1) {
      EXPECT_GT(pb, 0.05);  // the case exercises the horizon
    }
    if (sd == 0.003) {
      EXPECT_GT(pl, 0.05);  // and the light
    }
    if (sd == 0) {  // the RDF's orientation decides: along the offset it reaches the light
      const bool along = (cs.target.x > 0) == (cs.ratio < 1);
      if (along) {
        EXPECT_GT(pl, 0.05);
      } else {
        EXPECT_LT(pl, 0.01);
      }
    }
  }
}

TEST(NdfLobe, WeightsCombineFractionsWithFresnelSkyAndSea) {
  Scene s = testing::small_scene({});
  s.surface.fresnel = FresnelMode::schlick;
  s.sky = SkyDesc::constant(Rgb(0.2));
  const kd::Frame f = frame_of(s);
  const kd::Frame plain = frame_of(testing::small_scene({}));
  const vec3 v = normalize(vec3(0.0, 0.1, 1.0));
  const vec2 nc(0.01, -0.02);
  const mat2 cov(vec2(4e-4, 1e-4), vec2(1e-4, 3e-4));
  // The fractions from the frame without Fresnel, F from the centre normal.
  const kd::vec4 fractions = kd::ndf_lobe_weights(plain, v, nc, cov);
  const double F = kd::fresnel_schlick(dot(normalize(vec3(nc.x, 1, nc.y)), v));
  const kd::vec4 w = kd::ndf_lobe_weights(f, v, nc, cov);
  const kd::vec4 expect =
      kd::combine_weights(f, F, fractions.x, fractions.w, kd::reflect_about_ndf_point(nc, v).y);
  for (int c = 0; c < 4; ++c)
    EXPECT_NEAR(w[c], expect[c], 1e-15) << c;
  EXPECT_LT(F, 0.9);  // Fresnel matters here
  // A single normal (zero covariance) is shaded like the spec's point sample.
  for (double dz : {-0.2, -0.02, 0.0, 0.1}) {
    const vec2 n(0.003, dz);
    const kd::vec4 a = kd::ndf_lobe_weights(f, v, n, mat2(0.0));
    const kd::vec4 b = kd::water_weights(f, vec3(n.x, 1, n.y), v);
    for (int c = 0; c < 4; ++c)
      EXPECT_NEAR(a[c], b[c], 1e-12) << dz << " " << c;
  }
}

}  // namespace
}  // namespace sg
