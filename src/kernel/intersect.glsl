// Where a camera ray meets the water (scene spec, "Radiance along a camera ray", 1).
//
// flat: the plane y = 0. displaced: the first intersection with the height field
// y = h(x, z, t), marched inside the slab |y| <= sum |A_i| that bounds the surface. Along
// the ray, f(s) = y(s) - h(x(s), z(s), t) changes at most at the rate
//     Lip = |d.y| + (sum_i A_i |k_i|) |d.xz|
// so a step of f(s) / Lip cannot pass a zero of f: the first crossing is never skipped.
// Steps are at least graze_depth / Lip, so the only intersections that can be missed are
// grazes that dip less than graze_depth below the surface before leaving it (1e-6 m in
// double, 1e-4 m in float, where positions of ~100 m carry 1e-5 m of rounding). The
// bracketed root is refined by the Illinois variant of regula falsi (Dowell and Jarratt
// 1971) to |f| <= root_tolerance (1e-9 m in double, 1e-5 m in float) or a bracket at
// rounding width. A descending ray that reaches the slab's floor unbracketed (f > 0 there
// by rounding only) hits there. The march stops after kMaxMarchSteps steps (a graze along
// the whole slab at the smallest step), as a miss.
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
};

SG_FN real graze_depth() {
  return kDoublePrecision ? 1e-6 : 1e-4;
}
SG_FN real root_tolerance() {
  return kDoublePrecision ? 1e-9 : 1e-5;
}

SG_FN RayHit no_hit() {
  RayHit r;
  r.hit = false;
  r.s = 0.0;
  r.point = vec3(0.0);
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

// f(s) = y(s) - h at the point o + s d, the first n waves summed.
SG_FN real height_above_first(IN(WaveBuffer) waves, IN(Frame) f, int n, vec3 o, vec3 d, real s,
                              real dt) {
  vec3 p = o + s * d;
  return p.y - water_height_first(waves, f, n, p.x, p.z, dt);
}

// The first n waves' bounds on the ray: the slab |y| <= amplitude (entry and exit
// parameters) and the Lipschitz bound of f along d.
struct MarchSet {
  int n;
  real lip;
  real s_enter;
  real s_exit;
  bool empty;  // the ray misses the slab
};

SG_FN MarchSet march_set(IN(WaveBuffer) waves, IN(Frame) f, int n, vec3 o, vec3 d) {
  MarchSet m;
  m.n = n;
  real amax = f.amplitude_bound;
  real slope = f.slope_bound;
  if (n < f.wave_count) {
    vec4 b = wave_bounds_at(waves, f, n);
    amax = b.y;
    slope = b.z;
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

// The first intersection with y = h(x, z, t), dt = t - display time; `d` unit length.
SG_FN RayHit intersect_displaced(IN(WaveBuffer) waves, IN(Frame) f, vec3 o, vec3 d, real dt) {
  RayHit r = no_hit();
  // The height the left-out waves may have, per unit of ray length (0: every wave).
  real tol = f.intersect_tolerance > 0.0 ? f.intersect_tolerance * pixel_angle(f.camera, d) : 0.0;
  MarchSet m = march_set(waves, f, f.wave_count, o, d);
  if (m.empty) return r;
  real s = m.s_enter;
  if (tol > 0.0) {
    m = march_set(waves, f, first_wave_below(waves, f, tol * s), o, d);
    if (m.empty) return r;
    s = max(s, m.s_enter);
  }
  real s_chosen = s;  // where the set was last chosen
  real min_step = graze_depth() / max(m.lip, 1e-30);
  real fs = height_above_first(waves, f, m.n, o, d, s, dt);
  if (fs <= 0.0) {
    // The ray starts at or below the surface (only when the camera is inside the slab).
    r.hit = true;
    r.s = s;
    r.point = o + s * d;
    return r;
  }
  for (int step = 0; step < kMaxMarchSteps && s < m.s_exit; ++step) {
    if (tol > 0.0 && s > 1.25 * s_chosen) {
      // Further along the ray: fewer waves are visible.
      s_chosen = s;
      int n = first_wave_below(waves, f, tol * s);
      if (n < m.n) {
        m = march_set(waves, f, n, o, d);
        if (m.empty) return r;
        min_step = graze_depth() / max(m.lip, 1e-30);
        if (s < m.s_enter) s = m.s_enter;
        fs = height_above_first(waves, f, m.n, o, d, s, dt);
        if (fs <= 0.0) {
          // The fewer waves are above the ray already: within the tolerance of the surface
          // (the previous set had the ray above it, both are within tau eps s of the whole).
          r.hit = true;
          r.s = s;
          r.point = o + s * d;
          return r;
        }
      }
    }
    real next = min(m.s_exit, s + max(fs / m.lip, min_step));
    if (!(next < kRealMax)) break;
    real fn = height_above_first(waves, f, m.n, o, d, next, dt);
    if (fn <= 0.0) {
      // Root bracketed in [s, next] (f(s) > 0 >= f(next)): Illinois iterations.
      real a = s;
      real fa = fs;
      real b = next;
      real fb = fn;
      int side = 0;
      for (int it = 0; it < kMaxRefineSteps && -fb > root_tolerance(); ++it) {
        real c = (a * fb - b * fa) / (fb - fa);
        if (!(c > a && c < b)) c = 0.5 * (a + b);
        real fc = height_above_first(waves, f, m.n, o, d, c, dt);
        if (fc > 0.0) {
          a = c;
          fa = fc;
          if (side == -1) fb *= 0.5;
          side = -1;
        } else {
          b = c;
          fb = fc;
          if (side == 1) fa *= 0.5;
          side = 1;
        }
        if (b - a <= 4.0 * kRealEpsilon * abs(b)) break;
      }
      // b is on the surface's side f <= 0 within the tolerance; keep its exact height.
      fb = height_above_first(waves, f, m.n, o, d, b, dt);
      r.hit = true;
      r.s = b;
      r.point = o + b * d;
      r.point.y = r.point.y - fb;
      return r;
    }
    s = next;
    fs = fn;
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
    r.point.y = r.point.y - height_above_first(waves, f, m.n, o, d, m.s_exit, dt);
  }
  return r;
}
