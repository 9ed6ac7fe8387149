// The reference estimator (`--method reference`): the pixel's box-filtered mean over the
// pixel square and the shutter interval (the scene spec's value), with the time integral
// done exactly on flat water, so that only the spatial sampling leaves noise.
//
// Flat water. A spatial sample's hit point does not move, so its radiance over the shutter
// depends only on the path of the gradient g(t) = grad h(x, z, t) there:
//   1. The path: g and dg/dt at the instants t_k = end - duration (K - k) / K, k = 0..K
//      (one sine and cosine per wave, the other instants by angle addition with the
//      rotations of the wave buffer: path_derivatives, kernel/reference_path.glsl). Between
//      two instants g is the cubic Hermite interpolant H(s), s in [0, 1], of those values;
//      its error is at most h^4 / 384 max |g''''| <= h^4 / 384 sum A |k| c^4 (h = duration
//      / K), and the host picks K so that this bound is at most 1e-4 of the light's radius
//      (methods/reference.h, reference_time_split).
//   2. The light in gradient space (kernel/light_conic.glsl). With m = (-g_x, 1, -g_z) the
//      reflection r = 2 (m.v) m / (m.m) - v lies in the disk (r.L >= cos rho) exactly when
//          Q(g) = 2 (m.v)(m.L) - (v.L + cos rho)(m.m) >= 0,
//      a quadratic in g: the light is a conic of the gradient plane (an ellipse about the
//      gradient g* whose normal is the half vector of v and L). Written about g*, where
//      Q = (1 - cos rho)(1 + |g*|^2) and grad Q = 2 (1 - cos rho) g* exactly, every term is
//      of the size of the disk, so the test keeps its digits in float. The horizon
//      likewise: r.y > 0 exactly when R(g) = v.y (1 - g.g) - 2 v_xz . g > 0.
//   3. On each sub-interval Q(H(s)) and R(H(s)) are polynomials of degree 6 in s. A cheap
//      bound (|H(s) - H(0)| <= |c1| + |c2| + |c3| with the gradients of Q and R at H(0))
//      proves most sub-intervals free of crossings; the others have the roots of the
//      polynomials isolated in [0, 1] by Bernstein subdivision (the coefficients' sign
//      changes bound the roots: none, exactly one, or split, at most 24 halvings) and
//      refined by safeguarded Newton steps to 1e-12 of the sub-interval (2e-6 in float;
//      kernel/poly6_roots.glsl).
//   4. Between consecutive crossings the state (light, sky, below the horizon) is
//      constant: without Fresnel and sky gradient the weights are the pieces' lengths,
//      exactly; otherwise the smooth factors (Fresnel, the sky's zenith share) are
//      integrated over each piece by 4-point Gauss-Legendre on H.
//   Sub-intervals with a root pair closer than 2^-24 of their length (a path tangent to
//   the rim within that) are taken as not crossing: the error is at most that length.
//   Windows. When K = kMaxSegments sub-intervals cannot meet the bound over the whole
//   shutter (a shutter of many periods of a fast wave: the host's reference_time_split),
//   the shutter is cut into W equal windows (Frame::windows) and each spatial sample
//   integrates exactly over one of them, drawn at random (stratified over the T samples of
//   its cell): the mean over windows is the shutter's mean, so the estimate stays
//   unbiased, and the draw adds noise that the batches measure. The pilot then takes every
//   pixel as busy (its instants cover the last window only).
//
// Displaced water, or a camera that moves during the shutter (format /3): the hit point
// moves, so each sample is traced at its own time (the camera's ray at that time), and
// every pixel takes the full sampling (the pilot below assumes a still camera): every
// spatial stratum takes T samples, each with its own jittered position and its own time
// stratum (positions not shared between times).
//
// Sampling. B independent batches (B >= 2), each S_x x S_y jittered positions, one per
// cell of the pixel, each cell with T samples; the pixel's value is the batches' mean and
// its spread the estimate of its variance (returned per batch: the host applies the
// radiances and forms the variance per channel). Random numbers from the stream of
// (seed, frame, pixel) (rng.glsl) in a fixed order: per batch, per cell in row-major order,
// per sample: x, y (and t on displaced water). Same inputs, same bytes. `first_batch`
// renders batches first_batch .. first_batch + batches - 1 of that order (a study's
// reference renders each batch of a frame as its own unit of work, report/plan.h).

// States between crossings.
const int kStateSky = 0;
const int kStateLight = 1;
const int kStateBelow = 2;

// The weights at gradient g in a piece of state `state` (the integrand of the smooth
// terms): water_weights with the state's light/sky/below decided.
SG_FN vec4 state_weights(IN(Frame) f, vec3 v, vec2 g, int state) {
  if (state == kStateBelow) return sea_weights();
  vec3 m = normal_direction(g);
  real mm = dot(m, m);
  real mv = dot(m, v);
  real F = fresnel_factor(f.fresnel, mv * inversesqrt(mm));
  vec4 above = light_weights();
  if (state == kStateSky) above = sky_weights(f, horizon_r(v, g) / mm);
  return F * above + (1.0 - F) * sea_weights();
}

// The integral over [a, b] (in units of s) of a piece in state `state`.
SG_FN vec4 piece_weights(IN(Frame) f, vec3 v, IN(HermitePath) H, real a, real b, int state) {
  real len = b - a;
  bool smooth_terms = f.fresnel != 0 || f.sky_gradient;
  if (state == kStateBelow) return len * sea_weights();
  if (!smooth_terms)
    return state == kStateLight ? len * light_weights() : len * vec4(0.0, 0.0, 1.0, 0.0);
  // 4-point Gauss-Legendre.
  SG_COUNT(nodes, 4);
  real mid = 0.5 * (a + b);
  real half_len = 0.5 * len;
  vec4 sum = vec4(0.0);
  sum += 0.3478548451374538 *
         state_weights(f, v, hermite_at(H, mid - 0.8611363115940526 * half_len), state);
  sum += 0.6521451548625461 *
         state_weights(f, v, hermite_at(H, mid - 0.3399810435848563 * half_len), state);
  sum += 0.6521451548625461 *
         state_weights(f, v, hermite_at(H, mid + 0.3399810435848563 * half_len), state);
  sum += 0.3478548451374538 *
         state_weights(f, v, hermite_at(H, mid + 0.8611363115940526 * half_len), state);
  return half_len * sum;
}

// The weights of one sub-interval of length h between instants with gradients g0, g1 and
// time derivatives d0, d1, as a fraction of the sub-interval.
SG_FN vec4 subinterval_weights(IN(Frame) f, IN(LightConic) lc, vec2 g0, vec2 d0, vec2 g1, vec2 d1,
                               real h) {
  vec3 v = lc.v;
  HermitePath H = hermite_path(g0, d0, g1, d1, h);
  real reach = length(H.c1) + length(H.c2) + length(H.c3);  // |H(s) - g0| on [0, 1]
  // Q(g0 + e) <= Q(g0) + |grad Q(g0)| |e| + max(lambda_max, 0) |e|^2.
  bool light = lc.possible;
  if (light) {
    vec2 u0 = g0 - lc.centre;
    real q = conic_q(lc, g0);
    vec2 grad = lc.lin + 2.0 * vec2(lc.quad.x * u0.x + lc.quad.y * u0.y,
                                    lc.quad.y * u0.x + lc.quad.z * u0.y);
    light = q + length(grad) * reach + max(lc.lambda_max, 0.0) * reach * reach >= 0.0;
  }
  // R(g0 + e) >= R(g0) - |grad R(g0)| |e| - v.y |e|^2.
  real r0 = horizon_r(v, g0);
  vec2 grad_r = -2.0 * vec2(v.x, v.z) - (2.0 * v.y) * g0;
  bool horizon = r0 - length(grad_r) * reach - v.y * reach * reach <= 0.0;

  // The crossings, merged in increasing order, between the sub-interval's ends.
  real cuts[14];
  int n = 0;
  cuts[0] = 0.0;
  n = 1;
  Roots6 rq;
  rq.count = 0;
  Roots6 rr;
  rr.count = 0;
  if (light) rq = poly6_roots(conic_poly(lc, H.c0, H.c1, H.c2, H.c3));
  if (horizon) rr = poly6_roots(horizon_poly(v, H.c0, H.c1, H.c2, H.c3));
  for (int k = 0; k < 6; ++k) {
    rq.s[k] = k < rq.count ? rq.s[k] : 2.0;
    rr.s[k] = k < rr.count ? rr.s[k] : 2.0;
  }
  int iq = 0;
  int ir = 0;
  for (int k = 0; k < 12; ++k) {
    if (iq >= rq.count && ir >= rr.count) break;
    bool take_q = ir >= rr.count || (iq < rq.count && rq.s[iq] <= rr.s[ir]);
    real s = 0.0;
    if (take_q) {
      s = rq.s[iq];
      iq += 1;
    } else {
      s = rr.s[ir];
      ir += 1;
    }
    cuts[n] = clamp(s, cuts[n - 1], 1.0);
    n += 1;
  }
  cuts[n] = 1.0;
  n += 1;

  vec4 sum = vec4(0.0);
  for (int k = 0; k + 1 < n; ++k) {
    real a = cuts[k];
    real b = cuts[k + 1];
    if (!(b > a)) continue;
    vec2 g = hermite_at(H, 0.5 * (a + b));
    int state = kStateSky;
    if (horizon && horizon_r(v, g) <= 0.0) {
      state = kStateBelow;
    } else if (light && conic_q(lc, g) >= 0.0) {
      state = kStateLight;
    }
    sum += piece_weights(f, v, H, a, b, state);
  }
  return sum;
}

// The weights of a water point seen from unit direction v, averaged exactly over the
// shutter along its path p.
SG_FN vec4 path_time_weights(IN(Frame) f, vec3 v, IN(PathDerivatives) p) {
  LightConic lc = light_conic(f.light, v);
  real h = f.duration / real(f.windows * frame_segments(f));
  vec4 sum = vec4(0.0);
  for (int k = 0; k < frame_segments(f); ++k)
    sum += subinterval_weights(f, lc, p.g[k], p.dg[k], p.g[k + 1], p.dg[k + 1], h);
  return sum / real(frame_segments(f));
}

// One spatial sample on flat water, integrated over the shutter's window that ends dt
// (<= 0) after the display time (the whole shutter when there is one window).
SG_FN vec4 exact_time_sample(IN(WaveBuffer) waves, IN(Frame) f, real px, real py, real dt) {
  vec3 d = normalize(camera_direction(f.camera, px, py));
  RayHit hit = intersect_flat(f.camera.position, d);
  if (!hit.hit) return miss_weights(f, d);
  PathDerivatives p = path_derivatives(waves, f, hit.point, dt);
  return path_time_weights(f, -d, p);
}

// The pilot of the adaptive design: the reflections at the path's instants (K + 1) at the
// pixel's centre and four corners, at fixed positions (no random numbers, so the choice
// it makes does not depend on the estimate's samples, which stays unbiased). The pixel is
// busy when some reflection comes within margin (spread + step) of the disk's rim or of
// the horizon, where spread is the largest distance between the corners' and the centre's
// reflections at one instant and step the largest move of one between instants; or when
// some pilot ray misses the water and another meets it (the horizon's line); or when the
// visible light's disk covers part of the pixel (kernel/disk_coverage.glsl). A quiet pixel
// is still estimated without bias, from fewer samples; its variance is measured as any.
SG_FN bool reference_pixel_busy(IN(WaveBuffer) waves, IN(Frame) f, real margin, int i, int j) {
  // The visible disk over the pixel's square (the sky's part of the pixel sees it).
  if (f.light.visible && light_pixel_coverage(f.camera, f.light, i, j) > 0.0) return true;
  vec3 centre[kMaxSegments + 1];
  for (int k = 0; k <= kMaxSegments; ++k)
    centre[k] = vec3(0.0);
  real chord = sqrt(f.light.chord2);
  real dmin = kRealMax;
  real ymin = kRealMax;
  real spread = 0.0;
  real step = 0.0;
  int hits = 0;
  for (int q = 0; q < 5; ++q) {
    real px = real(i) + (q == 0 ? 0.5 : real(q % 2));
    real py = real(j) + (q == 0 ? 0.5 : real((q - 1) / 2));
    vec3 d = normalize(camera_direction(f.camera, px, py));
    vec3 o = f.camera.position;
    RayHit hit;
    if (f.displaced) {
      hit = intersect_displaced(waves, f, o, d, 0.0);
    } else {
      hit = intersect_flat(o, d);
    }
    if (!hit.hit) continue;
    hits += 1;
    PathGradients p = path_gradients(waves, f, hit.point);
    vec3 previous = vec3(0.0);
    for (int k = 0; k <= frame_segments(f); ++k) {
      vec3 m = normal_direction(p.g[k]);
      vec3 r = reflect_view(m, -d);
      dmin = min(dmin, length(r - f.light.L));
      ymin = min(ymin, r.y);
      if (k > 0) step = max(step, length(r - previous));
      previous = r;
      if (q == 0) {
        centre[k] = r;
      } else {
        spread = max(spread, length(r - centre[k]));
      }
    }
  }
  if (hits == 0) return false;
  if (hits < 5) return true;
  real reach = margin * (spread + step);
  return dmin < chord + reach || ymin < reach;
}

// Whether the pixel takes the full strata: every pixel when the pilot is off, when the
// camera moves (the pilot's rays are those of one instant) and when the shutter has
// windows (the pilot's instants are the last window's); else the pilot's choice.
SG_FN bool reference_busy(IN(WaveBuffer) waves, IN(Frame) f, IN(ReferenceParams) n, int i, int j) {
  return !n.adaptive || f.camera_keys.count > 0 || f.windows > 1 ||
         reference_pixel_busy(waves, f, n.margin, i, j);
}

// The strata of a pixel per batch: S_x x S_y when busy, quiet_sx x quiet_sy otherwise.
SG_FN ivec2 reference_strata(IN(ReferenceParams) n, bool busy) {
  return busy ? ivec2(n.sx, n.sy) : ivec2(n.quiet_sx, n.quiet_sy);
}

// The samples of one batch of a pixel (T per stratum).
SG_FN int reference_batch_samples(IN(ReferenceParams) n, bool busy) {
  ivec2 c = reference_strata(n, busy);
  return c.x * c.y * n.nt;
}

// The sum of the weights of samples [begin, next) of pixel (i, j), in the order of the
// rendered batches' samples (batch, then cell in row-major order, then time stratum; the
// batches first_batch onwards); `next` is `end` (or the pixel's count), or earlier where the
// platform's loop budget ran out after a traced sample (loop_budget_spent, sample_work: as
// stratified_samples, whose `next` follows each sample taken likewise; a flat sample's
// crossing search is bounded, and the pass's size counts it).
// The stream is advanced to the first sample's draws (two uniforms per sample, three on
// displaced water and with windows, two outputs each), so that any split of the samples into
// ranges gives the same samples as one range: the GL engine renders a pixel in several
// passes of a few samples each, each from where the last one stopped
// (gl_engine/gl_engine.cpp: llvmpipe ends every loop of an invocation after 65535
// iterations in all, docs/reference-renderer.md).
SG_FN vec4 reference_samples(IN(WaveBuffer) waves, IN(Frame) f, IN(ReferenceParams) n, bool busy,
                             int i, int j, int begin, int end, OUT(int) next) {
  ivec2 strata = reference_strata(n, busy);
  int sx = strata.x;
  int sy = strata.y;
  int per_batch = sx * sy * n.nt;
  int last = min(end, n.batches * per_batch);
  vec4 sum = vec4(0.0);
  next = begin;
  if (begin >= last) return sum;
  Pcg32 rng = pixel_rng(f.seed, f.frame, i, j);
  bool traced = f.displaced || f.camera_keys.count > 0;  // each sample at its own time
  bool windowed = !traced && f.windows > 1;              // each over its own window
  int draws = (traced || windowed ? 3 : 2) * 2;
  pcg32_advance(rng, uint(n.first_batch * per_batch + begin) * uint(draws));
  real work = 0.0;
  for (int s = begin; s < last; ++s) {
    if (s > begin && loop_budget_spent(work)) break;
    int q = s % n.nt;
    int cell = (s / n.nt) % (sx * sy);
    int cx = cell % sx;
    int cy = cell / sx;
    real px = real(i) + (real(cx) + pcg32_uniform(rng)) / real(sx);
    real py = real(j) + (real(cy) + pcg32_uniform(rng)) / real(sy);
    if (traced) {
      real dt = (real(q) + pcg32_uniform(rng)) / real(n.nt) * f.duration - f.duration;
      RayHit hit;
      vec3 dir;
      sum += sample_ray(waves, f, px, py, dt, hit, dir);
      work += sample_work(f, hit);
    } else if (windowed) {
      int w =
          min(int((real(q) + pcg32_uniform(rng)) / real(n.nt) * real(f.windows)), f.windows - 1);
      sum += exact_time_sample(waves, f, px, py, -real(w) * (f.duration / real(f.windows)));
    } else {
      sum += exact_time_sample(waves, f, px, py, 0.0);
    }
    next = s + 1;
  }
  return sum;
}

SG_FN ReferenceResult reference_pixel(IN(WaveBuffer) waves, IN(Frame) f, IN(ReferenceParams) n,
                                      int i, int j) {
  ReferenceResult r;
  r.weights = vec4(0.0);
  for (int b = 0; b < kMaxBatches; ++b)
    r.batch[b] = vec4(0.0);
  r.busy = reference_busy(waves, f, n, i, j);
  int per_batch = reference_batch_samples(n, r.busy);
  for (int b = 0; b < n.batches; ++b) {
    int next;
    r.batch[b] =
        reference_samples(waves, f, n, r.busy, i, j, b * per_batch, (b + 1) * per_batch, next) /
        real(per_batch);
    r.weights += r.batch[b];
  }
  r.weights = r.weights / real(n.batches);
  return r;
}
