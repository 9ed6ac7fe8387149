// A check shared by the tests of methods that override shade_tile (to share corners or
// quad neighbours between pixels): the image must not depend on the tiling, and must equal
// per-pixel shade().
#pragma once

#include <gtest/gtest.h>

#include "engine/render.h"

namespace sg::testing {

// Renders `frame` with tiles of 16 and of `odd_tile` pixels, compares them byte for byte,
// and compares every (3rd column, 4th row) pixel with shade().
inline void expect_tiles_equal_pixels(const SceneModel& m, Method& method, int frame,
                                      int odd_tile) {
  RenderSettings a, b;
  a.tile = 16;
  b.tile = odd_tile;
  const Image x = render_frame(m, method, frame, a), y = render_frame(m, method, frame, b);
  EXPECT_EQ(x.data, y.data);
  FrameContext ctx{m, frame_time(m.scene, frame), 0};
  for (int j = 0; j < m.height(); j += 4) {
    for (int i = 0; i < m.width(); i += 3)
      EXPECT_EQ(x.at(i, j), static_cast<float>(method.shade(ctx, i, j))) << i << "," << j;
  }
}

}  // namespace sg::testing
