// gl_info: which OpenGL a machine gives sunglint. Prints the headless EGL context's platform,
// GL_RENDERER and GL_VERSION and the limits the GL engine relies on; with --window, also
// opens a GLX window (needs DISPLAY, e.g. under Xvfb) and prints its renderer. Exits 1 with
// the reason when no OpenGL 4.5 core context can be made. scripts/gpu-run.sh runs it first.
//   gl_info [--platform auto|device|surfaceless] [--window]
#include <epoxy/gl.h>

#include <cstdio>
#include <cstring>
#include <string>

#include "gl/context.h"
#include "gl/error.h"
#include "gl/texture_buffer.h"
#include "viewer/window.h"

namespace {

void print_limits() {
  GLint groups[3], size[3], invocations = 0, tex3d = 0, layers = 0, shared = 0;
  for (GLuint k = 0; k < 3; ++k) {
    glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, k, &groups[k]);
    glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_SIZE, k, &size[k]);
  }
  glGetIntegerv(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS, &invocations);
  glGetIntegerv(GL_MAX_COMPUTE_SHARED_MEMORY_SIZE, &shared);
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &tex3d);
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &layers);
  std::printf("  work groups   %d x %d x %d, group size %d x %d x %d, %d invocations\n", groups[0],
              groups[1], groups[2], size[0], size[1], size[2], invocations);
  std::printf("  shared memory %d bytes; texture buffer %d texels; 3D texture %d; layers %d\n",
              shared, sg::gl::max_texture_buffer_texels(), tex3d, layers);
}

}  // namespace

int main(int argc, char** argv) {
  sg::gl::ContextOptions options;
  bool window = false;
  try {
    for (int k = 1; k < argc; ++k) {
      const std::string a = argv[k];
      if (a == "--platform" && k + 1 < argc) {
        options.platform = sg::gl::parse_platform(argv[++k]);
      } else if (a == "--window") {
        window = true;
      } else {
        std::fprintf(stderr,
                     "gl_info: unknown argument '%s'\n"
                     "usage: gl_info [--platform auto|device|surfaceless] [--window]\n",
                     a.c_str());
        return 2;
      }
    }
    {
      sg::gl::HeadlessContext ctx(options);
      const sg::gl::ContextInfo& i = ctx.info();
      std::printf(
          "EGL: %s\n  platform      %s\n  EGL           %s %s\n  GL_VENDOR     %s\n"
          "  GL_RENDERER   %s\n  GL_VERSION    %s\n  GLSL          %s\n",
          i.software ? "software rasteriser" : "hardware", i.platform.c_str(), i.egl_vendor.c_str(),
          i.egl_version.c_str(), i.gl_vendor.c_str(), i.gl_renderer.c_str(), i.gl_version.c_str(),
          i.glsl_version.c_str());
      print_limits();
    }
    if (window) {
      sg::viewer::Window w({64, 64, "gl_info"});
      const sg::gl::ContextInfo& i = w.info();
      std::printf("GLX window: %s\n  GL_VENDOR     %s\n  GL_RENDERER   %s\n  GL_VERSION    %s\n",
                  i.software ? "software rasteriser" : "hardware", i.gl_vendor.c_str(),
                  i.gl_renderer.c_str(), i.gl_version.c_str());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gl_info: %s\n", e.what());
    return 1;
  }
  return 0;
}
