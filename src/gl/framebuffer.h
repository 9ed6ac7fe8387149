// Reads the current read framebuffer (a window's back buffer before the swap, or a bound
// framebuffer object) into RGBA8: the viewer's screenshots. Rows come top first (GL's rows
// are bottom first), 4 bytes per pixel.
#pragma once

#include <cstdint>
#include <vector>

namespace sg::gl {

std::vector<std::uint8_t> read_framebuffer_rgba8(int x, int y, int width, int height);

}  // namespace sg::gl
