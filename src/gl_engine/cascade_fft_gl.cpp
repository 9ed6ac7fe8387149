#include "gl_engine/cascade_fft_gl.h"

#include <cmath>
#include <string>

#include "base/error.h"
#include "embedded/kernel_sources.h"
#include "gl/dispatch.h"
#include "gl/error.h"
#include "math/vec.h"

namespace sg::gl_engine {
namespace {

gl::Program compile(const char* main_file, const std::string& header, bool with_spectra) {
  const auto& table = kernel_sources();
  std::vector<gl::ShaderSource> s;
  if (with_spectra) {
    s.push_back(gl::embedded_source(table, "kernel/glsl_prelude.glsl"));
    s.push_back(gl::embedded_source(table, "kernel/cascade_spectrum.glsl"));
  }
  s.push_back(gl::embedded_source(table, std::string("gl_engine/shaders/") + main_file));
  return gl::Program::compute(s, header);
}

// Levels n, n/2, ..., 1: the first vec4 of each (two vec4 per texel).
std::vector<int> level_bases(int n) {
  std::vector<int> bases;
  int base = 0;
  for (int side = n; side >= 1; side /= 2) {
    bases.push_back(base);
    base += 2 * side * side;
  }
  bases.push_back(base);  // the total
  return bases;
}

}  // namespace

CascadeFftGl::CascadeFftGl(int n) : n_(n) {
  if (n < kMinLattice || n > kMaxLattice || (n & (n - 1)) != 0)
    throw Error("CascadeFftGl: the lattice must be a power of two in [4, 1024], got " +
                std::to_string(n));
  spectrum_ = compile("cascade_spectrum.glsl", "", true);
  fft_ = compile("cascade_fft.glsl", "#define SG_FFT_HALF " + std::to_string(n / 2) + "\n", false);
  chain_ = compile("cascade_moments.glsl", "", false);
  const size_t cells = static_cast<size_t>(n) * n;
  lattice_ = gl::Buffer(cells * 16);
  spectra_ = gl::Buffer(cells * 16);
  scratch_ = gl::Buffer(cells * 16);
  field_ = gl::Buffer(cells * 16);
  moments_ = gl::Buffer(static_cast<size_t>(level_bases(n).back()) * 16);
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

void CascadeFftGl::evaluate(double t) {
  time_ = t;
  lattice_.bind(GL_SHADER_STORAGE_BUFFER, 0);
  spectra_.bind(GL_SHADER_STORAGE_BUFFER, 1);
  spectrum_.set("n", n_);
  spectrum_.set("dk", static_cast<float>(kTwoPi / patch_size_));
  spectrum_.set("dt", static_cast<float>(t - t0_));
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
  field_.bind(GL_SHADER_STORAGE_BUFFER, 1);
  glDispatchCompute(static_cast<GLuint>(n_), 1, 1);
  gl::barrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void CascadeFftGl::build_moments() {
  const std::vector<int> bases = level_bases(n_);
  field_.bind(GL_SHADER_STORAGE_BUFFER, 0);
  moments_.bind(GL_SHADER_STORAGE_BUFFER, 1);
  int level = 0;
  for (int side = n_; side >= 1; side /= 2, ++level) {
    chain_.set("size", side);
    chain_.set("from_field", level == 0 ? 1 : 0);
    chain_.set("source_base", level == 0 ? 0 : bases[level - 1]);
    chain_.set("target_base", bases[level]);
    gl::dispatch_2d(chain_, side, side);
    gl::barrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
}

CascadeGrid CascadeFftGl::read_field() const {
  gl::barrier();
  const std::vector<float> f = field_.read<float>();
  CascadeGrid g;
  g.n = n_;
  g.patch_size = patch_size_;
  g.time = time_;
  const size_t cells = static_cast<size_t>(n_) * n_;
  g.height.resize(cells);
  g.slope_x.resize(cells);
  g.slope_z.resize(cells);
  for (size_t e = 0; e < cells; ++e) {
    g.slope_x[e] = f[4 * e];
    g.height[e] = f[4 * e + 1];
    g.slope_z[e] = f[4 * e + 2];
  }
  return g;
}

std::vector<MomentLevel> CascadeFftGl::read_moments() const {
  gl::barrier();
  const std::vector<float> m = moments_.read<float>();
  const std::vector<int> bases = level_bases(n_);
  std::vector<MomentLevel> levels;
  int level = 0;
  for (int side = n_; side >= 1; side /= 2, ++level) {
    MomentLevel l;
    l.n = side;
    const size_t cells = static_cast<size_t>(side) * side;
    for (auto* v : {&l.mx, &l.mz, &l.mxx, &l.mxz, &l.mzz})
      v->resize(cells);
    for (size_t e = 0; e < cells; ++e) {
      const size_t at = 4 * (static_cast<size_t>(bases[level]) + 2 * e);
      l.mx[e] = m[at];
      l.mz[e] = m[at + 1];
      l.mxx[e] = m[at + 2];
      l.mxz[e] = m[at + 3];
      l.mzz[e] = m[at + 4];
    }
    levels.push_back(std::move(l));
  }
  return levels;
}

}  // namespace sg::gl_engine
