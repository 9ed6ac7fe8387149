#include "report/figures.h"

#include <algorithm>
#include <cmath>

#include "base/error.h"
#include "image/display.h"
#include "image/image_io.h"

namespace sg {

Picture grey_picture(int width, int height, const std::vector<uint8_t>& grey) {
  Picture p(width, height);
  for (size_t k = 0; k < grey.size(); ++k)
    p.rgb[3 * k] = p.rgb[3 * k + 1] = p.rgb[3 * k + 2] = grey[k];
  return p;
}

Picture to_picture(int width, int height, int channels, const std::vector<uint8_t>& values) {
  if (channels == 1) return grey_picture(width, height, values);
  Picture p(width, height);
  p.rgb = values;
  return p;
}

void write_picture(const std::string& path, const Picture& p) {
  write_png_rgb8(path, p.width, p.height, p.rgb);
}

CropBox best_crop(const Image& img, const std::vector<unsigned char>& mask, int cw, int ch,
                  const CropBox* avoid) {
  const int w = img.width, h = img.height;
  cw = std::clamp(cw, 1, w);
  ch = std::clamp(ch, 1, h);
  // Summed-area table of the energy inside the mask.
  std::vector<double> sat(size_t(w + 1) * (h + 1), 0.0);
  auto S = [&](int i, int j) -> double& { return sat[size_t(j) * (w + 1) + i]; };
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      const size_t k = size_t(j) * w + i;
      double v = 0;
      for (int c = 0; c < img.channels && mask[k]; ++c) {
        const float x = img.data[k * img.channels + c];
        v += std::isfinite(x) ? std::max(0.0f, x) : 0.0f;
      }
      S(i + 1, j + 1) = v + S(i, j + 1) + S(i + 1, j) - S(i, j);
    }
  }
  auto overlaps = [&](int x, int y) {
    return avoid && x < avoid->x + avoid->width && avoid->x < x + cw &&
           y < avoid->y + avoid->height && avoid->y < y + ch;
  };
  CropBox best{(w - cw) / 2, (h - ch) / 2, cw, ch};
  double best_e = -1;
  bool best_free = false;
  for (int y = 0; y + ch <= h; ++y) {
    for (int x = 0; x + cw <= w; ++x) {
      if (!mask[size_t(y + ch / 2) * w + x + cw / 2]) continue;
      const double e = S(x + cw, y + ch) - S(x, y + ch) - S(x + cw, y) + S(x, y);
      const bool free = !overlaps(x, y);
      if ((free && !best_free) || (free == best_free && e > best_e)) {
        best = CropBox{x, y, cw, ch};
        best_e = e;
        best_free = free;
      }
    }
  }
  // Centre the window on the energy it holds, so the glints sit in the middle of the crop
  // rather than at the edge of the first window that holds them all.
  double e = 0, ex = 0, ey = 0;
  for (int j = best.y; j < best.y + ch; ++j) {
    for (int i = best.x; i < best.x + cw; ++i) {
      const double v = S(i + 1, j + 1) - S(i, j + 1) - S(i + 1, j) + S(i, j);
      e += v;
      ex += v * (i + 0.5);
      ey += v * (j + 0.5);
    }
  }
  if (e > 0) {
    best.x = std::clamp(static_cast<int>(std::lround(ex / e - cw / 2.0)), 0, w - cw);
    best.y = std::clamp(static_cast<int>(std::lround(ey / e - ch / 2.0)), 0, h - ch);
  }
  return best;
}

Picture zoomed_crop(const Picture& p, const CropBox& c, int zoom, int cell_w, int cell_h,
                    uint8_t background) {
  Picture out(cell_w, cell_h, background);
  const int zw = c.width * zoom, zh = c.height * zoom;
  const int ox = (cell_w - zw) / 2, oy = (cell_h - zh) / 2;
  for (int y = 0; y < zh; ++y) {
    for (int x = 0; x < zw; ++x) {
      const int X = ox + x, Y = oy + y;
      if (X < 0 || X >= cell_w || Y < 0 || Y >= cell_h) continue;
      const uint8_t* s = p.at(c.x + x / zoom, c.y + y / zoom);
      std::copy(s, s + 3, out.at(X, Y));
    }
  }
  return out;
}

Picture enlarged_crop(const Picture& p, const CropBox& c, int zoom) {
  return zoomed_crop(p, c, zoom, c.width * zoom, c.height * zoom, 0);
}

void draw_box(Picture& p, const CropBox& b, const uint8_t colour[3]) {
  auto put = [&](int i, int j) {
    if (i >= 0 && i < p.width && j >= 0 && j < p.height) std::copy(colour, colour + 3, p.at(i, j));
  };
  const int x1 = b.x + b.width - 1, y1 = b.y + b.height - 1;
  for (int i = b.x; i <= x1; ++i) {
    put(i, b.y);
    put(i, y1);
  }
  for (int j = b.y; j <= y1; ++j) {
    put(b.x, j);
    put(x1, j);
  }
}

Picture colour_scale(int width, int height) {
  Picture p(width, height);
  for (int i = 0; i < width; ++i) {
    const auto c = diverging_colour(width > 1 ? 2.0 * i / (width - 1) - 1.0 : 0.0);
    for (int j = 0; j < height; ++j)
      std::copy(c.begin(), c.end(), p.at(i, j));
  }
  return p;
}

Picture compose_grid(const std::vector<std::vector<Picture>>& cells, int gap, uint8_t background) {
  if (cells.empty() || cells[0].empty()) return Picture();
  const int cw = cells[0][0].width, ch = cells[0][0].height;
  const int rows = static_cast<int>(cells.size()), cols = static_cast<int>(cells[0].size());
  Picture out(cols * cw + (cols - 1) * gap, rows * ch + (rows - 1) * gap, background);
  for (int r = 0; r < rows; ++r) {
    if (static_cast<int>(cells[r].size()) != cols) throw Error("grid: rows differ in length");
    for (int c = 0; c < cols; ++c) {
      const Picture& p = cells[r][c];
      if (p.width != cw || p.height != ch) throw Error("grid: cells differ in size");
      for (int j = 0; j < ch; ++j) {
        std::copy(p.at(0, j), p.at(0, j) + 3 * cw, out.at(c * (cw + gap), r * (ch + gap) + j));
      }
    }
  }
  return out;
}

double error_scale(const Image& a, const Image& b, const std::vector<unsigned char>& mask,
                   double q) {
  std::vector<double> d;
  for (size_t k = 0; k < a.pixels(); ++k) {
    const double x = std::fabs(mean_difference(a, b, k));
    if (mask[k] && x > 0) d.push_back(x);
  }
  if (d.empty()) return 0;
  const size_t n = std::min(d.size() - 1, static_cast<size_t>(q * (d.size() - 1) + 0.5));
  std::nth_element(d.begin(), d.begin() + n, d.end());
  return d[n];
}

}  // namespace sg
