// Vector types for all of sunglint: glm's double-precision vectors under GLSL names.
//
// The shading math is written against these names (dot, normalize, cross, mix, clamp) so
// that a function reads the same as its GLSL counterpart and can be compiled as C++ for the
// CPU engine and the tests. Double precision throughout: the light disk of the sun is
// 0.27 degrees in radius, and a reflection test against cos(0.27 deg) = 1 - 1.1e-5 loses
// about 0.5% of the radius in single precision.
#pragma once

#include <glm/glm.hpp>

namespace sg {

using vec2 = glm::dvec2;
using vec3 = glm::dvec3;
using vec4 = glm::dvec4;
using mat2 = glm::dmat2;
using mat3 = glm::dmat3;

using glm::clamp;
using glm::cross;
using glm::dot;
using glm::length;
using glm::mix;
using glm::normalize;

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kTwoPi = 2.0 * kPi;

inline double radians(double deg) {
  return deg * (kPi / 180.0);
}
inline double degrees(double rad) {
  return rad * (180.0 / kPi);
}
inline double sqr(double x) {
  return x * x;
}

}  // namespace sg
