#include "gl/texture_buffer.h"

#include <string>

#include "gl/check.h"
#include "gl/error.h"

namespace sg::gl {
namespace {

int components_of(GLenum format) {
  switch (format) {
    case GL_R32F:
      return 1;
    case GL_RG32F:
      return 2;
    case GL_RGBA32F:
      return 4;
    default:
      throw GlError("texture buffer: format " + error_name(format) +
                    " is not GL_R32F, GL_RG32F or GL_RGBA32F");
  }
}

}  // namespace

int max_texture_buffer_texels() {
  GLint n = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &n);
  return n;
}

void check_texture_buffer_texels(std::size_t texels) {
  const size_t limit = size_t(max_texture_buffer_texels());
  if (texels > limit)
    throw GlError("texture buffer: " + std::to_string(texels) +
                  " texels exceed GL_MAX_TEXTURE_BUFFER_SIZE " + std::to_string(limit));
}

TextureBuffer::TextureBuffer(std::span<const float> data, GLenum format)
    : components_(components_of(format)) {
  if (data.empty() || data.size() % size_t(components_) != 0)
    throw GlError("texture buffer: " + std::to_string(data.size()) +
                  " floats is not a positive multiple of " + std::to_string(components_));
  texels_ = data.size() / size_t(components_);
  check_texture_buffer_texels(texels_);
  buffer_ = Buffer::of(data);
  glCreateTextures(GL_TEXTURE_BUFFER, 1, &texture_);
  glTextureBuffer(texture_, format, buffer_.id());
  check_errors("texture buffer of " + std::to_string(texels_) + " texels");
}

TextureBuffer::TextureBuffer(std::size_t texels, GLenum format)
    : texels_(texels), components_(components_of(format)) {
  if (texels == 0) throw GlError("texture buffer: 0 texels");
  check_texture_buffer_texels(texels_);
  buffer_ = Buffer(texels * size_t(components_) * sizeof(float));
  glCreateTextures(GL_TEXTURE_BUFFER, 1, &texture_);
  glTextureBuffer(texture_, format, buffer_.id());
  check_errors("texture buffer of " + std::to_string(texels_) + " texels");
}

TextureBuffer::~TextureBuffer() {
  if (texture_) glDeleteTextures(1, &texture_);
}

TextureBuffer::TextureBuffer(TextureBuffer&& o) noexcept
    : buffer_(std::move(o.buffer_)),
      texture_(o.texture_),
      texels_(o.texels_),
      components_(o.components_) {
  o.texture_ = 0;
  o.texels_ = 0;
}

TextureBuffer& TextureBuffer::operator=(TextureBuffer&& o) noexcept {
  if (this != &o) {
    if (texture_) glDeleteTextures(1, &texture_);
    buffer_ = std::move(o.buffer_);
    texture_ = o.texture_;
    texels_ = o.texels_;
    components_ = o.components_;
    o.texture_ = 0;
    o.texels_ = 0;
  }
  return *this;
}

void TextureBuffer::update(std::span<const float> data, std::size_t first_texel) {
  if (data.size() % size_t(components_) != 0)
    throw GlError("texture buffer update: " + std::to_string(data.size()) +
                  " floats is not a multiple of " + std::to_string(components_));
  buffer_.upload(data, first_texel * size_t(components_));
}

void TextureBuffer::bind(GLuint unit) const {
  glBindTextureUnit(unit, texture_);
  check_errors("texture buffer bind");
}

}  // namespace sg::gl
