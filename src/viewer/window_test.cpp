// The viewer's window under Xvfb (started by the test, testing/xvfb.h) with Mesa's GLX: a
// compute shader's RGBA32F image drawn to the window with ImGui on top, a few frames, a
// screenshot checked pixel by pixel; and the clear errors without a display, with a
// display that does not open, and with OpenGL below 4.5.
#include <gtest/gtest.h>
#include <imgui.h>

#include <cstdlib>
#include <memory>
#include <string>

#include "gl/dispatch.h"
#include "gl/error.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "testing/child_process.h"
#include "testing/gl_context.h"
#include "testing/xvfb.h"
#include "viewer/texture_view.h"
#include "viewer/window.h"

namespace sg::viewer {
namespace {

class WindowTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { server = std::make_unique<sg::testing::Xvfb>(); }
  static void TearDownTestSuite() { server.reset(); }
  void SetUp() override {
    if (!server->running()) {
      if (sg::testing::gl_required()) FAIL() << "SUNGLINT_REQUIRE_GL is set: " << server->reason();
      GTEST_SKIP() << server->reason();
    }
    setenv("DISPLAY", server->display().c_str(), 1);
  }
  static std::unique_ptr<sg::testing::Xvfb> server;
};
std::unique_ptr<sg::testing::Xvfb> WindowTest::server;

// The image: red left half, green right half, a blue band over the top 16 rows (row 0 is
// the top), exact 0 and 1 so that RGBA8 holds them exactly.
const char* kPattern = R"(
layout(local_size_x = 16, local_size_y = 16) in;
layout(rgba32f, binding = 0) uniform writeonly image2D image;
uniform ivec2 size;
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= size.x || p.y >= size.y) return;
  vec4 c = p.y < 16 ? vec4(0, 0, 1, 1) : (p.x < size.x / 2 ? vec4(1, 0, 0, 1) : vec4(0, 1, 0, 1));
  imageStore(image, p, c);
}
)";

struct Rgba {
  int r, g, b, a;
  bool operator==(const Rgba&) const = default;
};
std::ostream& operator<<(std::ostream& os, const Rgba& c) {
  return os << "(" << c.r << ", " << c.g << ", " << c.b << ", " << c.a << ")";
}
Rgba pixel(const std::vector<std::uint8_t>& shot, int w, int x, int y) {
  const std::uint8_t* p = &shot[size_t((y * w + x) * 4)];
  return {p[0], p[1], p[2], p[3]};
}

TEST_F(WindowTest, ComputeImageAndImGuiInAScreenshot) {
  const int w = 320, h = 180;
  Window window({w, h, "sunglint window test"});
  EXPECT_GE(window.info().major * 10 + window.info().minor, 45) << window.info().gl_version;
  std::cout << "window: " << window.info().gl_renderer << " | " << window.info().gl_version << "\n";
  ASSERT_EQ(window.width(), w);
  ASSERT_EQ(window.height(), h);

  const gl::ShaderSource source{"pattern.glsl", kPattern};
  gl::Program pattern = gl::Program::compute(std::span(&source, 1));
  gl::Texture image = gl::Texture::image_2d(w, h);
  TextureView view;
  std::vector<std::uint8_t> shot;
  for (int frame = 0; frame < 3; ++frame) {
    window.begin_frame();
    image.bind_image(0);
    pattern.set("size", glm::ivec2(w, h));
    gl::dispatch_2d(pattern, w, h);
    gl::barrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    view.draw(image, 0, 0, w, h);
    ImGui::SetNextWindowPos(ImVec2(200, 120));
    ImGui::SetNextWindowSize(ImVec2(110, 50));
    ImGui::Begin("panel");
    ImGui::Text("frame %d", frame);
    ImGui::End();
    window.end_frame(frame == 2 ? &shot : nullptr);
  }
  ASSERT_EQ(shot.size(), size_t(w * h * 4));
  EXPECT_EQ(pixel(shot, w, 10, 100), (Rgba{255, 0, 0, 255}));   // left: red
  EXPECT_EQ(pixel(shot, w, 150, 170), (Rgba{255, 0, 0, 255}));  // left, bottom
  EXPECT_EQ(pixel(shot, w, 170, 60), (Rgba{0, 255, 0, 255}));   // right: green
  EXPECT_EQ(pixel(shot, w, 40, 5), (Rgba{0, 0, 255, 255}));     // top band: row 0 on top
  EXPECT_EQ(pixel(shot, w, 300, 15), (Rgba{0, 0, 255, 255}));
  EXPECT_EQ(pixel(shot, w, 300, 16), (Rgba{0, 255, 0, 255}));
  // ImGui's panel covers (200, 120)-(310, 170): its title bar and body are not the image.
  EXPECT_NE(pixel(shot, w, 250, 125), (Rgba{0, 255, 0, 255}));
  EXPECT_NE(pixel(shot, w, 250, 150), (Rgba{0, 255, 0, 255}));
}

TEST_F(WindowTest, OneWindowAtATime) {
  Window a({64, 64, "a"});
  EXPECT_THROW(Window({64, 64, "b"}), Error);
}

TEST(WindowErrors, NoDisplay) {
  unsetenv("DISPLAY");
  unsetenv("WAYLAND_DISPLAY");
  try {
    Window w({64, 64, "no display"});
    FAIL() << "opened a window without a display";
  } catch (const gl::Unavailable& e) {
    EXPECT_NE(std::string(e.what()).find("no display: DISPLAY is not set"), std::string::npos)
        << e.what();
  }
}

TEST(WindowErrors, DisplayThatDoesNotOpen) {
  setenv("DISPLAY", ":31999", 1);  // no such server
  unsetenv("WAYLAND_DISPLAY");
  try {
    Window w({64, 64, "bad display"});
    FAIL() << "opened a window on :31999";
  } catch (const gl::Unavailable& e) {
    EXPECT_NE(std::string(e.what()).find("no display: X11: Failed to open display :31999"),
              std::string::npos)
        << e.what();
  }
}

// The exit codes of the child of BelowFourFiveIsAClearError.
constexpr int kRefused = 0, kMade = 1, kNotMesa = 77, kOther = 78;

TEST_F(WindowTest, BelowFourFiveIsAClearError) {
  // Mesa reads MESA_GL_VERSION_OVERRIDE once per process: the window is made in a fresh
  // child process (testing/child_process.h) on this test's display.
  if (sg::testing::in_child()) {
    setenv("MESA_GL_VERSION_OVERRIDE", "4.3", 1);
    try {
      Window w({64, 64, "old GL"});
      const bool mesa = w.info().gl_version.find("Mesa") != std::string::npos;
      std::fprintf(stderr, "made %s\n", w.info().gl_version.c_str());
      std::exit(mesa ? kMade : kNotMesa);
    } catch (const gl::Unavailable& e) {
      std::fprintf(stderr, "%s\n", e.what());
      std::exit(std::string(e.what()).find("no OpenGL 4.5 core window: ") != std::string::npos
                    ? kRefused
                    : kOther);
    }
  }
  const sg::testing::ChildResult child = sg::testing::run_child();
  if (child.exit_code == kNotMesa) GTEST_SKIP() << "needs Mesa (MESA_GL_VERSION_OVERRIDE)";
  EXPECT_EQ(child.exit_code, kRefused) << child.output;
}

}  // namespace
}  // namespace sg::viewer
