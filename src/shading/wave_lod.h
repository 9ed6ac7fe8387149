// The geometry-to-BRDF transition of Bruneton, Neyret, Holzschuch 2010 (docs/references.md,
// Sec. 3.2): each wave keeps a weight
// w(N_min, N_max, lambda / l) of its amplitude in the geometry and the normals, where lambda
// is its wavelength and l the projected size of a pixel (or grid cell) on the water, with
// the smoothstep
//     w(a, b, x) = 3 x'^2 - 2 x'^3,   x' = clamp((x - a) / (b - a), 0, 1).
// What the weight removes (w_r = 1 - w) goes into the BRDF's slope variance (Eq. 4).
//
// l for a wave: the pixel's footprint is anisotropic (long in the view direction at grazing
// angles), so l is measured along the wave's direction: the larger of the phase steps the
// wave makes between neighbouring pixel centres in x and in y, k . dX/dpx and k . dX/dpy,
// divided by |k|. That is the sampling interval the Nyquist argument of Sec. 3.2 ("N_min = 2
// according to Nyquist") applies to, and it is the projected frequency f of
// shading/aliasing.h (cycles per pixel, max norm): lambda / l = 1 / f.
//
// The cost per pixel (SortedWaves): as Sec. 7.1 does with its geometric progression of
// wavelengths ("we know in advance the indices i for which the weights w_p, w_n or w_r are
// not null, and restrict the sums to these indices"; Eq. 4 as the total variance minus the
// resolved waves'), a pixel keeps a prefix of the waves sorted by |k| and filters out
// everything past it, whose variance is a suffix sum (here the sum itself, not a
// difference, so that no precision is lost to cancellation).
// For a footprint Jacobian J with smallest singular value sigma, a wave of wavenumber
// kappa has f >= kappa sigma / (2 pi sqrt 2) (|J^T k| >= sigma |k|, and the larger axis
// frequency is at least the norm over sqrt 2), so every wave with
// kappa >= 2 pi sqrt 2 / (N_min sigma) has lambda / l <= N_min and w = 0 exactly: its
// slope covariance comes from a suffix sum, and the geometry and normals sum the prefix
// only (the smallest stored prefix of a power-of-two size that holds it).
#pragma once

#include <cstddef>
#include <vector>

#include "math/vec.h"
#include "scene/waves.h"

namespace sg {

// w(a, b, x) of Sec. 3.2.
double lod_weight(double a, double b, double x);

// w_i = w(n_min, n_max, lambda_i / l_i) for every wave, for a pixel whose footprint maps
// image-plane offsets to horizontal offsets by `xz_jacobian` (footprint.h). A wave with no
// phase change across the pixel keeps w = 1.
void wave_lod_weights(const WaveField& waves, const mat2& xz_jacobian, double n_min, double n_max,
                      std::vector<double>& w);

// The smaller singular value of a 2x2 matrix.
double smallest_singular_value(const mat2& m);

// A scene's waves sorted by |k| (ascending, ties in file order), as prefix fields of 16,
// 32, 64, ... waves and all of them, with the suffix sums of the slope covariance.
class SortedWaves {
 public:
  explicit SortedWaves(const WaveField& waves);

  size_t size() const { return k_.size(); }
  // The first position from which every wave has w = 0 for footprint Jacobian J and
  // N_min (size() when none is certain).
  size_t filtered_from(const mat2& xz_jacobian, double n_min) const;
  // The smallest stored prefix holding the first n waves (n <= size()).
  const WaveField& prefix(size_t n) const;
  // sum_{j >= i} A_j^2 / 2 k_j k_j^T (Eq. 4 for sines), i <= size().
  mat2 suffix_covariance(size_t i) const;

 private:
  std::vector<double> k_;            // |k| in sorted order
  std::vector<WaveField> prefixes_;  // increasing sizes, the last one holds every wave
  std::vector<vec3> suffix_cov_;     // (xx, xz, zz), size() + 1 entries
};

}  // namespace sg
