// The radiance weights of a Gaussian NDF seen from one view, shaded at its centre (the
// baselines that turn a pixel's normals into one Gaussian lobe: `specaa`'s filtering
// kernel, `lean`'s filtered moments). The lobe N(n_c, Sigma) on the NDF plane (rdf.glsl)
// maps to the light plane through the Jacobian at its centre (Podee et al. 2021, Eqs.
// 11-16: Sigma_r = J_c Sigma J_c^T); its mass in the light disk (gaussian.glsl) is the
// light's share, its mass beyond the horizon's line (reflection_footprint.glsl,
// horizon_share) the sea's, Fresnel is taken at the centre normal (radiance.glsl) and the
// sky's split at the centre reflection. A centre reflection more than 87 degrees from the
// light (r . L < 0.05) has no light-plane image worth linearising: the light's share is 0
// there (a lobe within specaa's clamp puts less than 1e-6 of its mass that far) and the
// sea's share is the centre's point test.

const real kNdfLobeMinLightCos = 0.05;

SG_FN vec4 ndf_lobe_weights(IN(Frame) f, vec3 v, vec2 nc, mat2 cov_ndf) {
  vec3 rc = reflect_about_ndf_point(nc, v);
  real in_light = 0.0;
  real below = rc.y <= 0.0 ? 1.0 : 0.0;
  if (dot(rc, f.light.L) >= kNdfLobeMinLightCos) {
    vec2 mean = light_to_plane(f.light, rc);
    mat2 cov_r = rdf_covariance(ndf_to_light_plane_jacobian(nc, v, f.light), cov_ndf);
    in_light = gaussian_disk_mass(mean, cov_r, f.light.tan_radius);
    below = horizon_share(f.light, mean, cov_r);
  }
  real F = fresnel_factor(f.fresnel, dot(normalize(normal_direction(-nc)), v));
  return combine_weights(f, F, in_light, below, rc.y);
}
