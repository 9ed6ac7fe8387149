// The pictures of a study: per scene a grid with one column per variant (the reference
// first) and five rows - the shown frame after the display pipeline (image/tonemap.h:
// exposure, glare, ACES, sRGB; identical for all variants), its near crop zoomed, the
// difference to the reference there in false colour (image/display.h's diverging map, on
// linear values), the far crop zoomed and its difference. Grid pictures carry no text: the labels
// are in the HTML report and the Markdown captions, so no font is needed.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"
#include "report/results.h"

namespace sg {

struct Picture {  // 8-bit RGB, rows top to bottom
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;
  Picture() = default;
  Picture(int w, int h, uint8_t grey = 0) : width(w), height(h), rgb(size_t(w) * h * 3, grey) {}
  uint8_t* at(int i, int j) { return &rgb[(size_t(j) * width + i) * 3]; }
  const uint8_t* at(int i, int j) const { return &rgb[(size_t(j) * width + i) * 3]; }
};

Picture grey_picture(int width, int height, const std::vector<uint8_t>& grey);
// A picture of `channels` (1: grey, 3: RGB) 8-bit values per pixel, as display_srgb8 gives.
Picture to_picture(int width, int height, int channels, const std::vector<uint8_t>& values);
void write_picture(const std::string& path, const Picture& p);

// The crop window of size (cw, ch) whose centre pixel lies in `mask` and that holds the
// most energy of `img` (sum of its values, all channels, over the mask's pixels); among windows
// that do not overlap `avoid` when there are any (ties: the first in row-major order); then moved
// to centre the energy it holds. The image centre when the mask is empty.
CropBox best_crop(const Image& img, const std::vector<unsigned char>& mask, int cw, int ch,
                  const CropBox* avoid = nullptr);

// `crop` of `p` enlarged `zoom` times (nearest neighbour), centred in a cell of
// (cell_w, cell_h) filled with `background`.
Picture zoomed_crop(const Picture& p, const CropBox& crop, int zoom, int cell_w, int cell_h,
                    uint8_t background);
// `crop` of `p` enlarged `zoom` times, exactly its size (zoom * crop.width, zoom * crop.height).
Picture enlarged_crop(const Picture& p, const CropBox& crop, int zoom);

// A one-pixel outline of `box` in `colour`.
void draw_box(Picture& p, const CropBox& box, const uint8_t colour[3]);

// The colour scale of the error maps, left (-range) to right (+range), in a cell.
Picture colour_scale(int width, int height);

// Rows x columns of equal-size cells separated by `gap` pixels of `background`.
Picture compose_grid(const std::vector<std::vector<Picture>>& cells, int gap, uint8_t background);

// The scale of an error map: the q-quantile (0..1) of |a - b| (the mean over the channels
// of a colour image) over the pixels of `mask`
// where a and b differ (glints cover few pixels, so a quantile over all pixels would be
// 0); 0 when they never differ.
double error_scale(const Image& a, const Image& b, const std::vector<unsigned char>& mask,
                   double q);

}  // namespace sg
