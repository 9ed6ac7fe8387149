// The path-integral tables of Podee et al. 2021, Sec. 3.5 (Eqs. 17-19) and Sec. 4, for the
// unit disk, with their lookups and their on-disk cache.
//
// Tables (float, as a GPU would hold them; float rounding, 6e-8 relative, is far below the
// interpolation error), 8 MiB in all (a game engine's budget for two textures):
//  * F(d, sigma) (disk_gaussian.h), n_distance = 512 samples of d per slice: Sec. 4's 2D
//    texture, for a reflection that does not move.
//  * S(u, v, sigma) = integral from -R to u of F(sqrt(u'^2 + v^2), sigma) du' (Eq. 18),
//    n_u = 192 samples of u in [-R, 0] by n_v = 168 samples of v in [0, R]: Sec. 4's 3D
//    texture. F is even in u, so S(u) = 2 S(0) - S(-u) and only u <= 0 is stored (the same
//    u step as 383 samples over [-R, R]); S is even in v, so only v >= 0 is stored; v is the
//    distance of the segment's line from the disk's centre ("closest distance", Sec. 4).
//  * The radial axes (d of F, v of S) are not uniform: kd::table_radial_node
//    (kernel/path_table_grid.glsl) crowds the nodes quadratically about the disk's edge
//    r = 1 from both sides, where a narrow Gaussian's F and S change fastest; the chord
//    sqrt(1 - v^2) of sigma = 0 is then linear in the grid coordinate near v = 1, and F's
//    step at d = 1 falls on a node. The u axis is uniform (the edge's u, sqrt(1 - v^2),
//    moves with v).
//  * Both share n_sigma = 64 slices. Slice 0 is sigma = 0, filled exactly (F the indicator
//    of d < 1 with 0.5 at d = 1, S the chord length clamp(u, -c, c) + c, c = sqrt(1 - v^2)).
//    Slices 1..63 are log-spaced from sigma_min = 2e-3 to sigma_max = 8. Log spacing because
//    F changes shape at a rate proportional to d sigma / sigma. sigma_min = 2e-3: a
//    narrower Gaussian is not resolved by the grid, so slice 0 stands in for it. sigma_max =
//    8 because beyond it the three-term wide-Gaussian expansion of disk_gaussian.h is within
//    3e-10 of F (measured: 2.6e-11 at sigma = 10, 6.6e-9 at 5), so lookups above sigma_max
//    use that expansion and its closed-form integral along u (erf and Gaussian moments),
//    with no table at all.
//  * Each slice has its own extent R(sigma) = 1 + 6 sigma: F(R, sigma) <= Phi(-6) = 1e-9 for
//    narrow Gaussians and exp(-18) = 1.5e-8 of the peak for wide ones, below float rounding
//    of S. Beyond the extent F is taken as 0 and S as constant in u and 0 in v.
//  * The sizes were chosen by measurement (docs/path-tables.md, "Size"): the slices set the
//    error above sigma = 0.02 (48 slices make it 1.8 times larger), the u and v steps below;
//    192 x 168 balances the two within 8 MiB.
//
// Lookups (kernel/path_table.glsl, the one implementation, which the methods below wrap):
// bilinear within a slice (in the grid coordinates of d for F, of (u, v) for S; a segment's
// S(u1) - S(u0) reads S(0) only when it crosses u = 0), linear between slices in the
// sigma coordinate c(sigma) = sigma / sigma_min below sigma_min (between slice 0 and
// slice 1) and 1 + log(sigma / sigma_min) / log(q) above, q the slice ratio.
//
// Generation: the radial symmetry of F makes each (v, sigma) row of S a running sum along u.
// Per slice F is evaluated once on a fine 1D distance grid (step min(sigma / 16, R / 1024),
// cubic Lagrange interpolation between its points), and each table cell [u_i, u_i+1] is
// integrated with 4-point Gauss-Legendre on ceil(cell / sigma) sub-panels, so that the
// rule resolves F's edge of width sigma; the cells are summed in double. The interpolation
// and the rule are the kernel's (kernel/path_table_gen.glsl), which `sunglint web` runs on
// the same fine grids in a browser (docs/web.md).
// The slices are independent and are computed in parallel, so the bytes do not depend on
// the number of threads.
//
// Cache: one file, path_tables.bin (8 MiB), in a folder the caller names
// (shading/path_table_store.h: the CLI's --cache-dir, else $SUNGLINT_CACHE_DIR, else
// $XDG_CACHE_HOME/sunglint, else $HOME/.cache/sunglint, else <temp>/sunglint).
// Little-endian: the magic "SGPATHTB", the format version, the dimensions, the fingerprint of
// the grid and generation sources (source_fingerprint), the parameters, the payload size, the F
// and S floats, and a zlib crc32 of everything before it. A missing, truncated, corrupt or stale
// (version, parameter or source mismatch) file is regenerated and rewritten atomically; a
// cache that cannot be written is not an error, the tables then live in memory only.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "kernel/kernel_types.h"
#include "math/vec.h"

namespace sg {

struct PathTableParams {
  int n_distance = 512;  // F: samples of d in [0, R] per slice (kd::table_radial_node)
  int n_u = 192;         // S: samples of u in [-R, 0]
  int n_v = 168;         // S: samples of v in [0, R] (kd::table_radial_node)
  int n_sigma = 64;      // slices: sigma = 0, then n_sigma - 1 log-spaced
  double sigma_min = 2e-3;
  double sigma_max = 8;
  double extent_k = 6;  // R(sigma) = 1 + extent_k sigma
  bool operator==(const PathTableParams&) const = default;
};

// How load_or_generate found its tables.
struct PathTableCacheResult {
  std::string path;      // the cache file, or "" for none
  bool loaded = false;   // read from the cache file
  bool written = false;  // generated and written to the cache file
  std::string note;      // why the file was not used, or why it could not be written
};

class PathTables {
 public:
  static constexpr uint32_t kFormatVersion = 2;
  // FNV-1a (64 bits folded to 32) of the sources that decide what the tables hold
  // (kernel/path_table_grid.glsl, kernel/path_table_gen.glsl, built into the program); a
  // cache file made by other sources is stale.
  static uint32_t source_fingerprint();

  // Computes the tables. threads = 0: one per hardware thread. Throws sg::Error naming a
  // bad parameter.
  static PathTables generate(const PathTableParams& params = {}, int threads = 0);
  // Reads `path` if it holds these tables, else generates them and tries to write it.
  static PathTables load_or_generate(const std::string& path, const PathTableParams& params = {},
                                     PathTableCacheResult* result = nullptr);
  static constexpr const char* kCacheFileName = "path_tables.bin";
  // One program run's tables, loaded or generated on first use: shading/path_table_store.h.

  std::string serialize() const;
  // The tables in `bytes` when they are whole, intact and made with `expected` by this
  // version; otherwise nullopt and, in *why, the reason.
  static std::optional<PathTables> deserialize(std::string_view bytes,
                                               const PathTableParams& expected,
                                               std::string* why = nullptr);

  // ---- lookups (all lengths in units of the disk radius, except path_average)
  // F(d, sigma) from the 2D table (sigma > sigma_max: the wide-Gaussian expansion).
  double disk_gaussian_table(double d, double sigma) const;
  // S(u, v, sigma) from the 3D table (sigma > sigma_max: closed form of the expansion).
  double path_table_S(double u, double v, double sigma) const;
  // The time-average of F along the segment from (u0, v) to (u1, v) at constant speed:
  // (S(u1) - S(u0)) / (u1 - u0), Eq. 19 divided by the segment's length. A segment shorter
  // than one u cell h of a slice turns the difference quotient into the slope of a single
  // cell, a first-order estimate, while F at the midpoint is second order: below h / 2 the
  // slice returns F(midpoint) from the 2D table, above h the quotient, and in between a
  // linear blend of the two, so that the result is continuous in the segment's length.
  double path_integral(double u0, double u1, double v, double sigma) const;
  // The time-average over the straight segment p0 -> p1 of the light plane of the mass of
  // N(p(t), sigma^2 I) inside the disk of radius disk_radius about the origin (Sec. 3.5,
  // last paragraph): rotates the segment parallel to U, divides lengths by disk_radius and
  // calls path_integral; a segment of length <= 1e-12 disk radii is a point (2D table).
  double path_average(vec2 p0, vec2 p1, double sigma, double disk_radius) const;

  // ---- the tables as the kernel reads them (R32F textures; kernel/path_table.glsl)
  kernel_tables::R32Texture2D f_texture() const { return {f_.data(), p_.n_distance, p_.n_sigma}; }
  kernel_tables::R32Texture3D s_texture() const { return {s_.data(), p_.n_u, p_.n_v, p_.n_sigma}; }
  kd::PathTableInfo kernel_info() const;
  kf::PathTableInfo kernel_info_float() const;

  // ---- generation (kernel/path_table_gen.glsl)
  // F(j step, sigma) for j = 0 .. ceil(sqrt(2) R / step) + 3, step = min(sigma / 16,
  // R / 1024): the fine grid slice (sigma > 0, extent R) is integrated from.
  struct FineGrid {
    double step = 0;
    std::vector<double> values;
  };
  static FineGrid fine_grid(double sigma, double R);
  // Sub-panels of a u cell of width hu: ceil(hu / sigma), at least 1.
  static int cell_panels(double hu, double sigma);

  // ---- the grid, for tests and tools
  const PathTableParams& params() const { return p_; }
  double slice_sigma(int k) const { return sigma_[k]; }
  double extent(int k) const { return extent_[k]; }
  double distance_node(int i, int k) const;
  double u_node(int i, int k) const { return -extent_[k] * (p_.n_u - 1 - i) / (p_.n_u - 1); }
  double u_cell(int k) const { return extent_[k] / (p_.n_u - 1); }  // the u step of slice k
  double v_node(int j, int k) const;
  float f_node(int i, int k) const { return f_[size_t(k) * p_.n_distance + i]; }
  float s_node(int iu, int iv, int k) const { return s_[(size_t(k) * p_.n_v + iv) * p_.n_u + iu]; }
  size_t bytes() const { return (f_.size() + s_.size()) * sizeof(float); }

 private:
  explicit PathTables(const PathTableParams& p);
  PathTableParams p_;
  std::vector<double> sigma_, extent_;
  double log_q_ = 1;
  std::vector<float> f_;  // [k][i]
  std::vector<float> s_;  // [k][iv][iu]
};

}  // namespace sg
