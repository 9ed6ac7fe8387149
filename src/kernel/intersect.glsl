// Where a camera ray meets the water (scene spec, "Radiance along a camera ray", 1).
//
// flat: the plane y = 0. displaced: the first intersection with the height field
// y = h(x, z, t), marched inside the slab |y| <= sum |A_i| that bounds the surface. Along
// the ray, f(s) = y(s) - h(x(s), z(s), t) changes at most at the rate
//     Lip = |d.y| + (sum_i A_i |k_i|) |d.xz|
// so a step of f(s) / Lip cannot pass a zero of f: the first crossing is never skipped.
// Two bounds make the steps longer where that one is short (march_probe), each a lower
// bound on f past s, so neither skips a crossing either:
//  - second order: |f''| <= curv = (sum_i A_i |k_i|^2) |d.xz|^2, so f(s + t) >=
//    f(s) + f'(s) t - curv t^2 / 2, with f'(s) = d.y - grad h . d.xz summed beside the
//    height; where the ray runs level with the water (f' near 0, a graze over a long
//    swell) the step grows as sqrt(f) instead of f;
//  - the long waves first: the waves are summed in |k| order, kMarchBlock at a time, and
//    after the first n, f >= f_n - e_n (e_n the amplitude of the rest), with f_n's own
//    smaller rate and curvature; the sum stops as soon as its step is at least what every
//    wave's first-order step could be.
// On the displaced test scenes at 160x90 (tests/scenes/displaced-swell.json,
// displaced-wind.json) this takes 9.9 and 13.9 steps a ray for 50.8 and 83.6 (the
// longest ray 208 and 328 for 3936 and 3486), and sums 5.7 and 8.3 times fewer wave
// terms (each a sine and a cosine where it was a sine): docs/ocean.md.
// Steps are at least graze_depth / Lip and two rounding units of s, so the only
// intersections that can be missed are grazes that dip less than graze_depth (1e-6 m in
// double, 1e-4 m in float, where positions of ~100 m carry 1e-5 m of rounding), or than
// the rounding of s itself, below the surface before leaving it. The
// bracketed root is refined by the Illinois variant of regula falsi (Dowell and Jarratt
// 1971) to |f| <= root_tolerance (1e-9 m in double, 1e-5 m in float) or a bracket at
// rounding width. A descending ray that reaches the slab's floor unbracketed (f > 0 there
// by rounding only) hits there. The march stops after kMaxMarchSteps steps (a graze along
// the whole slab at the smallest step), as a miss.
//
// Cascades shaded from their fields (cascade_grid.glsl) are marched as Catmull-Rom's
// bicubic of their height grids, summed before the first block: the bounds of the set
// and of each prefix add the interpolants' bounds of the cascades marched
// (cascade_interpolant_bounds: height, slope and curvature from the grids' maxima), so the
// steps stay safe; the fields are the display time's (dt = 0: the methods that read them
// take no other time). The tolerance below leaves out the last cascades (the finest, in
// the generator's order) as it leaves out the shortest waves, first: at s the march takes
// the fewest first cascades whose rest bounds the height by at most tau eps s, and the
// fewest waves whose suffix amplitude fits what is left of tau eps s; a cascade left out
// takes its curvature bound, which the finest cascade's texel makes large, out of the
// second-order step, so far rays step far longer.
//
// The waves a pixel cannot see in the geometry (Frame.intersect_tolerance = tau > 0).
// Leaving out the waves j >= n (the shortest: the wave buffer is sorted by |k|) changes
// the height by at most e_n = sum_{j>=n} A_j, the suffix's amplitude (waves.glsl). At ray
// parameter s the march sums the first n(s) waves, the fewest with e_n(s) <= tau eps s,
// where eps is a lower bound on the angle between neighbouring pixels' rays there
// (pixel_angle), so eps s is at most the width of the pixel's ray bundle; n(s) falls as
// s grows (re-chosen whenever s has grown by a quarter), and so do the slab and the
// Lipschitz bound of the waves summed (the table's prefix sums). What the bound gives:
//  - the hit returned at s_h lies within tau eps s_h (plus root_tolerance) of the full
//    surface, vertically, and before it the ray never dips more than tau eps s (plus
//    graze_depth) below the full surface;
//  - where the ray crosses the surface (not a graze), a vertical error e moves the hit
//    along the ray by e cos(beta) / sin(g) (beta the tangent plane's tilt, g the angle
//    between the ray and that plane), that is by e cos(beta) cos(g) / sin(g) across the
//    tangent plane, where a pixel's footprint is at least eps s / sin(g) long in that
//    direction: the water point moves by at most e / (eps s) <= tau of the pixel's
//    footprint, to first order;
//  - a crest that the ray passes within e of may be hit or missed (a graze): there the
//    bound holds vertically only.
// kernel/resolved_waves_test.cpp checks this against the full intersection on a 256-wave sea.
// tau = 0: every wave, the march above exactly.

const int kMaxMarchSteps = 2000000;
const int kMaxRefineSteps = 100;

struct RayHit {
  bool hit;
  real s;  // ray parameter along the direction given (point = origin + s dir)
  vec3 point;
  int steps;  // the displaced march's steps and refinements that found it (0 on flat water)
};

SG_FN real graze_depth() {
  return kDoublePrecision ? 1e-6 : 1e-4;
}
SG_FN real root_tolerance() {
  return kDoublePrecision ? 1e-9 : 1e-5;
}

// A root of f bracketed in [a, b] (f(a) > 0 >= f(b)), refined by the Illinois variant of
// regula falsi (Dowell and Jarratt 1971): the secant's point (the midpoint where rounding
// puts it outside), and the end kept twice in a row has its value halved.
struct RootBracket {
  real a;
  real fa;
  real b;
  real fb;
  int side;
};

SG_FN RootBracket root_bracket(real a, real fa, real b, real fb) {
  RootBracket br;
  br.a = a;
  br.fa = fa;
  br.b = b;
  br.fb = fb;
  br.side = 0;
  return br;
}
// Whether to refine further: f(a) > 0 and f(b) below the root tolerance.
SG_FN bool root_bracket_open(IN(RootBracket) br) {
  return br.fa > 0.0 && -br.fb > root_tolerance();
}
SG_FN real root_bracket_next(IN(RootBracket) br) {
  real c = (br.a * br.fb - br.b * br.fa) / (br.fb - br.fa);
  if (!(c > br.a && c < br.b)) c = 0.5 * (br.a + br.b);
  return c;
}
// Takes f(c) = fc; true once the bracket is at rounding width.
SG_FN bool root_bracket_take(INOUT(RootBracket) br, real c, real fc) {
  if (fc > 0.0) {
    br.a = c;
    br.fa = fc;
    if (br.side == -1) br.fb *= 0.5;
    br.side = -1;
  } else {
    br.b = c;
    br.fb = fc;
    if (br.side == 1) br.fa *= 0.5;
    br.side = 1;
  }
  return br.b - br.a <= 4.0 * kRealEpsilon * abs(br.b);
}

SG_FN RayHit no_hit() {
  RayHit r;
  r.hit = false;
  r.s = 0.0;
  r.point = vec3(0.0);
  r.steps = 0;
  return r;
}

// The plane y = 0; `d` need not be unit length.
SG_FN RayHit intersect_flat(vec3 o, vec3 d) {
  RayHit r = no_hit();
  if (o.y > 0.0 ? d.y >= 0.0 : d.y <= 0.0) return r;
  r.s = -o.y / d.y;
  r.point = o + r.s * d;
  r.point.y = 0.0;
  r.hit = true;
  return r;
}

// A lower bound on the angle between the rays through neighbouring pixel centres, at unit
// direction d of a camera ray: the smaller image-plane pixel size p of camera_direction's
// plane (at distance 1 along `forward`), times cos^2 of d's angle phi from the axis (the
// plane is 1 / cos(phi) away along d, and tilted by phi).
SG_FN real pixel_angle(IN(Camera) c, vec3 d) {
  real cphi = max(dot(d, c.forward), 0.0);
  return min(2.0 * c.half_w / c.width, 2.0 * c.half_h / c.height) * cphi * cphi;
}

// f(s) = y(s) - h at the point o + s d, the first n waves and the first nc cascades'
// fields summed (cascade_grid.glsl).
SG_FN real height_above_first(IN(WaveBuffer) waves, IN(Frame) f, int n, int nc, vec3 o, vec3 d,
                              real s, real dt) {
  vec3 p = o + s * d;
  real h = water_height_first(waves, f, n, p.x, p.z, dt);
  if (nc > 0) h += cascade_height_gradient_first(waves, f, nc, p.x, p.z).x;
  return p.y - h;
}

// The water's height at camera-relative (x, z) at path instant k (dt from the display
// time), every wave and cascade, and its slope along horizontal u: (h, grad h . u). The
// waves in the march's blocks (water_height_slope, in SIMD lanes on the CPU); a cascade's
// height from its fields at instant k (cascade_grid.glsl, cascade_height_gradient_of).
SG_FN vec2 water_height_slope_at_instant(IN(WaveBuffer) waves, IN(Frame) f, int k, real x, real z,
                                         real dt, vec2 u) {
  vec2 r = vec2(0.0);
  for (int lo = 0; lo < f.wave_count; lo += kMarchBlock)
    r += water_height_slope(waves, f, lo, min(lo + kMarchBlock, f.wave_count), x, z, dt, u.x, u.y);
  if (f.cascade_count > 0) {
    vec3 c = cascade_height_gradient_of(waves, f, f.cascade_count, k, x, z);
    r += vec2(c.x, c.y * u.x + c.z * u.y);
  }
  return r;
}

// The first n waves' and nc cascades' bounds on the ray: the slab |y| <= amplitude (entry
// and exit parameters) and the Lipschitz bound of f along d.
struct MarchSet {
  int n;
  int nc;
  real lip;
  real s_enter;
  real s_exit;
  bool empty;  // the ray misses the slab
};

SG_FN MarchSet march_set(IN(WaveBuffer) waves, IN(Frame) f, int n, int nc, vec3 o, vec3 d) {
  MarchSet m;
  m.n = n;
  m.nc = nc;
  real amax = f.amplitude_bound;
  real slope = f.slope_bound;
  if (n < f.wave_count || nc < f.cascade_count) {
    vec4 b = wave_bounds_at(waves, f, n);
    vec3 cb = cascade_bounds_first(waves, f, nc);
    amax = b.y + cb.x;
    slope = b.z + cb.y;
  }
  m.lip = abs(d.y) + slope * length(vec2(d.x, d.z));
  m.s_enter = 0.0;
  m.s_exit = 0.0;
  m.empty = false;
  if (d.y < 0.0) {
    m.s_enter = max(0.0, (o.y - amax) / -d.y);
    m.s_exit = (o.y + amax) / -d.y;
  } else if (d.y > 0.0) {
    m.empty = o.y > amax;
    m.s_exit = (amax - o.y) / d.y;
  } else {
    m.empty = abs(o.y) > amax;
    m.s_exit = kRealMax;
  }
  m.empty = m.empty || !(m.s_exit >= m.s_enter);
  return m;
}

// The largest step t with g + fp t - curv t^2 / 2 > 0 on [0, t): from a point where a lower
// bound on f is g > 0 and falls at rate -fp, with |f''| <= curv, no zero of f is nearer.
// Written so that no two near-equal numbers are subtracted (fp < 0: the root
// 2 g / (sqrt(fp^2 + 2 curv g) + |fp|)).
SG_FN real march_second_order_step(real g, real fp, real curv) {
  real root = sqrt(fp * fp + 2.0 * curv * g);
  if (fp < 0.0) return 2.0 * g / (root - fp);
  return curv > 0.0 ? (fp + root) / curv : kRealMax;
}

// One look at f from s (see the header): the march's waves m.n summed kMarchBlock at a
// time in |k| order with the height's derivative along the ray. After the first n waves,
// f >= f_n - e_n - graze_depth (e_n the amplitude of waves n..m.n, the margin for
// rounding) and f_n changes at most at the rate Lip_n = |d.y| + (sum_{j<n} A_j |k_j|) |d.xz|
// and curves at most by curv_n = (sum_{j<n} A_j |k_j|^2) |d.xz|^2, so no zero of f lies
// within the larger of (f_n - e_n) / Lip_n and the second-order step from f_n's derivative
// along the ray. The sum stops once that step is at least what every wave's first-order
// step could be, (f_n + e_n) / Lip; with every wave summed the step is also at least the
// first-order step and min_step, as before.
struct MarchProbe {
  real step;  // f has no zero in [s, s + step)
  bool full;  // every wave of the set summed: f is f(s)
  real f;
};

SG_FN MarchProbe march_probe(IN(WaveBuffer) waves, IN(Frame) fr, IN(MarchSet) m, vec3 o, vec3 d,
                             real s, real dt, real min_step) {
  MarchProbe r;
  vec3 p = o + s * d;
  r.step = 0.0;
  r.full = m.n == 0;
  r.f = p.y;
  real dxz = length(vec2(d.x, d.z));
  real e_all = wave_bounds_at(waves, fr, m.n).x;  // the amplitude of the waves past the set
  // The set's cascades' fields first, whole (their bounds beside each prefix's).
  vec3 cb = cascade_bounds_first(waves, fr, m.nc);
  vec2 hs = vec2(0.0);
  if (m.nc > 0) {
    vec3 hc = cascade_height_gradient_first(waves, fr, m.nc, p.x, p.z);
    hs = vec2(hc.x, hc.y * d.x + hc.z * d.z);
    r.f = p.y - hc.x;
  }
  for (int b = 0; b < m.n; b += kMarchBlock) {
    int hi = min(m.n, b + kMarchBlock);
    hs += water_height_slope(waves, fr, b, hi, p.x, p.z, dt, d.x, d.z);
    vec4 bounds = wave_bounds_at(waves, fr, hi);
    real fn = p.y - hs.x;
    real e = hi < m.n ? max(bounds.x - e_all, 0.0) + graze_depth() : 0.0;
    real g = fn - e;
    if (g > 0.0) {
      real lip = abs(d.y) + (bounds.z + cb.y) * dxz;
      r.step =
          max(r.step,
              max(g / lip, march_second_order_step(g, d.y - hs.y, (bounds.w + cb.z) * dxz * dxz)));
    }
    if (hi == m.n) {
      r.full = true;
      r.f = fn;
      break;
    }
    if (r.step >= max((fn + e) / m.lip, min_step)) break;
  }
  if (r.full) r.step = max(r.step, max(r.f / m.lip, min_step));
  if (r.full && m.n == 0 && m.nc > 0 && r.f > 0.0) {
    // The cascades alone: their second-order step, from the interpolant's slope along the
    // ray and its curvature bound.
    r.step = max(r.step, march_second_order_step(r.f, d.y - hs.y, cb.z * dxz * dxz));
  }
  return r;
}

// The waves and cascades a march needs where the left-out ones may have a height of at
// most `budget` (tau eps s at ray length s): the budget goes to the cascades first, the
// finest left out while their bounds sum to at most it (first_cascade_below), and what
// they leave of it to the explicit waves, the shortest left out likewise
// (first_wave_below).
struct MarchChoice {
  int n;   // the first n waves
  int nc;  // the first nc cascades
};

SG_FN MarchChoice march_choice(IN(WaveBuffer) waves, IN(Frame) f, real budget) {
  MarchChoice c;
  c.nc = first_cascade_below(waves, f, budget);
  real rest = cascade_bounds(waves, f).x - cascade_bounds_first(waves, f, c.nc).x;
  c.n = first_wave_below(waves, f, max(budget - rest, 0.0));
  return c;
}

// The first intersection with y = h(x, z, t), dt = t - display time; `d` unit length.
SG_FN RayHit intersect_displaced(IN(WaveBuffer) waves, IN(Frame) f, vec3 o, vec3 d, real dt) {
  RayHit r = no_hit();
  // The height the left-out waves may have, per unit of ray length (0: every wave).
  real tol = f.intersect_tolerance > 0.0 ? f.intersect_tolerance * pixel_angle(f.camera, d) : 0.0;
  MarchSet m = march_set(waves, f, f.wave_count, f.cascade_count, o, d);
  if (m.empty) return r;
  real s = m.s_enter;
  if (tol > 0.0) {
    MarchChoice c = march_choice(waves, f, tol * s);
    m = march_set(waves, f, c.n, c.nc, o, d);
    if (m.empty) return r;
    s = max(s, m.s_enter);
  }
  real s_chosen = s;  // where the set was last chosen
  real min_step = graze_depth() / max(m.lip, 1e-30);
  real s_prev = s;    // the last position looked at, f > 0 there
  real f_prev = 0.0;  // f(s_prev) when prev_full
  bool prev_full = false;
  bool first = true;      // s is the ray's first position in the slab
  bool rechosen = false;  // the set was chosen again at s
  for (int step = 0; step < kMaxMarchSteps; ++step) {
    SG_COUNT(march_steps, 1);
    r.steps = step + 1;
    if (tol > 0.0 && s > 1.25 * s_chosen) {
      // Further along the ray: fewer waves are visible.
      s_chosen = s;
      MarchChoice c = march_choice(waves, f, tol * s);
      // nc only falls as s grows; n may rise where a cascade left the set (what it leaves
      // out is taken from the waves' share): either set is within tau eps s of the whole.
      if (c.n != m.n || c.nc != m.nc) {
        m = march_set(waves, f, c.n, c.nc, o, d);
        if (m.empty) return r;
        min_step = graze_depth() / max(m.lip, 1e-30);
        if (s < m.s_enter) s = m.s_enter;
        rechosen = true;
      }
    }
    MarchProbe q = march_probe(waves, f, m, o, d, s, dt, min_step);
    if (q.full && q.f <= 0.0) {
      if (first || rechosen) {
        // The ray starts at or below the surface (only when the camera is inside the
        // slab), or the fewer waves are above the ray already: within the tolerance of the
        // surface (the previous set had the ray above it, both are within tau eps s of the
        // whole).
        r.hit = true;
        r.s = s;
        r.point = o + s * d;
        return r;
      }
      // Root bracketed in [s_prev, s] (f(s_prev) > 0 >= f(s)): Illinois iterations.
      real a = s_prev;
      real fa = prev_full ? f_prev : height_above_first(waves, f, m.n, m.nc, o, d, a, dt);
      real b = s;
      real fb = q.f;
      if (!(fa > 0.0)) {
        // Zero at s_prev by rounding (the bound said f > 0 there).
        b = a;
        fb = fa;
      }
      RootBracket br = root_bracket(a, fa, b, fb);
      for (int it = 0; it < kMaxRefineSteps && root_bracket_open(br); ++it) {
        r.steps += 1;
        real c = root_bracket_next(br);
        if (root_bracket_take(br, c, height_above_first(waves, f, m.n, m.nc, o, d, c, dt))) break;
      }
      // b is on the surface's side f <= 0 within the tolerance; keep its exact height.
      b = br.b;
      fb = height_above_first(waves, f, m.n, m.nc, o, d, b, dt);
      r.hit = true;
      r.s = b;
      r.point = o + b * d;
      r.point.y = r.point.y - fb;
      return r;
    }
    if (s >= m.s_exit) break;
    first = false;
    rechosen = false;
    s_prev = s;
    f_prev = q.f;
    prev_full = q.full;
    // At least the rounding unit of s: far from the camera in float (s of kilometres, a
    // unit of 1e-4 m and more) a step below it left s where it was, and the march stood
    // until kMaxMarchSteps (seconds a ray on the CPU; on llvmpipe, whose loop limit cut
    // it, a miss: random scene 96 of the engines' agreement run, seed 7).
    real next = min(m.s_exit, s + max(q.step, 2.0 * kRealEpsilon * abs(s)));
    if (!(next < kRealMax)) break;
    s = next;
  }
  if (d.y < 0.0 && s >= m.s_exit) {
    // The march reached the slab's floor going down, where the ray is at or below the
    // lowest the surface can be: f(s_exit) <= 0, positive only by rounding (a slab of zero
    // thickness when the tolerance leaves out every wave, a trough touching the floor). The
    // crossing is there; before, such rays missed the water and saw the sky (a 1-wave sea
    // seen from 191 m: kernel/resolved_waves_test.cpp).
    r.hit = true;
    r.s = m.s_exit;
    r.point = o + m.s_exit * d;
    r.point.y = r.point.y - height_above_first(waves, f, m.n, m.nc, o, d, m.s_exit, dt);
  }
  return r;
}
