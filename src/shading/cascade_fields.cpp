#include "shading/cascade_fields.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "kernel/kernel_double.h"

namespace sg::kd {
// (after the kernel's types, kernel_double.h)
#include "kernel/cascade_chain.glsl"
}  // namespace sg::kd

namespace sg {

namespace {

int log2_exact(int n) {
  int l = 0;
  while ((1 << l) < n)
    ++l;
  return l;
}

// Texels of one instant's chain (kernel/cascade_grid.glsl, cascade_instant_texels).
size_t instant_texels(int n) {
  return 2 * ((4 * static_cast<size_t>(n) * n - 1) / 3);
}

// Bounds on the bicubic interpolant of g's heights (kernel/cascade_grid.glsl,
// cascade_interpolant_bounds) from the maxima of the grid's differences
// (kernel/cascade_chain.glsl, cascade_height_differences), wrapping around the periodic
// patch.
glm::dvec3 grid_interpolant_bounds(const CascadeGrid& g) {
  const int n = g.n;
  auto h = [&](int i, int j) {
    return g.height[static_cast<size_t>((j + n) % n) * n + static_cast<size_t>((i + n) % n)];
  };
  std::array<double, 5> m{};
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const kd::CascadeHeightDifferences d = kd::cascade_height_differences(
          h(i, j), h(i + 1, j), h(i - 1, j), h(i, j + 1), h(i, j - 1), h(i + 1, j + 1));
      m = {std::max(m[0], d.height), std::max(m[1], d.step_x), std::max(m[2], d.step_z),
           std::max(m[3], d.second), std::max(m[4], d.mixed)};
    }
  }
  return cascade_bounds_from_maxima(m, g.patch_size / n);
}

// One instant's chain from grid g written at `out` (kernel/cascade_chain.glsl): level 0 from
// the grid in `mode` (kCascadeChain*: the height where the mode holds it, the curvatures in
// the whole chain), and with `levels` each level above from the texels of the one below,
// as written, down to one texel.
template <class V4>
void write_chain(const CascadeGrid& g, int mode, bool levels, V4* out) {
  const size_t count = static_cast<size_t>(g.n) * g.n;
  const bool height = mode != kd::kCascadeChainSlopes, full = mode == kd::kCascadeChainFull;
  for (size_t e = 0; e < count; ++e) {
    const kd::CascadeChainTexel t = kd::cascade_chain_level0(
        kd::vec2(g.slope_x[e], g.slope_z[e]), height ? g.height[e] : 0.0,
        full ? kd::vec3(g.curv_xx[e], g.curv_xz[e], g.curv_zz[e]) : kd::vec3(0.0), kd::vec2(0.0),
        mode);
    out[2 * e] = V4(t.a);
    out[2 * e + 1] = V4(t.b);
  }
  if (!levels) return;
  const V4* child = out;
  V4* parent = out + 2 * count;
  for (int side = g.n / 2, level = 0; side >= 1; side /= 2, ++level) {
    const size_t fine = 2 * static_cast<size_t>(side);
    auto read = [&](size_t x, size_t y) {
      const V4* p = child + 2 * (y * fine + x);
      kd::CascadeChainTexel t;
      t.a = kd::vec4(p[0]);
      t.b = kd::vec4(p[1]);
      return t;
    };
    for (size_t y = 0; y < static_cast<size_t>(side); ++y) {
      for (size_t x = 0; x < static_cast<size_t>(side); ++x) {
        const kd::CascadeChainTexel t = kd::cascade_chain_parent(
            read(2 * x, 2 * y), read(2 * x + 1, 2 * y), read(2 * x, 2 * y + 1),
            read(2 * x + 1, 2 * y + 1), level, mode);
        *parent++ = V4(t.a);
        *parent++ = V4(t.b);
      }
    }
    child += 2 * fine * fine;
  }
}

}  // namespace

CascadeDesc oversampled_cascade(const CascadeDesc& c) {
  const int n = c.lattice, m = n * cascade_oversampling(c);
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
  const bool heights = m.scene.surface.geometry == Geometry::displaced;
  // The cascades on oneTBB's threads (each cascade's transforms share its rows among them
  // too).
  tbb::parallel_for(size_t(0), cs.size(), [&](size_t c) {
    // The cascade's grid, kept from frame to frame (no allocation per frame).
    CascadeGrid& grid = scratch_[c].grid;
    const size_t per = instant_texels(lattices_[c]);
    auto instant = [&](int k) {
      return texels.data() + layout_.data[c] + static_cast<size_t>(k) * per;
    };
    // The other instants' slopes, with their heights on displaced water (where the path's
    // points follow the water: kernel/reflection_path.glsl, path_views).
    auto other_instant = [&](int k, bool levels) {
      const double t = cascade_instant(ft, segments, k);
      if (heights) {
        ffts_[c]->evaluate(t, false, grid);
      } else {
        ffts_[c]->evaluate_slopes(t, grid);
      }
      write_chain(grid, heights ? kd::kCascadeChainSlopesHeight : kd::kCascadeChainSlopes, levels,
                  instant(k));
    };
    if (reads == CascadeReads::instants_level0 || reads == CascadeReads::display_level0) {
      // Level 0 alone: the display time's slopes and height, the other instants' slopes.
      ffts_[c]->evaluate(cascade_instant(ft, segments, segments), false, grid);
      if (heights) bounds[c] = grid_interpolant_bounds(grid);
      write_chain(grid, kd::kCascadeChainSlopesHeight, false, instant(segments));
      for (int k = 0; k < segments && reads == CascadeReads::instants_level0; ++k)
        other_instant(k, false);
      return;
    }
    // The display time's curvatures and second moments; the other instants' slopes (and
    // heights) alone (what the kernel reads there: cascade_fields.glsl), the rest 0.
    const double end = cascade_instant(ft, segments, segments);
    ffts_[c]->evaluate(end, true, grid);
    if (heights) bounds[c] = grid_interpolant_bounds(grid);
    write_chain(grid, kd::kCascadeChainFull, true, instant(segments));
    if (reads == CascadeReads::display_chain) return;
    // A zero shutter: every instant is the display time's. On flat water level 0 of the
    // display time keeps instant 0's slopes (kernel/cascade_chain.glsl, cascade_chain_level0),
    // its own where the shutter is zero (before the copies, which then hold them too).
    const bool still = !(ft.duration() > 0);
    auto keep_start = [&](const V4* first) {
      V4* display = instant(segments);
      for (size_t e = 0; e < static_cast<size_t>(lattices_[c]) * lattices_[c]; ++e) {
        display[2 * e + 1].z = first[2 * e].x;
        display[2 * e + 1].w = first[2 * e].y;
      }
    };
    if (still && !heights) keep_start(instant(segments));
    for (int k = 0; k < segments; ++k) {
      if (still) {
        std::copy(instant(segments), instant(segments) + per, instant(k));
        continue;
      }
      other_instant(k, true);
    }
    if (!still && !heights) keep_start(instant(0));
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
