// Headless contexts on each EGL platform the machine has, and the clear error when none
// can give OpenGL 4.5. These tests make their own contexts (not the shared fixture's).
#include <gtest/gtest.h>

#include <epoxy/gl.h>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "gl/context.h"
#include "gl/error.h"
#include "testing/child_process.h"
#include "testing/gl_context.h"

namespace sg::gl {
namespace {

// A context on `platform`, or a skip (a fail under SUNGLINT_REQUIRE_GL) with the reason.
#define MAKE_OR_SKIP(ctx, options)                      \
  std::unique_ptr<HeadlessContext> ctx;                 \
  try {                                                 \
    ctx = std::make_unique<HeadlessContext>(options);   \
  } catch (const Unavailable& e) {                      \
    if (sg::testing::gl_required()) FAIL() << e.what(); \
    GTEST_SKIP() << e.what();                           \
  }

void expect_usable(const HeadlessContext& ctx) {
  const ContextInfo& info = ctx.info();
  EXPECT_GE(info.major * 10 + info.minor, 45);
  EXPECT_FALSE(info.gl_renderer.empty());
  EXPECT_FALSE(info.platform.empty());
  // A GL call works: a compute-shader limit of 4.3+.
  GLint invocations = 0;
  glGetIntegerv(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS, &invocations);
  EXPECT_GE(invocations, 1024);
  std::cout << info.summary() << "\n";
}

TEST(HeadlessContext, Automatic) {
  MAKE_OR_SKIP(ctx, ContextOptions{});
  expect_usable(*ctx);
#ifndef NDEBUG
  EXPECT_TRUE(ctx->info().debug);
#endif
}

TEST(HeadlessContext, Surfaceless) {
  ContextOptions o;
  o.platform = Platform::surfaceless;
  MAKE_OR_SKIP(ctx, o);
  EXPECT_EQ(ctx->info().platform, "surfaceless");
  expect_usable(*ctx);
}

TEST(HeadlessContext, Device) {
  ContextOptions o;
  o.platform = Platform::device;
  MAKE_OR_SKIP(ctx, o);
  EXPECT_EQ(ctx->info().platform.rfind("device ", 0), 0u) << ctx->info().platform;
  expect_usable(*ctx);
}

TEST(HeadlessContext, TwoContextsAtOnce) {
  MAKE_OR_SKIP(a, ContextOptions{});
  {
    HeadlessContext b;
    b.make_current();
    expect_usable(b);
  }
  a->make_current();
  expect_usable(*a);
}

// The exit codes of the child of BelowFourFiveIsAClearError.
constexpr int kRefused = 0, kMade = 1, kNotMesa = 77, kNoGl = 78;

TEST(HeadlessContext, BelowFourFiveIsAClearError) {
  // Mesa caps its version with MESA_GL_VERSION_OVERRIDE, read once per process: the context
  // is made in a fresh child process (testing/child_process.h).
  if (sg::testing::in_child()) {
    setenv("MESA_GL_VERSION_OVERRIDE", "4.3", 1);
    try {
      HeadlessContext ctx;
      const bool mesa = ctx.info().gl_version.find("Mesa") != std::string::npos;
      std::fprintf(stderr, "made %s\n", ctx.info().gl_version.c_str());
      std::exit(mesa ? kMade : kNotMesa);
    } catch (const Unavailable& e) {
      std::fprintf(stderr, "%s\n", e.what());
      std::exit(std::string(e.what()).find("no OpenGL 4.5 core context") != std::string::npos
                    ? kRefused
                    : kNoGl);
    }
  }
  const sg::testing::ChildResult child = sg::testing::run_child();
  if (child.exit_code == kNotMesa) GTEST_SKIP() << "needs Mesa (MESA_GL_VERSION_OVERRIDE)";
  if (child.exit_code == kNoGl) {
    // The child's error did not name 4.5: a failure where GL works (this process can make a
    // context, without the override), a skip where there is none at all.
    try {
      HeadlessContext ctx;
      FAIL() << "the refusal did not say \"no OpenGL 4.5 core context\":\n" << child.output;
    } catch (const Unavailable& e) {
      if (sg::testing::gl_required()) FAIL() << e.what();
      GTEST_SKIP() << e.what();
    }
  }
  EXPECT_EQ(child.exit_code, kRefused) << child.output;
  EXPECT_NE(child.output.find("OpenGL 4.5 unavailable: "), std::string::npos) << child.output;
}

TEST(Platform, Names) {
  EXPECT_EQ(parse_platform("auto"), Platform::automatic);
  EXPECT_EQ(parse_platform("device"), Platform::device);
  EXPECT_EQ(parse_platform("surfaceless"), Platform::surfaceless);
  EXPECT_STREQ(platform_name(Platform::surfaceless), "surfaceless");
  try {
    parse_platform("x11");
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'x11'"), std::string::npos);
  }
}

}  // namespace
}  // namespace sg::gl
