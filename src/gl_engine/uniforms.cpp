#include "gl_engine/uniforms.h"

#include <epoxy/gl.h>

namespace sg::gl_engine {

int UniformWriter::location(const std::string& name) {
  written_.insert(name);
  return glGetUniformLocation(program_.id(), name.c_str());
}

void UniformWriter::set(const std::string& name, float v) {
  if (int l = location(name); l >= 0) glProgramUniform1f(program_.id(), l, v);
}
void UniformWriter::set(const std::string& name, int v) {
  if (int l = location(name); l >= 0) glProgramUniform1i(program_.id(), l, v);
}
void UniformWriter::set(const std::string& name, bool v) {
  if (int l = location(name); l >= 0) glProgramUniform1i(program_.id(), l, v ? 1 : 0);
}
void UniformWriter::set(const std::string& name, const kf::vec2& v) {
  if (int l = location(name); l >= 0) glProgramUniform2f(program_.id(), l, v.x, v.y);
}
void UniformWriter::set(const std::string& name, const kf::vec3& v) {
  if (int l = location(name); l >= 0) glProgramUniform3f(program_.id(), l, v.x, v.y, v.z);
}
void UniformWriter::set(const std::string& name, const kf::uvec2& v) {
  if (int l = location(name); l >= 0) glProgramUniform2ui(program_.id(), l, v.x, v.y);
}
void UniformWriter::set(const std::string& name, const kf::ivec2& v) {
  if (int l = location(name); l >= 0) glProgramUniform2i(program_.id(), l, v.x, v.y);
}

void UniformWriter::set(const std::string& name, const kf::vec4& v) {
  if (int l = location(name); l >= 0) glProgramUniform4f(program_.id(), l, v.x, v.y, v.z, v.w);
}

void set_uniforms(UniformWriter& u, const std::string& n, const kf::Camera& c) {
  u.set(n + ".position", c.position);
  u.set(n + ".forward", c.forward);
  u.set(n + ".right", c.right);
  u.set(n + ".up", c.up);
  u.set(n + ".half_w", c.half_w);
  u.set(n + ".half_h", c.half_h);
  u.set(n + ".width", c.width);
  u.set(n + ".height", c.height);
}

void set_uniforms(UniformWriter& u, const std::string& n, const kf::Frame& f) {
  const std::string l = n + ".light.";
  set_uniforms(u, n + ".camera", f.camera);
  const std::string k = n + ".camera_keys.";
  u.set(k + "count", f.camera_keys.count);
  u.set(k + "up", f.camera_keys.up);
  for (int q = 0; q < kf::kMaxCameraKeys; ++q) {
    const std::string at = std::to_string(q) + "]";
    u.set(k + "time[" + at, f.camera_keys.time[q]);
    u.set(k + "position[" + at, f.camera_keys.position[q]);
    u.set(k + "look_at[" + at, f.camera_keys.look_at[q]);
  }
  u.set(l + "L", f.light.L);
  u.set(l + "e1", f.light.e1);
  u.set(l + "e2", f.light.e2);
  u.set(l + "radius", f.light.radius);
  u.set(l + "cos_radius", f.light.cos_radius);
  u.set(l + "sin_radius", f.light.sin_radius);
  u.set(l + "tan_radius", f.light.tan_radius);
  u.set(l + "chord2", f.light.chord2);
  u.set(l + "visible", f.light.visible);
  u.set(n + ".fresnel", f.fresnel);
  u.set(n + ".displaced", f.displaced);
  u.set(n + ".sky_gradient", f.sky_gradient);
  u.set(n + ".sky_exponent", f.sky_exponent);
  u.set(n + ".wave_count", f.wave_count);
  u.set(n + ".wave_stride", f.wave_stride);
  u.set(n + ".amplitude_bound", f.amplitude_bound);
  u.set(n + ".slope_bound", f.slope_bound);
  u.set(n + ".intersect_tolerance", f.intersect_tolerance);
  u.set(n + ".duration", f.duration);
  u.set(n + ".segments", f.segments);
  u.set(n + ".windows", f.windows);
  u.set(n + ".cascade_count", f.cascade_count);
  u.set(n + ".cascade_base", f.cascade_base);
  u.set(n + ".frame", f.frame);
  u.set(n + ".seed", f.seed);
}

void set_uniforms(UniformWriter& u, const std::string& n, const kf::StaaParams& p) {
  u.set(n + ".per_pixel_ndf", p.per_pixel_ndf);
  u.set(n + ".ndf_mean_shift", p.ndf_mean_shift);
  u.set(n + ".kernels", p.kernels);
  u.set(n + ".elongation_threshold", p.elongation_threshold);
  u.set(n + ".fallback_riemann", p.fallback_riemann);
  u.set(n + ".fallback_along_path", p.fallback_along_path);
  u.set(n + ".riemann_cells", p.riemann_cells);
  u.set(n + ".alias_start", p.alias_start);
  u.set(n + ".alias_end", p.alias_end);
  u.set(n + ".nyquist_max", p.nyquist_max);
  u.set(n + ".footprint", p.footprint);
  u.set(n + ".curvature_limit", p.curvature_limit);
  u.set(n + ".fold_cells", p.fold_cells);
  u.set(n + ".wave_remainder", p.wave_remainder);
  u.set(n + ".smooth_cells", p.smooth_cells);
  u.set(n + ".rdf_at_light", p.rdf_at_light);
}

void set_uniforms(UniformWriter& u, const std::string& n, const kf::SpecaaParams& p) {
  u.set(n + ".sigma2", p.sigma2);
  u.set(n + ".kappa", p.kappa);
  u.set(n + ".full_kernel", p.full_kernel);
  u.set(n + ".quad", p.quad);
}

void set_uniforms(UniformWriter& u, const std::string& n, const kf::MicrospecParams& p) {
  u.set(n + ".exact_area", p.exact_area);
}

void set_uniforms(UniformWriter& u, const std::string& n, const kf::BrunetonParams& p) {
  u.set(n + ".n_min", p.n_min);
  u.set(n + ".n_max", p.n_max);
  u.set(n + ".min_variance", p.min_variance);
  u.set(n + ".fresnel_integral", p.fresnel_integral);
}

void set_uniforms(UniformWriter& u, const std::string& n, const kf::LeanParams& p) {
  u.set(n + ".origin", p.origin);
  u.set(n + ".texel", p.texel);
  u.set(n + ".size", p.size);
  u.set(n + ".levels", p.levels);
  u.set(n + ".empty", p.empty);
  u.set(n + ".aniso", p.aniso);
  u.set(n + ".max_aniso", p.max_aniso);
  u.set(n + ".border", p.border);
  u.set(n + ".base", p.base);
}

void set_uniforms(UniformWriter& u, const std::string& n, const kf::TaaParams& p) {
  u.set(n + ".jitter", p.jitter);
  u.set(n + ".dt_prev", p.dt_prev);
  u.set(n + ".prev_camera_differs", p.prev_camera_differs);
  set_uniforms(u, n + ".prev_camera", p.prev_camera);
}

void set_uniforms(UniformWriter& u, const std::string& n, const kf::TaaResolveParams& p) {
  u.set(n + ".size", p.size);
  u.set(n + ".channels", p.channels);
  u.set(n + ".alpha", p.alpha);
  u.set(n + ".gamma", p.gamma);
  u.set(n + ".clamp", p.clamp);
  u.set(n + ".catmull_rom", p.catmull_rom);
}

void set_uniforms(UniformWriter& u, const std::string& n, const kf::SampleCounts& c) {
  u.set(n + ".sx", c.sx);
  u.set(n + ".sy", c.sy);
  u.set(n + ".nt", c.nt);
  u.set(n + ".time_at_frame", c.time_at_frame);
}

void set_uniforms(UniformWriter& u, const std::string& n, const kf::ReferenceParams& p) {
  u.set(n + ".sx", p.sx);
  u.set(n + ".sy", p.sy);
  u.set(n + ".nt", p.nt);
  u.set(n + ".batches", p.batches);
  u.set(n + ".first_batch", p.first_batch);
  u.set(n + ".adaptive", p.adaptive);
  u.set(n + ".quiet_sx", p.quiet_sx);
  u.set(n + ".quiet_sy", p.quiet_sy);
  u.set(n + ".margin", p.margin);
}

void set_uniforms(UniformWriter& u, const std::string& n, const kf::PathTableInfo& t) {
  u.set(n + ".n_distance", t.n_distance);
  u.set(n + ".n_u", t.n_u);
  u.set(n + ".n_v", t.n_v);
  u.set(n + ".n_sigma", t.n_sigma);
  u.set(n + ".sigma_min", t.sigma_min);
  u.set(n + ".sigma_max", t.sigma_max);
  u.set(n + ".log_q", t.log_q);
  u.set(n + ".extent_k", t.extent_k);
}

void set_uniforms(UniformWriter& u, const std::string& n, const kf::KernelFitInfo& t) {
  u.set(n + ".intervals", t.intervals);
  u.set(n + ".max_ratio", t.max_ratio);
  u.set(n + ".first_solved3", t.first_solved3);
  u.set(n + ".first_solved5", t.first_solved5);
  u.set(n + ".first_solved9", t.first_solved9);
}

std::vector<std::string> active_uniforms(const gl::Program& program) {
  GLint count = 0;
  glGetProgramInterfaceiv(program.id(), GL_UNIFORM, GL_ACTIVE_RESOURCES, &count);
  std::vector<std::string> names;
  for (GLint i = 0; i < count; ++i) {
    const GLenum props[2] = {GL_TYPE, GL_NAME_LENGTH};
    GLint values[2] = {0, 0};
    glGetProgramResourceiv(program.id(), GL_UNIFORM, i, 2, props, 2, nullptr, values);
    const GLenum type = static_cast<GLenum>(values[0]);
    if (type == GL_SAMPLER_BUFFER || type == GL_SAMPLER_2D || type == GL_SAMPLER_2D_ARRAY ||
        type == GL_IMAGE_2D)
      continue;
    std::string name(static_cast<size_t>(values[1]), '\0');
    glGetProgramResourceName(program.id(), GL_UNIFORM, i, values[1], nullptr, name.data());
    name.resize(name.find('\0') == std::string::npos ? name.size() : name.find('\0'));
    names.push_back(name);
  }
  return names;
}

}  // namespace sg::gl_engine
