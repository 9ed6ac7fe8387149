// The near and far halves partition the pixels that see water, split by distance.
#include <gtest/gtest.h>

#include "report/regions.h"
#include "shading/water_geometry.h"
#include "testing/testing.h"

namespace sg {
namespace {

void check_partition(const Scene& s) {
  const SceneModel m(s);
  const double t = s.frame_time(0);
  const WaterRegions r = water_regions(m, t);
  long water = 0, near = 0, far = 0;
  double max_near = 0, min_far = 1e300;
  for (int j = 0; j < s.height; ++j) {
    for (int i = 0; i < s.width; ++i) {
      const size_t k = size_t(j) * s.width + i;
      const PixelFootprint f = pixel_footprint(m, i + 0.5, j + 0.5, t);
      EXPECT_EQ(r.water[k] != 0, f.hit) << i << "," << j;
      EXPECT_FALSE(r.near[k] && r.far[k]) << "near and far overlap at " << i << "," << j;
      EXPECT_EQ(r.water[k] != 0, r.near[k] || r.far[k]) << "not a partition at " << i << "," << j;
      water += r.water[k] != 0;
      near += r.near[k] != 0;
      far += r.far[k] != 0;
      if (r.near[k]) max_near = std::max(max_near, f.distance);
      if (r.far[k]) min_far = std::min(min_far, f.distance);
    }
  }
  EXPECT_GT(water, 0);
  EXPECT_LT(water, long(s.width) * s.height);  // the sky is there too
  EXPECT_EQ(water, r.water_pixels);
  EXPECT_EQ(near, r.near_pixels);
  EXPECT_EQ(far, r.far_pixels);
  EXPECT_TRUE(near - far == 0 || near - far == 1) << near << " " << far;
  EXPECT_LE(max_near, min_far);
  EXPECT_DOUBLE_EQ(r.split_distance, max_near);
}

TEST(WaterRegions, HalvesPartitionTheWaterByDistance) {
  Scene flat = testing::small_scene({Wave{0.1, {0.2, -1.0}, 3.0, 0.5}}, 40, 24);
  check_partition(flat);
  Scene displaced = flat;
  displaced.surface.geometry = Geometry::displaced;
  displaced.camera.position.y = 1.0;
  check_partition(displaced);
  Scene odd = flat;
  set_image_size(odd, 37, 21);
  check_partition(odd);
}

}  // namespace
}  // namespace sg
