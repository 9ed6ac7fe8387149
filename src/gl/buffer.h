// A GL buffer object with immutable storage (glNamedBufferStorage): the storage buffers
// (SSBOs: waves, per-pixel output, tables read by index) and uniform buffers (std140 blocks
// of per-frame data) of the GL engine. Made with its size, optionally its contents; updated
// with upload (the storage has GL_DYNAMIC_STORAGE_BIT unless told otherwise), read back with
// read (which waits for the GPU), bound to an indexed binding point with bind. Move-only;
// the context must be current when it is made, used and destroyed.
#pragma once

#include <epoxy/gl.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace sg::gl {

class Buffer {
 public:
  Buffer() = default;
  // `bytes` > 0; `data` null leaves the contents undefined.
  explicit Buffer(std::size_t bytes, const void* data = nullptr,
                  GLbitfield flags = GL_DYNAMIC_STORAGE_BIT);
  template <class T>
  static Buffer of(std::span<const T> data, GLbitfield flags = GL_DYNAMIC_STORAGE_BIT) {
    return Buffer(data.size_bytes(), data.data(), flags);
  }
  ~Buffer();
  Buffer(Buffer&& o) noexcept : id_(o.id_), size_(o.size_) { o.id_ = 0, o.size_ = 0; }
  Buffer& operator=(Buffer&& o) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  GLuint id() const { return id_; }
  std::size_t size() const { return size_; }

  // Writes bytes [offset, offset + bytes); GlError when outside the buffer.
  void upload(std::size_t offset, std::size_t bytes, const void* data);
  template <class T>
  void upload(std::span<const T> data, std::size_t first_element = 0) {
    upload(first_element * sizeof(T), data.size_bytes(), data.data());
  }
  // Sets every 32-bit word to `word` (e.g. a NaN pattern to poison an output).
  void fill(std::uint32_t word);

  // Reads bytes [offset, offset + bytes) back (waits for the GPU's writes; issue the
  // matching glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT) after a shader wrote it).
  void read(std::size_t offset, std::size_t bytes, void* out) const;
  template <class T>
  std::vector<T> read() const {
    std::vector<T> out(size_ / sizeof(T));
    read(0, out.size() * sizeof(T), out.data());
    return out;
  }

  // glBindBufferBase(target, index): GL_SHADER_STORAGE_BUFFER (layout(binding = index)
  // buffer), GL_UNIFORM_BUFFER (layout(std140, binding = index) uniform).
  void bind(GLenum target, GLuint index) const;
  // glBindBufferRange: bytes [offset, offset + bytes) (offset a multiple of the target's
  // alignment).
  void bind_range(GLenum target, GLuint index, std::size_t offset, std::size_t bytes) const;

 private:
  GLuint id_ = 0;
  std::size_t size_ = 0;
};

}  // namespace sg::gl
