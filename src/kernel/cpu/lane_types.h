// The kernel's GLSL names over SIMD lanes: the third build of the per-wave terms
// (kernel/wave_terms.glsl, kernel/aliasing.glsl, kernel/ndf.glsl, kernel/staa_waves.glsl),
// after the C++ scalar one (kernel/cpp_types.h) and GLSL's. `real` is a Highway vector of
// the waves in a block, one wave per lane; vec2/3/4 and mat2 hold one such vector per
// component; a comparison of reals is a lane mask, which the kernel's text only hands to
// select() and any_lane(). Pixel-wide values (ints, bools, the footprint's Jacobian once
// broadcast) keep every lane the same, so a branch on them is the same for all lanes, as
// on a GPU's warp.
//
// Included inside Highway's per-target namespace (kernel/cpu/wave_sums.cpp), once per
// precision, with `T` the lanes' scalar type in scope; no include guard.
//
// namespace ld {
// using T = double;
// #include "kernel/cpu/lane_types.h"
// #include "kernel/wave_terms.glsl"   ...
// }

struct real;

// A comparison's result, lane by lane.
struct lane_mask {
  hn::Mask<hn::ScalableTag<T>> m;
  // Whether any lane holds: a branch around work that adds nothing in the lanes that fail.
  friend HWY_INLINE bool any_lane(lane_mask c) { return !hn::AllFalse(hn::ScalableTag<T>(), c.m); }
};

struct real {
  using D = hn::ScalableTag<T>;
  hn::Vec<D> v;
  real() = default;  // uninitialised, as a GLSL local: the kernel assigns before it reads
  HWY_INLINE real(hn::Vec<D> x) : v(x) {}
  // Every lane the scalar s (the kernel's literals and pixel-wide values).
  HWY_INLINE real(double s) : v(hn::Set(D(), T(s))) {}
  HWY_INLINE real(float s) : v(hn::Set(D(), T(s))) {}
  HWY_INLINE real(int s) : v(hn::Set(D(), T(s))) {}

  friend HWY_INLINE real operator+(real a, real b) { return hn::Add(a.v, b.v); }
  friend HWY_INLINE real operator-(real a, real b) { return hn::Sub(a.v, b.v); }
  friend HWY_INLINE real operator*(real a, real b) { return hn::Mul(a.v, b.v); }
  friend HWY_INLINE real operator/(real a, real b) { return hn::Div(a.v, b.v); }
  friend HWY_INLINE real operator-(real a) { return hn::Neg(a.v); }
  HWY_INLINE real& operator+=(real b) { return *this = *this + b; }
  HWY_INLINE real& operator-=(real b) { return *this = *this - b; }
  HWY_INLINE real& operator*=(real b) { return *this = *this * b; }
  HWY_INLINE real& operator/=(real b) { return *this = *this / b; }
  friend HWY_INLINE lane_mask operator<(real a, real b) { return {hn::Lt(a.v, b.v)}; }
  friend HWY_INLINE lane_mask operator>(real a, real b) { return {hn::Gt(a.v, b.v)}; }
  friend HWY_INLINE lane_mask operator<=(real a, real b) { return {hn::Le(a.v, b.v)}; }
  friend HWY_INLINE lane_mask operator>=(real a, real b) { return {hn::Ge(a.v, b.v)}; }
  friend HWY_INLINE lane_mask operator!=(real a, real b) { return {hn::Ne(a.v, b.v)}; }

  friend HWY_INLINE real abs(real a) { return hn::Abs(a.v); }
  friend HWY_INLINE real min(real a, real b) { return hn::Min(a.v, b.v); }
  friend HWY_INLINE real max(real a, real b) { return hn::Max(a.v, b.v); }
  friend HWY_INLINE real clamp(real x, real lo, real hi) {
    return hn::Min(hn::Max(x.v, lo.v), hi.v);
  }
  friend HWY_INLINE real sqrt(real a) { return hn::Sqrt(a.v); }
  friend HWY_INLINE real floor(real a) { return hn::Floor(a.v); }
  // Highway's contrib math (3 ULP); the kernel reduces its phases to [-pi, pi] first.
  friend HWY_INLINE real sin(real a) { return hn::Sin(D(), a.v); }
  friend HWY_INLINE real cos(real a) { return hn::Cos(D(), a.v); }
  // GLSL's mix(b, a, c) with a bool c, lane by lane (kernel/cpp_types.h: select).
  friend HWY_INLINE real select(lane_mask c, real a, real b) {
    return hn::IfThenElse(c.m, a.v, b.v);
  }
};

// The sum over the lanes (the block's waves).
HWY_INLINE T lane_sum(real a) {
  return hn::GetLane(hn::SumOfLanes(real::D(), a.v));
}
HWY_INLINE T lane_max(real a) {
  return hn::GetLane(hn::MaxOfLanes(real::D(), a.v));
}

struct vec2 {
  real x, y;
  vec2() = default;
  HWY_INLINE explicit vec2(real s) : x(s), y(s) {}
  HWY_INLINE vec2(real x_, real y_) : x(x_), y(y_) {}
  HWY_INLINE real& operator[](int i) { return i == 0 ? x : y; }
  HWY_INLINE const real& operator[](int i) const { return i == 0 ? x : y; }
  friend HWY_INLINE vec2 operator+(const vec2& a, const vec2& b) { return {a.x + b.x, a.y + b.y}; }
  friend HWY_INLINE vec2 operator-(const vec2& a, const vec2& b) { return {a.x - b.x, a.y - b.y}; }
  friend HWY_INLINE vec2 operator-(const vec2& a) { return {-a.x, -a.y}; }
  friend HWY_INLINE vec2 operator*(real s, const vec2& a) { return {s * a.x, s * a.y}; }
  friend HWY_INLINE vec2 operator*(const vec2& a, real s) { return {a.x * s, a.y * s}; }
  friend HWY_INLINE vec2 operator/(const vec2& a, real s) { return {a.x / s, a.y / s}; }
  HWY_INLINE vec2& operator+=(const vec2& b) { return *this = *this + b; }
  HWY_INLINE vec2& operator-=(const vec2& b) { return *this = *this - b; }
  friend HWY_INLINE real dot(const vec2& a, const vec2& b) { return a.x * b.x + a.y * b.y; }
};

struct vec3 {
  real x, y, z;
  vec3() = default;
  HWY_INLINE explicit vec3(real s) : x(s), y(s), z(s) {}
  HWY_INLINE vec3(real x_, real y_, real z_) : x(x_), y(y_), z(z_) {}
  friend HWY_INLINE vec3 operator+(const vec3& a, const vec3& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
  }
  friend HWY_INLINE vec3 operator-(const vec3& a, const vec3& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
  }
  friend HWY_INLINE vec3 operator*(real s, const vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
  HWY_INLINE vec3& operator+=(const vec3& b) { return *this = *this + b; }
  HWY_INLINE vec3& operator-=(const vec3& b) { return *this = *this - b; }
};

struct vec4 {
  real x, y, z, w;
  vec4() = default;
  HWY_INLINE vec4(const vec2& a, real z_, real w_) : x(a.x), y(a.y), z(z_), w(w_) {}
  HWY_INLINE vec4(real x_, real y_, real z_, real w_) : x(x_), y(y_), z(z_), w(w_) {}
};

// Two columns, as GLSL's (and glm's) mat2.
struct mat2 {
  vec2 c[2];
  mat2() = default;
  HWY_INLINE mat2(const vec2& c0, const vec2& c1) : c{c0, c1} {}
  HWY_INLINE vec2& operator[](int i) { return c[i]; }
  HWY_INLINE const vec2& operator[](int i) const { return c[i]; }
  friend HWY_INLINE vec2 operator*(const mat2& m, const vec2& v) {
    return m.c[0] * v.x + m.c[1] * v.y;
  }
};

// The pixel-wide scalar of the C++ build broadcast to every lane, and its vectors.
HWY_INLINE real lanes_of(T s) {
  return real(s);
}
HWY_INLINE vec2 lanes_of(const glm::vec<2, T>& v) {
  return vec2(real(v.x), real(v.y));
}
HWY_INLINE mat2 lanes_of(const glm::mat<2, 2, T>& m) {
  return mat2(lanes_of(m[0]), lanes_of(m[1]));
}
