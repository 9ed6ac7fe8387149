// The lattice cascades' FFT fields for the shading kernel (kernel/cascade_fields.glsl):
// per frame, each cascade transformed at the path's K + 1 instants (scene/cascade_fft.h,
// slopes and second derivatives), its LEAN chain built (means of s, s s^T and the
// curvatures over aligned 2^l blocks; every texel written by kernel/cascade_chain.glsl, the
// GL engine's text too), and all of it appended to the wave buffer after the waves' sums,
// with a two-texel header per cascade and a texel of the displaced march's bounds per
// cascade (kernel/cascade_grid.glsl has the layout). The per-pixel cost is then a few
// fetches per cascade whatever its waves (docs/ocean.md, "Shading from the cascades").
//
// Which methods read them: `point`, `supersample` with T = 1, `staa-temporal`, `staa` and
// `specaa` (both engines, flat and displaced water), `lean` and `bruneton` (both engines,
// flat water). Elsewhere (`reference` and `supersample` with T > 1, whose rays take other
// times, `lean` and `bruneton` on displaced water, `taa`, `microspec`) the cascades are their
// lattice sines among the waves, exactly, at a cost that follows the waves.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "scene/cascade_fft.h"
#include "scene/model.h"

namespace sg {

// The fields' grid: the lattice's points oversampled (a zero-padded spectrum), so that the
// cubic interpolation between them follows the cascade's shortest waves with at least 4
// grid points a period: 2 times per axis where the band reaches past half the lattice's
// Nyquist wavenumber N pi / L (the last cascade of a sea, whose band ends at its Nyquist),
// 1 time where it does not (a sea's other cascades, whose bands end at half their Nyquist:
// docs/ocean.md, "Bands, never doubled"); then doubled up to 8 times while the grid stays
// within 256 points a side (a last cascade of 32 -> 256, 64 -> 256, 128 -> 256, 256 ->
// 512; another of 256 -> 256). The cubic's slope error falls with the fourth power of the
// spacing (docs/ocean.md: 24.7% of the RMS slope with the top octave at 2 points a period,
// 2.5% at 4); on small lattices, whose texels are wide against a pixel, 2.5% was of the
// order of the sun's disk.
inline int cascade_oversampling(const CascadeDesc& c) {
  const double half_nyquist = 0.5 * c.lattice * kPi / c.patch_size;
  int o = c.band_max <= half_nyquist * (1 + 1e-9) ? 1 : 2;
  while (o < 8 && c.lattice * o * 2 <= 256)
    o *= 2;
  return o;
}

// The same lattice on a grid cascade_oversampling times finer: each lattice point at its
// own wave vector in the larger lattice (index m modulo the new size), the rest zero, so
// that the inverse FFT samples the same surface more densely. What every engine transforms.
CascadeDesc oversampled_cascade(const CascadeDesc& c);

// Bounds on the bicubic interpolant of a height grid of spacing `spacing` (the height,
// its slope along a horizontal direction, its second derivative along one:
// kernel/cascade_grid.glsl, cascade_interpolant_bounds) from the grid's maxima over its
// points (the differences wrapping around the periodic patch): max |h|, max |h(i+1,j) -
// h(i,j)|, max |h(i,j+1) - h(i,j)|, the larger of max |h(i-1,j) - 2 h(i,j) + h(i+1,j)| and
// max |h(i,j-1) - 2 h(i,j) + h(i,j+1)|, and max |h(i+1,j+1) - h(i+1,j) - h(i,j+1) +
// h(i,j)|, in that order (kernel/cascade_chain.glsl, cascade_height_differences: the
// differences at one point, for the host and the GL engine).
glm::dvec3 cascade_bounds_from_maxima(const std::array<double, 5>& maxima, double spacing);

// Where a frame's cascade data sit in the wave buffer: Frame.cascade_base (the headers),
// the bounds' first texel, each cascade's first data texel (instant 0, level 0) and grid
// side, and the end of the data.
struct CascadeLayout {
  int base = 0;
  size_t bounds_at = 0;
  std::vector<size_t> data;
  std::vector<int> grid;
  size_t end = 0;
};

// The time of the path's instant k of K = segments for frame ft (t_k = end - duration
// (K - k) / K): where every engine transforms the cascades.
inline double cascade_instant(const FrameTime& ft, int segments, int k) {
  return ft.end - ft.duration() * (segments - k) / segments;
}

// What a method's kernel reads of the fields, so that a frame builds no more:
//   all: every instant's chain (`staa`);
//   instants_level0: level 0 of every instant, the slopes (the display time's height
//     too; `staa-temporal`: its path's gradients are point reads);
//   display_level0: level 0 of the display time, its slopes and height (`point`,
//     `supersample` with T = 1);
//   display_chain: the display time's whole chain alone (`specaa`, whose kernel reads level
//     0's Hessian; `bruneton` and `lean`, the footprint's moments), its
//     texels those of `all`, the other instants' 0
//     (CascadeFields.DisplayChainIsTheWholeFieldsDisplayTime).
// With the level-0 reads, level 0 holds (s_x, s_z, 0, 0), (0, h, 0, 0) at the display time and
// (s_x, s_z, 0, 0), 0 at the other instants, (0, h, 0, 0) on displaced water, whose path follows
// the water's height (kernel/reflection_path.glsl, path_views); what is not built stays 0. The
// images are the same to the rounding (CascadeFields.ReducedReadsShadeTheSameAsTheWholeFields).
enum class CascadeReads { all, instants_level0, display_level0, display_chain };
// What a kernel method reads, by its name (`point`, `supersample`, `staa-temporal`, `staa`,
// `specaa`): the one choice both engines make.
inline CascadeReads cascade_reads_of(const std::string& method) {
  if (method == "staa") return CascadeReads::all;
  if (method == "staa-temporal") return CascadeReads::instants_level0;
  if (method == "specaa") return CascadeReads::display_chain;  // level 0's Hessian
  // The footprint's moments (kernel/bruneton.glsl, kernel/lean.glsl): its chain. On flat
  // water only: the filtered displaced surface weighs each wave's height by its own weight,
  // which a cascade's field does not have; there its lattice is sines among the waves.
  if (method == "bruneton" || method == "lean") return CascadeReads::display_chain;
  return CascadeReads::display_level0;
}

class CascadeFields {
 public:
  // Appends frame ft's fields (K = segments path sub-arcs, the instants
  // t_k = end - duration (K - k) / K) to `texels` for a camera at world (cam_x, cam_z); the
  // first appended texel's index is returned (Frame.cascade_base). The FFTs' lattices are
  // set once per scene model.
  int append(const SceneModel& m, const FrameTime& ft, int segments, double cam_x, double cam_z,
             std::vector<glm::dvec4>& texels, CascadeReads reads = CascadeReads::all);
  int append(const SceneModel& m, const FrameTime& ft, int segments, double cam_x, double cam_z,
             std::vector<glm::vec4>& texels, CascadeReads reads = CascadeReads::all);
  // The layout alone, for an engine that transforms the cascades itself (the GL engine's
  // CascadeFieldsGl): the headers are appended to `texels`, the bounds' texels appended as
  // zeros (set_bounds writes them), the data not appended; layout() says where it goes.
  int append_layout(const SceneModel& m, const FrameTime& ft, int segments, double cam_x,
                    double cam_z, std::vector<glm::dvec4>& texels);
  int append_layout(const SceneModel& m, const FrameTime& ft, int segments, double cam_x,
                    double cam_z, std::vector<glm::vec4>& texels);
  const CascadeLayout& layout() const { return layout_; }
  // Writes the bounds' texels of the last append (each cascade's interpolant bounds, the
  // texel of cascade c holding the sum over cascades 0..c) and keeps their sum
  // (interpolant_bounds).
  void set_bounds(const std::vector<glm::dvec3>& each, std::vector<glm::dvec4>& texels);
  void set_bounds(const std::vector<glm::dvec3>& each, std::vector<glm::vec4>& texels);
  // The scene's explicit waves alone (the wave buffer's, when the cascades are fields).
  const WaveField& explicit_waves(const SceneModel& m);
  // The cascades' sum A and sum A |k| (bounds of their sines).
  double amplitude_sum(const SceneModel& m);
  double slope_sum(const SceneModel& m);
  // The last append's bounds on the fields' interpolated height, its slope along a
  // horizontal direction and its second derivative along one, summed over the cascades
  // (kernel/cascade_grid.glsl, cascade_interpolant_bounds): what the frame's bounds add
  // for them, far tighter than the sines' sums. Displaced water's alone: the displaced
  // march is their only reader, and on flat water they are 0 (not computed).
  const glm::dvec3& interpolant_bounds() const { return bounds_; }

 private:
  template <class V4>
  int append_impl(const SceneModel& m, const FrameTime& ft, int segments, double cam_x,
                  double cam_z, std::vector<V4>& texels, bool data, CascadeReads reads);
  template <class V4>
  void set_bounds_impl(const std::vector<glm::dvec3>& each, std::vector<V4>& texels);
  void prepare(const SceneModel& m);

  uint64_t model_ = 0;
  std::vector<std::unique_ptr<CascadeFft>> ffts_;
  std::vector<int> lattices_;    // each field's grid side (the lattice's, oversampled)
  std::vector<glm::dvec3> cov_;  // each cascade's sum A^2 / 2 k k^T (xx, xz, zz)
  // Each cascade's grid, its storage kept from frame to frame.
  struct Scratch {
    CascadeGrid grid;
  };
  std::vector<Scratch> scratch_;
  WaveField explicit_;
  double amplitude_sum_ = 0, slope_sum_ = 0;
  glm::dvec3 bounds_{0.0};
  CascadeLayout layout_;
};

// Whether a frame of `m` shades its cascades from fields: it has cascades (flat or
// displaced water: the displaced intersection marches the fields' heights).
inline bool cascade_fields_apply(const SceneModel& m) {
  return !m.scene.surface.cascades.empty();
}

}  // namespace sg
