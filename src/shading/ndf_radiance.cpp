#include "shading/ndf_radiance.h"

#include <cmath>

#include "shading/gaussian_disk.h"
#include "shading/radiance.h"
#include "shading/rdf.h"

namespace sg {

GaussianNdfShading shade_gaussian_ndf(const SceneModel& m, const vec3& view, const vec2& centre,
                                      const mat2& cov) {
  GaussianNdfShading s;
  const vec3 r = reflect_about_ndf_point(centre, view);
  vec3 dr_dnx, dr_dnz;
  reflection_derivatives(centre, view, dr_dnx, dr_dnz);
  const vec2 g(dr_dnx.y, dr_dnz.y);
  const double var_y = dot(g, cov * g);
  if (var_y > 0) {
    s.below = 0.5 * std::erfc(r.y / std::sqrt(2.0 * var_y));
  } else {
    s.below = r.y <= 0 ? 1.0 : 0.0;
  }
  if (dot(r, m.light.L) > 0) {
    const vec2 mean = m.light.to_plane(r);
    const mat2 cov_r = rdf_covariance(ndf_to_light_plane_jacobian(centre, view, m.light), cov);
    const double R = m.light.tan_radius;
    const PrincipalAxes axes = principal_axes(cov_r);
    if (length(mean) - R <= 10 * axes.s1) s.in_light = gaussian_disk_mass(mean, cov_r, R);
  }
  s.F = fresnel(m.scene.surface.fresnel, dot(normalize(vec3(centre.x, 1.0, centre.y)), view));
  s.weights = combine_weights(m, s.F, s.in_light, s.below, r.y);
  return s;
}

}  // namespace sg
