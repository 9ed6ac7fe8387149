// Method variants as `compare` takes them: the same flags as `render`.
#include "cli/method_flags.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "base/error.h"
#include "cli/args.h"
#include "methods/method.h"
#include "methods/staa.h"
#include "methods/supersample.h"

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

TEST(MethodVariant, FlagsOfOtherMethodsAreRefused) {
  // Each flag configures some methods; given to another, it would be ignored.
  const std::pair<const char*, const char*> refused[] = {
      {"point --samples 4x4x1",
       "--methods: 'point --samples 4x4x1': --samples: not a flag of method point (it "
       "configures supersample, reference)"},
      {"staa --lean-size 256", "--lean-size: not a flag of method staa (it configures lean)"},
      {"lean --ndf uniform", "--ndf: not a flag of method lean (it configures staa)"},
      {"supersample --batches 4", "--batches: not a flag of method supersample"},
      {"staa-temporal --footprint none", "--footprint: not a flag of method staa-temporal"},
      {"taa --microspec-area approx", "--microspec-area: not a flag of method taa"},
  };
  for (const auto& [text, message] : refused) {
    try {
      parse_method_variant(text);
      ADD_FAILURE() << text << " was taken";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
  // ... and the methods that take them take them.
  for (const char* text :
       {"supersample --samples 4x4x1 --seed 2", "reference --batches 4 --adaptive off",
        "staa-temporal --segments 2 --precision float", "staa --ndf uniform --footprint none",
        "point --intersect-tolerance 0", "lean --lean-size 256", "taa --taa-alpha 0.2",
        "microspec --microspec-area approx", "specaa --specaa-kernel full",
        "bruneton --bruneton-nmin 2", "point --engine gl"}) {
    EXPECT_NO_THROW(parse_method_variant(text)) << text;
  }
}

// The displaced intersection's tolerance: every wave for the methods whose samples are
// radiances along rays, 0.25 pixel for staa, the flag's value for each when given (even
// when it is the default's own value).
TEST(MethodVariant, IntersectToleranceByMethodUnlessGiven) {
  const MethodOptions none = parse_method_variant("point").options;
  for (const char* m : {"reference", "supersample", "point", "staa-temporal"})
    EXPECT_EQ(intersect_tolerance_for(none, m), 0.0) << m;
  EXPECT_EQ(intersect_tolerance_for(none, "staa"), 0.25);
  for (const char* text : {"point --intersect-tolerance 0.25", "staa --intersect-tolerance 0.25"}) {
    const MethodVariant v = parse_method_variant(text);
    EXPECT_EQ(intersect_tolerance_for(v.options, v.name), 0.25) << text;
  }
  const MethodVariant s = parse_method_variant("staa --intersect-tolerance 0");
  EXPECT_EQ(intersect_tolerance_for(s.options, "staa"), 0.0);
  const MethodVariant ss =
      parse_method_variant("supersample --samples 4x4x1 --intersect-tolerance 1");
  EXPECT_EQ(stratified_intersect_tolerance(ss.options), 0.25);  // per sample cell
}

TEST(MethodVariant, RdfKernelsByFootprintUnlessGiven) {
  // Three with a footprint term, the paper's nine with --footprint none (its method), the
  // flag's count when given; as the kernel's parameters take it, in both precisions.
  const struct {
    const char* text;
    int kernels;
  } cases[] = {{"staa", 3},
               {"staa --footprint none", 9},
               {"staa --footprint exact", 3},
               {"staa --kernels 9", 9},
               {"staa --kernels 5", 5},
               {"staa --footprint none --kernels 3", 3},
               {"staa --footprint none --kernels 1", 1}};
  for (const auto& c : cases) {
    const MethodVariant v = parse_method_variant(c.text);
    EXPECT_EQ(rdf_kernels(v.options.staa), c.kernels) << c.text;
    EXPECT_EQ(staa_kernel_params<kd::StaaParams>(v.options.staa).kernels, c.kernels) << c.text;
    EXPECT_EQ(staa_kernel_params<kf::StaaParams>(v.options.staa).kernels, c.kernels) << c.text;
  }
  EXPECT_THROW(parse_method_variant("staa --kernels 0"), Error);
}

TEST(MethodFlags, EveryFlagNamesTheMethodsItConfigures) {
  CLI::App app{"test"};
  MethodFlags f;
  add_method_flags(app, f);
  EXPECT_TRUE(f.unscoped.empty()) << "a method flag without its methods: " << f.unscoped.front();
  EXPECT_GE(f.scoped.size(), 30u);
  std::vector<std::string> names;
  for (const auto& m : method_catalog())
    names.push_back(m.name);
  for (const MethodFlags::Scoped& s : f.scoped) {
    ASSERT_FALSE(s.methods.empty()) << s.option->get_name();
    for (const std::string& m : s.methods) {
      EXPECT_NE(std::find(names.begin(), names.end(), m), names.end())
          << s.option->get_name() << ": " << m << " is not a method";
    }
  }
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
