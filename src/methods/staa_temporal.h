// `--method staa-temporal`: the temporal method of Podee et al. 2021 (Sec. 3.3) for every
// pixel: the surface point at the pixel centre, its reflection path over the frame's
// shutter interval (all waves treated as resolved), and the fraction of that time during
// which the reflection lies in the light disk, computed exactly on the sphere for each of
// `--segments K` great-circle sub-arcs (shading/reflection_path.h, shading/arc.h). It
// removes flicker for the waves the pixel grid resolves; it still samples space at the
// pixel centre only, so waves above the Nyquist limit alias (the full method, `staa`,
// handles them).
#pragma once

#include "methods/method.h"

namespace sg {

class StaaTemporalMethod final : public Method {
 public:
  explicit StaaTemporalMethod(int segments) : segments_(segments) {}
  std::string name() const override { return "staa-temporal"; }
  RadianceWeights weights(const FrameContext& ctx, int i, int j) const override;

 private:
  int segments_;
};

}  // namespace sg
