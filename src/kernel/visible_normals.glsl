// The normals a displaced surface shows a view: a Gaussian of normals on the NDF plane
// weighted by the projected area of each facet, as a Gaussian again.
//
// A camera ray meets a displaced surface at its first intersection (scene spec,
// "Radiance along a camera ray", 1), so a pixel sees a facet of normal m = (s.x, 1, s.y)
// (s a point of the NDF plane, ndf.glsl) in proportion to the area it shows the view,
// (m . v)+ per unit of the water's horizontal area, and the facets that face away not at
// all (Heitz 2014, "Understanding the masking-shadowing function", Eq. 3; Smith's masking
// scales every normal alike there and drops out of the normalised distribution). For
// parallel rays at height v.y over a wave of slope a along the view the hit points fall
// (v.y + a) / v.y as densely as on water at rest, whatever the wave's amplitude: at
// grazing views the visible normals of waves of slope comparable to v.y are tilted
// towards the camera and so reflect higher. Water at rest (`flat`) takes every normal
// alike: the ray meets the plane y = 0.
//
// With m . v = v.y + z, z = s . (v.x, v.z), the weight depends on s through z alone: given
// z the Gaussian is unchanged, so the weighted distribution is the Gaussian with z's
// marginal reweighted by (v.y + z)+. Its mean and covariance (moment matching) follow from
// the reweighted marginal's first two moments. With X standard normal and
// t = (mu_z + v.y) / sigma_z (Gaussian integrals by parts):
//     E[(X + t)+]     = t Phi(t) + phi(t)             = m0
//     E[(X + t)+ X]   = Phi(t)                         -> mean of X: m1 = Phi / m0
//     E[(X + t)+ X^2] = 2 phi(t) + t Phi(t)            -> second moment: m2
// so the mean moves by Sigma e m1 / sigma_z and the covariance loses
// (Sigma e)(Sigma e)^T (1 - (m2 - m1^2)) / sigma_z^2 (e = (v.x, v.z)). For t large (a
// steep view, a narrow Gaussian) the shift tends to Sigma e / (v.y + mu_z) and the
// weighting to nothing. Below t = -3 (the Gaussian's centre faces far away from the view)
// m0 is a difference of nearly equal terms; t is held there.
//
// What it applies to: the normals that vary within a pixel's footprint faster than its
// first-order map (the aliasing NDF, the smooth terms' Gaussian in each cell). The resolved
// waves' normal at the centre's hit is already one the view sees (the pixel's ray meets
// the surface there), and the footprint, through the tangent plane at that hit, places the
// pixel's rays to first order.

struct VisibleNormals {
  vec2 mean;
  mat2 cov;
};

SG_FN VisibleNormals visible_normals(vec2 mean, mat2 cov, vec3 v) {
  VisibleNormals r;
  r.mean = mean;
  r.cov = cov;
  vec2 e = vec2(v.x, v.z);
  real c = v.y + dot(mean, e);
  vec2 ce = cov * e;
  real var = dot(e, ce);
  if (!(var > 0.0)) return r;
  real sz = sqrt(var);
  real t = max(c / sz, -3.0);
  real Phi = normal_cdf(t);
  real phi = kInvSqrtTwoPi * exp(-0.5 * t * t);
  real m0 = t * Phi + phi;
  real m1 = Phi / m0;
  real m2 = (2.0 * phi + t * Phi) / m0;
  r.mean = mean + ce * (m1 / sz);
  r.cov = cov - outerProduct(ce, ce) * ((1.0 - (m2 - m1 * m1)) / var);
  return r;
}
