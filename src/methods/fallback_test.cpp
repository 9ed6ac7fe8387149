// The baselines' fallback (methods/fallback.h): with the camera under the displaced
// surface, where no method's model applies, lean, specaa and microspec return the spec's
// radiance along the centre ray (point's value) at every pixel and count them all; where
// the camera is above the water they count none; bruneton, which intersects its filtered
// surface, stays finite and counts what it replaces.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/render.h"
#include "image/image_io.h"
#include "methods/fallback.h"
#include "methods/method.h"
#include "testing/direct_waves.h"
#include "testing/path_tables.h"
#include "testing/paths.h"

namespace sg {
namespace {

Scene under_the_surface() {
  // tests/scenes/edge/camera_below_crests.json: the camera 5 cm up, under a crest in frame 0.
  Scene s = load_scene(sg::testing::source_dir() + "/tests/scenes/edge/camera_below_crests.json");
  s.width = 32;
  s.height = 18;
  return s;
}

TEST(Fallback, UnderTheSurfaceEveryPixelIsTheCentreRay) {
  const Scene s = under_the_surface();
  const SceneModel m(s);
  const vec3 c = m.camera.position();
  ASSERT_GT(testing::direct_height(m.waves, c.x, c.z, s.frame_time(0)), c.y);  // under the surface
  RenderSettings rs;
  auto point = make_method("point", testing::with_tables(MethodOptions{}));
  const Image ref = render_frame(m, *point, 0, rs);
  ASSERT_EQ(count_nonfinite(ref), 0u);
  for (const char* name : {"lean", "specaa", "microspec"}) {
    auto meth = make_method(name, testing::with_tables(MethodOptions{}));
    const Image img = render_frame(m, *meth, 0, rs);
    EXPECT_EQ(count_nonfinite(img), 0u) << name;
    EXPECT_EQ(fallback_pixels(*meth), static_cast<long>(img.size())) << name;
    for (size_t k = 0; k < img.size(); ++k)
      ASSERT_EQ(img.data[k], ref.data[k]) << name << " pixel " << k;
  }
  auto bruneton = make_method("bruneton", testing::with_tables(MethodOptions{}));
  const Image b = render_frame(m, *bruneton, 0, rs);
  EXPECT_EQ(count_nonfinite(b), 0u);
  EXPECT_GE(fallback_pixels(*bruneton), 0);
  EXPECT_EQ(fallback_pixels(*point), -1);  // point does not count
}

TEST(Fallback, AboveTheWaterNothingFallsBack) {
  Scene s = under_the_surface();
  s.camera.position.y = 1.0;  // above every crest (amplitudes sum to 0.31 m)
  const SceneModel m(s);
  RenderSettings rs;
  for (const char* name : {"lean", "specaa", "microspec", "bruneton", "taa"}) {
    auto meth = make_method(name, testing::with_tables(MethodOptions{}));
    const Image img = render_frame(m, *meth, 3, rs);
    EXPECT_EQ(count_nonfinite(img), 0u) << name;
    EXPECT_EQ(fallback_pixels(*meth), 0) << name;
  }
}

}  // namespace
}  // namespace sg
