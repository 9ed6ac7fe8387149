// Geometric specular anti-aliasing: the slope-space filtering kernel of Kaplanyan, Hill,
// Patney, Lefohn 2016 ("Filtering Distributions of Normals for Shading Antialiasing", HPG)
// estimated from the screen-space derivatives of the projected half vector of Tokuyoshi and
// Kaplanyan 2019 ("Improved Geometric Specular Antialiasing", I3D), as Chermain et al. 2021
// (docs/references.md, Sec. 4.1 and 6.1) use them.
//
// The half vector h = normalize(v + l) is expressed in the shading frame (t, b, n) of the
// surface normal; its projected form is h_perp = (h . t, h . b) (Chermain Eq. 21). Across
// the pixel h_perp moves by D = [dh_perp/dpx, dh_perp/dpy]; under a Gaussian pixel filter
// of variance sigma^2 (pixels^2) the first-order spread of h_perp has covariance
// sigma^2 D D^T. The filtered slope distribution is the original one convolved with that
// kernel (Chermain Eq. 7); its variance adds to the lobe's. Two shapes of the kernel:
//   rect (Tokuyoshi & Kaplanyan 2019's listing for anisotropic, axis-aligned lobes): per
//     axis a of the tangent frame, the bounding rectangle b_a = |dh_a/dpx| + |dh_a/dpy|
//     (fwidth) gives kernel roughness alpha_a^2 = min(2 sigma^2 b_a^2, kappa);
//   full: the covariance sigma^2 D D^T, its principal variances clamped at kappa / 2.
// Roughness alpha^2 is twice the slope variance of a Beckmann (Gaussian) lobe, so the added
// slope variance per axis is alpha_a^2 / 2. The constants (sigma^2 = 0.25, "squared std dev
// of pixel filter kernel (in pixels)", kappa = 0.18, the clamp "to avoid overfiltering") are
// those of Tokuyoshi and Kaplanyan's I3D 2019 listings; sigma^2 = 0.25 is a kernel of half a
// pixel, the s_K = 0.5 that Chermain et al. (Sec. 6.1) also default to. (Their JCGT 2021
// follow-up uses sigma^2 = 1/(2 pi).)
//
// The kernel lives in the projected-half-vector space at the lobe's centre, the normal
// itself (h_perp = 0 there). The tangent slope of a normal m is m~ = -m_perp / m_z (Chermain
// Eq. 2's microslope), whose Jacobian with respect to m_perp at m = n is -I: to first order
// the kernel is a covariance of tangent slopes, unchanged. The NDF plane of shading/rdf.h
// is the world slope plane (normal (q.x, 1, q.y)); the pixel's normal tilts the tangent
// frame against it, so tangent slopes map to NDF-plane points through the Jacobian of
// m(m~) = n - m~_x t - m~_y b followed by q = (m.x, m.z) / m.y, taken at m~ = 0
// (tangent_slope_to_ndf_plane): Sigma_ndf = J_G Sigma_ts J_G^T.
#pragma once

#include "math/vec.h"
#include "scene/waves.h"

namespace sg {

// The shading frame of the water's normal for height gradient g = (dh/dx, dh/dz):
// n = normalize(-g.x, 1, -g.y), t = normalize(1, g.x, 0) (the surface's tangent along
// world x, already perpendicular to n), b = n x t (so t x b = n).
struct ShadingFrame {
  vec3 t{1, 0, 0}, b{0, 0, -1}, n{0, 1, 0};
};
ShadingFrame water_shading_frame(const vec2& g);

// h_perp = (h . t, h . b) with h = normalize(v + L) (Tokuyoshi & Kaplanyan 2019).
vec2 projected_half_vector(const ShadingFrame& f, const vec3& v, const vec3& L);

// The change of h_perp when the water point P seen from `camera` moves by dP along the
// surface, its gradient g moving by H (dP.x, dP.z) (H the height field's Hessian): the
// chain rule through the view v = normalize(camera - P), the half vector and the frame.
vec2 projected_half_vector_derivative(const vec3& camera, const vec3& P, const vec2& g,
                                      const Hessian& H, const vec3& dP, const vec3& L);

enum class KernelShape { rect, full };

// The kernel's added covariance of tangent slopes for derivatives ddx = dh_perp/dpx and
// ddy = dh_perp/dpy (see above for the two shapes).
mat2 filtering_kernel_covariance(const vec2& ddx, const vec2& ddy, double sigma2, double kappa,
                                 KernelShape shape);

// J_G: the Jacobian of the NDF-plane point with respect to the tangent slope m~ at m~ = 0.
mat2 tangent_slope_to_ndf_plane(const ShadingFrame& f);

}  // namespace sg
