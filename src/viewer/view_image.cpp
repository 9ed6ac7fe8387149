#include "viewer/view_image.h"

#include <algorithm>

#include "base/error.h"

namespace sg::viewer {

Image render_linear(gl_engine::GlEngine& engine, const FrameContext& ctx) {
  engine.dispatch(ctx);
  const std::vector<float> w = engine.read_weights();
  const int width = ctx.model.width(), height = ctx.model.height();
  Image img = Image::with_channels(width, height, ctx.model.scene.grey() ? 1 : 3);
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const float* p = &w[(static_cast<size_t>(j) * width + i) * 4];
      if (engine.outputs_radiances()) {  // `taa`: resolved on the GPU
        for (int c = 0; c < img.channels; ++c)
          img.at(i, j, c) = p[c];
      } else {
        store_pixel(ctx, img, i, j, RadianceWeights(p[0], p[1], p[2], p[3]));
      }
    }
  }
  return img;
}

Picture display_picture(const Image& img, const DisplaySettings& settings) {
  const std::vector<std::uint8_t> bytes = display_srgb8(img, settings);
  Picture p{img.width, img.height, {}};
  const size_t n = static_cast<size_t>(img.width) * img.height;
  if (img.channels == 3) {
    p.rgb = bytes;
  } else {
    p.rgb.resize(n * 3);
    for (size_t k = 0; k < n; ++k)
      p.rgb[3 * k] = p.rgb[3 * k + 1] = p.rgb[3 * k + 2] = bytes[k];
  }
  return p;
}

Picture split_picture(const Picture& left, const Picture& right, int divider) {
  if (left.width != right.width || left.height != right.height)
    throw Error("viewer: the split's pictures differ in size");
  divider = std::clamp(divider, 0, left.width);
  Picture p = left;
  for (int j = 0; j < p.height; ++j) {
    const size_t row = static_cast<size_t>(j) * p.width * 3;
    std::copy(right.rgb.begin() + row + divider * 3, right.rgb.begin() + row + p.width * 3,
              p.rgb.begin() + row + divider * 3);
  }
  return p;
}

Image split_image(const Image& left, const Image& right, int divider) {
  if (left.width != right.width || left.height != right.height || left.channels != right.channels)
    throw Error("viewer: the split's images differ in size");
  divider = std::clamp(divider, 0, left.width);
  Image out = left;
  for (int j = 0; j < out.height; ++j)
    for (int i = divider; i < out.width; ++i)
      for (int c = 0; c < out.channels; ++c)
        out.at(i, j, c) = right.at(i, j, c);
  return out;
}

std::vector<float> picture_texels(const Picture& p) {
  const size_t n = static_cast<size_t>(p.width) * p.height;
  std::vector<float> t(n * 4);
  for (size_t k = 0; k < n; ++k) {
    for (int c = 0; c < 3; ++c)
      t[4 * k + c] = p.rgb[3 * k + c] / 255.0f;
    t[4 * k + 3] = 1.0f;
  }
  return t;
}

}  // namespace sg::viewer
