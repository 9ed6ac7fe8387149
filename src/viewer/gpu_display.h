// The display pipeline of `render --display` (image/tonemap.h: exposure, glare, the ACES
// filmic curve, sRGB) as compute shaders, for the viewer: the same function as
// display_srgb8 of the same linear image, in float on the GPU instead of double on the
// CPU (the bytes agree within 1/255 where a value falls on a rounding boundary).
//
// The per-pixel functions are image/display.glsl's, which the web page's fragment shaders
// share (src/web/). Passes, each one invocation per pixel: exposure and the bright part b = max(x -
// t, 0) (non-finite values show white and do not glare); each Gaussian of the glare as two 1-D
// passes (rows, then columns, black outside the image), added to an accumulator with its
// weight; the star's streaks as a gather: the CPU's bilinear scatter of pixel q at
// q + t d onto its four neighbours (image/glare.cpp, streak_blur) read backwards, each
// output pixel p summing, per tap t, the four sources p - floor(t d) - (0|1, 0|1) with the
// same bilinear weights, so it adds the very same terms; then x - W b + the accumulator,
// the filmic curve, sRGB, rounded to bytes. The kernels' weights are glare.h's
// (gaussian_kernel, streak_kernel), in a storage buffer.
//
// The gather costs (2 r + 1) x 4 texel reads per streak per pixel (r = 4 L: 116 at 720
// rows) where the CPU's scatter visits only the bright pixels: on a real GPU it is a
// fraction of a millisecond; on llvmpipe, whose "GPU" is the CPU, the CPU path is faster
// (viewer.h picks it there). Needs a current GL context.
#pragma once

#include <memory>

#include "gl/buffer.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "image/image.h"
#include "image/tonemap.h"
#include "viewer/view_image.h"

namespace sg::viewer {

class GpuDisplay {
 public:
  GpuDisplay();
  // `img` (1 or 3 channels) through the display pipeline, as an RGB picture (a grey
  // image's byte in all three channels), as display_picture(img, settings).
  Picture picture(const Image& img, const DisplaySettings& settings);

 private:
  void resize(int width, int height);

  gl::Program expose_, blur_, streak_, finish_;
  gl::Texture linear_, x_, b_, tmp_, acc_, out_;
  int width_ = 0, height_ = 0;
};

}  // namespace sg::viewer
