// Geometric specular anti-aliasing, `specaa` (a baseline, methods/specaa.h): the slope-space
// filtering kernel of Kaplanyan, Hill, Patney, Lefohn 2016 ("Filtering Distributions of
// Normals for Shading Antialiasing", HPG) estimated from the screen-space derivatives of the
// projected half vector of Tokuyoshi and Kaplanyan 2019 ("Improved Geometric Specular
// Antialiasing", I3D), as Chermain et al. 2021 use them (docs/references.md, Sec. 4.1, 6.1,
// Eqs. 7, 20-21).
//
// The half vector h = normalize(v + L) is expressed in the shading frame (t, b, n) of the
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
// pixel, the s_K = 0.5 that Chermain et al. (Sec. 6.1) also default to.
//
// The kernel lives in the projected-half-vector space at the lobe's centre, the normal
// itself (h_perp = 0 there). The tangent slope of a normal m is m~ = -m_perp / m_z (Chermain
// Eq. 2's microslope), whose Jacobian with respect to m_perp at m = n is -I: to first order
// the kernel is a covariance of tangent slopes, unchanged. The NDF plane (rdf.glsl) is the
// world slope plane; the pixel's normal tilts the tangent frame against it, so tangent
// slopes map to NDF-plane points through the Jacobian of m(m~) = n - m~_x t - m~_y b
// followed by q = (m.x, m.z) / m.y, at m~ = 0 (specaa_tangent_to_ndf_plane):
// Sigma_ndf = J_G Sigma_ts J_G^T. The water is a mirror (no base roughness), so the kernel
// alone is the lobe, shaded as ndf_lobe.glsl shades a Gaussian NDF (mapped to the light
// plane, Eq. 16 of Podee et al.: its mass in the disk is the light's share, its mass
// beyond the horizon's line the sea's).
//
// Per pixel, at the display time: the water point through the pixel centre (flat or
// displaced, footprint.glsl), its gradient (the waves, and the cascades' fields where the
// frame has them); the derivatives of h_perp either as a GPU takes them, the differences
// within the 2x2 pixel quad (`quad`: the method as published and run in real time), or by
// the chain rule through the footprint's differentials and the height's Hessian
// (`analytic`). A quad neighbour that misses the water or has the camera under the surface
// leaves the pixel to the analytic form.

// The shading frame of the water's normal for height gradient g: n = normalize(-g.x, 1,
// -g.y), t = normalize(1, g.x, 0) (the surface's tangent along world x, perpendicular to
// n), b = n x t (so t x b = n).
struct ShadingFrame {
  vec3 t;
  vec3 b;
  vec3 n;
};

SG_FN ShadingFrame water_shading_frame(vec2 g) {
  ShadingFrame s;
  s.n = normalize(normal_direction(g));
  s.t = normalize(vec3(1.0, g.x, 0.0));
  s.b = cross(s.n, s.t);
  return s;
}

// h_perp = (h . t, h . b) with h = normalize(v + L) (Tokuyoshi & Kaplanyan 2019).
SG_FN vec2 projected_half_vector(IN(ShadingFrame) s, vec3 v, vec3 L) {
  vec3 h = normalize(v + L);
  return vec2(dot(h, s.t), dot(h, s.b));
}

// d normalize(x) = (dx - u (u . dx)) / |x| with u = normalize(x).
SG_FN vec3 normalize_derivative(vec3 x, vec3 dx) {
  real l = length(x);
  vec3 u = x / l;
  return (dx - u * dot(u, dx)) / l;
}

// The change of h_perp when the water point P seen from `camera` moves by dP along the
// surface, its gradient g moving by H (dP.x, dP.z) (H = (h_xx, h_xz, h_zz), the height's
// Hessian): the chain rule through the view v = normalize(camera - P), the half vector
// and the frame.
SG_FN vec2 projected_half_vector_derivative(vec3 camera, vec3 P, vec2 g, vec3 H, vec3 dP, vec3 L) {
  vec3 e = camera - P;
  vec3 v = normalize(e);
  vec3 dv = normalize_derivative(e, -dP);
  vec3 s = v + L;
  vec3 h = normalize(s);
  vec3 dh = normalize_derivative(s, dv);
  vec2 dg = vec2(H.x * dP.x + H.y * dP.z, H.y * dP.x + H.z * dP.z);
  vec3 T = vec3(1.0, g.x, 0.0);
  vec3 N = normal_direction(g);
  vec3 t = normalize(T);
  vec3 dt = normalize_derivative(T, vec3(0.0, dg.x, 0.0));
  vec3 n = normalize(N);
  vec3 dn = normalize_derivative(N, vec3(-dg.x, 0.0, -dg.y));
  vec3 b = cross(n, t);
  vec3 db = cross(dn, t) + cross(n, dt);
  return vec2(dot(dh, t) + dot(h, dt), dot(dh, b) + dot(h, db));
}

// The kernel's added covariance of tangent slopes for derivatives ddx = dh_perp/dpx and
// ddy = dh_perp/dpy, rect or full (above).
SG_FN mat2 specaa_kernel_covariance(vec2 ddx, vec2 ddy, real sigma2, real kappa, bool full) {
  if (!full) {
    // fwidth, then alpha^2 = min(2 sigma^2 b^2, kappa) per axis; slope variance alpha^2 / 2.
    vec2 bounds = abs(ddx) + abs(ddy);
    real vx = 0.5 * min(2.0 * sigma2 * bounds.x * bounds.x, kappa);
    real vy = 0.5 * min(2.0 * sigma2 * bounds.y * bounds.y, kappa);
    return mat2(vec2(vx, 0.0), vec2(0.0, vy));
  }
  // sigma^2 D D^T (columns of D: ddx, ddy), principal variances clamped at kappa / 2.
  mat2 D = mat2(ddx, ddy);
  mat2 C = sigma2 * D * transpose(D);
  PrincipalAxes p = principal_axes(C);
  real l1 = min(p.s1 * p.s1, 0.5 * kappa);
  real l2 = min(p.s2 * p.s2, 0.5 * kappa);
  vec2 u = p.u;
  vec2 w = vec2(-u.y, u.x);
  return l1 * outerProduct(u, u) + l2 * outerProduct(w, w);
}

// J_G: the Jacobian of the NDF-plane point with respect to the tangent slope m~ at m~ = 0.
// q(m) = (m.x, m.z) / m.y with m = n - s_x t - s_y b: dq/ds for a tangent direction d is
// -((d.x n.y - n.x d.y), (d.z n.y - n.z d.y)) / n.y^2.
SG_FN vec2 specaa_tangent_column(vec3 n, vec3 d) {
  return -vec2(d.x * n.y - n.x * d.y, d.z * n.y - n.z * d.y) / (n.y * n.y);
}
SG_FN mat2 specaa_tangent_to_ndf_plane(IN(ShadingFrame) s) {
  return mat2(specaa_tangent_column(s.n, s.t), specaa_tangent_column(s.n, s.b));
}

SG_FN SpecaaSample specaa_no_sample() {
  SpecaaSample s;
  s.hit = false;
  s.at_camera = false;
  s.point = vec3(0.0);
  s.view = vec3(0.0, 1.0, 0.0);
  s.dp_dpx = vec3(0.0);
  s.dp_dpy = vec3(0.0);
  s.g = vec2(0.0);
  s.h_perp = vec2(0.0);
  return s;
}

// The sample at image-plane point (px, py), at the display time.
SG_FN SpecaaSample specaa_sample(IN(WaveBuffer) waves, IN(Frame) f, real px, real py) {
  SpecaaSample s = specaa_no_sample();
  Footprint fp = pixel_footprint(waves, f, px, py, 0.0, f.displaced);
  if (!fp.hit) return s;
  s.hit = true;
  s.at_camera = !(fp.distance > 0.0);
  s.point = fp.point;
  s.view = fp.view;
  s.dp_dpx = fp.dp_dpx;
  s.dp_dpy = fp.dp_dpy;
  s.g = water_gradient(waves, f, fp.point.x, fp.point.z, 0.0);
  if (f.cascade_count > 0)
    s.g += cascade_gradient(waves, f, frame_segments(f), fp.point.x, fp.point.z);
  s.h_perp = projected_half_vector(water_shading_frame(s.g), s.view, f.light.L);
  return s;
}

// Whether a quad neighbour's h_perp can be differenced with the pixel's.
SG_FN bool specaa_quad_usable(IN(SpecaaSample) s) {
  return s.hit && !s.at_camera;
}

// The analytic derivatives (dh_perp/dpx, dh_perp/dpy) at a sample, as vec4(ddx, ddy).
SG_FN vec4 specaa_analytic_derivatives(IN(WaveBuffer) waves, IN(Frame) f, IN(SpecaaSample) s) {
  vec3 H = water_hessian(waves, f, s.point.x, s.point.z, 0.0);
  if (f.cascade_count > 0) H += cascade_hessian(waves, f, s.point.x, s.point.z);
  vec3 cam = f.camera.position;
  vec2 ddx = projected_half_vector_derivative(cam, s.point, s.g, H, s.dp_dpx, f.light.L);
  vec2 ddy = projected_half_vector_derivative(cam, s.point, s.g, H, s.dp_dpy, f.light.L);
  return vec4(ddx.x, ddx.y, ddy.x, ddy.y);
}

// The pixel's weights for its sample and the derivatives of its h_perp: the kernel's lobe
// about the normal, on the light plane (above).
SG_FN vec4 specaa_lobe_weights(IN(Frame) f, IN(SpecaaParams) p, IN(SpecaaSample) s, vec2 ddx,
                               vec2 ddy) {
  ShadingFrame fr = water_shading_frame(s.g);
  mat2 cov_ts = specaa_kernel_covariance(ddx, ddy, p.sigma2, p.kappa, p.full_kernel);
  mat2 JG = specaa_tangent_to_ndf_plane(fr);
  // The lobe about the centre normal -g on the NDF plane (ndf_lobe.glsl).
  return ndf_lobe_weights(f, s.view, -s.g, JG * cov_ts * transpose(JG));
}

// Pixel (i, j) from its own sample and those of its quad neighbours in x (i ^ 1) and in y
// (j ^ 1), of which only h_perp and specaa_quad_usable are read (a GPU's quad exchanges
// just those).
SG_FN FallbackResult specaa_shade(IN(WaveBuffer) waves, IN(Frame) f, IN(SpecaaParams) p,
                                  IN(SpecaaSample) own, IN(SpecaaSample) nx, IN(SpecaaSample) ny,
                                  int i, int j) {
  FallbackResult r;
  r.fallback = false;
  if (!own.hit) {
    r.weights = miss_pixel_weights(f, i, j);
    return r;
  }
  vec2 ddx;
  vec2 ddy;
  if (!own.at_camera) {
    if (p.quad && specaa_quad_usable(nx) && specaa_quad_usable(ny)) {
      // Within the quad the difference runs from the even to the odd pixel.
      ddx = (i % 2) != 0 ? own.h_perp - nx.h_perp : nx.h_perp - own.h_perp;
      ddy = (j % 2) != 0 ? own.h_perp - ny.h_perp : ny.h_perp - own.h_perp;
    } else {
      vec4 d = specaa_analytic_derivatives(waves, f, own);
      ddx = vec2(d.x, d.y);
      ddy = vec2(d.z, d.w);
    }
    r.weights = specaa_lobe_weights(f, p, own, ddx, ddy);
    if (finite_weights(r.weights)) return r;
  }
  // The camera under the surface (no footprint, no derivatives) or a lobe whose shading is
  // not finite: the centre ray's radiance (`point`'s, from the sample's own point and
  // gradient: no second intersection), counted by the host.
  r.weights = water_weights(f, normal_direction(own.g), own.view);
  r.fallback = true;
  return r;
}

// Pixel (i, j) alone: its sample and, for `quad`, its two neighbours' (a tile or a
// workgroup shares them instead: methods/specaa.cpp, gl_engine/shaders/main.glsl).
SG_FN FallbackResult specaa_pixel(IN(WaveBuffer) waves, IN(Frame) f, IN(SpecaaParams) p, int i,
                                  int j) {
  SpecaaSample own = specaa_sample(waves, f, real(i) + 0.5, real(j) + 0.5);
  SpecaaSample nx = specaa_no_sample();
  SpecaaSample ny = specaa_no_sample();
  if (p.quad && own.hit) {
    nx = specaa_sample(waves, f, real(i - i % 2 * 2 + 1) + 0.5, real(j) + 0.5);
    ny = specaa_sample(waves, f, real(i) + 0.5, real(j - j % 2 * 2 + 1) + 0.5);
  }
  return specaa_shade(waves, f, p, own, nx, ny, i, j);
}
