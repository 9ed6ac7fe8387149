#include "methods/lean_coverage.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "scene/camera.h"

namespace sg {

bool visible_water_bounds(const SceneModel& m, double y0, double D, vec2& lo, vec2& hi) {
  const CameraModel& cam = m.camera;
  const vec3 C = cam.position();
  const double W = cam.width(), H = cam.height();
  const vec3 corners[4] = {cam.direction(0, 0), cam.direction(W, 0), cam.direction(W, H),
                           cam.direction(0, H)};
  const vec3 centre = cam.direction(W / 2, H / 2);
  // The disk as a circumscribed polygon.
  const int n = 1024;
  const double rv = D / std::cos(kPi / n);
  std::vector<vec2> poly, next;
  poly.reserve(n + 8);
  for (int k = 0; k < n; ++k) {
    const double a = kTwoPi * k / n;
    poly.push_back(vec2(C.x + rv * std::cos(a), C.z + rv * std::sin(a)));
  }
  for (int e = 0; e < 4 && !poly.empty(); ++e) {
    vec3 nrm = cross(corners[e], corners[(e + 1) % 4]);
    if (dot(nrm, centre) < 0) nrm = -nrm;
    // f(x, z) = nrm . ((x, y0, z) - C) >= 0 inside.
    auto f = [&](const vec2& p) {
      return nrm.x * (p.x - C.x) + nrm.y * (y0 - C.y) + nrm.z * (p.y - C.z);
    };
    next.clear();
    for (size_t k = 0; k < poly.size(); ++k) {
      const vec2 &a = poly[k], &b = poly[(k + 1) % poly.size()];
      const double fa = f(a), fb = f(b);
      if (fa >= 0) next.push_back(a);
      if ((fa >= 0) != (fb >= 0)) next.push_back(a + (fa / (fa - fb)) * (b - a));
    }
    poly.swap(next);
  }
  if (poly.empty()) return false;
  lo = vec2(std::numeric_limits<double>::infinity());
  hi = -lo;
  for (const vec2& p : poly) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return true;
}

double min_footprint_side(const SceneModel& m) {
  const CameraModel& cam = m.camera;
  const vec3 C = cam.position(), up(0, 1, 0);
  double best = std::numeric_limits<double>::infinity();
  for (int j = 0; j < cam.height(); ++j) {
    for (int i = 0; i < cam.width(); ++i) {
      const vec3 d = cam.direction(i + 0.5, j + 0.5);
      if (!(d.y < 0)) continue;
      const double s = -C.y / d.y;  // the plane y = 0
      const vec3 dx = transfer_differential(d, s, cam.ddir_dpx(), up);
      const vec3 dy = transfer_differential(d, s, cam.ddir_dpy(), up);
      best = std::min({best, length(vec2(dx.x, dx.z)), length(vec2(dy.x, dy.z))});
    }
  }
  return best;
}

namespace {

// The box of the visible water within D over the planes the hits can lie on.
bool region_box(const SceneModel& m, double D, vec2& lo, vec2& hi) {
  const double A = m.displaced() ? m.waves.amplitude_bound() : 0.0;
  bool any = false;
  lo = vec2(std::numeric_limits<double>::infinity());
  hi = -lo;
  for (double y0 : {-A, std::min(A, m.camera.position().y)}) {
    vec2 l, h;
    if (visible_water_bounds(m, y0, D, l, h)) {
      lo = glm::min(lo, l);
      hi = glm::max(hi, h);
      any = true;
    }
    if (A == 0) break;
  }
  return any;
}

double box_side(const vec2& lo, const vec2& hi) {
  return std::max(hi.x - lo.x, hi.y - lo.y);
}

}  // namespace

LeanMapRegion lean_map_region(const SceneModel& m, int size, double far) {
  LeanMapRegion r;
  vec2 lo, hi;
  if (far > 0) {
    r.far = far;
    if (!region_box(m, far, lo, hi)) {
      r.empty = true;
      return r;
    }
    r.texel = std::max(box_side(lo, hi), 1e-9) / size;
  } else {
    const double h = min_footprint_side(m);
    if (!std::isfinite(h) || !region_box(m, 1e12, lo, hi)) {
      r.empty = true;
      return r;
    }
    const double target = h * size;
    if (box_side(lo, hi) <= target) {
      // All the visible water fits at a finer texel.
      r.far = std::numeric_limits<double>::infinity();
      r.texel = std::max(box_side(lo, hi), 1e-9) / size;
    } else {
      double dlo = 1e-6, dhi = 1e12;  // side(dlo) <= target < side(dhi)
      for (int it = 0; it < 100; ++it) {
        const double mid = std::sqrt(dlo * dhi);
        vec2 l, hh;
        if (!region_box(m, mid, l, hh) || box_side(l, hh) <= target) {
          dlo = mid;
        } else {
          dhi = mid;
        }
      }
      r.far = dlo;
      r.texel = h;
      if (!region_box(m, dlo, lo, hi)) {
        r.empty = true;
        return r;
      }
    }
  }
  // The square of side N texel holding the box; the spare room goes away from the camera.
  const double side = r.texel * size;
  const vec3 C = m.camera.position();
  const vec2 centre = 0.5 * (lo + hi);
  for (int a = 0; a < 2; ++a) {
    const double spare = side - (hi[a] - lo[a]);
    const double cam = a == 0 ? C.x : C.z;
    r.origin[a] = centre[a] >= cam ? lo[a] : lo[a] - spare;
  }
  return r;
}

}  // namespace sg
