#include "gl_engine/cascade_fft_gl.h"

#include <cmath>
#include <string>

#include "base/error.h"
#include "embedded/kernel_sources.h"
#include "gl/dispatch.h"
#include "gl/error.h"
#include "math/vec.h"

namespace sg::gl_engine {

gl::Program cascade_program(const char* main_file, const std::string& header,
                            const char* kernel_file) {
  const auto& table = kernel_sources();
  std::vector<gl::ShaderSource> s;
  if (kernel_file) {
    s.push_back(gl::embedded_source(table, "kernel/glsl_prelude.glsl"));
    s.push_back(gl::embedded_source(table, kernel_file));
  }
  s.push_back(gl::embedded_source(table, std::string("gl_engine/shaders/") + main_file));
  return gl::Program::compute(s, header);
}

CascadeFftGl::CascadeFftGl(int n) : n_(n) {
  if (n < kMinLattice || n > kMaxLattice || (n & (n - 1)) != 0)
    throw Error("CascadeFftGl: the lattice must be a power of two in [4, 1024], got " +
                std::to_string(n));
  spectrum_ = cascade_program("cascade_spectrum.glsl", "", "kernel/cascade_spectrum.glsl");
  fft_ =
      cascade_program("cascade_fft.glsl", "#define SG_FFT_QUARTER " + std::to_string(n / 4) + "\n");
  const size_t cells = static_cast<size_t>(n) * n;
  lattice_ = gl::Buffer(cells * 16);
  spectra_ = gl::Buffer(cells * 16);
  scratch_ = gl::Buffer(cells * 16);
  fields_[0] = gl::Buffer(cells * 16);
  fields_[1] = gl::Buffer(cells * 16);
  // e^{i pi k / p} at p + k, for p = 1, 2, ..., n/2 and k < p (index 0 unused).
  std::vector<float> tw(2 * static_cast<size_t>(n), 0.0f);
  for (int p = 1; p < n; p <<= 1) {
    for (int k = 0; k < p; ++k) {
      tw[2 * static_cast<size_t>(p + k)] = static_cast<float>(std::cos(kPi * k / p));
      tw[2 * static_cast<size_t>(p + k) + 1] = static_cast<float>(std::sin(kPi * k / p));
    }
  }
  twiddles_ = gl::Buffer::of<float>(tw);
}

void CascadeFftGl::set_lattice(const CascadeDesc& c, const Dispersion& water, double t0) {
  if (!c.data || c.data->n != n_)
    throw Error("CascadeFftGl: the cascade's lattice is not " + std::to_string(n_));
  const size_t cells = static_cast<size_t>(n_) * n_;
  std::vector<float> v(4 * cells, 0.0f);
  for (size_t e = 0; e < cells; ++e) {
    const double a = c.data->amplitude[e];
    if (a == 0) continue;
    const vec2 k =
        lattice_wave_vector(c.patch_size, n_, static_cast<int>(e % n_), static_cast<int>(e / n_));
    const double omega = water.omega(length(k));
    v[4 * e] = static_cast<float>(a);
    v[4 * e + 1] = static_cast<float>(std::remainder(c.data->phase[e] + omega * t0, kTwoPi));
    v[4 * e + 2] = static_cast<float>(omega);
  }
  lattice_.upload<float>(v);
  patch_size_ = c.patch_size;
  t0_ = t0;
}

void CascadeFftGl::transform(Pair pair, double t, double t1, bool has_t1, int target) {
  if (target < 0 || target > 1) throw Error("CascadeFftGl: field " + std::to_string(target));
  time_ = t;
  lattice_.bind(GL_SHADER_STORAGE_BUFFER, 0);
  spectra_.bind(GL_SHADER_STORAGE_BUFFER, 1);
  spectrum_.set("n", n_);
  spectrum_.set("dk", static_cast<float>(kTwoPi / patch_size_));
  spectrum_.set("dt0", static_cast<float>(t - t0_));
  spectrum_.set("dt1", static_cast<float>(has_t1 ? t1 - t0_ : 0.0));
  spectrum_.set("mode", static_cast<int>(pair));
  spectrum_.set("second", has_t1 ? 1 : 0);
  gl::dispatch_2d(spectrum_, n_, n_);
  gl::barrier(GL_SHADER_STORAGE_BARRIER_BIT);
  twiddles_.bind(GL_SHADER_STORAGE_BUFFER, 2);
  fft_.use();
  // Rows of the spectra into the scratch's columns, then rows of that into the field's
  // columns: the 2-D transform, in the spectra's orientation.
  spectra_.bind(GL_SHADER_STORAGE_BUFFER, 0);
  scratch_.bind(GL_SHADER_STORAGE_BUFFER, 1);
  glDispatchCompute(static_cast<GLuint>(n_), 1, 1);
  gl::barrier(GL_SHADER_STORAGE_BARRIER_BIT);
  scratch_.bind(GL_SHADER_STORAGE_BUFFER, 0);
  fields_[target].bind(GL_SHADER_STORAGE_BUFFER, 1);
  glDispatchCompute(static_cast<GLuint>(n_), 1, 1);
  gl::barrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void CascadeFftGl::evaluate(double t) {
  transform(Pair::full, t, 0.0, false, 0);
}

CascadeGrid CascadeFftGl::read_field() const {
  gl::barrier();
  const std::vector<float> f = fields_[0].read<float>();
  CascadeGrid g;
  g.n = n_;
  g.patch_size = patch_size_;
  g.time = time_;
  const size_t cells = static_cast<size_t>(n_) * n_;
  g.height.resize(cells);
  g.slope_x.resize(cells);
  g.slope_z.resize(cells);
  g.curv_xz.resize(cells);
  for (size_t e = 0; e < cells; ++e) {
    g.slope_x[e] = f[4 * e];
    g.height[e] = f[4 * e + 1];
    g.slope_z[e] = f[4 * e + 2];
    g.curv_xz[e] = f[4 * e + 3];
  }
  return g;
}

}  // namespace sg::gl_engine
