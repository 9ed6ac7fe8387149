// The kernel's structs (kernel/interface.glsl) as a program's uniforms: each field set by
// its GLSL name ("frame.camera.position"), the way the kernel declares it, so that no byte
// layout is written twice. A field the compiler dropped (the method does not read it) has no
// location and is skipped; the names written are kept, and a test holds them to the
// program's active uniforms (every active uniform is written).
#pragma once

#include <set>
#include <string>
#include <vector>

#include "gl/program.h"
#include "kernel/kernel_types.h"

namespace sg::gl_engine {

class UniformWriter {
 public:
  explicit UniformWriter(const gl::Program& program) : program_(program) {}
  void set(const std::string& name, float v);
  void set(const std::string& name, int v);
  void set(const std::string& name, bool v);
  void set(const std::string& name, const kf::vec2& v);
  void set(const std::string& name, const kf::vec3& v);
  void set(const std::string& name, const kf::uvec2& v);
  void set(const std::string& name, const kf::ivec2& v);
  void set(const std::string& name, const kf::vec4& v);
  // Every name passed to set, active or not.
  const std::set<std::string>& written() const { return written_; }

 private:
  int location(const std::string& name);
  const gl::Program& program_;
  std::set<std::string> written_;
};

void set_uniforms(UniformWriter& u, const std::string& name, const kf::Camera& c);
void set_uniforms(UniformWriter& u, const std::string& name, const kf::Frame& f);
void set_uniforms(UniformWriter& u, const std::string& name, const kf::StaaParams& p);
void set_uniforms(UniformWriter& u, const std::string& name, const kf::SpecaaParams& p);
void set_uniforms(UniformWriter& u, const std::string& name, const kf::MicrospecParams& p);
void set_uniforms(UniformWriter& u, const std::string& name, const kf::BrunetonParams& p);
void set_uniforms(UniformWriter& u, const std::string& name, const kf::LeanParams& p);
void set_uniforms(UniformWriter& u, const std::string& name, const kf::TaaParams& p);
void set_uniforms(UniformWriter& u, const std::string& name, const kf::TaaResolveParams& p);
void set_uniforms(UniformWriter& u, const std::string& name, const kf::SampleCounts& n);
void set_uniforms(UniformWriter& u, const std::string& name, const kf::ReferenceParams& p);
void set_uniforms(UniformWriter& u, const std::string& name, const kf::PathTableInfo& t);
void set_uniforms(UniformWriter& u, const std::string& name, const kf::KernelFitInfo& t);

// The program's active uniforms, as GL names them (struct fields "frame.light.L"; arrays
// "a[0]"), samplers and images excluded.
std::vector<std::string> active_uniforms(const gl::Program& program);

}  // namespace sg::gl_engine
