#include "gl/framebuffer.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <string>

#include "gl/check.h"
#include "gl/error.h"

namespace sg::gl {

std::vector<std::uint8_t> read_framebuffer_rgba8(int x, int y, int width, int height) {
  if (width < 1 || height < 1)
    throw GlError("read_framebuffer_rgba8: empty rectangle " + std::to_string(width) + " x " +
                  std::to_string(height));
  const size_t row = size_t(width) * 4;
  std::vector<std::uint8_t> pixels(row * size_t(height));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(x, y, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  check_errors("glReadPixels");
  for (int j = 0; j < height / 2; ++j)
    std::swap_ranges(pixels.begin() + std::ptrdiff_t(row * size_t(j)),
                     pixels.begin() + std::ptrdiff_t(row * size_t(j + 1)),
                     pixels.begin() + std::ptrdiff_t(row * size_t(height - 1 - j)));
  return pixels;
}

}  // namespace sg::gl
