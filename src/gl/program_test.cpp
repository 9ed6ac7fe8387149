// Shader assembly and error logs: a compile error in one of several source strings is
// reported with that string's name and line, by the driver (with GL) and by the log
// rewriting on the formats of Mesa, NVIDIA and AMD/Intel (without GL).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "gl/dispatch.h"
#include "gl/error.h"
#include "gl/program.h"
#include "testing/gl_context.h"

namespace sg::gl {
namespace {

// Header: lines 1-2 (#version, one define); prelude.glsl: lines 3-5; kernel/waves.glsl:
// lines 6-9; main.glsl: from line 10.
AssembledShader three_parts() {
  const ShaderSource sources[] = {
      {"prelude.glsl", "a\nb\nc\n"}, {"kernel/waves.glsl", "d\ne\nf\ng"}, {"main.glsl", "h\n"}};
  return assemble_shader(sources, "#define N 3\n");
}

TEST(ShaderAssembly, TextAndLineTable) {
  const AssembledShader a = three_parts();
  EXPECT_EQ(a.text, "#version 450 core\n#define N 3\na\nb\nc\nd\ne\nf\ng\nh\n");
  EXPECT_EQ(a.locate(1), "<header>:1");
  EXPECT_EQ(a.locate(2), "<header>:2");
  EXPECT_EQ(a.locate(3), "prelude.glsl:1");
  EXPECT_EQ(a.locate(5), "prelude.glsl:3");
  EXPECT_EQ(a.locate(6), "kernel/waves.glsl:1");
  EXPECT_EQ(a.locate(9), "kernel/waves.glsl:4");
  EXPECT_EQ(a.locate(10), "main.glsl:1");
  EXPECT_EQ(a.locate(0), "<line 0>");
}

TEST(ShaderAssembly, PartsStartingMidFile) {
  const ShaderSource sources[] = {{"a.glsl", "x\n", 1}, {"b.glsl", "y\nz\n", 7}};
  const AssembledShader a = assemble_shader(sources, "");
  EXPECT_EQ(a.locate(2), "a.glsl:1");
  EXPECT_EQ(a.locate(3), "b.glsl:7");
  EXPECT_EQ(a.locate(4), "b.glsl:8");
}

// kernel.glsl includes constants.glsl and waves.glsl (which includes nothing), with text
// before, between and after.
const std::vector<EmbeddedFile> kIncludeTable = {
    {"kernel/kernel.glsl",
     "// kernel\n#include \"kernel/constants.glsl\"\n  #include \"kernel/waves.glsl\"\nfloat k;\n"},
    {"kernel/constants.glsl", "const float c = 1.0;\n"},
    {"kernel/waves.glsl", "// waves\nfloat w;\n"},
    {"cycle/a.glsl", "#include \"cycle/b.glsl\"\n"},
    {"cycle/b.glsl", "\n#include \"cycle/a.glsl\"\n"},
    {"twice.glsl", "#include \"kernel/constants.glsl\"\n#include \"kernel/constants.glsl\"\n"},
    {"missing.glsl", "x\n#include \"kernel/nope.glsl\"\n"},
};

TEST(ShaderIncludes, ExpandedInOrderWithTheirLines) {
  const std::vector<ShaderSource> parts = expand_includes(kIncludeTable, "kernel/kernel.glsl");
  ASSERT_EQ(parts.size(), 4u);
  EXPECT_EQ(parts[0].name, "kernel/kernel.glsl");
  EXPECT_EQ(parts[0].text, "// kernel\n");
  EXPECT_EQ(parts[0].first_line, 1);
  EXPECT_EQ(parts[1].name, "kernel/constants.glsl");
  EXPECT_EQ(parts[1].first_line, 1);
  EXPECT_EQ(parts[2].name, "kernel/waves.glsl");
  EXPECT_EQ(parts[3].name, "kernel/kernel.glsl");
  EXPECT_EQ(parts[3].text, "float k;\n");
  EXPECT_EQ(parts[3].first_line, 4);
  const AssembledShader a = assemble_shader(parts, "");
  // Text: #version, "// kernel", c, "// waves", "float w;", "float k;".
  EXPECT_EQ(a.locate(3), "kernel/constants.glsl:1");
  EXPECT_EQ(a.locate(5), "kernel/waves.glsl:2");
  EXPECT_EQ(a.locate(6), "kernel/kernel.glsl:4");
}

TEST(ShaderIncludes, ErrorsNameTheInclude) {
  auto message = [](const char* root) {
    try {
      expand_includes(kIncludeTable, root);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("cycle/a.glsl"), "cycle/b.glsl:2: #include \"cycle/a.glsl\" makes a cycle");
  EXPECT_EQ(message("twice.glsl"),
            "twice.glsl:2: #include \"kernel/constants.glsl\": included twice");
  EXPECT_EQ(message("missing.glsl"),
            "missing.glsl:2: #include \"kernel/nope.glsl\": no such embedded file");
}

TEST(ShaderLog, MesaFormat) {
  EXPECT_EQ(map_shader_log("0:8(12): error: `undeclared' undeclared", three_parts()),
            "kernel/waves.glsl:3(12): error: `undeclared' undeclared");
}

TEST(ShaderLog, NvidiaFormat) {
  EXPECT_EQ(map_shader_log("0(8) : error C1008: undefined variable \"x\"\n"
                           "0(14) : warning C7050: \"y\" might be used before being initialized",
                           three_parts()),
            "kernel/waves.glsl:3 : error C1008: undefined variable \"x\"\n"
            "main.glsl:5 : warning C7050: \"y\" might be used before being initialized");
}

TEST(ShaderLog, AmdIntelFormat) {
  EXPECT_EQ(map_shader_log("ERROR: 0:4: 'foo' : undeclared identifier", three_parts()),
            "ERROR: prelude.glsl:2: 'foo' : undeclared identifier");
}

TEST(ShaderLog, OtherLinesKept) {
  EXPECT_EQ(map_shader_log("0:2(1): error: bad define\nlink failed\n", three_parts()),
            "<header>:2(1): error: bad define\nlink failed\n");
}

TEST(Dispatch, GroupCountsRoundUp) {
  EXPECT_EQ(group_counts(1920, 1080, 16, 16), (std::array<int, 2>{120, 68}));
  EXPECT_EQ(group_counts(1, 1, 8, 8), (std::array<int, 2>{1, 1}));
  EXPECT_EQ(group_counts(17, 16, 16, 16), (std::array<int, 2>{2, 1}));
  EXPECT_THROW(group_counts(0, 16, 16, 16), GlError);
}

using ShaderCompile = sg::testing::GlTest;

// Three source strings; the second has an error on its line 3.
const ShaderSource kBroken[] = {
    {"prelude.glsl",
     "layout(local_size_x = 8, local_size_y = 8) in;\nfloat twice(float x) {\n"
     "  return 2.0 * x;\n}\n"},
    {"kernel/waves.glsl",
     "// waves\nfloat height(float x) {\n  return twice(undeclared_name);\n}\n"},
    {"main.glsl", "void main() { float h = height(1.0); }\n"},
};

TEST_F(ShaderCompile, ErrorNamesTheSecondSourceAndItsLine) {
  try {
    Program::compute(kBroken);
    FAIL() << "the broken shader compiled";
  } catch (const GlError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("compute shader (prelude.glsl, kernel/waves.glsl, main.glsl)"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("kernel/waves.glsl:3"), std::string::npos) << what;
    EXPECT_NE(what.find("undeclared_name"), std::string::npos) << what;
    EXPECT_EQ(what.find("prelude.glsl:"), std::string::npos) << what;
    std::cout << what << "\n";
  }
}

TEST_F(ShaderCompile, ErrorInAnIncludedFileNamesIt) {
  const std::vector<EmbeddedFile> table = {
      {"main.glsl", "layout(local_size_x = 1) in;\n#include \"lib.glsl\"\nvoid main() {}\n"},
      {"lib.glsl", "// lib\n\nfloat f() { return missing_name; }\n"}};
  try {
    Program::compute(expand_includes(table, "main.glsl"));
    FAIL() << "compiled";
  } catch (const GlError& e) {
    EXPECT_NE(std::string(e.what()).find("lib.glsl:3"), std::string::npos) << e.what();
  }
}

TEST_F(ShaderCompile, ErrorInTheHeaderNamesIt) {
  const ShaderSource ok[] = {{"main.glsl", "layout(local_size_x = 1) in;\nvoid main() {}\n"}};
  EXPECT_NO_THROW(Program::compute(ok));
  try {
    Program::compute(ok, "#define X\n#error from the header\n");
    FAIL() << "compiled";
  } catch (const GlError& e) {
    EXPECT_NE(std::string(e.what()).find("<header>:3"), std::string::npos) << e.what();
  }
}

TEST_F(ShaderCompile, LinkErrorIsReported) {
  // A compute shader without main compiles and fails to link.
  const ShaderSource no_main[] = {
      {"lib.glsl", "layout(local_size_x = 1) in;\nfloat f() { return 1.0; }\n"}};
  try {
    Program::compute(no_main);
    FAIL() << "linked";
  } catch (const GlError& e) {
    EXPECT_NE(std::string(e.what()).find("program (lib.glsl): link failed"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace sg::gl
