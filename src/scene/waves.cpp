#include "scene/waves.h"

#include <cmath>

namespace sg {

WaveField::WaveField(const std::vector<Wave>& waves) {
  for (const Wave& w : waves) {
    A.push_back(w.amplitude);
    a.push_back(w.wave_vector.x);
    b.push_back(w.wave_vector.y);
    c.push_back(w.angular_frequency);
    phi.push_back(w.phase);
    amplitude_bound_ += std::fabs(w.amplitude);
    slope_bound_ += std::fabs(w.amplitude) * length(w.wave_vector);
  }
}

}  // namespace sg
