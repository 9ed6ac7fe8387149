// The GL layer on a real context (Mesa llvmpipe here and in CI, NVIDIA's EGL on a GPU
// machine): a compute shader's image and SSBO writes read back exactly, texelFetch from a
// buffer texture and a 3D table returns what was uploaded, a std140 block matches its C++
// mirror, the timer measures a positive time. Skipped with the reason where no context can
// be made (testing/gl_context.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "embedded/gl_test_shaders.h"
#include "gl/buffer.h"
#include "gl/check.h"
#include "gl/dispatch.h"
#include "gl/error.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "gl/texture_buffer.h"
#include "gl/timer.h"
#include "math/rng.h"
#include "testing/gl_context.h"

namespace sg::gl {
namespace {

using GlLayer = sg::testing::GlTest;

ShaderSource test_shader(const char* name) {
  return embedded_source(gl_test_shaders(), std::string("gl/test_shaders/") + name);
}

Program pattern_program() {
  const ShaderSource sources[] = {test_shader("pattern_common.glsl"), test_shader("pattern.glsl")};
  return Program::compute(sources);
}

// Random floats in [-1e3, 1e3] with all mantissa bits in use (no denormals, which GPUs
// may flush).
std::vector<float> random_floats(size_t n, std::uint64_t seed) {
  Pcg32 rng(seed, 7);
  std::vector<float> v(n);
  for (float& x : v)
    x = float((rng.uniform() * 2.0 - 1.0) * 1e3);
  return v;
}

TEST_F(GlLayer, ContextIsCoreFourFiveWithComputeShaders) {
  const ContextInfo& info = context()->info();
  EXPECT_GE(info.major * 10 + info.minor, 45) << info.gl_version;
  EXPECT_FALSE(info.gl_renderer.empty());
  GLint groups = 0;
  glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 0, &groups);
  EXPECT_GE(groups, 65535);
  EXPECT_GE(max_texture_buffer_texels(), 65536 * 4);
  std::cout << "GL context: " << info.summary() << "\n";
}

TEST_F(GlLayer, ComputeShaderWritesImageAndBufferExactly) {
  // Not a multiple of 16 either way: the grid is rounded up and the shader skips the rest.
  const int w = 37, h = 23;
  Program program = pattern_program();
  EXPECT_EQ(program.local_size(), (std::array<int, 3>{16, 16, 1}));
  Texture image = Texture::image_2d(w, h);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  image.fill(glm::vec4(nan));  // poison: every texel must be written
  // One more word than pixels: the last must stay as poisoned.
  Buffer words(size_t(w * h + 1) * sizeof(std::uint32_t));
  words.fill(0xdeadbeefu);
  image.bind_image(0, GL_WRITE_ONLY);
  words.bind(GL_SHADER_STORAGE_BUFFER, 1);
  program.set("size", glm::ivec2(w, h));
  dispatch_2d(program, w, h);
  barrier();

  const std::vector<float> texels = image.read();
  ASSERT_EQ(texels.size(), size_t(w * h * 4));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float* t = &texels[size_t((y * w + x) * 4)];
      ASSERT_EQ(t[0], float(x)) << x << "," << y;
      ASSERT_EQ(t[1], float(y)) << x << "," << y;
      ASSERT_EQ(t[2], float(x * 1000 + y)) << x << "," << y;
      ASSERT_EQ(t[3], 0.25f * float(x - y)) << x << "," << y;
    }
  const std::vector<std::uint32_t> got = words.read<std::uint32_t>();
  for (std::uint32_t i = 0; i < std::uint32_t(w * h); ++i)
    ASSERT_EQ(got[i], (i * 2654435761u) ^ 0x9e3779b9u) << i;
  EXPECT_EQ(got[size_t(w * h)], 0xdeadbeefu);
  check_errors("pattern test");
}

TEST_F(GlLayer, TexelFetchReturnsUploadedValues) {
  // A per-wave array at the size the engine needs (65536 waves x 4 texels would be 2^18;
  // 4096 x 4 keeps llvmpipe quick) and a table of 64 x 32 x 8 floats.
  const int n_texels = 4096 * 4;
  const std::vector<float> wave_data = random_floats(size_t(n_texels) * 4, 1);
  TextureBuffer waves(wave_data);
  EXPECT_EQ(waves.texels(), size_t(n_texels));
  const int tw = 64, th = 32, td = 8;
  const std::vector<float> table_data = random_floats(size_t(tw * th * td), 2);
  Texture table = Texture::table(GL_TEXTURE_3D, tw, th, td, table_data);
  EXPECT_EQ(table.read(), table_data);

  const ShaderSource source = test_shader("fetch.glsl");
  Program program = Program::compute(std::span(&source, 1));
  Buffer texels(wave_data.size() * sizeof(float));
  Buffer values(table_data.size() * sizeof(float));
  texels.fill(0xffffffffu);
  values.fill(0xffffffffu);
  waves.bind(0);
  table.bind_texture(1);
  texels.bind(GL_SHADER_STORAGE_BUFFER, 2);
  values.bind(GL_SHADER_STORAGE_BUFFER, 3);
  program.set("n_texels", n_texels);
  program.set("table_size", glm::ivec3(tw, th, td));
  program.use();
  glDispatchCompute(GLuint(n_texels / 64), 1, 1);
  barrier();
  check_errors("fetch dispatch");
  const std::vector<float> got_texels = texels.read<float>();
  const std::vector<float> got_values = values.read<float>();
  ASSERT_EQ(std::memcmp(got_texels.data(), wave_data.data(), wave_data.size() * sizeof(float)), 0);
  ASSERT_EQ(std::memcmp(got_values.data(), table_data.data(), table_data.size() * sizeof(float)),
            0);
}

TEST_F(GlLayer, TextureBufferRejectsTooManyTexels) {
  const size_t limit = size_t(max_texture_buffer_texels());
  EXPECT_NO_THROW(check_texture_buffer_texels(limit));
  try {
    check_texture_buffer_texels(limit + 1);
    FAIL() << "no error";
  } catch (const GlError& e) {
    EXPECT_NE(std::string(e.what()).find("GL_MAX_TEXTURE_BUFFER_SIZE"), std::string::npos)
        << e.what();
  }
}

TEST_F(GlLayer, TableTexturesOfTheEnginesSize) {
  // 64 sigma slices of 512 x 512: as a 3D texture and as a 2D array.
  const std::vector<float> data = random_floats(size_t(64) * 512 * 512, 3);
  for (GLenum target : {GL_TEXTURE_3D, GL_TEXTURE_2D_ARRAY}) {
    Texture t = Texture::table(target, 512, 512, 64, data);
    const std::vector<float> back = t.read();
    ASSERT_EQ(std::memcmp(back.data(), data.data(), data.size() * sizeof(float)), 0) << target;
  }
  EXPECT_THROW(Texture(GL_TEXTURE_3D, GL_R32F, 1 << 16, 1, 1), GlError);
}

TEST_F(GlLayer, Std140BlockMatchesItsMirror) {
  // The C++ mirror of block.glsl's Frame under std140: vec3 aligned to 16 with a float
  // after it, array elements padded to 16 bytes.
  struct alignas(16) Frame {
    float camera[4];
    float light[3];
    float radius;
    float size[2];
    std::int32_t waves;
    std::uint32_t seed;
    float phases[3][4];  // float[3] takes a vec4 slot each
  };
  static_assert(sizeof(Frame) == 96);
  Frame f{};
  const float camera[4] = {1.5f, -2.25f, 3.125f, 4.0f};
  std::memcpy(f.camera, camera, sizeof camera);
  f.light[0] = 0.1f, f.light[1] = 0.2f, f.light[2] = 0.3f;
  f.radius = 0.0047f;
  f.size[0] = 640, f.size[1] = 360;
  f.waves = 37;
  f.seed = 12345;
  f.phases[0][0] = -1.0f, f.phases[1][0] = 2.0f, f.phases[2][0] = -3.5f;

  const ShaderSource source = test_shader("block.glsl");
  Program program = Program::compute(std::span(&source, 1));
  EXPECT_EQ(program.uniform_block_size("Frame"), int(sizeof(Frame)));
  program.bind_uniform_block("Frame", 0);
  Buffer ubo(sizeof f, &f);
  Buffer copy(15 * sizeof(float));
  ubo.bind(GL_UNIFORM_BUFFER, 0);
  copy.bind(GL_SHADER_STORAGE_BUFFER, 1);
  program.use();
  glDispatchCompute(1, 1, 1);
  barrier();
  const std::vector<float> got = copy.read<float>();
  const float want[15] = {1.5f, -2.25f, 3.125f, 4.0f,  0.1f, 0.2f, 0.3f, 0.0047f,
                          640,  360,    37,     12345, -1,   2,    -3.5f};
  for (int k = 0; k < 15; ++k)
    EXPECT_EQ(got[size_t(k)], want[k]) << k;
  EXPECT_THROW(program.uniform_block_size("Missing"), GlError);
}

TEST_F(GlLayer, TimerMeasuresAPositiveTime) {
  const int w = 512, h = 512;
  Program program = pattern_program();
  Texture image = Texture::image_2d(w, h);
  Buffer words(size_t(w * h) * sizeof(std::uint32_t));
  image.bind_image(0);
  words.bind(GL_SHADER_STORAGE_BUFFER, 1);
  program.set("size", glm::ivec2(w, h));
  GpuTimer timer;
  EXPECT_THROW(timer.milliseconds(), GlError);
  dispatch_2d(program, w, h);  // warm-up
  glFinish();
  // Ten dispatches take about ten times one: the timer measures the dispatches, not a
  // constant. The fastest of three of each, against a busy machine.
  double one = 1e30, ten = 1e30;
  for (int rep = 0; rep < 3; ++rep) {
    one = std::min(one, timer.time([&] { dispatch_2d(program, w, h); }));
    ten = std::min(ten, timer.time([&] {
      for (int k = 0; k < 10; ++k)
        dispatch_2d(program, w, h);
    }));
  }
  std::cout << "512 x 512 pattern dispatch: " << one << " ms, ten: " << ten << " ms\n";
  EXPECT_GT(one, 0.0);
  EXPECT_GT(ten, 3.0 * one);
  EXPECT_LT(ten, 10000.0);
}

TEST_F(GlLayer, UnknownUniformIsNamed) {
  Program program = pattern_program();
  try {
    program.set("sise", glm::ivec2(1, 1));
    FAIL() << "no error";
  } catch (const GlError& e) {
    EXPECT_NE(std::string(e.what()).find("'sise'"), std::string::npos) << e.what();
  }
}

TEST_F(GlLayer, ErrorCheckReportsTheCall) {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 123456);  // no such buffer
  try {
    check_errors("binding buffer 123456");
    FAIL() << "no error";
  } catch (const GlError& e) {
    EXPECT_NE(std::string(e.what()).find("binding buffer 123456: GL_INVALID_"), std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(check_errors("after the error was reported"));
}

}  // namespace
}  // namespace sg::gl
