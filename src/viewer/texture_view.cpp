#include "viewer/texture_view.h"

#include <epoxy/gl.h>

#include "gl/check.h"
#include "gl/error.h"

namespace sg::viewer {
namespace {

const char* kVertex = R"(
// A triangle covering the viewport: vertices (-1,-1), (3,-1), (-1,3).
void main() {
  vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
  gl_Position = vec4(p, 0.0, 1.0);
}
)";

const char* kFragment = R"(
layout(binding = 0) uniform sampler2D image;
uniform ivec4 rect;  // x, y, w, h of the viewport in framebuffer pixels
out vec4 color;
void main() {
  ivec2 size = textureSize(image, 0);
  vec2 f = (gl_FragCoord.xy - vec2(rect.xy)) / vec2(rect.zw);  // 0..1, y up
  ivec2 t = clamp(ivec2(floor(vec2(f.x, 1.0 - f.y) * vec2(size))), ivec2(0), size - 1);
  color = texelFetch(image, t, 0);
}
)";

}  // namespace

TextureView::TextureView() {
  const gl::ShaderSource vs[] = {{"viewer/texture_view.vert", kVertex}};
  const gl::ShaderSource fs[] = {{"viewer/texture_view.frag", kFragment}};
  program_ = gl::Program::graphics(vs, fs);
  glCreateVertexArrays(1, &vertex_array_);
  gl::check_errors("texture view");
}

TextureView::~TextureView() {
  glDeleteVertexArrays(1, &vertex_array_);
}

void TextureView::draw(const gl::Texture& texture, int x, int y, int w, int h) const {
  if (texture.target() != GL_TEXTURE_2D) throw gl::GlError("texture view: not a 2D texture");
  glViewport(x, y, w, h);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  program_.set("rect", glm::ivec4(x, y, w, h));
  texture.bind_texture(0);
  program_.use();
  glBindVertexArray(vertex_array_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  gl::check_errors("texture view draw");
}

}  // namespace sg::viewer
