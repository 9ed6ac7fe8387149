// The image the viewer shows, from the GL engine's output to display bytes: the engine's
// radiance weights read back and the scene's radiances applied as the CPU engine's tiles
// apply them (store_pixel), so a view's linear image is `render --engine gl`'s; then the
// display pipeline of `render --display` (exposure, glare, filmic curve, sRGB;
// image/tonemap.h), run here on the CPU on that read-back image (viewer/gpu_display.h runs
// it on the GPU), so the displayed bytes are the same function of the same values; then
// the split: columns left of the divider
// from the first method, the rest from the second.
#pragma once

#include <cstdint>
#include <vector>

#include "gl_engine/gl_engine.h"
#include "image/image.h"
#include "image/tonemap.h"
#include "methods/method.h"

namespace sg::viewer {

// The engine's frame `ctx` as a linear image (1 channel for a grey scene, 3 for colour),
// after its dispatch; also dispatches it.
Image render_linear(gl_engine::GlEngine& engine, const FrameContext& ctx);

// An 8-bit RGB picture, rows top first (a grey image's byte in all three channels).
struct Picture {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
};

// `img` through the display pipeline, as RGB.
Picture display_picture(const Image& img, const DisplaySettings& settings);

// Columns [0, divider) from `left`, [divider, width) from `right` (same size); divider is
// clamped to [0, width].
Picture split_picture(const Picture& left, const Picture& right, int divider);
// The same split of two linear images.
Image split_image(const Image& left, const Image& right, int divider);

// The picture as RGBA floats (byte / 255, alpha 1) for an RGBA32F texture: an 8-bit
// framebuffer stores each byte back exactly.
std::vector<float> picture_texels(const Picture& p);

}  // namespace sg::viewer
