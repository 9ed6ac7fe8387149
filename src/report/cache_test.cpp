// Cache keys follow what a frame's pixels depend on, and nothing else; a frame is trusted
// only when its image and sidecar are both complete.
#include <gtest/gtest.h>

#include <filesystem>

#include "gl_engine/kernel_program.h"
#include "report/cache.h"
#include "testing/testing.h"

namespace sg {
namespace {
namespace fs = std::filesystem;

Scene scene() {
  return testing::small_scene({Wave{0.1, {0.2, -1.0}, 3.0, 0.5}, Wave{0.05, {-0.4, -2}, 4.4, 1}},
                              32, 18);
}

TEST(FrameKey, ChangesWithSceneFrameSizeAndSamplesOnly) {
  const Scene s = scene();
  const std::string ref = "reference --samples 4x4x2";
  const std::string base = frame_key(s, ref, 3);
  // The same inputs, built again: the same key (and path).
  EXPECT_EQ(frame_key(scene(), ref, 3), base);
  // Whitespace in the label does not matter.
  EXPECT_EQ(frame_key(s, "  reference   --samples 4x4x2 ", 3), base);

  Scene waves = s;
  waves.surface.waves[1].amplitude *= 1.0001;
  EXPECT_NE(frame_key(waves, ref, 3), base);
  Scene light = s;
  light.light.angular_radius_deg = 0.5;
  EXPECT_NE(frame_key(light, ref, 3), base);
  EXPECT_NE(frame_key(s, ref, 4), base);
  Scene size = s;
  set_image_size(size, 33, 18);
  EXPECT_NE(frame_key(size, ref, 3), base);
  EXPECT_NE(frame_key(s, "reference --samples 4x4x4", 3), base);
  EXPECT_NE(frame_key(s, "reference --samples 4x4x2 --seed 1", 3), base);
  EXPECT_NE(frame_key(s, "point", 3), base);
  // The renderer: the shading kernel's fingerprint is part of the key, so frames from
  // another build of the kernel are rendered again.
  const std::string fp = gl_engine::kernel_fingerprint();
  EXPECT_EQ(fp.size(), 16u);
  EXPECT_NE(base.find("renderer=" + fp + "/"), std::string::npos);
  // And the reference estimator's revision: a fixed estimator (another revision) gives
  // every frame another key and file, so no frame of the estimator of before is served.
  EXPECT_NE(base.find("renderer=" + renderer_version() + "\n"), std::string::npos);
  EXPECT_NE(renderer_version().find("/reference-" + std::to_string(kReferenceRevision)),
            std::string::npos);
  const std::string before = renderer_version(kReferenceRevision - 1);
  EXPECT_NE(before, renderer_version());
  EXPECT_EQ(frame_key(s, ref, 3, -1, renderer_version()), base);
  EXPECT_NE(frame_key(s, ref, 3, -1, before), base);
  EXPECT_NE(frame_key(s, "point", 3, -1, before), frame_key(s, "point", 3));
  // Stateful methods: the first frame of the history is part of the key.
  EXPECT_NE(frame_key(s, ref, 3, 0), base);
  EXPECT_NE(frame_key(s, ref, 3, 0), frame_key(s, ref, 3, 1));

  FrameCache c((fs::path(sg::testing::binary_dir()) / "test_out/cache_keys").string());
  EXPECT_EQ(c.path(ref, base), c.path(ref, frame_key(scene(), ref, 3)));
  EXPECT_NE(c.path(ref, base), c.path(ref, frame_key(s, ref, 4)));
  EXPECT_EQ(fs::path(c.path(ref, base)).filename().string().rfind("reference-samples-4x4x2-", 0),
            0u);
}

TEST(FrameKey, LabelsAndSlugs) {
  EXPECT_EQ(canonical_label(" supersample \t --samples  6x6x1 "), "supersample --samples 6x6x1");
  EXPECT_EQ(file_slug("supersample --samples 6x6x1"), "supersample-samples-6x6x1");
  EXPECT_EQ(file_slug("STAA --ndf=per-pixel"), "staa-ndf-per-pixel");
  EXPECT_EQ(file_slug("--"), "method");
  EXPECT_LE(file_slug(std::string(100, 'a')).size(), 48u);
  EXPECT_EQ(fnv1a64(""), 0xcbf29ce484222325ull);
  EXPECT_EQ(fnv1a64("a"), 0xaf63dc4c8601ec8cull);  // published FNV-1a test vector
}

TEST(FrameCache, TrustsOnlyCompleteFramesWithTheirKey) {
  const std::string dir = (fs::path(sg::testing::binary_dir()) / "test_out/cache_store").string();
  fs::remove_all(dir);
  FrameCache c(dir);
  Image img(4, 3, 0.25f);
  img.at(1, 2) = 0.75f;
  const std::string key = frame_key(scene(), "point", 0);
  EXPECT_FALSE(c.has("point", key));
  c.store("point", key, img, 12.5);
  ASSERT_TRUE(c.has("point", key));
  auto f = c.load("point", key);
  ASSERT_TRUE(f);
  EXPECT_EQ(f->image.data, img.data);
  EXPECT_EQ(f->ms, 12.5);
  const std::string p = c.path("point", key);
  // A sidecar holding another key (a hash collision) is not trusted.
  const std::string other = frame_key(scene(), "point", 1);
  fs::copy_file(p, c.path("point", other));
  fs::copy_file(p + ".json", c.path("point", other) + ".json");
  EXPECT_FALSE(c.has("point", other));
  // The image without its sidecar (killed between the two writes), or the sidecar
  // without a readable image: not trusted.
  fs::remove(p + ".json");
  EXPECT_FALSE(c.has("point", key));
  c.store("point", key, img, 1);
  fs::resize_file(p, 10);
  EXPECT_FALSE(c.load("point", key));
}

}  // namespace
}  // namespace sg
