// The light disk and the horizon in the gradient plane (step 2 of kernel/reference.glsl).
// With m = (-g_x, 1, -g_z) the reflection r = 2 (m.v) m / (m.m) - v lies in the disk
// (r.L >= cos rho) exactly when Q(g) = 2 (m.v)(m.L) - (v.L + cos rho)(m.m) >= 0, a quadratic
// in g: a conic about the gradient g* whose normal is the half vector of v and L. Written
// about g*, where Q = (1 - cos rho)(1 + |g*|^2) and grad Q = 2 (1 - cos rho) g* exactly,
// every term is of the size of the disk, so the test keeps its digits in float. The
// horizon likewise: r.y > 0 exactly when R(g) = v.y (1 - g.g) - 2 v_xz . g > 0. Along a
// cubic Hermite path H(s) both become polynomials of degree 6 in s (kernel/poly6_roots.glsl).

// The light disk and the horizon in the gradient plane for unit view direction v
// (towards the camera): Q(centre + u) = q0 + lin . u + u^T A u, A = (a11, a12, a22).
struct LightConic {
  bool possible;  // some of the disk is above the horizon
  vec2 centre;
  real q0;
  vec2 lin;
  vec3 quad;
  real lambda_max;  // the larger eigenvalue of A
  vec3 v;
};

SG_FN LightConic light_conic(IN(Light) l, vec3 v) {
  LightConic c;
  c.v = v;
  c.possible = l.L.y > -l.sin_radius;
  real one_minus_cos = 0.5 * l.chord2;
  real kappa = dot(v, l.L) + l.cos_radius;
  c.quad = vec3(2.0 * v.x * l.L.x - kappa, v.x * l.L.z + v.z * l.L.x, 2.0 * v.z * l.L.z - kappa);
  real tr = 0.5 * (c.quad.x + c.quad.z);
  real df = 0.5 * (c.quad.x - c.quad.z);
  c.lambda_max = tr + sqrt(df * df + c.quad.y * c.quad.y);
  vec3 h = v + l.L;
  if (h.y > 1e-3 * length(h)) {
    // About g*, the gradient of the normal along h: the exact values there.
    c.centre = vec2(-h.x / h.y, -h.z / h.y);
    c.q0 = one_minus_cos * (1.0 + dot(c.centre, c.centre));
    c.lin = (2.0 * one_minus_cos) * c.centre;
  } else {
    // No upward normal mirrors v onto L (a light at the horizon, a grazing view): Q about
    // g = 0, as written.
    c.centre = vec2(0.0);
    c.q0 = 2.0 * v.y * l.L.y - kappa;
    c.lin = -2.0 * (v.y * vec2(l.L.x, l.L.z) + l.L.y * vec2(v.x, v.z));
  }
  return c;
}

// u^T A y for A = (a11, a12, a22).
SG_FN real conic_form(vec3 A, vec2 u, vec2 y) {
  return u.x * (A.x * y.x + A.y * y.y) + u.y * (A.y * y.x + A.z * y.y);
}

SG_FN real conic_q(IN(LightConic) c, vec2 g) {
  vec2 u = g - c.centre;
  return c.q0 + dot(c.lin, u) + conic_form(c.quad, u, u);
}

// |m|^2 r.y for the gradient g: positive above the horizon.
SG_FN real horizon_r(vec3 v, vec2 g) {
  return v.y * (1.0 - dot(g, g)) - 2.0 * (v.x * g.x + v.z * g.y);
}

// Q(H(s)) for the Hermite coefficients c0..c3 (H = c0 + c1 s + c2 s^2 + c3 s^3).
SG_FN Poly6 conic_poly(IN(LightConic) lc, vec2 c0, vec2 c1, vec2 c2, vec2 c3) {
  vec2 u[4];
  u[0] = c0 - lc.centre;
  u[1] = c1;
  u[2] = c2;
  u[3] = c3;
  Poly6 p;
  for (int n = 0; n <= 6; ++n)
    p.c[n] = 0.0;
  for (int a = 0; a < 4; ++a) {
    p.c[a] += dot(lc.lin, u[a]);
    for (int b = 0; b < 4; ++b)
      p.c[a + b] += conic_form(lc.quad, u[a], u[b]);
  }
  p.c[0] += lc.q0;
  return p;
}

// R(H(s)) likewise.
SG_FN Poly6 horizon_poly(vec3 v, vec2 c0, vec2 c1, vec2 c2, vec2 c3) {
  vec2 h[4];
  h[0] = c0;
  h[1] = c1;
  h[2] = c2;
  h[3] = c3;
  vec2 vh = vec2(v.x, v.z);
  Poly6 p;
  for (int n = 0; n <= 6; ++n)
    p.c[n] = 0.0;
  for (int a = 0; a < 4; ++a) {
    p.c[a] -= 2.0 * dot(vh, h[a]);
    for (int b = 0; b < 4; ++b)
      p.c[a + b] -= v.y * dot(h[a], h[b]);
  }
  p.c[0] += v.y;
  return p;
}
