// The reflection path of a pixel (Podee et al. 2021, Sec. 3.3, Fig. 1 and 4): the water
// point seen through the pixel centre, and the reflection of the view about the normal of
// the resolved waves at K + 1 instants of the shutter, t_k = start + k (end - start) / K
// (K sub-arcs, "dividing the frame time into subintervals", Sec. 3.5; K = 1 is the paper's
// path from the previous frame to the current one). On flat water under a still camera the
// point is the one at the display time, for the whole interval (the paper samples "a
// single point on the water surface corresponding to the pixel centre"); on displaced water
// each instant's point is where the pixel's ray meets that instant's water (path_views).
//
// The gradients at the instants come from the phases at the display time by angle
// subtraction, cos(theta - c dt) = cos(theta) cos(c dt) + sin(theta) sin(c dt), with the
// rotations of the wave buffer (waves.glsl).
//
// The temporal method (Sec. 3.3) on a path: for each sub-arc, the fractions of time in the
// light disk and below the horizon (arc.glsl, exact for a constant-speed great-circle
// arc), combined into weights with the sub-arc's mean Fresnel factor (the sky at the
// height of the sub-arc's middle), averaged over the sub-arcs.
//
// A camera that moves over the shutter (format /3, camera.glsl; docs/method.md, "A moving
// camera"): at instant t_k the pixel's ray is that of camera_at(t_k), which meets the water
// at its own point p_k; the gradient of instant k is the waves' at p_k and t_k (their
// phases there: the display time's, turned back in time by the rotations and on by
// k . (p_k - p_K), path_terms.glsl), and the reflection of instant k is that
// of the view from p_k towards camera_at(t_k) (PathViews); so on displaced water, whose
// points move along the one ray. A fixed camera over flat water keeps the one point and
// view, and the phases by rotation as above.

// The water points and views of the path's instants. moving false: every instant has the
// display time's point and view (a camera that stands still over flat water, or a zero
// shutter); true under a moving camera, and on displaced water, where the seen point moves
// along the pixel's ray as the water rises and falls (path_views).
struct PathViews {
  bool moving;
  bool camera_moves;             // a moving camera (the instants' views differ too)
  vec2 point[kMaxSegments + 1];  // (x, z) of p_k (camera-relative, as Footprint.point)
  vec3 view[kMaxSegments + 1];   // unit, from p_k towards the camera at t_k
};

// dt of instant k: t_k - end = -duration (K - k) / K (interface.glsl, Frame.segments).
SG_FN real path_instant_dt(IN(Frame) f, int k) {
  return -f.duration * real(frame_segments(f) - k) / real(frame_segments(f));
}

SG_FN PathViews path_views_fixed(vec3 point, vec3 view) {
  PathViews v;
  v.moving = false;
  v.camera_moves = false;
  for (int k = 0; k <= kMaxSegments; ++k) {
    v.point[k] = vec2(point.x, point.z);
    v.view[k] = view;
  }
  return v;
}

// The instants' points and views of image-plane point (px, py), whose display-time
// footprint is fp (its point p_K and view).
// - Under a moving camera the ray of camera_at(t_k) through (px, py) meets the horizontal
//   plane at p_K's height: the water at rest on flat water. An instant whose ray does not
//   reach that plane keeps p_K and its view.
// - On displaced water the water is not where it was at the display time: as it rises and
//   falls over the shutter the ray meets it nearer or further. One Newton step of
//   y(s) - h(x(s), z(s), t_k) = 0 along the instant's ray from that point q (p_K under a
//   fixed camera) moves it to the water of instant k: s += (h_k(q) - q.y) / (d.y - grad
//   h_k(q) . d_xz), every wave and cascade at t_k (intersect.glsl,
//   water_height_slope_at_instant). The step is exact to first order in the height's change
//   (a camera 2.5 m up over a wind sea of 15 m/s: 1 to 3 cm a thirtieth of a second, enough
//   to move a near glint by a pixel at 640 x 360; docs/targets.md). Where the water falls
//   away from the ray the denominator is held at d.y / 2 at least, so the point moves at
//   most twice the height's change over the vertical.
SG_FN PathViews path_views(IN(WaveBuffer) waves, IN(Frame) f, IN(Footprint) fp, real px, real py) {
  PathViews v = path_views_fixed(fp.point, fp.view);
  bool rising = f.displaced && f.duration > 0.0;
  bool camera_moves = false;
#ifndef SG_FIXED_CAMERA
  camera_moves = f.camera_keys.count > 0;
#endif
  if (!rising && !camera_moves) return v;
  v.moving = true;
  v.camera_moves = camera_moves;
  for (int k = 0; k < frame_segments(f); ++k) {
    real dt = path_instant_dt(f, k);
    vec3 o = f.camera.position;
    vec3 d = -fp.view;
    vec3 q = fp.point;
    bool on_ray = true;
#ifndef SG_FIXED_CAMERA
    if (camera_moves) {
      Camera c = camera_at(f, dt);
      o = c.position;
      d = normalize(camera_direction(c, px, py));
      real height = c.position.y - fp.point.y;
      on_ray = d.y < 0.0 && height > 0.0;
      if (on_ray) q = c.position + (height / -d.y) * d;
    }
#endif
    if (rising && on_ray) {
      vec2 hs = water_height_slope_at_instant(waves, f, k, q.x, q.z, dt, vec2(d.x, d.z));
      real den = min(d.y - hs.y, 0.5 * d.y);
      if (den < 0.0) q += ((hs.x - q.y) / den) * d;
    }
    if (on_ray) {
      v.point[k] = vec2(q.x, q.z);
      v.view[k] = normalize(o - q);
    }
  }
  return v;
}

// The instants as the sums over the waves take them (wave_terms.glsl): K, the waves'
// stride, and whether the instants' points move (their points are set apart).
SG_FN void path_instants_base(IN(Frame) f, bool moving, OUT(PathInstants) inst) {
  inst.segments = frame_segments(f);
  inst.wave_stride = f.wave_stride;
  inst.moving = moving;
}

// A fixed camera's.
SG_FN PathInstants path_instants_fixed(IN(Frame) f) {
  PathInstants inst;
  path_instants_base(f, false, inst);
  return inst;
}

// Where the instants' points move (v.moving), each instant's water point as well; written
// in place (`staa`'s pixel inputs hold them: a returned struct of kMaxSegments + 1 points
// was copied whole into them on the CPU, docs/benchmarks.md).
SG_FN void path_instants_into(IN(Frame) f, IN(PathViews) v, OUT(PathInstants) inst) {
  path_instants_base(f, v.moving, inst);
  if (v.moving) {
    for (int k = 0; k <= frame_segments(f); ++k)
      inst.points[k] = v.point[k];
  }
}
SG_FN PathInstants path_instants(IN(Frame) f, IN(PathViews) v) {
  PathInstants inst;
  path_instants_into(f, v, inst);
  return inst;
}

// Every wave at full amplitude: the path of staa-temporal (the definition; the CPU engine
// runs the same terms, path_terms.glsl, in SIMD lanes under SG_CPU_WAVE_SUMS).
// The instants `inst`, the display time's phases at `point` (x, z).
SG_FN PathGradients wave_sum_path_of(IN(WaveBuffer) waves, IN(Frame) f, IN(PathInstants) inst,
                                     vec2 point) {
  PathGradients p = path_gradients_zero(frame_segments(f));
  for (int i = 0; i < f.wave_count; ++i) {
    Wave w = wave_at(waves, f, i);
    real theta = wave_phase(w, point.x, point.y, 0.0);
    path_gradients_add(p, inst, waves, i, w, w.A, sin(theta), cos(theta));
  }
  return p;
}
SG_FN PathGradients wave_sum_path(IN(WaveBuffer) waves, IN(Frame) f, vec3 point) {
  return wave_sum_path_of(waves, f, path_instants_fixed(f), vec2(point.x, point.z));
}

#ifdef SG_CPU_WAVE_SUMS
PathGradients path_gradients(IN(WaveBuffer) waves, IN(Frame) f, vec3 point);
#else
SG_FN PathGradients path_gradients(IN(WaveBuffer) waves, IN(Frame) f, vec3 point) {
  return wave_sum_path(waves, f, point);
}
#endif

// The same under a moving camera (the definition; in SIMD lanes on the CPU, as above).
SG_FN PathGradients wave_sum_path_moving(IN(WaveBuffer) waves, IN(Frame) f, IN(PathViews) v) {
  return wave_sum_path_of(waves, f, path_instants(f, v), v.point[frame_segments(f)]);
}

#ifdef SG_CPU_WAVE_SUMS
PathGradients path_gradients_moving(IN(WaveBuffer) waves, IN(Frame) f, IN(PathViews) v);
#else
SG_FN PathGradients path_gradients_moving(IN(WaveBuffer) waves, IN(Frame) f, IN(PathViews) v) {
  return wave_sum_path_moving(waves, f, v);
}
#endif

struct PathShares {
  vec4 weights;   // the temporal method's weights (sub-arcs combined one by one)
  real in_light;  // fractions of the interval in the light and below the horizon
  real below;
  real fresnel;  // the mean Fresnel factor
};

// The instants' views are v's (a fixed camera: all the same).
SG_FN PathShares temporal_shares_along(IN(Frame) f, IN(PathGradients) p, IN(PathViews) v) {
  PathShares s;
  s.weights = vec4(0.0);
  s.in_light = 0.0;
  s.below = 0.0;
  s.fresnel = 0.0;
  int K = frame_segments(f);
  real inv_k = 1.0 / real(K);
  vec3 n0 = normalize(normal_direction(p.g[0]));
  vec3 r0 = reflect_view(n0, v.view[0]);
  real F0 = fresnel_factor(f.fresnel, dot(n0, v.view[0]));
  for (int k = 0; k < K; ++k) {
    vec3 n1 = normalize(normal_direction(p.g[k + 1]));
    vec3 r1 = reflect_view(n1, v.view[k + 1]);
    real F1 = fresnel_factor(f.fresnel, dot(n1, v.view[k + 1]));
    real F = 0.5 * (F0 + F1);
    ArcFractions a = arc_fractions(r0, r1, f.light);
    vec3 mid = r0 + r1;
    real sky_y = mid.y / max(length(mid), 1e-30);
    s.in_light += a.in_light * inv_k;
    s.below += a.below * inv_k;
    s.fresnel += F * inv_k;
    s.weights += combine_weights(f, F, a.in_light, a.below, sky_y) * inv_k;
    r0 = r1;
    F0 = F1;
  }
  return s;
}

// The temporal method with one view for every instant (a fixed camera).
SG_FN PathShares temporal_shares(IN(Frame) f, IN(PathGradients) p, vec3 view) {
  return temporal_shares_along(f, p, path_views_fixed(vec3(0.0), view));
}
