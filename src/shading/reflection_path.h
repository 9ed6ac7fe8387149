// The reflection path of a pixel (Podee et al. 2021, Sec. 3.3) and the temporal method on
// it, for host code and tests: the kernel's (kernel/reflection_path.glsl, where the
// formulas are) evaluated for one footprint of a scene model, every wave at full
// amplitude, with the path's instants, gradients, normals and reflections kept for
// inspection.
#pragma once

#include <vector>

#include "kernel/kernel_double.h"
#include "math/vec.h"
#include "scene/footprint.h"
#include "scene/model.h"
#include "shading/kernel_frame.h"

namespace sg {

struct ReflectionPath {
  vec3 view{0};                   // unit, towards the camera
  vec2 xz{0};                     // the surface point
  std::vector<double> times;      // K + 1 instants
  std::vector<vec2> gradients;    // (dh/dx, dh/dz) at each instant
  std::vector<vec3> normals;      // unit normals
  std::vector<vec3> reflections;  // unit reflections of the view
  KernelInputsD inputs;           // the frame as the kernel sees it
  kd::PathGradients kernel_path;  // the kernel's gradients
  int segments() const { return static_cast<int>(times.size()) - 1; }
};

// The path of footprint `fp` over frame `ft` with `segments` sub-arcs (1 to 32).
void reflection_path(const SceneModel& m, const PixelFootprint& fp, const FrameTime& ft,
                     int segments, ReflectionPath& path);

// The temporal method's shares for a path: the fractions of the interval in the light and
// below the horizon, the mean Fresnel factor and the weights.
struct PathShares {
  double in_light = 0, below = 0, fresnel = 1;
  RadianceWeights weights{0.0};
};
PathShares temporal_shares(const ReflectionPath& path);

inline RadianceWeights temporal_weights(const ReflectionPath& path) {
  return temporal_shares(path).weights;
}

}  // namespace sg
