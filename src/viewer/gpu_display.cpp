#include "viewer/gpu_display.h"

#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include "base/error.h"
#include "embedded/display_sources.h"
#include "gl/dispatch.h"
#include "image/glare.h"

namespace sg::viewer {
namespace {

// Every pass: the pipeline's functions (image/display.glsl, shared with the web page) and
// where its glare passes read (unused by the others).
const char* kCommon = R"(
layout(local_size_x = 16, local_size_y = 16) in;
uniform ivec2 size;
)";

// x = linear * 2^exposure (0 where not finite; alpha: a bit per non-finite channel),
// b = max(x - threshold, 0).
const char* kExpose = R"(
layout(binding = 0) uniform sampler2D linear;
layout(rgba32f, binding = 0) uniform writeonly image2D x_out;
layout(rgba32f, binding = 1) uniform writeonly image2D b_out;
uniform float scale;
uniform float threshold;
vec3 glare_source(ivec2 q) { return vec3(0.0); }
float glare_tap(int i) { return 0.0; }
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (!display_inside(p, size)) return;
  vec4 x = display_expose(texelFetch(linear, p, 0).rgb, scale);
  imageStore(x_out, p, x);
  imageStore(b_out, p, vec4(display_bright(x.rgb, threshold), 0.0));
}
)";

// One 1-D pass of a normalised kernel k[offset .. offset + 2 radius] along `axis`, black
// outside; accumulate: dst += weight * sum, else dst = sum.
const char* kBlur = R"(
layout(rgba32f, binding = 0) uniform readonly image2D src;
layout(rgba32f, binding = 1) uniform image2D dst;
layout(std430, binding = 0) readonly buffer Kernels { float k[]; };
uniform int offset;
uniform int radius;
uniform ivec2 axis;
uniform float weight;
uniform int accumulate;
vec3 glare_source(ivec2 q) { return imageLoad(src, q).rgb; }
float glare_tap(int i) { return k[i]; }
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (!display_inside(p, size)) return;
  vec3 s = display_blur(p, size, offset, radius, axis);
  vec3 prev = accumulate != 0 ? imageLoad(dst, p).rgb : vec3(0.0);
  imageStore(dst, p, vec4(accumulate != 0 ? prev + weight * s : s, 0.0));
}
)";

// A streak along `dir`: the bilinear scatter of glare.cpp gathered (image/display.glsl).
const char* kStreak = R"(
layout(rgba32f, binding = 0) uniform readonly image2D src;
layout(rgba32f, binding = 1) uniform image2D dst;
layout(std430, binding = 0) readonly buffer Kernels { float k[]; };
uniform int offset;
uniform int radius;
uniform vec2 dir;
uniform float weight;
vec3 glare_source(ivec2 q) { return imageLoad(src, q).rgb; }
float glare_tap(int i) { return k[i]; }
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (!display_inside(p, size)) return;
  vec3 s = display_streak(p, size, offset, radius, dir);
  imageStore(dst, p, vec4(imageLoad(dst, p).rgb + weight * s, 0.0));
}
)";

// x - W b + the glare, the filmic curve, sRGB, rounded to bytes, stored as byte / 255.
const char* kFinish = R"(
layout(rgba32f, binding = 0) uniform readonly image2D x_in;
layout(rgba32f, binding = 1) uniform readonly image2D b_in;
layout(rgba32f, binding = 2) uniform readonly image2D acc_in;
layout(rgba32f, binding = 3) uniform writeonly image2D out_image;
uniform float total_weight;
uniform int glare;
vec3 glare_source(ivec2 q) { return vec3(0.0); }
float glare_tap(int i) { return 0.0; }
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (!display_inside(p, size)) return;
  vec3 o = display_finish(imageLoad(x_in, p), imageLoad(b_in, p).rgb, imageLoad(acc_in, p).rgb,
                          total_weight, glare != 0);
  imageStore(out_image, p, vec4(o, 1.0));
}
)";

gl::Program compute(const char* name, const char* body) {
  const gl::ShaderSource s[3] = {{"display_common.glsl", kCommon},
                                 gl::embedded_source(display_sources(), "image/display.glsl"),
                                 {name, body}};
  return gl::Program::compute(std::span(s, 3));
}

}  // namespace

GpuDisplay::GpuDisplay()
    : expose_(compute("display_expose.glsl", kExpose)),
      blur_(compute("display_blur.glsl", kBlur)),
      streak_(compute("display_streak.glsl", kStreak)),
      finish_(compute("display_finish.glsl", kFinish)) {}

void GpuDisplay::resize(int width, int height) {
  if (width == width_ && height == height_) return;
  linear_ = gl::Texture::image_2d(width, height);
  x_ = gl::Texture::image_2d(width, height);
  b_ = gl::Texture::image_2d(width, height);
  tmp_ = gl::Texture::image_2d(width, height);
  acc_ = gl::Texture::image_2d(width, height);
  out_ = gl::Texture::image_2d(width, height);
  width_ = width;
  height_ = height;
}

Picture GpuDisplay::picture(const Image& img, const DisplaySettings& s) {
  if (img.channels != 1 && img.channels != 3)
    throw Error("viewer: the display takes 1 or 3 channels");
  const int w = img.width, h = img.height;
  resize(w, h);
  const size_t n = static_cast<size_t>(w) * h;
  std::vector<float> texels(n * 4);
  for (size_t k = 0; k < n; ++k) {
    for (int c = 0; c < 3; ++c)
      texels[4 * k + c] = img.data[k * img.channels + (img.channels == 3 ? c : 0)];
    texels[4 * k + 3] = 1;
  }
  linear_.upload(texels);
  const glm::ivec2 size(w, h);

  const GlareSettings& g = s.glare_settings;
  linear_.bind_texture(0);
  x_.bind_image(0, GL_WRITE_ONLY);
  b_.bind_image(1, GL_WRITE_ONLY);
  expose_.set("size", size);
  expose_.set("scale", static_cast<float>(std::exp2(s.exposure)));
  expose_.set("threshold", static_cast<float>(g.threshold));
  gl::dispatch_2d(expose_, w, h);
  gl::barrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);

  double total_weight = 0;
  if (s.glare) {
    // The kernels, one after the other (glare.h's weights), and their offsets.
    std::vector<float> k;
    auto add_kernel = [&](const std::vector<double>& kernel) {
      const int offset = static_cast<int>(k.size());
      for (double v : kernel)
        k.push_back(static_cast<float>(v));
      return offset;
    };
    const double px = h;  // sizes are fractions of the image height
    std::vector<int> blur_offsets, blur_radii;
    for (const GlareBlur& b : g.blurs) {
      const std::vector<double> kernel = gaussian_kernel(b.sigma * px);
      blur_offsets.push_back(add_kernel(kernel));
      blur_radii.push_back(static_cast<int>(kernel.size() / 2));
    }
    const std::vector<double> streak = streak_kernel(g.star_length * px);
    const int streak_offset = add_kernel(streak), streak_radius = int(streak.size() / 2);
    const gl::Buffer kernels = gl::Buffer::of(std::span<const float>(k));
    kernels.bind(GL_SHADER_STORAGE_BUFFER, 0);
    acc_.fill(glm::vec4(0));

    for (size_t i = 0; i < g.blurs.size(); ++i) {
      for (int pass = 0; pass < 2; ++pass) {
        (pass == 0 ? b_ : tmp_).bind_image(0, GL_READ_ONLY);
        (pass == 0 ? tmp_ : acc_).bind_image(1, GL_READ_WRITE);
        blur_.set("size", size);
        blur_.set("offset", blur_offsets[i]);
        blur_.set("radius", blur_radii[i]);
        blur_.set("axis", pass == 0 ? glm::ivec2(1, 0) : glm::ivec2(0, 1));
        blur_.set("weight", static_cast<float>(g.blurs[i].weight));
        blur_.set("accumulate", pass);
        gl::dispatch_2d(blur_, w, h);
        gl::barrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
      }
      total_weight += g.blurs[i].weight;
    }
    if (g.star_points > 0 && g.star_weight > 0) {
      const int streaks = g.star_points / 2;
      for (int i = 0; i < streaks; ++i) {
        const double a = (g.star_angle_deg + 180.0 * i / streaks) * std::numbers::pi / 180.0;
        b_.bind_image(0, GL_READ_ONLY);
        acc_.bind_image(1, GL_READ_WRITE);
        streak_.set("size", size);
        streak_.set("offset", streak_offset);
        streak_.set("radius", streak_radius);
        streak_.set("dir", glm::vec2(std::cos(a), std::sin(a)));
        streak_.set("weight", static_cast<float>(g.star_weight / streaks));
        gl::dispatch_2d(streak_, w, h);
        gl::barrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        total_weight += g.star_weight / streaks;
      }
    }
  }
  x_.bind_image(0, GL_READ_ONLY);
  b_.bind_image(1, GL_READ_ONLY);
  acc_.bind_image(2, GL_READ_ONLY);
  out_.bind_image(3, GL_WRITE_ONLY);
  finish_.set("size", size);
  finish_.set("total_weight", static_cast<float>(total_weight));
  finish_.set("glare", s.glare ? 1 : 0);
  gl::dispatch_2d(finish_, w, h);
  gl::barrier(GL_ALL_BARRIER_BITS);

  const std::vector<float> o = out_.read();
  Picture p{w, h, std::vector<std::uint8_t>(n * 3)};
  for (size_t k = 0; k < n; ++k)
    for (int c = 0; c < 3; ++c)
      p.rgb[3 * k + c] = static_cast<std::uint8_t>(std::lround(o[4 * k + c] * 255.0f));
  return p;
}

}  // namespace sg::viewer
