// A scene's frames first..last rendered by one method with 2x2x2 samples where it samples
// (the method's own options otherwise at their defaults), for tests that compare whole
// sequences of a method across scene variants (colour_test, moving_camera_test).
#pragma once

#include <string>
#include <vector>

#include "engine/render.h"
#include "methods/method.h"
#include "testing/path_tables.h"

namespace sg::testing {

inline std::vector<Image> render_range(const Scene& s, const std::string& method, int first,
                                       int last) {
  MethodOptions o;
  o.samples = SampleCounts{2, 2, 2};
  const SceneModel model(s);
  auto m = make_method(method, testing::with_tables(o));
  std::vector<Image> frames;
  render_frames(model, *m, first, last, RenderSettings{},
                [&](int, const Image& img) { frames.push_back(img); });
  return frames;
}

}  // namespace sg::testing
