// Arc fractions on the sphere (Podee et al. 2021, Sec. 3.3): the host's checked entry to
// the kernel's (kernel/arc.glsl, where the derivation is).
#include "shading/arc.h"

#include <cmath>
#include <sstream>

#include "base/error.h"
#include "kernel/kernel_double.h"
#include "shading/kernel_frame.h"

namespace sg {
namespace {

vec3 checked(const vec3& r, const char* name) {
  const double len = length(r);
  if (!std::isfinite(len) || !(len > 0)) {
    std::ostringstream msg;
    msg << "arc_fractions: " << name << " must be a finite non-zero vector (got (" << r.x << ", "
        << r.y << ", " << r.z << "))";
    throw Error(msg.str());
  }
  return r;
}

}  // namespace

ArcFractions arc_fractions(const vec3& r0, const vec3& r1, const LightModel& light) {
  const kd::ArcFractions f =
      kd::arc_fractions(checked(r0, "r0"), checked(r1, "r1"), light.kernel_light());
  return ArcFractions{f.in_light, f.below};
}

}  // namespace sg
