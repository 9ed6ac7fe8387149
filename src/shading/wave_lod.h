// The geometry-to-BRDF transition of Bruneton, Neyret, Holzschuch 2010 (docs/references.md,
// Sec. 3.2), the host's double wrappers of the kernel's (kernel/bruneton_waves.glsl, which
// says what the weight and l are; kernel/bruneton.glsl, the prefix of the waves a pixel
// keeps): each wave keeps a weight w(N_min, N_max, lambda / l) of its amplitude in the
// geometry and the normals, the smoothstep w(a, b, x) = 3 x'^2 - 2 x'^3,
// x' = clamp((x - a) / (b - a), 0, 1), lambda / l = 1 / f with f the wave's projected
// frequency (max norm).
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

// The smaller singular value of a 2x2 matrix.
double smallest_singular_value(const mat2& m);

}  // namespace sg
