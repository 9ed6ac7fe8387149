// How the reflection of the resolved waves moves across a pixel: the derivatives of its
// light-plane position P with respect to the image-plane coordinates (px, py), for the
// pixel-footprint term of `staa` (docs/method.md).
//
// The pixel centre sees water point X(px, py) (footprint.glsl: dX/dpx, dX/dpy). There the
// resolved waves have gradient g and Hessian H, so the NDF-plane point is n = -g + shift,
// the normal m = (n.x, 1, n.y); the view is v = (C - X) / |C - X|; the reflection
// r = 2 (m . v) / (m . m) m - v meets the light plane at P = Phi(r) (Eqs. 8-10). By the
// chain rule
//     dP/dpx = dP/dr [ dr/dm dm/dpx + dr/dv dv/dpx ],
//     dm/dpx = -(H (dX/dpx)_xz) in the x and z slots,
//     dv/dpx = -(I - v v^T) (dX/dpx) / |C - X|
// (rdf.glsl gives dP/dr, dr/dm, dr/dv). To first order the pixel square maps to the
// parallelogram P + [dP/dpx dP/dpy] [-1/2, 1/2]^2 on the light plane: the "reflection quad"
// of the micro-specular highlight paper (Podee et al.), linearised at the pixel centre.

struct ReflectionFootprint {
  bool valid;  // false when the reflection points away from the light (r . L <= 0)
  vec2 P;      // light-plane position of the centre reflection
  mat2 D;      // columns dP/dpx, dP/dpy
};

// The chain rule's factors at normal nm, which do not depend on the waves' Hessian:
// dP/dr dr/dm (what a change of the normal moves P by) and the view's part of D,
// dP/dr dr/dv dv/dp (the pixel's rays turning). D(H) is then linear in H
// (reflection_chain_d); along a fixed camera's shutter, with the derivatives taken at the
// light's anchor, only H changes between the path's instants.
struct ReflectionChain {
  mat3x2 dPdm;  // dP/dr dr/dm
  mat2 view;    // columns dP/dr dr/dv dv/dpx, dv/dpy
};

SG_FN vec3 reflection_footprint_dv(IN(Footprint) fp, vec3 dX) {
  vec3 v = fp.view;
  return -(dX - dot(v, dX) * v) / fp.distance;
}

SG_FN ReflectionChain reflection_chain(IN(Light) l, IN(Footprint) fp, vec3 nm) {
  vec3 v = fp.view;
  mat3x2 dPdr = light_plane_jacobian(reflect_view(nm, v), l);
  ReflectionChain c;
  c.dPdm = dPdr * reflection_jacobian_normal(nm, v);
  mat3x2 dPdv = dPdr * reflection_jacobian_view(nm);
  c.view = mat2(dPdv * reflection_footprint_dv(fp, fp.dp_dpx),
                dPdv * reflection_footprint_dv(fp, fp.dp_dpy));
  return c;
}

// The normal's change across the pixel, dm/dp = -(H (dX/dp)_xz) in the x and z slots.
SG_FN vec3 reflection_footprint_dm(vec3 hess, vec3 dX) {
  return vec3(-(hess.x * dX.x + hess.y * dX.z), 0.0, -(hess.y * dX.x + hess.z * dX.z));
}

// D = [dP/dpx dP/dpy] for the Hessian hess (xx, xz, zz) from the chain's factors.
SG_FN mat2 reflection_chain_d(IN(ReflectionChain) c, IN(Footprint) fp, vec3 hess) {
  return c.view + mat2(c.dPdm * reflection_footprint_dm(hess, fp.dp_dpx),
                       c.dPdm * reflection_footprint_dm(hess, fp.dp_dpy));
}

// The normal at which reflection_footprint_at takes the chain rule's factors: the light's
// anchor n_L where `a` is valid (rdf.glsl, light_anchor; a valid anchor of the view
// fp.view), else the centre normal -g + shift.
SG_FN vec3 reflection_footprint_normal(vec2 g, vec2 shift, IN(LightAnchor) a) {
  vec2 n = a.valid ? a.n : -g + shift;
  return vec3(n.x, 1.0, n.y);
}

// The footprint with D from the chain rule's factors `c`, taken at
// reflection_footprint_normal(g, shift, a) by the caller (`staa` reads them again along the
// shutter: one evaluation serves both). Under Phi linearised at the light (a valid) P =
// J_L (n - n_L) and D's derivatives are n_L's, where the reflection is the light's centre:
// defined whatever the centre normal reflects to. Without an anchor, the centre's: P the
// exact light-plane point of its reflection, valid where that reflects toward the light.
SG_FN ReflectionFootprint reflection_footprint_at(IN(Light) l, IN(Footprint) fp,
                                                  IN(ReflectionChain) c, vec2 g, vec3 hess,
                                                  vec2 shift, IN(LightAnchor) a) {
  vec2 n = -g + shift;
  vec3 r = reflect_view(vec3(n.x, 1.0, n.y), fp.view);
  ReflectionFootprint res;
  res.valid = a.valid || dot(r, l.L) > 0.0;
  res.P = vec2(0.0);
  res.D = mat2(0.0);
  if (res.valid) {
    res.P = a.valid ? anchored_light_plane(a, n) : light_to_plane(l, r);
    res.D = reflection_chain_d(c, fp, hess);
  }
  return res;
}

// g, hess (xx, xz, zz): the resolved waves' gradient and Hessian at the point; shift: the
// NDF's mean shift. The footprint at the centre normal, no anchor.
SG_FN ReflectionFootprint reflection_footprint(IN(Light) l, IN(Footprint) fp, vec2 g, vec3 hess,
                                               vec2 shift) {
  LightAnchor none = light_anchor_none();
  ReflectionChain c = reflection_chain(l, fp, reflection_footprint_normal(g, shift, none));
  return reflection_footprint_at(l, fp, c, g, hess, shift, none);
}

// The pixel square's Gaussian on the light plane (docs/method.md, "The pixel box as a
// Gaussian"). The light's share of a pixel averages the light over the box [-1/2, 1/2]^2 of
// the image plane, which D maps to a parallelogram of the light plane; the RDF takes it as
// the Gaussian D V D^T, V = diag(v_x, v_y) in the pixel's own axes. The box's own
// variance, v = 1/12, gives that Gaussian a peak sqrt(6 / pi) = 1.38 times the box's along
// each axis: light narrower than the pixel, a glint of the resolved waves, read up to 1.9
// times its share at the pixel's centre and less than half of it near the pixel's edges,
// and a row of pixels summed a glint to between 0.37 and 1.9 times its light as it moved
// across them (by Poisson's summation, 1 + 2 sum_k exp(-2 pi^2 k^2 v) cos(2 pi k delta)
// along each axis). Where the rest of the light's spread along the axis, sigma pixels (the
// disk and the aliasing RDF), is wide against the pixel, the box's shape does not matter
// and 1/12 is right.
//
// Each axis takes the variance whose response, N(0, sigma^2 + v) convolved over the
// light's offsets, is nearest the box's (the box convolved with N(0, sigma^2)) in squared
// error over every offset: the error of a glint anywhere in the pixel. That least-squares v
// is 0.1162 at sigma = 0 (the relative error of the pixel's response 0.46 in 2D, against
// 0.52 with 1/12 and 0.50 with the variance that matches the peaks, 1 / (2 pi)) and falls
// to 1/12 as sigma grows; the kernel takes
//   v = 1/12 + kBoxVarianceExcess / (1 + kBoxVarianceFall sigma^2),
// whose error is within 2.4e-5 of the least at every sigma (fitted on sigma = 0 to 1; the
// test, reflection_footprint_test.cpp, BoxVarianceNearTheLeastSquaredError, holds it against
// a search). No branch and one division an axis: uniform across neighbouring pixels.
const real kBoxVarianceExcess = 0.0335;
const real kBoxVarianceFall = 19.0;

// V's diagonal for footprint D against the light's other spread S on the light plane (the
// aliasing RDF's covariance and the disk's R^2 / 4 I): the pixel axes' sigma^2 are the
// diagonal of D^-1 S D^-T, u^T S u / det(D)^2 with u a row of D's adjugate; a degenerate D
// takes the box's 1/12.
SG_FN vec2 footprint_box_variances(mat2 D, mat2 S) {
  real det = D[0][0] * D[1][1] - D[1][0] * D[0][1];
  vec2 u0 = vec2(D[1][1], -D[1][0]);
  vec2 u1 = vec2(-D[0][1], D[0][0]);
  vec2 d2 = vec2(det * det);
  vec2 q = vec2(dot(u0, S * u0), dot(u1, S * u1));
  return vec2(0.083333333333333333333) +
         kBoxVarianceExcess * d2 / (d2 + kBoxVarianceFall * q + vec2(1e-30));
}

// The pixel square's Gaussian D V D^T with V = diag(var).
SG_FN mat2 footprint_box_covariance(mat2 D, vec2 var) {
  return var.x * outerProduct(D[0], D[0]) + var.y * outerProduct(D[1], D[1]);
}

// The share of N(p, cov) (light-plane coordinates) whose direction lies below the
// horizon. The horizon r.y = 0 is a great circle, so on the light plane it is the line
// elevation_on_plane(p) = L.y + p . (e1.y, e2.y) = 0, and the share beyond it is the
// Gaussian's mass in that half-plane (gaussian.glsl). A light at the zenith has the
// horizon at infinity on its plane.
SG_FN real horizon_share(IN(Light) l, vec2 p, mat2 cov) {
  vec2 g = light_horizon_normal(l);
  if (dot(g, g) < 1e-24) return l.L.y > 0.0 ? 0.0 : 1.0;
  return gaussian_half_plane_mass(p, cov, g, l.L.y);
}

// The mass of the Gaussian NDF N(n, cov) whose normals reflect unit view v (v.y > 0) below
// the horizon. A normal m = (n.x, 1, n.y) reflects v to r.y = 2 (m . v) / (m . m) - v.y
// (Eq. 10), which is <= 0 where
//     v.y (1 + |n|^2) - 2 (n . v_h + v.y) >= 0,  v_h = (v.x, v.z):
// outside the circle of centre c = v_h / v.y and radius 1 / v.y (the flat normal lies
// inside it, 1 / v.y - |c| ~ v.y / 2 from its edge at a grazing view). The circle is
// taken as its tangent line at the point nearest n, and the share is the Gaussian's mass
// beyond that line (gaussian.glsl, one erfc). The radius is 1 / v.y: at a grazing view,
// where the share is neither 0 nor 1, the circle is nearly its tangent over the NDF's
// width; at a steep view it lies many deviations out.
SG_FN real ndf_below_horizon_share(vec3 v, vec2 n, mat2 cov) {
  real inv_y = 1.0 / max(v.y, 1e-6);
  vec2 c = vec2(v.x, v.z) * inv_y;
  vec2 d = n - c;
  real dd = dot(d, d);
  vec2 u = dd > 0.0 ? d * inversesqrt(dd) : vec2(1.0, 0.0);
  // Below: u . (n - c) >= 1 / v.y, i.e. -u . n + (u . c + 1 / v.y) <= 0.
  return gaussian_half_plane_mass(n, cov, -u, dot(u, c) + inv_y);
}
