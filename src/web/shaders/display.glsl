// The web page's display passes (GLSL ES 3.00 fragment shaders): the display pipeline of
// `render --display` with image/display.glsl's functions, the viewer's compute passes
// (viewer/gpu_display.cpp) as fragment passes, one fragment per pixel, texel (i, j) pixel
// (i, j) with row 0 on top:
//   SG_PASS_EXPOSE  the kernel's weights times the scene's radiances (Radiances::apply,
//                   scene/model.h), exposed: x (alpha: non-finite flags) and the bright
//                   part b, two render targets;
//   SG_PASS_BLUR    one 1-D pass of a glare Gaussian, added with its weight to the
//                   accumulator read from acc_in (a pass cannot read what it writes);
//   SG_PASS_STREAK  one star streak, added likewise;
//   SG_PASS_FINISH  x - W b + the glare, the filmic curve, sRGB: bytes / 255 (an RGBA8
//                   target stores them exactly);
//   SG_PASS_COMPOSE the canvas: columns left of the divider from one side's bytes, the rest
//                   from the other's, row 0 at the top of the canvas.
uniform ivec2 size;
uniform sampler2D src;     // EXPOSE: weights; BLUR, STREAK: the image filtered
uniform sampler2D acc_in;  // BLUR, STREAK: the accumulator so far
uniform sampler2D taps;    // BLUR, STREAK: glare.h's kernels, one after the other (row 0)

vec3 glare_source(ivec2 q) {
  return texelFetch(src, q, 0).rgb;
}
float glare_tap(int i) {
  return texelFetch(taps, ivec2(i, 0), 0).x;
}

#if defined(SG_PASS_EXPOSE)
uniform vec4 radiance_r;  // (light, zenith, horizon, sea) of each channel
uniform vec4 radiance_g;
uniform vec4 radiance_b;
uniform float scale;
uniform float threshold;
layout(location = 0) out vec4 x_out;
layout(location = 1) out vec4 b_out;
void main() {
  vec4 w = texelFetch(src, ivec2(gl_FragCoord.xy), 0);
  vec3 linear = vec3(dot(w, radiance_r), dot(w, radiance_g), dot(w, radiance_b));
  x_out = display_expose(linear, scale);
  b_out = vec4(display_bright(x_out.rgb, threshold), 0.0);
}
#elif defined(SG_PASS_BLUR)
uniform int offset;
uniform int radius;
uniform ivec2 axis;
uniform float weight;
uniform bool accumulate;
out vec4 acc_out;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec3 s = display_blur(p, size, offset, radius, axis);
  acc_out = vec4(accumulate ? texelFetch(acc_in, p, 0).rgb + weight * s : s, 0.0);
}
#elif defined(SG_PASS_STREAK)
uniform int offset;
uniform int radius;
uniform vec2 dir;
uniform float weight;
out vec4 acc_out;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec3 s = display_streak(p, size, offset, radius, dir);
  acc_out = vec4(texelFetch(acc_in, p, 0).rgb + weight * s, 0.0);
}
#elif defined(SG_PASS_FINISH)
uniform sampler2D x_in;
uniform sampler2D b_in;
uniform float total_weight;
uniform bool glare;
out vec4 bytes_out;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec3 acc = glare ? texelFetch(acc_in, p, 0).rgb : vec3(0.0);
  bytes_out = vec4(
      display_finish(texelFetch(x_in, p, 0), texelFetch(b_in, p, 0).rgb, acc, total_weight, glare),
      1.0);
}
#elif defined(SG_PASS_COMPOSE)
uniform sampler2D left;
uniform sampler2D right;
uniform int divider;  // columns [0, divider) from `left`
out vec4 canvas_out;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  p.y = size.y - 1 - p.y;  // the canvas's row 0 is at its bottom
  canvas_out = p.x < divider ? texelFetch(left, p, 0) : texelFetch(right, p, 0);
}
#endif
