// Pixel footprints against finite differences of neighbouring pixel centres.
#include "scene/footprint.h"

#include <gtest/gtest.h>

#include "testing/testing.h"

namespace sg {
namespace {

TEST(Footprint, FlatMatchesNeighbouringRays) {
  SceneModel m(testing::project_scene("simple"));
  for (double py : {190.5, 250.5, 355.5}) {
    for (double px : {20.5, 320.5}) {
      PixelFootprint f = pixel_footprint(m, px, py, 0);
      ASSERT_TRUE(f.hit);
      const double h = 1e-3;
      vec3 fx =
          (pixel_footprint(m, px + h, py, 0).point - pixel_footprint(m, px - h, py, 0).point) /
          (2 * h);
      vec3 fy =
          (pixel_footprint(m, px, py + h, 0).point - pixel_footprint(m, px, py - h, 0).point) /
          (2 * h);
      EXPECT_LT(length(fx - f.dp_dpx), 1e-6 * length(fx));
      EXPECT_LT(length(fy - f.dp_dpy), 1e-6 * length(fy));
      EXPECT_NEAR(length(f.view), 1, 1e-15);
      EXPECT_GT(dot(f.view, m.camera.position() - f.point), 0);
    }
  }
  EXPECT_FALSE(pixel_footprint(m, 320.5, 10.5, 0).hit);  // sky
}

TEST(Footprint, DisplacedMatchesNeighbouringRaysToFirstOrder) {
  Scene s = testing::project_scene("simple");
  s.surface.geometry = Geometry::displaced;
  SceneModel m(s);
  for (double py : {250.5, 330.5}) {
    const double px = 300.5, h = 1e-4;
    PixelFootprint f = pixel_footprint(m, px, py, 0.4);
    ASSERT_TRUE(f.hit);
    vec3 fx =
        (pixel_footprint(m, px + h, py, 0.4).point - pixel_footprint(m, px - h, py, 0.4).point) /
        (2 * h);
    // The tangent-plane transfer is exact to first order; the surface's curvature adds
    // O(h) to the difference quotient.
    EXPECT_LT(length(fx - f.dp_dpx), 1e-3 * length(fx));
    // The hit lies on the surface.
    EXPECT_NEAR(f.point.y, m.waves.height(f.point.x, f.point.z, 0.4), 1e-8);
  }
}

TEST(Footprint, RestPlaneIsTheFlatFootprintWhateverTheGeometry) {
  Scene s = testing::project_scene("simple");
  SceneModel flat(s);
  s.surface.geometry = Geometry::displaced;
  SceneModel displaced(s);
  for (double py : {200.5, 300.5}) {
    const PixelFootprint a = rest_plane_footprint(displaced, 100.5, py);
    const PixelFootprint b = pixel_footprint(flat, 100.5, py, 0.7);
    ASSERT_TRUE(a.hit);
    EXPECT_EQ(a.point, b.point);
    EXPECT_EQ(a.dp_dpx, b.dp_dpx);
    EXPECT_EQ(a.dp_dpy, b.dp_dpy);
    EXPECT_EQ(a.point.y, 0.0);
    EXPECT_NE(pixel_footprint(displaced, 100.5, py, 0.7).point.y, 0.0);
  }
}

}  // namespace
}  // namespace sg
