// The LEAN map (Olano and Baker 2010, "LEAN Mapping", I3D): a texture of the first and
// second moments of the surface slope, MIP-mapped, and its filtered lookups.
//
// Each texel stores, in single precision (as the paper's GPU textures),
//     B = (b_x, b_z)                  the slope (dh/dx, dh/dz): LEAN's first-moment texture
//     M = (b_x^2, b_z^2, b_x b_z)     its second moments: LEAN's second-moment texture
// Moments filter linearly, so any linear filter (box MIP levels, bilinear, trilinear, a sum
// of probes) of B and M gives the mean and second moments of the slopes under the filter,
// and the filtered slope distribution is LEAN's Gaussian of covariance
//     Sigma = M - B B^T = [M_xx - B_x^2, M_xz - B_x B_z; M_xz - B_x B_z, M_zz - B_z^2]
// with its correlation M_xz - B_x B_z (the non-axis-aligned covariance of Chermain et al.
// 2021, Sec. 5.1, Eq. 16, "computed from precomputed MIP maps of x, y, x^2, y^2 and xy"; the
// same as Podee et al. 2021, Eq. 4). Sums and subtractions are done in double.
//
// Layout: level 0 is N x N texels (N a power of two) over the square [0, N]^2 of texel
// coordinates (texel (i, j) covers [i, i+1] x [j, j+1]); level l is N/2^l texels a side,
// each the box mean of its 2 x 2 children in level l - 1 (the GPU MIP chain), down to 1 x 1.
// Addressing outside the map returns the border moments (GL_CLAMP_TO_BORDER with a border
// "colour"): the caller sets them to what lies beyond the map (lean.h: the analytic moments
// of the unbounded wave field).
//
// The filters and the chain's texels are the kernel's (kernel/lean.glsl, which states them);
// this class holds the texels on the host and builds the chain.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "kernel/kernel_double.h"
#include "math/vec.h"
#include "methods/options.h"

namespace sg {

// One texel, single precision: b_x, b_z, b_x^2, b_z^2, b_x b_z (20 bytes; the kernel reads
// them as five floats, kernel/lean.glsl).
struct LeanTexel {
  float bx = 0, bz = 0, mxx = 0, mzz = 0, mxz = 0;
};

// Filtered moments in double precision: the kernel's (B, M = (xx, zz, xz)).
using LeanMoments = kd::LeanMoments;
LeanTexel to_texel(const LeanMoments& m);

class LeanMap {
 public:
  // N texels a side (a power of two >= 1). Keeps the storage when N does not change.
  void allocate(int size);
  int size() const { return size_; }
  int levels() const { return levels_; }  // L + 1
  int level_size(int level) const { return size_ >> level; }
  size_t bytes() const { return texels_.capacity() * sizeof(LeanTexel); }

  // The border's second moments (xx, zz, xz); its mean slope is 0 (kernel/lean.glsl).
  void set_border(const vec3& m) { border_ = m; }
  const vec3& border() const { return border_; }

  // Level-0 texels, row-major (row j = texel coordinate z from j to j + 1).
  LeanTexel* level0() { return texels_.data(); }
  // Fills level 0 from slope(i, j) at each texel in parallel (oneTBB), for tests and
  // generic maps; the wave map is filled faster by lean.cpp.
  void fill(const std::function<vec2(int i, int j)>& slope);
  // Levels 1..L, each the 2 x 2 box mean of the one before (parallel).
  void build_mips();

  // The kernel's view of the texels, and its filters over them (kernel/lean.glsl) with the
  // map's size and border; the filter's options where one applies.
  kd::MapTexels texels() const;
  kd::LeanParams params(LeanFilter filter = LeanFilter::trilinear, int max_aniso = 16) const;
  LeanMoments texel(int level, int i, int j) const;  // border outside the level
  LeanMoments bilinear(int level, const vec2& s) const;
  LeanMoments trilinear(const vec2& s, double lambda) const;
  LeanMoments lookup(const vec2& s, const vec2& ds_dpx, const vec2& ds_dpy, LeanFilter filter,
                     int max_aniso) const;

 private:
  int size_ = 0;
  int levels_ = 0;
  std::vector<LeanTexel> texels_;
  vec3 border_{0.0};
};

}  // namespace sg
