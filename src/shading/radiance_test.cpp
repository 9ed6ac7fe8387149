// The radiance terms of the scene spec.
#include "shading/radiance.h"

#include <gtest/gtest.h>

#include <cmath>

#include "math/rng.h"
#include "testing/testing.h"

namespace sg {
namespace {

TEST(Radiance, MirrorReflectionLaw) {
  Pcg32 rng(9, 9);
  for (int k = 0; k < 1000; ++k) {
    vec3 n = normalize(vec3(rng.uniform() - 0.5, 1, rng.uniform() - 0.5));
    vec3 v = normalize(vec3(rng.uniform() - 0.5, rng.uniform(), rng.uniform() - 0.5));
    vec3 r = reflect_view(n, v);
    EXPECT_NEAR(length(r), 1, 1e-14);
    EXPECT_NEAR(dot(r, n), dot(v, n), 1e-14);          // equal angles
    EXPECT_NEAR(dot(cross(v, n), r), 0, 1e-14);        // coplanar
    EXPECT_LT(length(reflect_view(n, r) - v), 1e-14);  // involution
  }
}

TEST(Radiance, SchlickEndpointsAndMonotone) {
  EXPECT_DOUBLE_EQ(fresnel_schlick(1.0), kSchlickR0);
  EXPECT_DOUBLE_EQ(fresnel_schlick(0.0), 1.0);
  EXPECT_DOUBLE_EQ(fresnel_schlick(-0.3), 1.0);  // clamped
  EXPECT_NEAR(fresnel_schlick(0.5), 0.02 + 0.98 * std::pow(0.5, 5), 1e-15);
  for (double c = 0; c < 1; c += 0.01)
    EXPECT_GT(fresnel_schlick(c), fresnel_schlick(c + 0.01));
  EXPECT_DOUBLE_EQ(fresnel(FresnelMode::none, 0.3), 1.0);
}

TEST(Radiance, WaterRadianceCases) {
  Scene s = testing::small_scene({});
  s.light.radiance = Rgb(5);
  s.sky = SkyDesc::constant(Rgb(0.25));
  s.surface.sea_radiance = Rgb(0.125);
  s.surface.fresnel = FresnelMode::schlick;
  SceneModel m(s);
  const vec3 n(0, 1, 0);
  // View that mirrors exactly into the light centre.
  const vec3 v_light = vec3(-m.light.L.x, m.light.L.y, -m.light.L.z);
  const double F = fresnel_schlick(dot(n, v_light));
  EXPECT_NEAR(grey_value(m, water_weights(m, n, v_light)), F * 5 + (1 - F) * 0.125, 1e-15);
  // Mirrors into the sky, away from the light.
  const vec3 v_sky = normalize(vec3(0.5, 0.3, 0.2));
  const double Fs = fresnel_schlick(dot(n, v_sky));
  EXPECT_NEAR(grey_value(m, water_weights(m, n, v_sky)), Fs * 0.25 + (1 - Fs) * 0.125, 1e-15);
  // Below the horizon: a normal tilted so that r.y < 0.
  const vec3 n_steep = normalize(vec3(0, 1, -3));
  const vec3 v_low = normalize(vec3(0, 0.1, 1));
  ASSERT_LE(reflect_view(n_steep, v_low).y, 0);
  EXPECT_DOUBLE_EQ(grey_value(m, water_weights(m, n_steep, v_low)), 0.125);
  // A ray that misses: sky, or the light only when visible.
  EXPECT_DOUBLE_EQ(grey_value(m, miss_weights(m, m.light.L)), 0.25);
  s.light.visible = true;
  SceneModel mv(s);
  EXPECT_DOUBLE_EQ(grey_value(mv, miss_weights(mv, mv.light.L)), 5.0);
}

TEST(Radiance, NormalLengthDoesNotMatter) {
  Scene s = testing::small_scene({});
  s.sky = SkyDesc::constant(Rgb(0.25));
  s.surface.sea_radiance = Rgb(0.125);
  s.surface.fresnel = FresnelMode::schlick;
  SceneModel m(s);
  const vec3 n(0, 1, 0), v_light = vec3(-m.light.L.x, m.light.L.y, -m.light.L.z);
  for (double scale : {1e-3, 0.7, 1.0, 40.0}) {
    EXPECT_NEAR(grey_value(m, water_weights(m, scale * n, v_light)),
                grey_value(m, water_weights(m, n, v_light)), 1e-15);
  }
  const double F = fresnel_schlick(dot(n, v_light));
  EXPECT_NEAR(grey_value(m, water_weights(m, n, v_light)), F + (1 - F) * 0.125, 1e-15);
}

TEST(Radiance, CombineEqualsTheMeanOfSampledValues) {
  // A set of samples, a fraction in the light, below the horizon, in the sky, all with
  // the same normal-view angle: their mean radiance equals combine_radiance.
  Scene s = testing::small_scene({});
  s.light.radiance = Rgb(3);
  s.sky = SkyDesc::constant(Rgb(0.5));
  s.surface.sea_radiance = Rgb(0.2);
  s.surface.fresnel = FresnelMode::schlick;
  SceneModel m(s);
  const double F = 0.3, in_light = 0.25, below = 0.4;
  const double sampled = in_light * (F * 3 + (1 - F) * 0.2) + below * 0.2 +
                         (1 - in_light - below) * (F * 0.5 + (1 - F) * 0.2);
  EXPECT_NEAR(grey_value(m, combine_weights(m, F, in_light, below, 1.0)), sampled, 1e-15);
  EXPECT_NEAR(grey_value(m, combine_weights(m, 1.0, 1.0, 0.0, 1.0)), 3.0, 1e-15);
}

}  // namespace
}  // namespace sg

namespace sg {
namespace {

TEST(Radiance, WeightsApplyTheSkyGradientAndColour) {
  // A colour scene with a gradient sky: the weights applied to the radiances give the
  // spec's formula, channel by channel.
  Scene s = testing::small_scene({});
  s.light.radiance = Rgb(60, 38, 18);
  s.sky = SkyDesc{Rgb(0.05, 0.09, 0.2), Rgb(0.55, 0.32, 0.18), 0.5, true};
  s.surface.sea_radiance = Rgb(0.002, 0.01, 0.014);
  s.surface.fresnel = FresnelMode::schlick;
  SceneModel m(s);
  auto sky = [&](const vec3& d) {
    return s.sky.horizon + (s.sky.zenith - s.sky.horizon) * std::pow(std::max(d.y, 0.0), 0.5);
  };
  const vec3 n(0, 1, 0);
  const vec3 v = normalize(vec3(0.5, 0.3, 0.2));
  const vec3 r = reflect_view(n, v);
  const double F = fresnel_schlick(dot(n, v));
  const Rgb want = F * sky(r) + (1 - F) * s.surface.sea_radiance;
  const Rgb got = m.radiances.apply(water_weights(m, n, v));
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(got[c], want[c], 1e-15) << c;
  const vec3 up = normalize(vec3(0.1, 0.7, -0.3));
  const Rgb miss = m.radiances.apply(miss_weights(m, up));
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(miss[c], sky(up)[c], 1e-15) << c;
  // A constant sky puts its weight on the horizon, whatever the direction.
  Scene g = testing::small_scene({});
  g.sky = SkyDesc::constant(Rgb(0.25));
  SceneModel mg(g);
  EXPECT_EQ(miss_weights(mg, up), RadianceWeights(0, 0, 1, 0));
}

}  // namespace
}  // namespace sg
