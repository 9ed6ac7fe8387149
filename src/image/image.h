// A float image of the linear pixel value of the scene spec (the fraction of a pixel's
// footprint and shutter time that mirrors the light, times radiances): one channel for a
// grey scene, three (R, G, B, linear Rec. 709) for a colour scene. Channels are
// interleaved: value c of pixel (i, j) is data[(j * width + i) * channels + c]. Row 0 is
// the top row (pixel j grows downwards, as in the spec).
//
// A grey image stands for three equal channels (scene spec, format /2): metrics and
// pictures treat a one-channel image against a three-channel one that way.
#pragma once

#include <cassert>
#include <cstddef>
#include <vector>

namespace sg {

struct Image {
  int width = 0;
  int height = 0;
  int channels = 1;  // 1 (grey) or 3 (RGB)
  std::vector<float> data;

  Image() = default;
  // A grey image.
  Image(int w, int h, float fill = 0.0f)
      : width(w), height(h), data(static_cast<size_t>(w) * static_cast<size_t>(h), fill) {}
  // An image of `c` channels (1 or 3).
  static Image with_channels(int w, int h, int c, float fill = 0.0f) {
    assert(c == 1 || c == 3);
    Image img;
    img.width = w;
    img.height = h;
    img.channels = c;
    img.data.assign(static_cast<size_t>(w) * static_cast<size_t>(h) * c, fill);
    return img;
  }

  float& at(int i, int j, int c = 0) {
    assert(i >= 0 && i < width && j >= 0 && j < height && c >= 0 && c < channels);
    return data[(static_cast<size_t>(j) * width + i) * channels + c];
  }
  float at(int i, int j, int c = 0) const {
    assert(i >= 0 && i < width && j >= 0 && j < height && c >= 0 && c < channels);
    return data[(static_cast<size_t>(j) * width + i) * channels + c];
  }
  // Values (pixels x channels).
  size_t size() const { return data.size(); }
  size_t pixels() const { return static_cast<size_t>(width) * static_cast<size_t>(height); }
  bool same_size(const Image& o) const { return width == o.width && height == o.height; }
  bool same_shape(const Image& o) const { return same_size(o) && channels == o.channels; }

  // Channel c as a grey image, and its inverse.
  Image channel(int c) const {
    assert(c >= 0 && c < channels);
    Image out(width, height);
    for (size_t p = 0; p < out.data.size(); ++p)
      out.data[p] = data[p * channels + c];
    return out;
  }
  void set_channel(int c, const Image& grey) {
    assert(c >= 0 && c < channels && grey.channels == 1 && same_size(grey));
    for (size_t p = 0; p < grey.data.size(); ++p)
      data[p * channels + c] = grey.data[p];
  }
};

// Value c of pixel p (row-major index) of `img`, a grey image standing for three equal
// channels.
inline float channel_value(const Image& img, size_t p, int c) {
  return img.data[p * img.channels + (img.channels == 1 ? 0 : c)];
}

// The mean over the channels of a - b at pixel p (a grey image as three equal channels).
inline double mean_difference(const Image& a, const Image& b, size_t p) {
  const int n = a.channels > b.channels ? a.channels : b.channels;
  double d = 0;
  for (int c = 0; c < n; ++c)
    d += static_cast<double>(channel_value(a, p, c)) - channel_value(b, p, c);
  return n == 1 ? d : d / n;
}

}  // namespace sg
