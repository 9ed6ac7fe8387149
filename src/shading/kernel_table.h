// The fitted kernel parameters as a function of the elongation, tabulated and interpolated
// (Podee et al. 2021, Appendix C: "the parameters for an arbitrary value of sigma_y are
// obtained by interpolation"; its curve fits, Tables S1-S3, are not public, so we fit our
// own with tools/fit_kernels).
//
// A table holds, for 2N + 1 kernels, the parameters of Appendix C (unit minor std) at
// ratios r_j whose t_j = sqrt(r_j^2 - 1) are evenly spaced on [0, t_max]. t rather than r,
// because the offsets grow like t, at both ends of the range: near r = 1 the mixture's
// second moment must match, sum w (sigma^2 + d^2) = r^2 = 1 + t^2, and there the offsets
// have an infinite slope in r. Between rows the parameters are interpolated by a
// Catmull-Rom spline in t.
//
// Near r = 1 the fits are so good (relative L2 error below 1e-6) that the optimum is flat
// and ill-determined; the fitter stops there, at row `first_solved`, and below it the
// kernels of that row are scaled to the ratio (scale_to_ratio), which keeps their error
// below that row's. docs/kernel-fits.md gives the interpolation error.
#pragma once

#include <span>
#include <vector>

#include "kernel/kernel_types.h"
#include "shading/kernel_fit.h"

namespace sg {

// A view of one table: rows j = 0..intervals of `columns()` values each:
//   ratio, w_a, sigma_a, then d_i, sigma_i, w_i for i = 1..pairs.
// Rows below `first_solved` are scale_to_ratio of that row (kept for reading, not used).
struct KernelTable {
  int pairs = 0;
  int intervals = 0;
  double max_ratio = 1;
  int first_solved = 0;
  std::span<const double> values;

  int columns() const { return 3 + 3 * pairs; }
};

// t = sqrt(ratio^2 - 1), the interpolation variable.
double ratio_to_t(double ratio);

// The grid's ratios: t_j = t_max j / intervals, t_max = ratio_to_t(max_ratio); the last
// one is max_ratio exactly.
double table_ratio(double max_ratio, int intervals, int j);

// Kernels fitted at ratio `from`, scaled to the ratio `to` <= `from`: offsets in proportion
// to t, stds blended linearly in t towards 1 (the minor std), weights kept. At `to` = 1 the
// kernels all coincide with unit std, which is G itself.
SymmetricKernels scale_to_ratio(const SymmetricKernels& p, double from, double to);

// The parameters at `ratio` (clamped to [1, max_ratio]): between solved rows a Catmull-Rom
// spline in t through the four rows around it, with a missing row past either end of the
// solved rows extrapolated quadratically; below them, scale_to_ratio of the first. The
// weights of both sum to 1, so interpolated weights still sum to 1.
SymmetricKernels interpolate(const KernelTable& table, double ratio);

// The compiled-in table for `count` = 3, 5 or 9 kernels (kernel_table.inc).
const KernelTable& compiled_kernel_table(int count);

// The compiled-in tables as the kernel reads them (kernel/kernel_fit.glsl): one R32F
// texture of 15 columns (the 9-kernel row's width; shorter rows padded with 0) and
// 3 (intervals + 1) rows, the tables of 3, 5 and 9 kernels one after the other, and its
// shape in both precisions.
struct KernelFitTexture {
  std::vector<float> texels;
  kd::KernelFitInfo info;
  kf::KernelFitInfo info_float;
  kernel_tables::R32Texture2D view() const {
    return {texels.data(), 15, static_cast<int>(texels.size() / 15)};
  }
};
const KernelFitTexture& kernel_fit_texture();

}  // namespace sg
