// Float textures with immutable storage and one level: the GL engine's output image
// (GL_TEXTURE_2D, GL_RGBA32F, written as an image2D with imageStore) and its tables (R32F
// 2D, 3D or 2D-array textures up to 64 x 512 x 512, read with texelFetch and interpolated
// in the shader: hardware filtering weights have 8 fractional bits). Texel (x, y, z) is
// element ((z * height + y) * width + x) * components of the data handed in or read back.
// Sampling state is nearest and clamp-to-edge. Sizes are checked against the context's
// limits (GL_MAX_TEXTURE_SIZE, GL_MAX_3D_TEXTURE_SIZE, GL_MAX_ARRAY_TEXTURE_LAYERS).
#pragma once

#include <epoxy/gl.h>

#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace sg::gl {

class Texture {
 public:
  Texture() = default;
  // `target` GL_TEXTURE_2D, GL_TEXTURE_3D or GL_TEXTURE_2D_ARRAY; `format` GL_R32F,
  // GL_RG32F or GL_RGBA32F; depth 1 for 2D. Contents undefined until upload or fill.
  Texture(GLenum target, GLenum format, int width, int height, int depth = 1);
  // A 2D image for imageStore (layout(rgba32f, binding = unit) uniform image2D).
  static Texture image_2d(int width, int height, GLenum format = GL_RGBA32F) {
    return Texture(GL_TEXTURE_2D, format, width, height);
  }
  // A table of floats (R32F), uploaded.
  static Texture table(GLenum target, int width, int height, int depth,
                       std::span<const float> data);
  ~Texture();
  Texture(Texture&& o) noexcept;
  Texture& operator=(Texture&& o) noexcept;
  Texture(const Texture&) = delete;
  Texture& operator=(const Texture&) = delete;

  // The whole texture: width * height * depth * components floats.
  void upload(std::span<const float> data);
  void fill(glm::vec4 value);
  std::vector<float> read() const;
  // The 2D region [0, width) x [0, height) of level 0: width * height * components floats.
  std::vector<float> read_region(int width, int height) const;

  // glBindTextureUnit: sampler2D/sampler3D/sampler2DArray with layout(binding = unit).
  void bind_texture(GLuint unit) const;
  // glBindImageTexture (all layers of a 3D or array texture).
  void bind_image(GLuint unit, GLenum access = GL_WRITE_ONLY) const;

  GLuint id() const { return id_; }
  GLenum target() const { return target_; }
  GLenum format() const { return format_; }
  int width() const { return width_; }
  int height() const { return height_; }
  int depth() const { return depth_; }
  int components() const;
  std::size_t floats() const;

 private:
  GLuint id_ = 0;
  GLenum target_ = GL_TEXTURE_2D;
  GLenum format_ = GL_RGBA32F;
  int width_ = 0, height_ = 0, depth_ = 0;
};

}  // namespace sg::gl
