#include "shading/radiance.h"

#include "kernel/kernel_double.h"
#include "shading/kernel_frame.h"
#include "shading/water_geometry.h"

namespace sg {

namespace {

// The kernel's view of the model's shading inputs: a Frame whose light, Fresnel mode and
// sky are the model's (kernel/radiance.glsl reads no other field; the rest is not set).
kd::Frame radiance_frame(const SceneModel& m) {
  kd::Frame f;
  f.light = m.light.kernel_light();
  f.fresnel = m.scene.surface.fresnel == FresnelMode::none ? 0 : 1;
  f.sky_gradient = m.scene.sky.gradient;
  f.sky_exponent = m.scene.sky.exponent;
  return f;
}

}  // namespace

const double kSchlickR0 = kd::kSchlickR0;

vec3 reflect_view(const vec3& n, const vec3& v) {
  return kd::reflect_view(n, v);
}
double fresnel_schlick(double n_dot_v) {
  return kd::fresnel_schlick(n_dot_v);
}
double fresnel(FresnelMode mode, double n_dot_v) {
  return kd::fresnel_factor(mode == FresnelMode::none ? 0 : 1, n_dot_v);
}
RadianceWeights sky_weights(const SceneModel& m, double dir_y) {
  return kd::sky_weights(radiance_frame(m), dir_y);
}
RadianceWeights light_weights() {
  return kd::light_weights();
}
RadianceWeights sea_weights() {
  return kd::sea_weights();
}
RadianceWeights miss_weights(const SceneModel& m, const vec3& dir) {
  return kd::miss_weights(radiance_frame(m), dir);
}
RadianceWeights water_weights(const SceneModel& m, const vec3& nm, const vec3& v) {
  return kd::water_weights(radiance_frame(m), nm, v);
}
vec3 normal_direction(vec2 g) {
  return kd::normal_direction(g);
}
RadianceWeights combine_weights(const SceneModel& m, double F, double in_light, double below,
                                double sky_y) {
  return kd::combine_weights(radiance_frame(m), F, in_light, below, sky_y);
}

RadianceWeights weights_along_ray(const WaterGeometry& water, const vec3& origin, const vec3& dir,
                                  double t, RayHit* hit_out) {
  const SceneModel& m = water.model();
  const vec3 d = normalize(dir);
  const RayHit hit = water.intersect(origin, d, t);
  if (hit_out) *hit_out = hit;
  if (!hit.hit) return miss_weights(m, d);
  return water_weights(m, normal_direction(water.gradient(hit.point.x, hit.point.z, t)), -d);
}

RadianceWeights miss_pixel_weights(const SceneModel& m, int i, int j) {
  const double cover =
      kd::light_pixel_coverage(m.camera.kernel_camera(), m.light.kernel_light(), i, j);
  const vec3 d = normalize(m.camera.direction(i + 0.5, j + 0.5));
  return cover * light_weights() + (1.0 - cover) * sky_weights(m, d.y);
}

}  // namespace sg
