// Host wrappers of the kernel's Gaussians on the light plane (kernel/gaussian.glsl).
#include "shading/gaussian_disk.h"

#include "kernel/kernel_double.h"

namespace sg {

PrincipalAxes principal_axes(const mat2& c) {
  const kd::PrincipalAxes k = kd::principal_axes(c);
  PrincipalAxes p;
  p.s1 = k.s1;
  p.s2 = k.s2;
  p.u = k.u;
  return p;
}

double gaussian_disk_mass(const vec2& mean, const mat2& cov, double R) {
  return kd::gaussian_disk_mass(mean, cov, R);
}

double gaussian_disk_mass_riemann(const vec2& mean, const mat2& cov, double R, int n) {
  return kd::gaussian_disk_mass_riemann(mean, cov, R, n);
}

double gaussian_half_plane_mass(const vec2& mean, const mat2& cov, const vec2& a, double c) {
  return kd::gaussian_half_plane_mass(mean, cov, a, c);
}

}  // namespace sg
