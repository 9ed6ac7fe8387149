// Arc fractions on the sphere (Podee et al. 2021, Sec. 3.3); the derivation is in arc.h.
#include "shading/arc.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "base/error.h"

namespace sg {
namespace {

// |r0 x r1| at or below this is a degenerate arc (no motion, or antipodal endpoints).
constexpr double kDegenerateSin = 1e-12;

// The arc r(psi) = cos(psi) a + sin(psi) w, psi in [0, theta]; n = a x w.
struct GreatArc {
  vec3 a, w, n;
  double theta = 0;
};

// At most two disjoint intervals of [0, theta].
struct Intervals {
  double lo[3] = {0, 0, 0};
  double hi[3] = {0, 0, 0};
  int count = 0;

  void add(double l, double h) {
    if (h > l) {
      lo[count] = l;
      hi[count] = h;
      ++count;
    }
  }
  double measure() const {
    double m = 0;
    for (int i = 0; i < count; ++i)
      m += hi[i] - lo[i];
    return m;
  }
};

double overlap(const Intervals& p, const Intervals& q) {
  double m = 0;
  for (int i = 0; i < p.count; ++i) {
    for (int j = 0; j < q.count; ++j) {
      m += std::max(0.0, std::min(p.hi[i], q.hi[j]) - std::max(p.lo[i], q.lo[j]));
    }
  }
  return m;
}

// The set {psi in [0, theta] : angle(r(psi), X) <= rho} for unit X (see arc.h).
Intervals cap_on_arc(const GreatArc& arc, const vec3& X, double sin_rho, double cos_rho) {
  Intervals out;
  const double A = dot(arc.a, X);
  const double B = dot(arc.w, X);
  if (A == 0 && B == 0) {
    // X is a pole of the circle: every point of it lies at exactly 90 degrees from X.
    if (cos_rho <= 0) out.add(0, arc.theta);
    return out;
  }
  const double sin_beta = std::abs(dot(arc.n, X));
  const double s2 = (sin_rho - sin_beta) * (sin_rho + sin_beta);
  if (s2 < 0) return out;  // the circle passes outside the cap
  const double alpha = std::atan2(std::sqrt(s2), cos_rho);
  if (alpha >= kPi) {
    out.add(0, arc.theta);
    return out;
  }
  const double phi = std::atan2(B, A);  // in [-pi, pi]
  // theta <= pi and 2 alpha < 2 pi: the copies phi + 2 pi m, m in {-1, 0, 1}, cover every
  // intersection with [0, theta], and they are disjoint.
  for (int m = -1; m <= 1; ++m) {
    const double c = phi + kTwoPi * m;
    out.add(std::max(0.0, c - alpha), std::min(arc.theta, c + alpha));
  }
  return out;
}

vec3 checked_unit(const vec3& r, const char* name) {
  const double len = length(r);
  if (!std::isfinite(len) || !(len > 0)) {
    std::ostringstream msg;
    msg << "arc_fractions: " << name << " must be a finite non-zero vector (got (" << r.x << ", "
        << r.y << ", " << r.z << "))";
    throw Error(msg.str());
  }
  return r / len;
}

// The fractions for a direction that does not move.
ArcFractions still(const vec3& r, const LightModel& light) {
  ArcFractions f;
  if (r.y <= 0) {
    f.below = 1;
  } else if (dot(r, light.L) >= light.cos_radius) {
    f.in_light = 1;
  }
  return f;
}

}  // namespace

ArcFractions arc_fractions(const vec3& r0_in, const vec3& r1_in, const LightModel& light) {
  const vec3 r0 = checked_unit(r0_in, "r0");
  const vec3 r1 = checked_unit(r1_in, "r1");
  // Early outs, exact: every point of the arc lies within theta/2 of an endpoint, so when
  // both endpoints are further than rho + theta/2 from L the arc misses the light's cone,
  // and when both lie above the horizon by more than theta/2 it never dips below it.
  // Half the arc's angle from chord lengths, without inverse trigonometry:
  // sin(theta/2) = |r1 - r0| / 2, cos(theta/2) = |r1 + r0| / 2; then
  // cos(rho + theta/2) = cos(rho) cos(theta/2) - sin(rho) sin(theta/2).
  const double sh = 0.5 * length(r1 - r0), ch = 0.5 * length(r1 + r0);
  const double cos_reach = light.cos_radius * ch - std::sin(light.radius) * sh;
  const bool misses_light =
      light.radius < kPi / 2 && ch > 0 && std::max(dot(r0, light.L), dot(r1, light.L)) < cos_reach;
  const bool stays_above = std::min(r0.y, r1.y) > sh;
  if (misses_light && stays_above) return ArcFractions{};

  const vec3 cr = cross(r0, r1);
  const double s = length(cr);
  const double c = dot(r0, r1);

  GreatArc arc;
  arc.a = r0;
  if (s > kDegenerateSin) {
    arc.theta = std::atan2(s, c);
    arc.n = cr / s;
    arc.w = normalize(cross(arc.n, r0));
  } else if (c > 0) {
    return still(normalize(r0 + r1), light);
  } else {
    // Antipodal: the half circle through the zenith side (arc.h).
    vec3 w = vec3(0, 1, 0) - r0.y * r0;
    if (length(w) < 1e-6) {
      w = vec3(light.L.x, 0, light.L.z);
      if (length(w) < 1e-6) w = vec3(1, 0, 0);
      w -= dot(w, r0) * r0;
    }
    arc.w = normalize(w);
    arc.n = normalize(cross(r0, arc.w));
    arc.theta = kPi;
  }

  const Intervals cone = misses_light
                             ? Intervals{}
                             : cap_on_arc(arc, light.L, std::sin(light.radius), light.cos_radius);
  const Intervals below = stays_above ? Intervals{} : cap_on_arc(arc, vec3(0, -1, 0), 1.0, 0.0);
  ArcFractions f;
  f.below = std::clamp(below.measure() / arc.theta, 0.0, 1.0);
  f.in_light = std::clamp((cone.measure() - overlap(cone, below)) / arc.theta, 0.0, 1.0 - f.below);
  return f;
}

}  // namespace sg
