#include "gl/texture.h"

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
      throw GlError("texture: format " + error_name(format) +
                    " is not GL_R32F, GL_RG32F or GL_RGBA32F");
  }
}

GLenum pixel_format(GLenum format) {
  switch (format) {
    case GL_R32F:
      return GL_RED;
    case GL_RG32F:
      return GL_RG;
    default:
      return GL_RGBA;
  }
}

int limit(GLenum name) {
  GLint v = 0;
  glGetIntegerv(name, &v);
  return v;
}

std::string size_text(int w, int h, int d) {
  return std::to_string(w) + " x " + std::to_string(h) + " x " + std::to_string(d);
}

}  // namespace

Texture::Texture(GLenum target, GLenum format, int width, int height, int depth)
    : target_(target), format_(format), width_(width), height_(height), depth_(depth) {
  components_of(format);
  const std::string size = size_text(width, height, depth);
  if (width < 1 || height < 1 || depth < 1) throw GlError("texture " + size + ": empty");
  if (target == GL_TEXTURE_2D || target == GL_TEXTURE_2D_ARRAY) {
    const int max = limit(GL_MAX_TEXTURE_SIZE);
    if (width > max || height > max)
      throw GlError("texture " + size + ": exceeds GL_MAX_TEXTURE_SIZE " + std::to_string(max));
  }
  if (target == GL_TEXTURE_2D && depth != 1)
    throw GlError("texture " + size + ": a 2D texture has depth 1");
  if (target == GL_TEXTURE_2D_ARRAY && depth > limit(GL_MAX_ARRAY_TEXTURE_LAYERS))
    throw GlError("texture " + size + ": exceeds GL_MAX_ARRAY_TEXTURE_LAYERS " +
                  std::to_string(limit(GL_MAX_ARRAY_TEXTURE_LAYERS)));
  if (target == GL_TEXTURE_3D) {
    const int max = limit(GL_MAX_3D_TEXTURE_SIZE);
    if (width > max || height > max || depth > max)
      throw GlError("texture " + size + ": exceeds GL_MAX_3D_TEXTURE_SIZE " + std::to_string(max));
  }
  if (target != GL_TEXTURE_2D && target != GL_TEXTURE_3D && target != GL_TEXTURE_2D_ARRAY)
    throw GlError("texture: target " + error_name(target) + " is not 2D, 3D or 2D array");

  glCreateTextures(target, 1, &id_);
  if (target == GL_TEXTURE_2D)
    glTextureStorage2D(id_, 1, format, width, height);
  else
    glTextureStorage3D(id_, 1, format, width, height, depth);
  glTextureParameteri(id_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(id_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTextureParameteri(id_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id_, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  check_errors("texture " + size);
}

Texture Texture::table(GLenum target, int width, int height, int depth,
                       std::span<const float> data) {
  Texture t(target, GL_R32F, width, height, depth);
  t.upload(data);
  return t;
}

Texture::~Texture() {
  if (id_) glDeleteTextures(1, &id_);
}

Texture::Texture(Texture&& o) noexcept
    : id_(o.id_),
      target_(o.target_),
      format_(o.format_),
      width_(o.width_),
      height_(o.height_),
      depth_(o.depth_) {
  o.id_ = 0;
}

Texture& Texture::operator=(Texture&& o) noexcept {
  if (this != &o) {
    if (id_) glDeleteTextures(1, &id_);
    id_ = o.id_;
    target_ = o.target_;
    format_ = o.format_;
    width_ = o.width_;
    height_ = o.height_;
    depth_ = o.depth_;
    o.id_ = 0;
  }
  return *this;
}

int Texture::components() const {
  return components_of(format_);
}

std::size_t Texture::floats() const {
  return size_t(width_) * size_t(height_) * size_t(depth_) * size_t(components());
}

void Texture::upload(std::span<const float> data) {
  if (data.size() != floats())
    throw GlError("texture " + size_text(width_, height_, depth_) + " upload: " +
                  std::to_string(data.size()) + " floats, expected " + std::to_string(floats()));
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  if (target_ == GL_TEXTURE_2D)
    glTextureSubImage2D(id_, 0, 0, 0, width_, height_, pixel_format(format_), GL_FLOAT,
                        data.data());
  else
    glTextureSubImage3D(id_, 0, 0, 0, 0, width_, height_, depth_, pixel_format(format_), GL_FLOAT,
                        data.data());
  check_errors("texture upload");
}

void Texture::fill(glm::vec4 value) {
  glClearTexImage(id_, 0, GL_RGBA, GL_FLOAT, &value[0]);
  check_errors("texture fill");
}

std::vector<float> Texture::read() const {
  std::vector<float> out(floats());
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTextureImage(id_, 0, pixel_format(format_), GL_FLOAT,
                    static_cast<GLsizei>(out.size() * sizeof(float)), out.data());
  check_errors("texture read");
  return out;
}

std::vector<float> Texture::read_region(int width, int height) const {
  if (width < 1 || height < 1 || width > width_ || height > height_)
    throw GlError("texture read: region " + std::to_string(width) + "x" + std::to_string(height) +
                  " outside the " + std::to_string(width_) + "x" + std::to_string(height_) +
                  " texture");
  std::vector<float> out(size_t(width) * size_t(height) * size_t(components()));
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTextureSubImage(id_, 0, 0, 0, 0, width, height, 1, pixel_format(format_), GL_FLOAT,
                       static_cast<GLsizei>(out.size() * sizeof(float)), out.data());
  check_errors("texture read");
  return out;
}

void Texture::bind_texture(GLuint unit) const {
  glBindTextureUnit(unit, id_);
  check_errors("glBindTextureUnit(" + std::to_string(unit) + ")");
}

void Texture::bind_image(GLuint unit, GLenum access) const {
  const GLboolean layered = target_ == GL_TEXTURE_2D ? GL_FALSE : GL_TRUE;
  glBindImageTexture(unit, id_, 0, layered, 0, access, format_);
  check_errors("glBindImageTexture(" + std::to_string(unit) + ")");
}

}  // namespace sg::gl
