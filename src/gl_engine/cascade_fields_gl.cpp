#include "gl_engine/cascade_fields_gl.h"

#include <epoxy/gl.h>

#include <array>
#include <cmath>
#include <cstring>
#include <string>

#include "base/error.h"
#include "gl/dispatch.h"
#include "kernel/kernel_double.h"
#include "scene/dispersion.h"

namespace sg::kd {
// (after the kernel's types, kernel_double.h)
#include "kernel/cascade_chain.glsl"
}  // namespace sg::kd

namespace sg::gl_engine {

CascadeFieldsGl::CascadeFieldsGl()
    : chain_(cascade_program("cascade_chain.glsl", "", "kernel/cascade_chain.glsl")),
      bounds_(cascade_program("cascade_bounds.glsl", "", "kernel/cascade_chain.glsl")) {}

CascadeFieldsGl::~CascadeFieldsGl() = default;

void CascadeFieldsGl::prepare(const SceneModel& m, double t0) {
  if (model_ != m.id || ffts_.empty()) {
    std::vector<std::unique_ptr<CascadeFftGl>> ffts;
    padded_.clear();
    for (const CascadeDesc& c : m.scene.surface.cascades) {
      padded_.push_back(oversampled_cascade(c));
      const int n = padded_.back().lattice;
      if (n > kMaxLattice) {
        throw Error("a cascade of lattice " + std::to_string(c.lattice) + " transforms on a " +
                    std::to_string(n) + " grid, past the GL FFT's " + std::to_string(kMaxLattice) +
                    ": use --cascade-fft host");
      }
      // A transform per cascade (its lattice stays on the GPU), the last model's kept where
      // its size is the same (the viewer's wind regenerates the lattices as a slider moves).
      const size_t at = ffts.size();
      if (at < ffts_.size() && ffts_[at] && ffts_[at]->n() == n) {
        ffts.push_back(std::move(ffts_[at]));
      } else {
        ffts.push_back(std::make_unique<CascadeFftGl>(n));
      }
    }
    ffts_ = std::move(ffts);
    model_ = m.id;
    t0_ = std::nan("");
  }
  if (t0 == t0_) return;
  const Dispersion water{m.scene.surface.depth};
  for (size_t c = 0; c < ffts_.size(); ++c)
    ffts_[c]->set_lattice(padded_[c], water, t0);
  t0_ = t0;
}

void CascadeFieldsGl::chain(const CascadeFftGl& fft, Chain kind, int field, int slot, size_t at,
                            const gl::Buffer& waves, bool levels) {
  // The pass's `full` is the chain's mode.
  static_assert(int(Chain::slopes) == kd::kCascadeChainSlopes &&
                int(Chain::full) == kd::kCascadeChainFull &&
                int(Chain::slopes_height) == kd::kCascadeChainSlopesHeight);
  const int n = fft.n();
  fft.field(field).bind(GL_SHADER_STORAGE_BUFFER, 0);
  fft.field(kind == Chain::full ? 1 : field).bind(GL_SHADER_STORAGE_BUFFER, 1);
  waves.bind(GL_SHADER_STORAGE_BUFFER, 2);
  chain_.set("full", static_cast<int>(kind));
  chain_.set("slot", slot);
  int level = 0;
  for (int side = n; side >= 1 && (levels || level == 0); side /= 2, ++level) {
    chain_.set("size", side);
    chain_.set("level", level);
    chain_.set("source", level == 0 ? 0 : int(at) + kd::cascade_level_offset(n, level - 1));
    chain_.set("target", int(at) + kd::cascade_level_offset(n, level));
    gl::dispatch_2d(chain_, side, side);
    gl::barrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
}

std::vector<glm::dvec3> CascadeFieldsGl::fill(const SceneModel& m, const FrameTime& ft,
                                              int segments, const CascadeLayout& layout,
                                              const gl::Buffer& waves, CascadeReads reads) {
  const std::vector<CascadeDesc>& cs = m.scene.surface.cascades;
  if (layout.data.size() != cs.size() || layout.grid.size() != cs.size())
    throw Error("CascadeFieldsGl: the layout is not the scene's cascades'");
  if (layout.end * 16 > waves.size())
    throw Error("CascadeFieldsGl: the wave buffer is smaller than the layout");
  prepare(m, kTimeEpoch * std::floor(ft.end / kTimeEpoch));
  const size_t count = std::max<size_t>(1, 5 * cs.size());
  const bool still = !(ft.duration() > 0);
  const bool heights = m.displaced();
  if (maxima_.size() != count * 4) maxima_ = gl::Buffer(count * 4);
  if (heights) maxima_.fill(0u);
  using Pair = CascadeFftGl::Pair;
  for (size_t c = 0; c < cs.size(); ++c) {
    CascadeFftGl& fft = *ffts_[c];
    const int n = fft.n();
    if (layout.grid[c] != n)
      throw Error("CascadeFieldsGl: cascade " + std::to_string(c) + "'s grid");
    const size_t per = static_cast<size_t>(kd::cascade_instant_texels(n));
    auto at = [&](int k) { return layout.data[c] + static_cast<size_t>(k) * per; };
    auto time = [&](int k) { return cascade_instant(ft, segments, k); };
    auto bound = [&] {
      fft.field(0).bind(GL_SHADER_STORAGE_BUFFER, 0);
      maxima_.bind(GL_SHADER_STORAGE_BUFFER, 1);
      bounds_.set("n", n);
      bounds_.set("base", static_cast<int>(5 * c));
      gl::dispatch_2d(bounds_, n, n);
    };
    if (reads == CascadeReads::instants_level0 || reads == CascadeReads::display_level0) {
      // Level 0 alone: the display time's slopes and height, the other instants' slopes
      // two to a transform.
      fft.transform(Pair::full, time(segments), 0.0, false, 0);
      chain(fft, Chain::slopes_height, 0, 0, at(segments), waves, false);
      if (heights) bound();
      if (reads == CascadeReads::display_level0) continue;
      for (int k = 0; k < segments; k += heights ? 1 : 2) {
        const bool pair = !heights && k + 1 < segments;
        gl::barrier(GL_SHADER_STORAGE_BARRIER_BIT);
        if (heights) {
          // Displaced water: the instant's height too, one transform an instant.
          fft.transform(Pair::full, time(k), 0.0, false, 0);
          chain(fft, Chain::slopes_height, 0, 0, at(k), waves, false);
          continue;
        }
        fft.transform(Pair::two_slopes, time(k), pair ? time(k + 1) : 0.0, pair, 0);
        chain(fft, Chain::slopes, 0, 0, at(k), waves, false);
        if (pair) chain(fft, Chain::slopes, 0, 1, at(k + 1), waves, false);
      }
      continue;
    }
    // The display time: (dh/dx, h, dh/dz, d2h/dxdz), then (d2h/dx2, d2h/dz2) with the
    // slopes at t_0, which level 0 of its chain keeps (kernel/cascade_chain.glsl), the
    // still camera's too (t_0 is then the display time); not on displaced water, whose
    // instants each take a full transform below, nor for the display time alone.
    fft.transform(Pair::full, time(segments), 0.0, false, 0);
    fft.transform(Pair::curvature_and_slopes, time(segments), time(0),
                  !heights && reads != CascadeReads::display_chain, 1);
    chain(fft, Chain::full, 0, 0, at(segments), waves, true);
    if (heights) bound();
    if (reads == CascadeReads::display_chain) continue;
    if (still) {
      // Every instant is the display time's.
      gl::barrier();
      for (int k = 0; k < segments; ++k)
        glCopyNamedBufferSubData(waves.id(), waves.id(), GLintptr(at(segments) * 16),
                                 GLintptr(at(k) * 16), GLsizeiptr(per * 16));
      continue;
    }
    if (heights) {
      // Displaced water, whose path follows the water's height (kernel/reflection_path.glsl,
      // path_views): each other instant's slopes and height, one transform each.
      for (int k = 0; k < segments; ++k) {
        gl::barrier(GL_SHADER_STORAGE_BARRIER_BIT);
        fft.transform(Pair::full, time(k), 0.0, false, 0);
        chain(fft, Chain::slopes_height, 0, 0, at(k), waves, true);
      }
      continue;
    }
    chain(fft, Chain::slopes, 1, 1, at(0), waves, true);
    for (int k = 1; k < segments; k += 2) {
      const bool pair = k + 1 < segments;
      fft.transform(Pair::two_slopes, time(k), pair ? time(k + 1) : 0.0, pair, 0);
      chain(fft, Chain::slopes, 0, 0, at(k), waves, true);
      if (pair) chain(fft, Chain::slopes, 0, 1, at(k + 1), waves, true);
    }
  }
  // The kernel's fetches and the host's read of the maxima after every write above; on
  // flat water no maxima (and no wait for them).
  gl::barrier();
  std::vector<glm::dvec3> bounds(cs.size(), glm::dvec3(0.0));
  if (!heights) return bounds;
  std::vector<std::uint32_t> bits(count);
  maxima_.read(0, count * 4, bits.data());
  for (size_t c = 0; c < cs.size(); ++c) {
    std::array<double, 5> mx{};
    for (int j = 0; j < 5; ++j) {
      float v;
      std::memcpy(&v, &bits[5 * c + j], 4);
      mx[j] = v;
    }
    bounds[c] = cascade_bounds_from_maxima(mx, cs[c].patch_size / ffts_[c]->n());
  }
  return bounds;
}

}  // namespace sg::gl_engine
