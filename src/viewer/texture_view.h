// Draws an RGBA32F texture (the GL engine's image) into a rectangle of the current
// framebuffer, texel for texel: nearest texels by texelFetch, texture row 0 at the top of
// the rectangle (the engine's images run top to bottom), the values written as they are
// (the display pipeline makes them display-referred before). A full-screen triangle with no
// vertex buffer.
#pragma once

#include "gl/program.h"
#include "gl/texture.h"

namespace sg::viewer {

class TextureView {
 public:
  TextureView();  // compiles the program; needs a current context
  ~TextureView();
  TextureView(const TextureView&) = delete;
  TextureView& operator=(const TextureView&) = delete;

  // Draws `texture` (GL_TEXTURE_2D) into the rectangle (x, y from the framebuffer's
  // bottom-left, GL's convention), scaled to w x h.
  void draw(const gl::Texture& texture, int x, int y, int w, int h) const;

 private:
  gl::Program program_;
  unsigned vertex_array_ = 0;
};

}  // namespace sg::viewer
