// The smooth terms of the water's radiance averaged over the pixel's distribution of
// normals: the Fresnel-weighted sky, F(n . v) sky(r), and the sea, (1 - F) on the part
// that reflects above the horizon and 1 below it (radiance.glsl). Taken at the mean normal
// (the temporal method, Podee et al. 2021 Sec. 3.3), they miss the curvature of Schlick's
// factor in the slope, strong at grazing view, and the horizon's cut through the
// distribution; `staa` integrates them over the same Gaussian that it maps to the light
// plane for the light (Eqs. 4-7), widened by the pixel footprint of the resolved waves and
// the path of the normal over the shutter (docs/method.md, "The smooth terms").
//
// In NDF-plane coordinates s (the normal m = (s.x, 1, s.y)) and the unit view v with
// v.y > 0, write s = a e + b e' with e the view's horizontal direction (v.x, v.z) / h,
// h = |(v.x, v.z)|, and e' across it. Then m . v = a h + v.y and m . m = 1 + a^2 + b^2:
// F(m . v / |m|) and the reflection's height r.y = 2 (m . v) / (m . m) - v.y depend on the
// slope across the view only through b^2, which enters |m|^2 beside 1 + a^2. The integral
// over the 2D Gaussian is taken as one over a, with b^2 at its conditional mean given a:
// with a = mu_a + sigma_a u, u ~ N(0, 1), E[b^2 | u] = (mu_b + gamma u)^2 + S_c,
// gamma = S_ab / sigma_a and S_c = S_bb - S_ab^2 / S_aa (the Gaussian's conditional
// moments). The reflection points above the horizon where
//     G = v.y (a^2 + b^2) - 2 h a - v.y < 0,
// (r.y > 0 <=> 2 (m . v) - v.y (m . m) > 0), with b^2 as above a quadratic in u: the set
// above is an interval [lo, hi] between its roots. Where neither root lies within 8
// deviations the u integral is 5-point Gauss-Hermite; otherwise it is integrated over the
// interval only, in the normal's tail probability, so that the horizon's cut and the sky's
// square root at it cost no accuracy (smooth_cut_piece). 5 evaluations of F and the sky
// per Gaussian away from the horizon, 8 (16 when both roots cut) where it crosses the
// distribution, a third of the 2D rule's (3-point Gauss-Hermite across the cut's
// direction times the same rules along it) that it replaced. Against a dense 2D grid over
// the same Gaussian: within 6e-5 where the spread across the view is at most 0.2 in slope;
// up to 7e-4 in E[F ...] and 4e-3 in the share above where it is 0.25-0.3 both ways with
// the mean tilted across (b^2 fluctuates about its mean there). `staa`'s images moved by
// under 3e-7 RMSE (docs/method.md, "The smooth terms").
// The pixel's view is taken at its centre (its change across a pixel, ~1e-3 rad, is far
// below the normals'). Tested against the dense grid (kernel/smooth_terms_test.cpp).

// Probabilists' Gauss-Hermite nodes and weights: 5 points, 0, +-sqrt(5 -+ sqrt(10)).
const real kGh5P = 1.3556261799742659;    // sqrt(5 - sqrt(10))
const real kGh5Q = 2.8569700138728056;    // sqrt(5 + sqrt(10))
const real kGh5W0 = 0.53333333333333333;  // 8 / 15
const real kGh5WP = 0.22207592200561265;
const real kGh5WQ = 0.011257411327720691;

// The integrand at NDF-plane point s: vec3(F, F z, F h), with z the sky's zenith share
// and h its horizon share (radiance.glsl: sky_shares; z = 0 and h = 1 where r points
// below the horizon: the rule's nodes all lie above it, or far enough from it not to
// matter, and without a gradient). Both shares are summed, not one and 1 minus it: each
// keeps its digits where the other is near 1.
SG_FN vec3 smooth_integrand(IN(Frame) f, vec2 s, vec3 v) {
  vec3 m = vec3(s.x, 1.0, s.y);
  real F = f.fresnel == 0 ? 1.0 : fresnel_schlick(dot(m, v) * inversesqrt(dot(m, m)));
  real ry = reflect_view(m, v).y;
  vec2 zh = vec2(0.0, 1.0);
  if (f.sky_gradient) zh = sky_shares(f, ry);
  return vec3(F, F * zh.x, F * zh.y);
}

// The one-dimensional form of a Gaussian of normals (above): the NDF-plane point at
// standard coordinate u along the view's direction, a e + sqrt(E[b^2 | u]) e'. The sign
// of b does not matter (F and r.y see b^2 only).
struct SmoothLine {
  vec2 e;  // the view's horizontal direction in the NDF plane
  vec2 e_across;
  real mu_a;  // the mean slope along e
  real sigma_a;
  real mu_b;  // across: mean, the regression on u, the conditional variance
  real gamma;
  real s_c;
};

SG_FN vec2 smooth_line_point(IN(SmoothLine) l, real u) {
  real b = l.mu_b + l.gamma * u;
  return (l.mu_a + l.sigma_a * u) * l.e + sqrt(b * b + l.s_c) * l.e_across;
}

// (E[F], E[F z], E[F h], mass) of the standard normal u over [c, e], c > -8 the horizon's cut
// (e may be the clamp at 10), along the line's u times `dir` (+1, or -1 for a cut at the
// upper end turned to the lower). In the upper-tail probability q = Q(u) the piece runs
// from Q(c) down to Q(e) with the density uniform; with q = Q(c) - mass g(tau),
// g = tau^2 (3 - 2 tau), the integrand's square-root behaviour at the cut (r.y ~ u - c
// there, the sky's (r.y)^exponent) becomes smooth in tau, and the quantile's logarithmic
// growth at the far end (q -> 0) is pressed into g's flat end: mass int_0^1 h(Q^-1(q))
// g'(tau) dtau by 8-point Gauss-Legendre, with Q^-1(q) = -Phi^-1(q) (special.glsl:
// normal_quantile). Against a dense grid the pieces err by about 1e-5 (the test), where
// g = tau^2 alone erred by 3e-4.
SG_FN vec4 smooth_cut_piece(IN(Frame) f, IN(SmoothLine) l, real dir, vec3 v, real c, real e) {
  real qc = 0.5 * erfc(c * kInvSqrtTwo);
  real mass = normal_mass(c, e);
  vec3 sum = vec3(0.0);
  SG_COUNT(nodes, 8);
  for (int q = 0; q < 8; ++q) {
    real x = q < 4 ? -kGl8X[q] : kGl8X[q - 4];
    real wq = 0.5 * (q < 4 ? kGl8W[q] : kGl8W[q - 4]);
    real tau = 0.5 * (1.0 + x);
    real g = tau * tau * (3.0 - 2.0 * tau);
    real dg = 6.0 * tau * (1.0 - tau);
    real u = -normal_quantile(qc - mass * g);
    sum += (wq * dg) * smooth_integrand(f, smooth_line_point(l, dir * u), v);
  }
  return vec4(mass * sum, mass);
}

// The integrals over N(mu, cov) in NDF-plane coordinates for the unit view v.
SG_FN SmoothTerms smooth_terms(IN(Frame) f, vec2 mu, mat2 cov, vec3 v) {
  SmoothTerms res;
  res.f_above = 0.0;
  res.f_zenith = 0.0;
  res.f_horizon = 0.0;
  res.above = 0.0;
  vec2 vh = vec2(v.x, v.z);
  real h2 = dot(vh, vh);
  real h = sqrt(h2);
  SmoothLine l;
  // Straight down (h = 0) every direction is alike: any e.
  l.e = h2 > 0.0 ? vh / h : vec2(1.0, 0.0);
  l.e_across = vec2(-l.e.y, l.e.x);
  real s_aa = max(dot(l.e, cov * l.e), 0.0);
  real s_ab = dot(l.e, cov * l.e_across);
  real s_bb = max(dot(l.e_across, cov * l.e_across), 0.0);
  l.mu_a = dot(mu, l.e);
  l.mu_b = dot(mu, l.e_across);
  l.sigma_a = sqrt(s_aa);
  l.gamma = s_aa > 0.0 ? s_ab / l.sigma_a : 0.0;
  l.s_c = max(s_bb - l.gamma * l.gamma, 0.0);
  // G(u) = a2 u^2 + 2 b1 u + c0: above where negative.
  real a2 = v.y * (s_aa + l.gamma * l.gamma);
  real b1 = v.y * (l.mu_a * l.sigma_a + l.mu_b * l.gamma) - h * l.sigma_a;
  real c0 = v.y * (l.mu_a * l.mu_a + l.mu_b * l.mu_b + l.s_c) - 2.0 * h * l.mu_a - v.y;
  real lo = -10.0;
  real hi = 10.0;
  if (a2 > 0.0) {
    real disc = b1 * b1 - a2 * c0;
    if (disc <= 0.0) return res;
    // The roots in the form that does not cancel: q / a2 and c0 / q.
    real q = -(b1 + (b1 >= 0.0 ? 1.0 : -1.0) * sqrt(disc));
    real r1 = q / a2;
    real r2 = c0 / q;
    lo = max(lo, min(r1, r2));
    hi = min(hi, max(r1, r2));
  } else if (c0 >= 0.0) {
    // No spread along u (a point distribution): all or nothing.
    return res;
  }
  if (hi <= lo) return res;
  if (f.fresnel == 0 && !f.sky_gradient) {
    // F = 1 and z = 0: the share above the horizon is all.
    real m0 = normal_mass(lo, hi);
    res.f_above = m0;
    res.f_horizon = m0;
    res.above = m0;
    return res;
  }
  // Roots beyond 8 deviations cut off less than 1e-15: no cut.
  bool cut_lo = lo > -8.0;
  bool cut_hi = hi < 8.0;
  vec4 t;  // (E[F], E[F z], E[F h], mass) over the interval
  if (!cut_lo && !cut_hi) {
    t = vec4(0.0, 0.0, 0.0, 1.0);
    SG_COUNT(nodes, 5);
    for (int q = 0; q < 5; ++q) {
      real x = q == 0 ? 0.0 : (q < 3 ? kGh5P : kGh5Q) * (q % 2 == 1 ? 1.0 : -1.0);
      vec3 g = smooth_integrand(f, smooth_line_point(l, x), v);
      real wq = q == 0 ? kGh5W0 : (q < 3 ? kGh5WP : kGh5WQ);
      t.x += wq * g.x;
      t.y += wq * g.y;
      t.z += wq * g.z;
    }
  } else {
    // One piece with its cut at the lower end (the cut at the upper end turned there by
    // u -> -u), or, both ends cut, two split at the middle, each with its cut at one end.
    // One call in a loop rather than a call for each case: a GL program holds the
    // piece's code once, which llvmpipe runs whether taken or not (docs/gpu.md).
    bool both = cut_lo && cut_hi;
    real mid = 0.5 * (lo + hi);
    t = vec4(0.0);
    for (int piece = 0; piece < (both ? 2 : 1); ++piece) {
      bool upper = piece == 1 || !cut_lo;
      real c = upper ? -hi : lo;
      real e = both ? (upper ? -mid : mid) : (upper ? -lo : hi);
      t += smooth_cut_piece(f, l, upper ? -1.0 : 1.0, v, c, e);
    }
  }
  res.f_above = clamp(t.x, 0.0, t.w);
  res.f_zenith = clamp(t.y, 0.0, res.f_above);
  res.f_horizon = clamp(t.z, 0.0, res.f_above);
  res.above = t.w;
  return res;
}

// The weights (light, zenith, horizon, sea) from the smooth terms, with a share in_light
// of the normals reflecting into the light at Fresnel factor F_light: the light replaces
// the sky there (its zenith weight taken at the light's height).
SG_FN vec4 smooth_weights(IN(Frame) f, IN(SmoothTerms) s, real F_light, real in_light) {
  real lit = F_light * min(in_light, s.above);
  vec4 sl = sky_weights(f, f.light.L.y);
  real zenith = max(0.0, s.f_zenith - lit * sl.y);
  real horizon = max(0.0, s.f_horizon - lit * sl.z);
  return vec4(lit, zenith, horizon, 1.0 - s.f_above);
}
