// From normals to reflections (Podee et al. 2021, Sec. 3.4, Eqs. 8-16).
//
// A point n of the NDF plane is the normal m = (n.x, 1, n.y); it reflects the view v into
//     r(n) = 2 (m . v) / (m . m) m - v                                  (Eqs. 9-10)
// which meets the light plane at Phi(n) = r / (r . L) (Eq. 8). Phi is linearised at the
// NDF's centre n_c (Eq. 11) with its 2x2 Jacobian J_c (Eq. 12, by the chain rule through
// r and the projection; tested against finite differences), so a Gaussian NDF of
// covariance Sigma maps to a Gaussian RDF of covariance J_c Sigma J_c^T (Eq. 16).

SG_FN vec3 reflect_about_ndf_point(vec2 n, vec3 v) {
  return reflect_view(vec3(n.x, 1.0, n.y), v);
}

// d(light-plane point) / d(direction r): 3 columns of 2 rows, for r of any length:
// dP_i/dr = (e_i (r . L) - (r . e_i) L) / (r . L)^2.
SG_FN mat3x2 light_plane_jacobian(vec3 r, IN(Light) l) {
  real rl = dot(r, l.L);
  real inv = 1.0 / (rl * rl);
  vec3 row1 = (l.e1 * rl - dot(r, l.e1) * l.L) * inv;
  vec3 row2 = (l.e2 * rl - dot(r, l.e2) * l.L) * inv;
  return mat3x2(vec2(row1.x, row2.x), vec2(row1.y, row2.y), vec2(row1.z, row2.z));
}

// d r / d m for r = 2 (m . v) / (m . m) m - v (m the unnormalised normal):
// dr/dm_j = 2 [v_j m + (m . v) e_j] / (m . m) - 4 (m . v) m_j m / (m . m)^2.
SG_FN mat3 reflection_jacobian_normal(vec3 m, vec3 v) {
  real mm = dot(m, m);
  real mv = dot(m, v);
  mat3 J = mat3(0.0);
  for (int j = 0; j < 3; ++j) {
    vec3 e = vec3(0.0);
    e[j] = 1.0;
    J[j] = (2.0 / mm) * (v[j] * m + mv * e) - (4.0 * mv * m[j] / (mm * mm)) * m;
  }
  return J;
}

// d r / d v: 2 m m^T / (m . m) - I.
SG_FN mat3 reflection_jacobian_view(vec3 m) {
  return (2.0 / dot(m, m)) * outerProduct(m, m) - mat3(1.0);
}

// J_c = dPhi/dn at n (Eq. 12); columns dPhi/dn_x and dPhi/dn_z.
SG_FN mat2 ndf_to_light_plane_jacobian(vec2 n, vec3 v, IN(Light) l) {
  vec3 m = vec3(n.x, 1.0, n.y);
  vec3 r = reflect_view(m, v);
  mat3x2 JP = light_plane_jacobian(r, l) * reflection_jacobian_normal(m, v);
  return mat2(JP[0], JP[2]);
}

// Eq. 16.
SG_FN mat2 rdf_covariance(mat2 J, mat2 ndf_cov) {
  return J * ndf_cov * transpose(J);
}

// Phi linearised at the light instead of at the NDF's centre (sunglint; docs/method.md,
// "The RDF linearised at the light"). The light's share is the NDF's mass over the
// normals that reflect v into the disk, Phi^-1(disk). With n_L the point whose normal
// reflects v onto the light's centre (the half vector h = v + L: n_L = (h.x, h.z) / h.y,
// Phi(n_L) = 0) and J_L = dPhi/dn there,
//     Phi(n) = J_L (n - n_L) + O(|n - n_L|^2),
// so over the disk (|Phi| <= tan_radius) the map is exact to first order in the disk's
// radius whatever the NDF's width, and a Gaussian NDF N(n_c, Sigma) has there the RDF
//     N(J_L (n_c - n_L), J_L Sigma J_L^T).
// Eqs. 11-16 linearise at n_c instead: exact where the NDF is narrow or centred on the
// light, but where the NDF is wide and the light sits in its tail (the far water, a
// grazing or a side light) the density they give the disk is that of a Gaussian whose
// Jacobian was taken far from the disk. `valid` is false where the half vector is within
// kMinAnchorCos of the horizon (a normal tilted by more than 84 degrees).
//
// First order in the radius is not enough where J_L is nearly singular: where the view
// ray passes close to the light (h = v + L short), the normal n_L turns the view by
// almost 180 degrees on a facet seen edge-on (m . v = |h| / 2), and a large disk's
// preimage under J_L, an ellipse of semi-axis tan_radius / s_min along J_L's weaker
// direction, reaches slopes far from n_L where Phi has bent away from its tangent (a
// low sun 6 degrees wide over water 9 degrees from it: the ellipse took in the flat
// water's normals, whose reflections miss the disk by 8 radii, and gave the pixel half
// the light). So the anchor is also tested at that axis's two ends n_L +- e: Phi's
// departure from linear there, |Phi(n_L + e) + Phi(n_L - e)| / 2 (the second-order
// term; the first cancels), must stay within kAnchorBend of the radius, and both ends
// must reflect towards the light's side (r . L > 0); elsewhere the anchor is not valid
// and the RDF is linearised at the NDF's centre (Eqs. 11-16).
// The test costs two reflections a pixel; the bend is about |Phi''| tan_radius / (2 s_min^2)
// of the radius, so it is made only where tan_radius / s_min^2 exceeds kAnchorBendCheck (of
// 1000 random anchors, kernel/rdf_anchor_test.cpp, none was refused below 0.58; the sun's
// 0.27 degrees reach 0.1 only where s_min < 0.22).
const real kMinAnchorCos = 0.1;
const real kAnchorBend = 0.25;
const real kAnchorBendCheck = 0.1;

struct LightAnchor {
  bool valid;
  vec2 n;  // n_L
  mat2 J;  // J_L
};

SG_FN LightAnchor light_anchor(vec3 v, IN(Light) l) {
  LightAnchor a;
  vec3 h = v + l.L;
  a.valid = h.y > kMinAnchorCos * length(h);
  a.n = a.valid ? vec2(h.x, h.z) / h.y : vec2(0.0);
  a.J = a.valid ? ndf_to_light_plane_jacobian(a.n, v, l) : mat2(0.0);
  if (a.valid) {
    // The preimage's longer semi-axis e: J_L^T J_L's smaller eigenvalue s_min^2 and its
    // eigenvector, |e| = tan_radius / s_min.
    mat2 S = transpose(a.J) * a.J;
    real half_trace = 0.5 * (S[0][0] + S[1][1]);
    real half_diff = 0.5 * (S[0][0] - S[1][1]);
    real s_min2 = half_trace - sqrt(half_diff * half_diff + S[0][1] * S[0][1]);
    vec2 u = half_diff >= 0.0 ? vec2(S[0][1], s_min2 - S[0][0]) : vec2(s_min2 - S[1][1], S[0][1]);
    real lu = length(u);
    a.valid = s_min2 > 0.0;
    if (a.valid && l.tan_radius > kAnchorBendCheck * s_min2) {
      vec2 e = lu > 0.0 ? (l.tan_radius / (sqrt(s_min2) * lu)) * u
                        : vec2(l.tan_radius / sqrt(s_min2), 0.0);
      vec3 r_plus = reflect_about_ndf_point(a.n + e, v);
      vec3 r_minus = reflect_about_ndf_point(a.n - e, v);
      a.valid = dot(r_plus, l.L) > 0.0 && dot(r_minus, l.L) > 0.0 &&
                length(light_to_plane(l, r_plus) + light_to_plane(l, r_minus)) <=
                    2.0 * kAnchorBend * l.tan_radius;
    }
    if (!a.valid) {
      a.n = vec2(0.0);
      a.J = mat2(0.0);
    }
  }
  return a;
}

// No anchor: the paper's linearisation at the NDF's centre wherever it is read.
SG_FN LightAnchor light_anchor_none() {
  LightAnchor a;
  a.valid = false;
  a.n = vec2(0.0);
  a.J = mat2(0.0);
  return a;
}

// The light-plane point of NDF-plane point n under the linearisation at the light.
SG_FN vec2 anchored_light_plane(IN(LightAnchor) a, vec2 n) {
  return a.J * (n - a.n);
}
