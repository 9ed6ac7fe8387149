// The display pipeline of `render --display` (image/tonemap.h: exposure, glare, the ACES
// filmic curve, sRGB) per pixel, in GLSL, written once for the GPU's two hosts: the
// viewer's GL 4.50 compute shaders (viewer/gpu_display.cpp) and the web page's GLSL ES 3.00
// fragment shaders (web/shaders/display.glsl). In float; the CPU's display_srgb8 computes
// the same function in double (the bytes agree within 1/255 where a value falls on a
// rounding boundary).
//
// The stage that includes this file defines, after it, where the glare's passes read:
//   vec3 glare_source(ivec2 q): the image a pass filters at pixel q (inside the image);
//   float glare_tap(int i): the kernels' weights (image/glare.h's gaussian_kernel and
//   streak_kernel), one kernel after the other.

vec3 glare_source(ivec2 q);
float glare_tap(int i);

bool display_inside(ivec2 p, ivec2 size) {
  return all(greaterThanEqual(p, ivec2(0))) && all(lessThan(p, size));
}

// Exposure: x = v * scale where finite, 0 where not; alpha: a bit per non-finite channel
// (shown white, never glaring).
vec4 display_expose(vec3 v, float scale) {
  vec3 x;
  float flags = 0.0;
  for (int c = 0; c < 3; ++c) {
    bool finite = !isnan(v[c]) && !isinf(v[c]);
    x[c] = finite ? v[c] * scale : 0.0;
    if (!finite) flags += float(1 << c);
  }
  return vec4(x, flags);
}

// The bright part b = max(x - threshold, 0) that glares.
vec3 display_bright(vec3 x, float threshold) {
  return max(x - vec3(threshold), vec3(0.0));
}

// One 1-D pass of the normalised kernel glare_tap(offset .. offset + 2 radius) along
// `axis` at p: black outside the image.
vec3 display_blur(ivec2 p, ivec2 size, int offset, int radius, ivec2 axis) {
  vec3 s = vec3(0.0);
  for (int t = -radius; t <= radius; ++t) {
    ivec2 q = p + t * axis;
    if (display_inside(q, size)) s += glare_tap(offset + t + radius) * glare_source(q);
  }
  return s;
}

// A streak along `dir` at p: the CPU's bilinear scatter of pixel q onto the four
// neighbours of q + t dir (image/glare.cpp, streak_blur) read backwards, each pixel summing
// per tap t the four sources p - floor(t dir) - (0|1, 0|1) with the same bilinear weights,
// so it adds the very terms of the scatter.
vec3 display_streak_at(ivec2 q, ivec2 size) {
  return display_inside(q, size) ? glare_source(q) : vec3(0.0);
}
vec3 display_streak(ivec2 p, ivec2 size, int offset, int radius, vec2 dir) {
  vec3 s = vec3(0.0);
  for (int t = -radius; t <= radius; ++t) {
    vec2 o = float(t) * dir;
    vec2 fl = floor(o);
    vec2 f = o - fl;
    ivec2 q = p - ivec2(fl);
    vec3 v = (1.0 - f.x) * (1.0 - f.y) * display_streak_at(q, size) +
             f.x * (1.0 - f.y) * display_streak_at(q - ivec2(1, 0), size) +
             (1.0 - f.x) * f.y * display_streak_at(q - ivec2(0, 1), size) +
             f.x * f.y * display_streak_at(q - ivec2(1, 1), size);
    s += glare_tap(offset + t + radius) * v;
  }
  return s;
}

// Narkowicz's fit of the ACES filmic curve (image/tonemap.cpp, aces_filmic).
float display_aces(float x) {
  if (isnan(x)) return 1.0;
  if (!(x > 0.0)) return 0.0;
  if (isinf(x)) return 1.0;
  return clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

// The sRGB encoding (image/display.cpp).
float display_srgb(float x) {
  x = clamp(x, 0.0, 1.0);
  return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}

// The displayed bytes / 255 of exposed value x (alpha: expose's flags): x - W b + the
// glare's sum when `glare`, the filmic curve, sRGB, rounded to bytes.
vec3 display_finish(vec4 x, vec3 b, vec3 acc, float total_weight, bool glare) {
  vec3 v = x.rgb;
  if (glare) v = v - total_weight * b + acc;
  int flags = int(x.a);
  vec3 o;
  for (int c = 0; c < 3; ++c) {
    float d = (flags & (1 << c)) != 0 ? 1.0 : display_aces(v[c]);
    o[c] = floor(255.0 * display_srgb(d) + 0.5) / 255.0;
  }
  return o;
}
