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
#pragma once

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

}  // namespace sg
