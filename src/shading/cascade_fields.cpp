#include "shading/cascade_fields.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "kernel/kernel_double.h"

namespace sg {

namespace {

int log2_exact(int n) {
  int l = 0;
  while ((1 << l) < n)
    ++l;
  return l;
}

// Texels of one instant's chain (kernel/cascade_fields.glsl, cascade_instant_texels).
size_t instant_texels(int n) {
  return 2 * ((4 * static_cast<size_t>(n) * n - 1) / 3);
}

// Bounds on the bicubic interpolant of g's heights (kernel/cascade_grid.glsl,
// cascade_interpolant_bounds) from the grid's maxima, the differences wrapping around
// the periodic patch.
glm::dvec3 grid_interpolant_bounds(const CascadeGrid& g) {
  const int n = g.n;
  auto h = [&](int i, int j) {
    return g.height[static_cast<size_t>((j + n) % n) * n + static_cast<size_t>((i + n) % n)];
  };
  double m0 = 0, mx = 0, mz = 0, m2 = 0, mxz = 0;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const double c = h(i, j);
      m0 = std::max(m0, std::abs(c));
      mx = std::max(mx, std::abs(h(i + 1, j) - c));
      mz = std::max(mz, std::abs(h(i, j + 1) - c));
      m2 = std::max(m2, std::abs(h(i - 1, j) - 2 * c + h(i + 1, j)));
      m2 = std::max(m2, std::abs(h(i, j - 1) - 2 * c + h(i, j + 1)));
      mxz = std::max(mxz, std::abs(h(i + 1, j + 1) - h(i + 1, j) - h(i, j + 1) + c));
    }
  }
  return cascade_bounds_from_maxima({m0, mx, mz, m2, mxz}, g.patch_size / n);
}

}  // namespace

CascadeDesc oversampled_cascade(const CascadeDesc& c) {
  const int n = c.lattice, m = n * cascade_oversampling(n);
  CascadeDesc o = c;
  o.lattice = m;
  auto d = std::make_shared<LatticeData>();
  d->n = m;
  d->amplitude.assign(static_cast<size_t>(m) * m, 0.0);
  d->phase.assign(static_cast<size_t>(m) * m, 0.0);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int ii = (lattice_frequency(i, n) + m) % m, jj = (lattice_frequency(j, n) + m) % m;
      const size_t e = static_cast<size_t>(j) * n + i, f = static_cast<size_t>(jj) * m + ii;
      d->amplitude[f] = c.data->amplitude[e];
      d->phase[f] = c.data->phase[e];
    }
  }
  o.data = d;
  return o;
}

glm::dvec3 cascade_bounds_from_maxima(const std::array<double, 5>& maxima, double spacing) {
  const kd::vec3 b = kd::cascade_interpolant_bounds(maxima[0], kd::vec2(maxima[1], maxima[2]),
                                                    maxima[3], maxima[4], spacing);
  return glm::dvec3(b.x, b.y, b.z);
}

void CascadeFields::prepare(const SceneModel& m) {
  if (model_ == m.id && !ffts_.empty()) return;
  const Dispersion water{m.scene.surface.depth};
  ffts_.clear();
  cov_.clear();
  lattices_.clear();
  explicit_ = WaveField(m.scene.surface.waves);
  amplitude_sum_ = slope_sum_ = 0;
  for (const CascadeDesc& c : m.scene.surface.cascades) {
    const CascadeDesc padded = oversampled_cascade(c);
    auto fft = std::make_unique<CascadeFft>(padded.lattice);
    fft->set_lattice(padded, water);
    lattices_.push_back(padded.lattice);
    glm::dvec3 cov(0.0);
    const int n = c.lattice;
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const double a = c.data->amplitude[static_cast<size_t>(j) * n + i];
        if (a == 0) continue;
        const vec2 k = lattice_wave_vector(c.patch_size, n, i, j);
        const double e = 0.5 * a * a;
        amplitude_sum_ += a;
        slope_sum_ += a * length(k);
        cov += e * glm::dvec3(k.x * k.x, k.x * k.y, k.y * k.y);
      }
    }
    ffts_.push_back(std::move(fft));
    cov_.push_back(cov);
  }
  scratch_.assign(ffts_.size(), Scratch{});
  model_ = m.id;
}

template <class V4>
int CascadeFields::append_impl(const SceneModel& m, const FrameTime& ft, int segments, double cam_x,
                               double cam_z, std::vector<V4>& texels, bool data,
                               CascadeReads reads) {
  using R = typename V4::value_type;
  prepare(m);
  const std::vector<CascadeDesc>& cs = m.scene.surface.cascades;
  const int base = static_cast<int>(texels.size());
  for (size_t c = 0; c < cs.size(); ++c) {
    const double L = cs[c].patch_size;
    texels.push_back(V4(R(L), R(lattices_[c]), R(L * (cam_x / L - std::floor(cam_x / L))),
                        R(L * (cam_z / L - std::floor(cam_z / L)))));
    texels.push_back(V4(R(cov_[c].x), R(cov_[c].y), R(cov_[c].z), R(log2_exact(lattices_[c]) + 1)));
  }
  // The interpolants' bounds (the display time's), one texel per cascade after the
  // headers: the sum over the cascades up to it (kernel/cascade_grid.glsl,
  // cascade_bounds_first), written by set_bounds.
  layout_.base = base;
  layout_.bounds_at = texels.size();
  texels.resize(texels.size() + cs.size(), V4(0));
  // Each cascade's data at its own offset.
  layout_.data.assign(cs.size(), 0);
  layout_.grid = lattices_;
  size_t at = texels.size();
  for (size_t c = 0; c < cs.size(); ++c) {
    layout_.data[c] = at;
    at += (segments + 1) * instant_texels(lattices_[c]);
  }
  layout_.end = at;
  if (!data) return base;
  texels.resize(at);
  std::vector<glm::dvec3> bounds(cs.size(), glm::dvec3(0.0));
  // The cascades on oneTBB's threads (each cascade's transforms share its rows among them
  // too).
  tbb::parallel_for(size_t(0), cs.size(), [&](size_t c) {
    // The cascade's grid and chain, kept from frame to frame (no allocation per frame).
    CascadeGrid& grid = scratch_[c].grid;
    std::vector<MomentLevel>& chain = scratch_[c].chain;
    if (reads != CascadeReads::all) {
      // Level 0 alone: the display time's slopes and height, the other instants' slopes.
      const size_t per = instant_texels(lattices_[c]);
      for (int k = segments; k >= 0; --k) {
        if (k < segments && reads == CascadeReads::display_level0) break;
        const double t = cascade_instant(ft, segments, k);
        if (k == segments) {
          ffts_[c]->evaluate(t, false, grid);
          bounds[c] = grid_interpolant_bounds(grid);
        } else {
          ffts_[c]->evaluate_slopes(t, grid);
        }
        V4* out = texels.data() + layout_.data[c] + static_cast<size_t>(k) * per;
        const size_t count = static_cast<size_t>(grid.n) * grid.n;
        for (size_t e = 0; e < count; ++e) {
          *out++ = V4(R(grid.slope_x[e]), R(grid.slope_z[e]), R(0), R(0));
          *out++ = V4(R(0), R(k == segments ? grid.height[e] : 0.0), R(0), R(0));
        }
      }
      return;
    }
    V4* out = texels.data() + layout_.data[c];
    // A zero shutter: every instant is the display time's.
    const bool still = !(ft.duration() > 0);
    if (still) {
      ffts_[c]->evaluate(ft.end, true, grid);
      moment_chain(grid, chain);
      bounds[c] = grid_interpolant_bounds(grid);
    }
    for (int k = 0; k <= segments; ++k) {
      const double t = cascade_instant(ft, segments, k);
      // The display time's curvatures and second moments; the other instants' slopes alone
      // (what the kernel reads there: cascade_fields.glsl), the rest of their texels 0.
      if (!still) {
        if (k == segments) {
          ffts_[c]->evaluate(t, true, grid);
          bounds[c] = grid_interpolant_bounds(grid);
        } else {
          ffts_[c]->evaluate_slopes(t, grid);
        }
        moment_chain(grid, chain);
      }
      for (const MomentLevel& lv : chain) {
        const size_t count = static_cast<size_t>(lv.n) * lv.n;
        const bool full = !lv.hxx.empty();
        // Level 0's s_x^2 is never read (a grid point has no spread): the height there.
        const std::vector<double>& second = &lv == &chain[0] && full ? grid.height : lv.mxx;
        for (size_t e = 0; e < count; ++e) {
          if (full) {
            *out++ = V4(R(lv.mx[e]), R(lv.mz[e]), R(lv.hxx[e]), R(lv.hzz[e]));
            *out++ = V4(R(lv.hxz[e]), R(second[e]), R(lv.mxz[e]), R(lv.mzz[e]));
          } else {
            *out++ = V4(R(lv.mx[e]), R(lv.mz[e]), R(0), R(0));
            *out++ = V4(R(0));
          }
        }
      }
    }
  });
  set_bounds_impl(bounds, texels);
  return base;
}

template <class V4>
void CascadeFields::set_bounds_impl(const std::vector<glm::dvec3>& each, std::vector<V4>& texels) {
  using R = typename V4::value_type;
  glm::dvec3 sum(0.0);
  for (size_t c = 0; c < each.size(); ++c) {
    sum += each[c];
    texels[layout_.bounds_at + c] = V4(R(sum.x), R(sum.y), R(sum.z), R(0));
  }
  bounds_ = sum;
}

const WaveField& CascadeFields::explicit_waves(const SceneModel& m) {
  prepare(m);
  return explicit_;
}
double CascadeFields::amplitude_sum(const SceneModel& m) {
  prepare(m);
  return amplitude_sum_;
}
double CascadeFields::slope_sum(const SceneModel& m) {
  prepare(m);
  return slope_sum_;
}

int CascadeFields::append(const SceneModel& m, const FrameTime& ft, int segments, double cam_x,
                          double cam_z, std::vector<glm::dvec4>& texels, CascadeReads reads) {
  return append_impl(m, ft, segments, cam_x, cam_z, texels, true, reads);
}
int CascadeFields::append(const SceneModel& m, const FrameTime& ft, int segments, double cam_x,
                          double cam_z, std::vector<glm::vec4>& texels, CascadeReads reads) {
  return append_impl(m, ft, segments, cam_x, cam_z, texels, true, reads);
}
int CascadeFields::append_layout(const SceneModel& m, const FrameTime& ft, int segments,
                                 double cam_x, double cam_z, std::vector<glm::dvec4>& texels) {
  return append_impl(m, ft, segments, cam_x, cam_z, texels, false, CascadeReads::all);
}
int CascadeFields::append_layout(const SceneModel& m, const FrameTime& ft, int segments,
                                 double cam_x, double cam_z, std::vector<glm::vec4>& texels) {
  return append_impl(m, ft, segments, cam_x, cam_z, texels, false, CascadeReads::all);
}
void CascadeFields::set_bounds(const std::vector<glm::dvec3>& each,
                               std::vector<glm::dvec4>& texels) {
  set_bounds_impl(each, texels);
}
void CascadeFields::set_bounds(const std::vector<glm::dvec3>& each,
                               std::vector<glm::vec4>& texels) {
  set_bounds_impl(each, texels);
}

}  // namespace sg
