#include "gl/buffer.h"

#include <string>

#include "gl/check.h"
#include "gl/error.h"

namespace sg::gl {

Buffer::Buffer(std::size_t bytes, const void* data, GLbitfield flags) : size_(bytes) {
  if (bytes == 0) throw GlError("buffer: size 0");
  glCreateBuffers(1, &id_);
  glNamedBufferStorage(id_, static_cast<GLsizeiptr>(bytes), data, flags);
  check_errors("buffer of " + std::to_string(bytes) + " bytes");
}

Buffer::~Buffer() {
  if (id_) glDeleteBuffers(1, &id_);
}

Buffer& Buffer::operator=(Buffer&& o) noexcept {
  if (this != &o) {
    if (id_) glDeleteBuffers(1, &id_);
    id_ = o.id_;
    size_ = o.size_;
    o.id_ = 0;
    o.size_ = 0;
  }
  return *this;
}

static void check_range(std::size_t offset, std::size_t bytes, std::size_t size, const char* what) {
  if (offset > size || bytes > size - offset)
    throw GlError(std::string("buffer ") + what + ": bytes [" + std::to_string(offset) + ", " +
                  std::to_string(offset + bytes) + ") outside its " + std::to_string(size));
}

void Buffer::upload(std::size_t offset, std::size_t bytes, const void* data) {
  check_range(offset, bytes, size_, "upload");
  if (bytes == 0) return;
  glNamedBufferSubData(id_, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
  check_errors("buffer upload");
}

void Buffer::fill(std::uint32_t word) {
  glClearNamedBufferData(id_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &word);
  check_errors("buffer fill");
}

void Buffer::read(std::size_t offset, std::size_t bytes, void* out) const {
  check_range(offset, bytes, size_, "read");
  if (bytes == 0) return;
  glGetNamedBufferSubData(id_, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), out);
  check_errors("buffer read");
}

void Buffer::bind(GLenum target, GLuint index) const {
  glBindBufferBase(target, index, id_);
  check_errors("glBindBufferBase(" + std::to_string(index) + ")");
}

void Buffer::bind_range(GLenum target, GLuint index, std::size_t offset, std::size_t bytes) const {
  glBindBufferRange(target, index, id_, GLintptr(offset), GLsizeiptr(bytes));
  check_errors("glBindBufferRange(" + std::to_string(index) + ", " + std::to_string(offset) + ", " +
               std::to_string(bytes) + ")");
}

}  // namespace sg::gl
