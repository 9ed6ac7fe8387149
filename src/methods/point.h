// Point sampling (`--method point`, the paper's "No AA"): one camera ray through the
// pixel centre at the frame's display time t_f, shaded with the radiance of the scene
// spec. It aliases in space (glints smaller than a pixel are hit or missed) and in time
// (a glint that crosses the pixel between frames is seen or not).
#pragma once

#include "methods/method.h"

namespace sg {

class PointMethod final : public Method {
 public:
  std::string name() const override { return "point"; }
  RadianceWeights weights(const FrameContext& ctx, int i, int j) const override;
};

}  // namespace sg
