// The elliptical Gaussian RDF as 1, 3, 5 or 9 circular Gaussians along its major axis
// (Podee et al. 2021, Sec. 3.5, 3.6 and Appendix C), with parameters interpolated from
// the fitted table (shading/kernel_table.h: how the fits were made and how well they
// hold; tools/fit_kernels makes them).
//
// The table (R32F texture, 15 columns, 3 x (intervals + 1) rows: the fits for 3, 5 and 9
// kernels one after the other) holds, per row j, the parameters at the ratio r_j whose
// t_j = sqrt(r_j^2 - 1) are evenly spaced on [0, t_max]: ratio, w_a, sigma_a, then d_i,
// sigma_i, w_i for each pair (unit minor standard deviation; weights are masses summing
// to 1). Between rows, a Catmull-Rom spline in t; a missing row past either end of the
// solved rows is extrapolated quadratically; below the first solved row the kernels of
// that row are scaled to the ratio (offsets in proportion to t, stds blended towards 1).
// One kernel is Sec. 3.5's equal-area circle, sigma^2 = sigma_minor sigma_major.

// The kernels for one RDF: offsets along its major axis, standard deviations, weights, in
// the RDF's units.
struct KernelSet {
  int count;
  real offset[kMaxKernels];
  real sigma[kMaxKernels];
  real weight[kMaxKernels];
  real ratio;           // sigma_major / sigma_minor
  bool past_threshold;  // ratio > count: where the paper renders with its fallback
  bool beyond_table;    // ratio > max_ratio: the last row's fit scaled, a stand-in
};

SG_FN real ratio_to_t(real ratio) {
  return sqrt(max(0.0, (ratio - 1.0) * (ratio + 1.0)));
}

SG_FN real fit_value(IN(R32Texture2D) table, int base, int row, int column) {
  return texelFetch(table, ivec2(column, base + row), 0).x;
}

// A row past the solved ones, from the nearest rows going inwards (a, a + step, ...):
// quadratic extrapolation (weights 3, -3, 1), or linear with only two rows.
SG_FN real fit_beyond(IN(R32Texture2D) table, int base, int first, int n, int a, int step,
                      int col) {
  int d = a + 2 * step;
  if (d >= first && d <= n) {
    return 3.0 * fit_value(table, base, a, col) - 3.0 * fit_value(table, base, a + step, col) +
           fit_value(table, base, d, col);
  }
  return 2.0 * fit_value(table, base, a, col) - fit_value(table, base, a + step, col);
}

// `count` kernels of an RDF of axis ratio `ratio`, not yet filled in: offsets and weights
// 0 (deviations 1, never read past `count`).
SG_FN KernelSet kernel_set_blank(int count, real ratio) {
  KernelSet set;
  for (int i = 0; i < kMaxKernels; ++i) {
    set.offset[i] = 0.0;
    set.sigma[i] = 1.0;
    set.weight[i] = 0.0;
  }
  set.count = count;
  set.ratio = ratio;
  set.past_threshold = ratio > real(count);
  set.beyond_table = false;
  return set;
}

// A vanishing RDF (a point): one kernel of deviation 0 at the centre.
SG_FN KernelSet point_kernel() {
  KernelSet set = kernel_set_blank(1, 1.0);
  set.sigma[0] = 0.0;
  set.weight[0] = 1.0;
  return set;
}

// The kernels of `count` (1, 3, 5 or 9) for an RDF with standard deviations
// 0 < sigma_minor <= sigma_major (a ratio within rounding below 1 is taken as 1).
SG_FN KernelSet elliptical_kernels(IN(R32Texture2D) table, IN(KernelFitInfo) info, int count,
                                   real sigma_minor, real sigma_major) {
  real ratio = max(1.0, sigma_major / sigma_minor);
  KernelSet set = kernel_set_blank(count, ratio);
  if (count == 1) {
    set.sigma[0] = sqrt(ratio) * sigma_minor;
    set.weight[0] = 1.0;
    return set;
  }
  real scale = sigma_minor;
  real r = ratio;
  if (ratio > info.max_ratio) {
    // Past the table: the fit for max_ratio, scaled to match the major std; across the
    // major axis it is then ratio / max_ratio times too wide.
    set.beyond_table = true;
    scale = sigma_major / info.max_ratio;
    r = info.max_ratio;
  }
  int pairs = (count - 1) / 2;
  int base = count == 3 ? 0 : (count == 5 ? info.intervals + 1 : 2 * (info.intervals + 1));
  int first =
      count == 3 ? info.first_solved3 : (count == 5 ? info.first_solved5 : info.first_solved9);
  int n = info.intervals;
  real t_max = ratio_to_t(info.max_ratio);
  real u = clamp(ratio_to_t(r) / t_max, 0.0, 1.0) * real(n);
  // The parameters (unit minor std): column 1 w_a, 2 sigma_a, then 3 + 3 i + (0 d, 1 sigma, 2 w).
  real params[15];
  for (int c = 0; c < 15; ++c)
    params[c] = 0.0;
  if (first > 0 && u <= real(first)) {
    // Below the solved rows: the first solved row scaled to the ratio.
    real from = fit_value(table, base, first, 0);
    real f = ratio_to_t(max(1.0, r)) / ratio_to_t(from);
    params[1] = fit_value(table, base, first, 1);
    params[2] = 1.0 + f * (fit_value(table, base, first, 2) - 1.0);
    for (int i = 0; i < pairs; ++i) {
      params[3 + 3 * i] = f * fit_value(table, base, first, 3 + 3 * i);
      params[4 + 3 * i] = 1.0 + f * (fit_value(table, base, first, 4 + 3 * i) - 1.0);
      params[5 + 3 * i] = fit_value(table, base, first, 5 + 3 * i);
    }
  } else {
    int j = min(int(u), n - 1);
    real fr = u - real(j);
    // Catmull-Rom weights of rows j - 1, j, j + 1, j + 2 (they sum to 1).
    real f2 = fr * fr;
    real f3 = f2 * fr;
    real b0 = -0.5 * f3 + f2 - 0.5 * fr;
    real b1 = 1.5 * f3 - 2.5 * f2 + 1.0;
    real b2 = -1.5 * f3 + 2.0 * f2 + 0.5 * fr;
    real b3 = 0.5 * f3 - 0.5 * f2;
    for (int c = 1; c < 3 + 3 * pairs; ++c) {
      real p0 = j - 1 >= first ? fit_value(table, base, j - 1, c)
                               : fit_beyond(table, base, first, n, j, 1, c);
      real p3 = j + 2 <= n ? fit_value(table, base, j + 2, c)
                           : fit_beyond(table, base, first, n, j + 1, -1, c);
      params[c] = b0 * p0 + b1 * fit_value(table, base, j, c) +
                  b2 * fit_value(table, base, j + 1, c) + b3 * p3;
    }
  }
  // Expanded: the central kernel, then +d_1, -d_1, +d_2, -d_2, ... in the RDF's units.
  set.offset[0] = 0.0;
  set.sigma[0] = params[2] * scale;
  set.weight[0] = params[1];
  for (int i = 0; i < pairs; ++i) {
    set.offset[1 + 2 * i] = params[3 + 3 * i] * scale;
    set.offset[2 + 2 * i] = -params[3 + 3 * i] * scale;
    set.sigma[1 + 2 * i] = params[4 + 3 * i] * scale;
    set.sigma[2 + 2 * i] = params[4 + 3 * i] * scale;
    set.weight[1 + 2 * i] = params[5 + 3 * i];
    set.weight[2 + 2 * i] = params[5 + 3 * i];
  }
  return set;
}
