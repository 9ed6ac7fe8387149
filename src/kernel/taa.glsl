// Temporal anti-aliasing (`taa`): the accumulation that real-time engines ship, the
// alternative Podee et al. 2021 argue against (Sec. 2.2: reprojection "cannot track the
// movement of the reflection direction"). Karis 2014, "High Quality Temporal
// Supersampling"; Salvi 2016, "An Excursion in Temporal Supersampling" (variance
// clipping); Yang, Liu and Salvi 2020, "A Survey of Temporal Antialiasing Techniques"
// (Secs. 3-5). Its two passes, one function each: the sample (taa_sample, per pixel, on
// the frame's inputs) and the resolve (taa_resolve_pixel, per pixel, on images: the
// current samples' radiances and the history). methods/taa.h says the whole method.
//
//  - Jitter: the Halton (2, 3) sequence (radical inverses in bases 2 and 3, Survey Sec. 3.1),
//    indices 1..K cycling with the frame (index (f mod K) + 1: index 0 is the origin, which
//    engines skip), as an offset in [-1/2, 1/2)^2 from the pixel centre.
//  - Motion (the engine's velocity buffer): where the point a sample sees was on the image
//    of the previous frame, whose camera is the camera at the previous display time. Flat
//    water, the plane y = 0, does not move; displaced water is a height field displaced
//    vertically, as a displaced grid mesh: the point (x, h(x, z, t_f), z) was at (x, h(x, z,
//    t_{f-1}), z). The sky, at infinity, moves by its direction alone. motion = p - p'.
//  - History resampling at a reprojected image-plane point (pixel centres at i + 1/2):
//    bilinear, or Catmull-Rom (the cubic convolution of Keys 1981 with a = -1/2, 4 x 4
//    texels; Karis 2014), whose overshoot is clamped to the range of the 2 x 2 nearest texels
//    (anti-ringing). Texel indices clamp to the image's edge; a point outside [0, W] x [0, H]
//    has no history (the pixel shows its current sample).
//  - Neighbourhood box of the current samples in the 3 x 3 pixels around (i, j) (those
//    inside the image): minmax is [min, max] (Karis 2014); variance is [mu - gamma sigma, mu
//    + gamma sigma] (Salvi 2016). Clipping the history towards the box's centre and
//    clamping it to the box are the same operation on one channel.
//  - Blend: out = lerp(history, current, alpha) = (1 - alpha) history + alpha current.
// Each channel is resolved alone, its clamp's box too, as engines that clip in RGB do.

// Radical inverse of `index` (>= 0) in `base` (>= 2).
SG_FN real halton(int index, int base) {
  real f = 1.0;
  real r = 0.0;
  for (int i = index; i > 0; i /= base) {
    f /= real(base);
    r += f * real(i % base);
  }
  return r;
}

// The jitter offset of frame `frame` (any integer) for a cycle of `count` (>= 1) offsets
// (both operands of % kept non-negative: GLSL leaves a negative one's result undefined).
SG_FN vec2 taa_jitter(int frame, int count) {
  int k = (frame >= 0 ? frame % count : count - 1 - (-(frame + 1)) % count) + 1;
  return vec2(halton(k, 2) - 0.5, halton(k, 3) - 0.5);
}

// The ray through the pixel's jittered point at the display time, shaded as `point` shades
// (sampling.glsl, sample_ray), and where the point it sees was on the previous image. A
// fixed camera over flat water sees the plane and the sky stand still: motion 0, exactly.
// A point behind the previous camera has no history.
SG_FN TaaSample taa_sample(IN(WaveBuffer) waves, IN(Frame) f, IN(TaaParams) p, int i, int j) {
  vec2 at = vec2(real(i) + 0.5, real(j) + 0.5) + p.jitter;
  RayHit hit;
  vec3 dir;
  TaaSample r;
  r.weights = sample_ray(waves, f, at.x, at.y, 0.0, hit, dir);
  r.motion = vec2(0.0);
  if (!p.prev_camera_differs && !(f.displaced && hit.hit)) return r;
  Camera c = f.camera;  // (WebGL's GLSL ES takes no ternary on structs)
  if (p.prev_camera_differs) c = p.prev_camera;
  // The point the sample sees, as it was at the previous display time; the sky (dir, the
  // ray's direction) at infinity.
  if (hit.hit) {
    vec3 before = hit.point;
    if (f.displaced) before.y = water_height(waves, f, before.x, before.z, p.dt_prev);
    dir = before - c.position;
  }
  ImagePoint q = camera_project(c, dir);
  r.motion = q.seen ? at - q.p : vec2(kTaaNoHistory);
  return r;
}

// Channel c of texel (x, y), the indices clamped to the image's edge.
SG_FN real taa_texel(IN(ImagePlanes) img, ivec2 size, int x, int y, int c) {
  return plane_value(img, clamp(x, 0, size.x - 1), clamp(y, 0, size.y - 1), c);
}

// Channel c of the history at image-plane point p; found false when p lies outside
// [0, W] x [0, H].
struct TaaHistory {
  bool found;
  real value;
};

SG_FN TaaHistory taa_history(IN(ImagePlanes) h, ivec2 size, vec2 p, bool catmull_rom, int c) {
  TaaHistory r;
  r.found = p.x >= 0.0 && p.x <= real(size.x) && p.y >= 0.0 && p.y <= real(size.y);
  r.value = 0.0;
  if (!r.found) return r;
  real u = p.x - 0.5;
  real v = p.y - 0.5;
  real fu = floor(u);
  real fv = floor(v);
  int i0 = int(fu);
  int j0 = int(fv);
  real a = u - fu;
  real b = v - fv;
  real t00 = taa_texel(h, size, i0, j0, c);
  real t10 = taa_texel(h, size, i0 + 1, j0, c);
  real t01 = taa_texel(h, size, i0, j0 + 1, c);
  real t11 = taa_texel(h, size, i0 + 1, j0 + 1, c);
  if (!catmull_rom) {
    r.value = (1.0 - b) * ((1.0 - a) * t00 + a * t10) + b * ((1.0 - a) * t01 + a * t11);
    return r;
  }
  vec4 wu = catmull_rom_weights(a);  // Keys 1981, a = -1/2 (cascade_grid.glsl)
  vec4 wv = catmull_rom_weights(b);
  real sum = 0.0;
  for (int y = 0; y < 4; ++y) {
    real row = 0.0;
    for (int x = 0; x < 4; ++x)
      row += wu[x] * taa_texel(h, size, i0 - 1 + x, j0 - 1 + y, c);
    sum += wv[y] * row;
  }
  r.value = clamp(sum, min(min(t00, t10), min(t01, t11)), max(max(t00, t10), max(t01, t11)));
  return r;
}

// The box (lo, hi) of channel c of the current samples around pixel (i, j) for clamp mode
// `mode` (kTaaClampMinmax or kTaaClampVariance; kTaaClampNone clips nothing and asks none).
SG_FN vec2 taa_box(IN(ImagePlanes) cur, ivec2 size, int i, int j, int mode, real gamma, int c) {
  real lo = kRealMax;
  real hi = -kRealMax;
  real s = 0.0;
  real s2 = 0.0;
  int n = 0;
  for (int y = max(0, j - 1); y <= min(size.y - 1, j + 1); ++y) {
    for (int x = max(0, i - 1); x <= min(size.x - 1, i + 1); ++x) {
      real v = plane_value(cur, x, y, c);
      lo = min(lo, v);
      hi = max(hi, v);
      s += v;
      s2 += v * v;
      n += 1;
    }
  }
  if (mode == kTaaClampMinmax) return vec2(lo, hi);
  real mu = s / real(n);
  real sigma = sqrt(max(0.0, s2 / real(n) - mu * mu));
  return vec2(mu - gamma * sigma, mu + gamma * sigma);
}

SG_FN real taa_blend(real history, real current, real alpha) {
  return (1.0 - alpha) * history + alpha * current;
}

// Pixel (i, j) of the output: the history reprojected by the pixel's motion, rectified by
// the current samples' box, blended with its current sample; the current sample alone
// where there is no history (outside the previous image, or none yet: has_history false).
SG_FN TaaResolved taa_resolve_pixel(IN(ImagePlanes) current, IN(ImagePlanes) history,
                                    IN(TaaResolveParams) p, bool has_history, vec2 motion, int i,
                                    int j) {
  TaaResolved r;
  r.value = vec4(0.0);
  r.fallback = false;
  vec2 at = vec2(real(i) + 0.5, real(j) + 0.5) - motion;
  for (int c = 0; c < p.channels; ++c) {
    real now = plane_value(current, i, j, c);
    TaaHistory h;
    h.found = false;
    h.value = 0.0;
    if (has_history) h = taa_history(history, p.size, at, p.catmull_rom, c);
    real out_c = now;
    if (h.found) {
      real kept = h.value;
      if (p.clamp != kTaaClampNone) {
        vec2 box = taa_box(current, p.size, i, j, p.clamp, p.gamma, c);
        kept = clamp(kept, box.x, box.y);
      }
      real blended = taa_blend(kept, now, p.alpha);
      if (isnan(blended) || isinf(blended)) {
        r.fallback = true;
      } else {
        out_c = blended;
      }
    }
    r.value[c] = out_c;
  }
  return r;
}
