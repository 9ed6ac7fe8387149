// The GL tests' fixture: one headless context per test program (gl/context.h), made before
// the first test of a suite that needs it. Where no context can be made (no libEGL, no
// driver), each test is skipped with the reason, as CTest shows ("Skipped"); with
// SUNGLINT_REQUIRE_GL=1 in the environment (CI, where Mesa is installed) it fails instead,
// so a broken GL setup cannot pass as skipped.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <string>

#include "gl/context.h"
#include "gl/error.h"

namespace sg::testing {

inline bool gl_required() {
  const char* v = std::getenv("SUNGLINT_REQUIRE_GL");
  return v && *v && std::string(v) != "0";
}

class GlTest : public ::testing::Test {
 public:
  // The shared context, or null with `reason` set.
  static gl::HeadlessContext* context(std::string* reason = nullptr) {
    static std::string why;
    static std::unique_ptr<gl::HeadlessContext> ctx = [] {
      try {
        return std::make_unique<gl::HeadlessContext>();
      } catch (const gl::Unavailable& e) {
        why = e.what();
        return std::unique_ptr<gl::HeadlessContext>();
      }
    }();
    if (reason) *reason = why;
    return ctx.get();
  }

 protected:
  void SetUp() override {
    std::string reason;
    gl::HeadlessContext* ctx = context(&reason);
    if (!ctx) {
      if (gl_required()) FAIL() << "SUNGLINT_REQUIRE_GL is set: " << reason;
      GTEST_SKIP() << reason;
    }
    ctx->make_current();
  }
};

}  // namespace sg::testing
