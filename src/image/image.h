// A single-channel float image: the linear pixel value of the scene spec (the fraction
// of a pixel's footprint and shutter time that mirrors the light, times radiances).
// Row 0 is the top row (pixel j grows downwards, as in the spec).
#pragma once

#include <cassert>
#include <cstddef>
#include <vector>

namespace sg {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<float> data;

  Image() = default;
  Image(int w, int h, float fill = 0.0f)
      : width(w), height(h), data(static_cast<size_t>(w) * static_cast<size_t>(h), fill) {}

  float& at(int i, int j) {
    assert(i >= 0 && i < width && j >= 0 && j < height);
    return data[static_cast<size_t>(j) * width + i];
  }
  float at(int i, int j) const {
    assert(i >= 0 && i < width && j >= 0 && j < height);
    return data[static_cast<size_t>(j) * width + i];
  }
  size_t size() const { return data.size(); }
  bool same_size(const Image& o) const { return width == o.width && height == o.height; }
};

}  // namespace sg
