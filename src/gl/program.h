// GLSL programs: compute shaders (the GL engine's kernel) and the vertex/fragment pair of
// the viewer's blit, compiled from several source strings. A shader is assembled into one
// text: a header (#version 450 core, then the caller's #defines), then each source, with
// a table of the line where each begins. A compile or link failure throws GlError whose log
// names the original file and line ("kernel/waves.glsl:12(3): error: ..."): map_shader_log
// rewrites the "0:L(C)" (Mesa), "0(L)" (NVIDIA) and "ERROR: 0:L:" (AMD, Intel) prefixes
// through the table. Not `#line N S` directives: Mesa's compiler reports source string 0
// for most errors whatever `#line` says (its line numbers are right), so the one reliable
// coordinate is the line of the whole text. Sources must not contain `#line` themselves.
//
// Uniforms: `set(name, value)` (glProgramUniform*: no need to bind the program) for the
// few per-dispatch values; per-frame blocks go into a uniform buffer (gl/buffer.h) with
// std140 layout, bound with `bind_uniform_block`, whose size `uniform_block_size` reports so
// that a C++ mirror struct can be checked against it.
#pragma once

#include <epoxy/gl.h>

#include <array>
#include <glm/glm.hpp>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "base/embedded_file.h"

namespace sg::gl {

struct ShaderSource {
  std::string name;  // the file it came from, as the logs name it
  std::string text;
  int first_line = 1;  // the line of that file the text begins at
};

// The source called `name` in an embedded table (cmake/sg_embed.cmake).
ShaderSource embedded_source(const std::vector<EmbeddedFile>& table, std::string_view name);

// The file `root` of an embedded table with its `#include "name"` lines (names as in the
// table, e.g. "kernel/waves.glsl") replaced by those files, recursively: the pieces in
// order, each with its file's name and first line, so that errors name the included file
// and line. A file not in the table, an include cycle or a file included twice (the kernel's
// files have no include guards, as in C++ it would not compile) throws an sg::Error naming
// the file and the line of the include.
std::vector<ShaderSource> expand_includes(const std::vector<EmbeddedFile>& table,
                                          std::string_view root);

// The text handed to the driver and where each part begins.
struct AssembledShader {
  struct Part {
    std::string name;     // "<header>" for the #version line and the header
    int first_line;       // line of the text (from 1) where the part begins
    int source_line = 1;  // the line of its file that is
  };
  std::string text;  // "#version 450 core\n" + header + each source (with a final newline)
  std::vector<Part> parts;

  // The part and its line for line `line` of the text: "kernel/waves.glsl:12".
  std::string locate(int line) const;
};
AssembledShader assemble_shader(std::span<const ShaderSource> sources, std::string_view header);

// Rewrites the driver log's line references into file:line. Lines in no known format are
// kept as they are.
std::string map_shader_log(std::string_view log, const AssembledShader& shader);

class Program {
 public:
  Program() = default;
  ~Program();
  Program(Program&& o) noexcept : id_(o.id_), local_size_(o.local_size_) { o.id_ = 0; }
  Program& operator=(Program&& o) noexcept;
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;

  // Compiles and links a compute shader; `header` comes after #version (e.g. "#define N 8\n").
  static Program compute(std::span<const ShaderSource> sources, std::string_view header = {});
  static Program graphics(std::span<const ShaderSource> vertex,
                          std::span<const ShaderSource> fragment, std::string_view header = {});

  GLuint id() const { return id_; }
  void use() const { glUseProgram(id_); }

  // The compute shader's local_size (x, y, z), read once at link time; 0s for graphics.
  std::array<int, 3> local_size() const { return local_size_; }

  // The location of an active uniform; GlError naming it when the program has none (the
  // compiler drops unused uniforms, so a typo or an unused one is caught here).
  GLint uniform_location(std::string_view name) const;
  void set(std::string_view name, int v) const;
  void set(std::string_view name, unsigned v) const;
  void set(std::string_view name, float v) const;
  void set(std::string_view name, glm::vec2 v) const;
  void set(std::string_view name, glm::vec3 v) const;
  void set(std::string_view name, glm::vec4 v) const;
  void set(std::string_view name, glm::ivec2 v) const;
  void set(std::string_view name, glm::ivec3 v) const;
  void set(std::string_view name, glm::ivec4 v) const;
  void set(std::string_view name, const glm::mat4& v) const;

  // Binds uniform block `name` to binding point `binding` (or throws naming it);
  // uniform_block_size is its GL_UNIFORM_BLOCK_DATA_SIZE in bytes.
  void bind_uniform_block(std::string_view name, GLuint binding) const;
  int uniform_block_size(std::string_view name) const;

 private:
  explicit Program(GLuint id) : id_(id) {}
  GLuint block_index(std::string_view name) const;
  GLuint id_ = 0;
  std::array<int, 3> local_size_ = {0, 0, 0};
};

}  // namespace sg::gl
