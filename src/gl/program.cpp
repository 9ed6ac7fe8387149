#include "gl/program.h"

#include <algorithm>
#include <glm/gtc/type_ptr.hpp>
#include <regex>

#include "gl/check.h"
#include "gl/error.h"

namespace sg::gl {
namespace {

std::string shader_log(GLuint shader) {
  GLint n = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &n);
  std::string log(static_cast<size_t>(n > 0 ? n : 0), '\0');
  if (n > 0) glGetShaderInfoLog(shader, n, nullptr, log.data());
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n'))
    log.pop_back();
  return log;
}

std::string program_log(GLuint program) {
  GLint n = 0;
  glGetProgramiv(program, GL_INFO_LOG_LENGTH, &n);
  std::string log(static_cast<size_t>(n > 0 ? n : 0), '\0');
  if (n > 0) glGetProgramInfoLog(program, n, nullptr, log.data());
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n'))
    log.pop_back();
  return log;
}

// The files of the sources, each once (a file split by its includes is several sources).
std::vector<std::string> names_of(std::span<const ShaderSource> sources) {
  std::vector<std::string> names;
  for (const ShaderSource& s : sources)
    if (std::find(names.begin(), names.end(), s.name) == names.end()) names.push_back(s.name);
  return names;
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) {
    if (!out.empty()) out += ", ";
    out += n;
  }
  return out;
}

// Compiles one stage; throws with the mapped log.
GLuint compile(GLenum stage, const char* stage_name, std::span<const ShaderSource> sources,
               std::string_view header) {
  const AssembledShader assembled = assemble_shader(sources, header);
  const std::vector<std::string> names = names_of(sources);
  GLuint shader = glCreateShader(stage);
  const char* ptr = assembled.text.c_str();
  const GLint len = static_cast<GLint>(assembled.text.size());
  glShaderSource(shader, 1, &ptr, &len);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    std::string log = map_shader_log(shader_log(shader), assembled);
    glDeleteShader(shader);
    throw GlError(std::string(stage_name) + " shader (" + joined(names) + "): compile failed:\n" +
                  log);
  }
  return shader;
}

GLuint link(std::initializer_list<GLuint> shaders, const std::vector<std::string>& names) {
  GLuint program = glCreateProgram();
  for (GLuint s : shaders)
    glAttachShader(program, s);
  glLinkProgram(program);
  for (GLuint s : shaders) {
    glDetachShader(program, s);
    glDeleteShader(s);
  }
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    std::string log = program_log(program);
    glDeleteProgram(program);
    throw GlError("program (" + joined(names) + "): link failed:\n" + log);
  }
  check_errors("linking program (" + joined(names) + ")");
  return program;
}

}  // namespace

ShaderSource embedded_source(const std::vector<EmbeddedFile>& table, std::string_view name) {
  const EmbeddedFile& f = find_embedded(table, name);
  return {std::string(f.name), std::string(f.bytes)};
}

namespace {

int count_lines(std::string_view text) {
  int n = 0;
  for (char c : text)
    n += c == '\n';
  return n;
}

}  // namespace

namespace {

// `#include "name"` at the start of a line (after blanks): the name, else "".
std::string include_target(std::string_view line) {
  size_t k = line.find_first_not_of(" \t");
  if (k == std::string_view::npos || line.substr(k, 8) != "#include") return "";
  k = line.find('"', k + 8);
  const size_t end = k == std::string_view::npos ? k : line.find('"', k + 1);
  if (end == std::string_view::npos) return "";
  return std::string(line.substr(k + 1, end - k - 1));
}

void expand(const std::vector<EmbeddedFile>& table, const std::string& name,
            const std::string& from, std::vector<std::string>& stack,
            std::vector<std::string>& done, std::vector<ShaderSource>& out) {
  for (const std::string& s : stack)
    if (s == name) throw Error(from + ": #include \"" + name + "\" makes a cycle");
  for (const std::string& d : done)
    if (d == name) throw Error(from + ": #include \"" + name + "\": included twice");
  const EmbeddedFile* file = nullptr;
  for (const EmbeddedFile& f : table)
    if (f.name == name) file = &f;
  if (!file) throw Error(from + ": #include \"" + name + "\": no such embedded file");
  stack.push_back(name);
  done.push_back(name);
  const std::string_view text = file->bytes;
  ShaderSource piece{name, "", 1};
  int line = 1;
  for (size_t pos = 0; pos < text.size(); ++line) {
    size_t end = text.find('\n', pos);
    end = end == std::string_view::npos ? text.size() : end + 1;
    const std::string_view l = text.substr(pos, end - pos);
    const std::string target = include_target(l);
    if (target.empty()) {
      piece.text += l;
    } else {
      if (!piece.text.empty()) out.push_back(piece);
      expand(table, target, name + ":" + std::to_string(line), stack, done, out);
      piece = ShaderSource{name, "", line + 1};
    }
    pos = end;
  }
  if (!piece.text.empty()) out.push_back(piece);
  stack.pop_back();
}

}  // namespace

std::vector<ShaderSource> expand_includes(const std::vector<EmbeddedFile>& table,
                                          std::string_view root) {
  std::vector<std::string> stack, done;
  std::vector<ShaderSource> out;
  expand(table, std::string(root), "expand_includes", stack, done, out);
  return out;
}

AssembledShader assemble_shader(std::span<const ShaderSource> sources, std::string_view header) {
  AssembledShader a;
  a.text = "#version 450 core\n";
  a.text += header;
  if (a.text.back() != '\n') a.text += '\n';
  a.parts.push_back({"<header>", 1, 1});
  for (const ShaderSource& s : sources) {
    a.parts.push_back({s.name, count_lines(a.text) + 1, s.first_line});
    a.text += s.text;
    if (!s.text.empty() && s.text.back() != '\n') a.text += '\n';
  }
  return a;
}

std::string AssembledShader::locate(int line) const {
  const Part* part = nullptr;
  for (const Part& p : parts)
    if (p.first_line <= line) part = &p;
  if (!part) return "<line " + std::to_string(line) + ">";
  return part->name + ":" + std::to_string(line - part->first_line + part->source_line);
}

std::string map_shader_log(std::string_view log, const AssembledShader& shader) {
  // Mesa "0:12(5): error", AMD/Intel "ERROR: 0:12: error", NVIDIA "0(12) : error".
  static const std::regex colon(R"(^(\s*(?:ERROR|WARNING):\s*)?(\d+):(\d+)(\(\d+\))?)");
  static const std::regex paren(R"(^(\s*)(\d+)\((\d+)\))");
  std::string out;
  size_t pos = 0;
  while (pos <= log.size()) {
    size_t end = log.find('\n', pos);
    if (end == std::string_view::npos) end = log.size();
    std::string line(log.substr(pos, end - pos));
    std::smatch m;
    if (std::regex_search(line, m, colon)) {
      line = m[1].str() + shader.locate(std::stoi(m[3].str())) + m[4].str() + m.suffix().str();
    } else if (std::regex_search(line, m, paren)) {
      line = m[1].str() + shader.locate(std::stoi(m[3].str())) + m.suffix().str();
    }
    out += line;
    if (end == log.size()) break;
    out += '\n';
    pos = end + 1;
  }
  return out;
}

Program::~Program() {
  if (id_) glDeleteProgram(id_);
}

Program& Program::operator=(Program&& o) noexcept {
  if (this != &o) {
    if (id_) glDeleteProgram(id_);
    id_ = o.id_;
    local_size_ = o.local_size_;
    o.id_ = 0;
  }
  return *this;
}

Program Program::compute(std::span<const ShaderSource> sources, std::string_view header) {
  GLuint cs = compile(GL_COMPUTE_SHADER, "compute", sources, header);
  Program p(link({cs}, names_of(sources)));
  GLint size[3] = {0, 0, 0};
  glGetProgramiv(p.id_, GL_COMPUTE_WORK_GROUP_SIZE, size);
  check_errors("glGetProgramiv(GL_COMPUTE_WORK_GROUP_SIZE)");
  p.local_size_ = {size[0], size[1], size[2]};
  return p;
}

Program Program::graphics(std::span<const ShaderSource> vertex,
                          std::span<const ShaderSource> fragment, std::string_view header) {
  GLuint vs = compile(GL_VERTEX_SHADER, "vertex", vertex, header);
  GLuint fs = 0;
  try {
    fs = compile(GL_FRAGMENT_SHADER, "fragment", fragment, header);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  std::vector<std::string> names = names_of(vertex);
  for (const ShaderSource& s : fragment)
    names.push_back(s.name);
  return Program(link({vs, fs}, names));
}

GLint Program::uniform_location(std::string_view name) const {
  GLint loc = glGetUniformLocation(id_, std::string(name).c_str());
  if (loc < 0) throw GlError("uniform '" + std::string(name) + "': not an active uniform");
  return loc;
}

void Program::set(std::string_view name, int v) const {
  glProgramUniform1i(id_, uniform_location(name), v);
}
void Program::set(std::string_view name, unsigned v) const {
  glProgramUniform1ui(id_, uniform_location(name), v);
}
void Program::set(std::string_view name, float v) const {
  glProgramUniform1f(id_, uniform_location(name), v);
}
void Program::set(std::string_view name, glm::vec2 v) const {
  glProgramUniform2fv(id_, uniform_location(name), 1, glm::value_ptr(v));
}
void Program::set(std::string_view name, glm::vec3 v) const {
  glProgramUniform3fv(id_, uniform_location(name), 1, glm::value_ptr(v));
}
void Program::set(std::string_view name, glm::vec4 v) const {
  glProgramUniform4fv(id_, uniform_location(name), 1, glm::value_ptr(v));
}
void Program::set(std::string_view name, glm::ivec2 v) const {
  glProgramUniform2iv(id_, uniform_location(name), 1, glm::value_ptr(v));
}
void Program::set(std::string_view name, glm::ivec3 v) const {
  glProgramUniform3iv(id_, uniform_location(name), 1, glm::value_ptr(v));
}
void Program::set(std::string_view name, glm::ivec4 v) const {
  glProgramUniform4iv(id_, uniform_location(name), 1, glm::value_ptr(v));
}
void Program::set(std::string_view name, const glm::mat4& v) const {
  glProgramUniformMatrix4fv(id_, uniform_location(name), 1, GL_FALSE, glm::value_ptr(v));
}

GLuint Program::block_index(std::string_view name) const {
  GLuint index = glGetUniformBlockIndex(id_, std::string(name).c_str());
  if (index == GL_INVALID_INDEX)
    throw GlError("uniform block '" + std::string(name) + "': not an active block");
  return index;
}

void Program::bind_uniform_block(std::string_view name, GLuint binding) const {
  glUniformBlockBinding(id_, block_index(name), binding);
  check_errors("glUniformBlockBinding(" + std::string(name) + ")");
}

int Program::uniform_block_size(std::string_view name) const {
  GLint size = 0;
  glGetActiveUniformBlockiv(id_, block_index(name), GL_UNIFORM_BLOCK_DATA_SIZE, &size);
  check_errors("glGetActiveUniformBlockiv(" + std::string(name) + ")");
  return size;
}

}  // namespace sg::gl
