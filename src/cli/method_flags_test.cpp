// Method variants as `compare` takes them: the same flags as `render`.
#include "cli/method_flags.h"

#include <gtest/gtest.h>

#include "base/error.h"
#include "cli/args.h"

namespace sg {
namespace {

TEST(MethodVariant, NameAndFlags) {
  MethodVariant v = parse_method_variant("supersample --samples 6x6x1 --seed 3");
  EXPECT_EQ(v.name, "supersample");
  EXPECT_EQ(v.label, "supersample --samples 6x6x1 --seed 3");
  EXPECT_EQ(v.options.samples.sx, 6);
  EXPECT_EQ(v.options.samples.st, 1);
  EXPECT_EQ(v.options.seed, 3u);
  MethodVariant p = parse_method_variant("point");
  EXPECT_EQ(p.options.samples.total(), 512);
}

TEST(MethodVariant, ErrorsNameTheVariant) {
  try {
    parse_method_variant("supersample --samples 6x6");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("--methods: 'supersample --samples 6x6': --samples", 0),
              0u)
        << e.what();
  }
  EXPECT_THROW(parse_method_variant("nope"), Error);
  EXPECT_THROW(parse_method_variant("point --bogus 1"), Error);
  EXPECT_THROW(parse_method_variant("  "), Error);
}

TEST(Args, FrameRanges) {
  FrameRange r = parse_frame_range("3-7", "--frames");
  EXPECT_EQ(r.first, 3);
  EXPECT_EQ(r.count(), 5);
  EXPECT_EQ(parse_frame_range("4", "--frames").last, 4);
  EXPECT_THROW(parse_frame_range("7-3", "--frames"), Error);
  EXPECT_THROW(parse_frame_range("a-b", "--frames"), Error);
  EXPECT_THROW(parse_frame_range("-2", "--frames"), Error);
}

}  // namespace
}  // namespace sg
