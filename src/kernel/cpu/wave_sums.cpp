// The CPU engine's vectorised sums over the waves (kernel/cpu/wave_sums.h): each function
// is the kernel loop named beside it, with the waves in SIMD lanes.
#include "kernel/cpu/wave_sums.h"

#include <algorithm>
#include <cstdint>

// Highway's per-target compilation: this file is included once per instruction set. The
// order of these lines matters, so they are kept out of clang-format's include sorting.
// clang-format off
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "kernel/cpu/wave_sums.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>
// clang-format on

HWY_BEFORE_NAMESPACE();
namespace sg::wave_simd {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// kernel/special.glsl, wrap_angle: x - 2 pi round(x / 2 pi), 2 pi split Cody-Waite style.
template <class D, class V>
HWY_INLINE V Wrap(D d, V x) {
  using T = hn::TFromD<D>;
  const V k = hn::Floor(hn::MulAdd(x, hn::Set(d, T(0.15915494309189533577)), hn::Set(d, T(0.5))));
  const V r = hn::NegMulAdd(k, hn::Set(d, T(6.28125)), x);
  return hn::NegMulAdd(k, hn::Set(d, T(0.0019353071795864769252867665590)), r);
}

// sin(x) / x from x and its sine (kernel/special.glsl, sinc_from).
template <class D, class V>
HWY_INLINE V SincFrom(D d, V x, V sin_x) {
  using T = hn::TFromD<D>;
  const auto small = hn::Lt(hn::Abs(x), hn::Set(d, T(1e-4)));
  const V one = hn::Set(d, T(1));
  return hn::IfThenElse(small, hn::NegMulAdd(hn::Mul(x, x), hn::Set(d, T(1.0 / 6.0)), one),
                        hn::Div(sin_x, hn::IfThenElse(small, one, x)));
}

// The phase a x + b z + theta0 + c dt (kernel/waves.glsl, wave_phase), wrapped.
template <class D, class V>
HWY_INLINE V Phase(D d, const V a, const V b, const V theta0, const V c, V x, V z, V dt) {
  return Wrap(d, hn::MulAdd(c, dt, hn::Add(hn::MulAdd(a, x, hn::Mul(b, z)), theta0)));
}

// The amplitudes of lanes i.. with the lanes at positions >= n set to 0.
template <class D, class T>
HWY_INLINE auto AmplitudesBelow(D d, const T* A, size_t i, size_t n) {
  const auto v = hn::LoadU(d, A + i);
  return i + hn::Lanes(d) <= n ? v : hn::IfThenElseZero(hn::FirstN(d, n - i), v);
}

template <class T>
T HeightT(const Arrays<T>& w, int n0, T x0, T z0, T dt0) {
  const hn::ScalableTag<T> d;
  const size_t N = hn::Lanes(d);
  const auto x = hn::Set(d, x0), z = hn::Set(d, z0), dt = hn::Set(d, dt0);
  auto h = hn::Zero(d);
  const size_t n = size_t(n0);
  for (size_t i = 0; i < n; i += N) {
    const auto th = Phase(d, hn::LoadU(d, w.a + i), hn::LoadU(d, w.b + i),
                          hn::LoadU(d, w.theta0 + i), hn::LoadU(d, w.c + i), x, z, dt);
    h = hn::MulAdd(AmplitudesBelow(d, w.A, i, n), hn::Sin(d, th), h);
  }
  return hn::GetLane(hn::SumOfLanes(d, h));
}

// kernel/waves.glsl, wave_sum_height_slope: waves lo <= i < hi (the lanes outside masked).
template <class T>
void HeightSlopeT(const Arrays<T>& w, int lo0, int hi0, T x0, T z0, T dt0, T ux0, T uz0, T& h0,
                  T& dh0) {
  const hn::ScalableTag<T> d;
  const size_t N = hn::Lanes(d);
  const auto x = hn::Set(d, x0), z = hn::Set(d, z0), dt = hn::Set(d, dt0);
  const auto ux = hn::Set(d, ux0), uz = hn::Set(d, uz0);
  auto h = hn::Zero(d), dh = hn::Zero(d);
  const size_t lo = size_t(lo0), hi = size_t(hi0);
  for (size_t i = lo - lo % N; i < hi; i += N) {
    const auto a = hn::LoadU(d, w.a + i), b = hn::LoadU(d, w.b + i);
    const auto th = Phase(d, a, b, hn::LoadU(d, w.theta0 + i), hn::LoadU(d, w.c + i), x, z, dt);
    auto A = AmplitudesBelow(d, w.A, i, hi);
    if (i < lo) A = hn::IfThenZeroElse(hn::FirstN(d, lo - i), A);
    h = hn::MulAdd(A, hn::Sin(d, th), h);
    dh = hn::MulAdd(hn::Mul(A, hn::Cos(d, th)), hn::MulAdd(a, ux, hn::Mul(b, uz)), dh);
  }
  h0 = hn::GetLane(hn::SumOfLanes(d, h));
  dh0 = hn::GetLane(hn::SumOfLanes(d, dh));
}

template <class T>
void GradientT(const Arrays<T>& w, T x0, T z0, T dt0, T& gx0, T& gz0) {
  const hn::ScalableTag<T> d;
  const size_t N = hn::Lanes(d);
  const auto x = hn::Set(d, x0), z = hn::Set(d, z0), dt = hn::Set(d, dt0);
  auto gx = hn::Zero(d), gz = hn::Zero(d);
  for (size_t i = 0; i < size_t(w.count); i += N) {
    const auto a = hn::LoadU(d, w.a + i), b = hn::LoadU(d, w.b + i);
    const auto th = Phase(d, a, b, hn::LoadU(d, w.theta0 + i), hn::LoadU(d, w.c + i), x, z, dt);
    const auto k = hn::Mul(hn::LoadU(d, w.A + i), hn::Cos(d, th));
    gx = hn::MulAdd(k, a, gx);
    gz = hn::MulAdd(k, b, gz);
  }
  gx0 = hn::GetLane(hn::SumOfLanes(d, gx));
  gz0 = hn::GetLane(hn::SumOfLanes(d, gz));
}

// kernel/reflection_path.glsl, path_gradients_add: the display time's gradient and, by
// cos(theta - c dt) = cos(theta) cos(c dt) + sin(theta) sin(c dt), the others'.
template <class T>
void PathT(const Arrays<T>& w, T x0, T z0, int K, T* gx_out, T* gz_out) {
  const hn::ScalableTag<T> d;
  const size_t N = hn::Lanes(d);
  const auto x = hn::Set(d, x0), z = hn::Set(d, z0), zero = hn::Zero(d);
  decltype(hn::Zero(d)) gx[kMaxInstants], gz[kMaxInstants];
  for (int k = 0; k <= K; ++k)
    gx[k] = gz[k] = hn::Zero(d);
  const size_t n = size_t(w.count);
  for (size_t i = 0; i < n; i += N) {
    const auto a = hn::LoadU(d, w.a + i), b = hn::LoadU(d, w.b + i);
    const auto th = Phase(d, a, b, hn::LoadU(d, w.theta0 + i), zero, x, z, zero);
    const auto A = hn::LoadU(d, w.A + i);
    const auto s = hn::Sin(d, th), c = hn::Cos(d, th);
    const auto Ac = hn::Mul(A, c);
    gx[K] = hn::MulAdd(Ac, a, gx[K]);
    gz[K] = hn::MulAdd(Ac, b, gz[K]);
    for (int k = 0; k < K; ++k) {
      const auto ck = hn::MulAdd(c, hn::LoadU(d, w.rot_c + k * n + i),
                                 hn::Mul(s, hn::LoadU(d, w.rot_s + k * n + i)));
      const auto Ack = hn::Mul(A, ck);
      gx[k] = hn::MulAdd(Ack, a, gx[k]);
      gz[k] = hn::MulAdd(Ack, b, gz[k]);
    }
  }
  for (int k = 0; k <= K; ++k) {
    gx_out[k] = hn::GetLane(hn::SumOfLanes(d, gx[k]));
    gz_out[k] = hn::GetLane(hn::SumOfLanes(d, gz[k]));
  }
}

// kernel/reflection_path.glsl, wave_sum_path_moving: instant k's gradient from the phase at
// its own point and time (one cosine per instant), instant K's at the display time.
template <class T>
void PathMovingT(const Arrays<T>& w, const T* px, const T* pz, const T* pdt, int K, T* gx_out,
                 T* gz_out) {
  const hn::ScalableTag<T> d;
  const size_t N = hn::Lanes(d);
  const auto zero = hn::Zero(d);
  decltype(hn::Zero(d)) gx[kMaxInstants], gz[kMaxInstants];
  for (int k = 0; k <= K; ++k)
    gx[k] = gz[k] = hn::Zero(d);
  const size_t n = size_t(w.count);
  for (size_t i = 0; i < n; i += N) {
    const auto a = hn::LoadU(d, w.a + i), b = hn::LoadU(d, w.b + i);
    const auto theta0 = hn::LoadU(d, w.theta0 + i), c = hn::LoadU(d, w.c + i);
    const auto A = hn::LoadU(d, w.A + i);
    const auto th = Phase(d, a, b, theta0, zero, hn::Set(d, px[K]), hn::Set(d, pz[K]), zero);
    const auto Ac = hn::Mul(A, hn::Cos(d, th));
    gx[K] = hn::MulAdd(Ac, a, gx[K]);
    gz[K] = hn::MulAdd(Ac, b, gz[K]);
    for (int k = 0; k < K; ++k) {
      const auto thk =
          Phase(d, a, b, theta0, c, hn::Set(d, px[k]), hn::Set(d, pz[k]), hn::Set(d, pdt[k]));
      const auto Ack = hn::Mul(A, hn::Cos(d, thk));
      gx[k] = hn::MulAdd(Ack, a, gx[k]);
      gz[k] = hn::MulAdd(Ack, b, gz[k]);
    }
  }
  for (int k = 0; k <= K; ++k) {
    gx_out[k] = hn::GetLane(hn::SumOfLanes(d, gx[k]));
    gz_out[k] = hn::GetLane(hn::SumOfLanes(d, gz[k]));
  }
}

// kernel/reference.glsl, wave_sum_path_derivatives: the gradients and their time
// derivatives at the path's instants, theta_k = theta - c (end - t_k) by angle subtraction.
template <class T>
void PathDerivativesT(const Arrays<T>& w, T x0, T z0, T dt0, int K, T* gx_out, T* gz_out,
                      T* dgx_out, T* dgz_out) {
  const hn::ScalableTag<T> d;
  using V = decltype(hn::Zero(d));
  const size_t N = hn::Lanes(d);
  const auto x = hn::Set(d, x0), z = hn::Set(d, z0), dt = hn::Set(d, dt0), zero = hn::Zero(d);
  V gx[kMaxInstants], gz[kMaxInstants], dgx[kMaxInstants], dgz[kMaxInstants];
  for (int k = 0; k <= K; ++k)
    gx[k] = gz[k] = dgx[k] = dgz[k] = zero;
  const size_t n = size_t(w.count);
  for (size_t i = 0; i < n; i += N) {
    const V a = hn::LoadU(d, w.a + i), b = hn::LoadU(d, w.b + i);
    const V cw = hn::LoadU(d, w.c + i);
    const V th = Phase(d, a, b, hn::LoadU(d, w.theta0 + i), cw, x, z, dt);
    const V A = hn::LoadU(d, w.A + i);
    const V Ac = hn::Mul(A, cw);
    const V s = hn::Sin(d, th), c = hn::Cos(d, th);
    const V gk = hn::Mul(A, c), dk = hn::Mul(Ac, s);
    gx[K] = hn::MulAdd(gk, a, gx[K]);
    gz[K] = hn::MulAdd(gk, b, gz[K]);
    dgx[K] = hn::NegMulAdd(dk, a, dgx[K]);
    dgz[K] = hn::NegMulAdd(dk, b, dgz[K]);
    for (int k = 0; k < K; ++k) {
      const V rc = hn::LoadU(d, w.rot_c + k * n + i), rs = hn::LoadU(d, w.rot_s + k * n + i);
      const V ck = hn::MulAdd(c, rc, hn::Mul(s, rs));
      const V sk = hn::MulSub(s, rc, hn::Mul(c, rs));
      const V g = hn::Mul(A, ck), dg = hn::Mul(Ac, sk);
      gx[k] = hn::MulAdd(g, a, gx[k]);
      gz[k] = hn::MulAdd(g, b, gz[k]);
      dgx[k] = hn::NegMulAdd(dg, a, dgx[k]);
      dgz[k] = hn::NegMulAdd(dg, b, dgz[k]);
    }
  }
  for (int k = 0; k <= K; ++k) {
    gx_out[k] = hn::GetLane(hn::SumOfLanes(d, gx[k]));
    gz_out[k] = hn::GetLane(hn::SumOfLanes(d, gz[k]));
    dgx_out[k] = hn::GetLane(hn::SumOfLanes(d, dgx[k]));
    dgz_out[k] = hn::GetLane(hn::SumOfLanes(d, dgz[k]));
  }
}

// kernel/staa.glsl, wave_sum_staa: Eq. 20's split, the resolved waves' path and Hessian
// and the aliasing waves' NDF (kernel/ndf.glsl), in one pass over the waves [0, count)
// (the remainder's sums are the caller's: kernel/cpu/wave_sums_hooks.inc). A vector that
// starts at or past alias_from has resolved shares 0 in every lane: its path and Hessian
// terms, zeros, are skipped. Under a moving camera (in.moving) the path's instants take
// their own points' phases, and Eq. 20 and Appendix A's half-width the swept footprint
// (kernel/aliasing.glsl, swept_frequency; kernel/ndf.glsl, swept_half_width).
template <class T>
void StaaT(const Arrays<T>& w, const StaaPassIn<T>& in, StaaPassOut<T>& out) {
  const hn::ScalableTag<T> d;
  using V = decltype(hn::Zero(d));
  const size_t N = hn::Lanes(d);
  const int K = in.segments;
  const V zero = hn::Zero(d), one = hn::Set(d, T(1)), half = hn::Set(d, T(0.5));
  const V x = hn::Set(d, in.x), z = hn::Set(d, in.z);
  const V j00 = hn::Set(d, in.j00), j01 = hn::Set(d, in.j01), j10 = hn::Set(d, in.j10),
          j11 = hn::Set(d, in.j11);
  const V i00 = hn::Set(d, in.i00), i01 = hn::Set(d, in.i01), i10 = hn::Set(d, in.i10),
          i11 = hn::Set(d, in.i11);
  const V start = hn::Set(d, in.alias_start);
  const V width = hn::Set(d, in.alias_end - in.alias_start);
  const V inv_two_pi = hn::Set(d, T(0.15915494309189533577));
  const V limit = hn::Set(d, in.limit);
  const bool moving = in.moving;
  const V sweep_x = hn::Set(d, in.sweep_x), sweep_z = hn::Set(d, in.sweep_z);
  V ipx[kMaxInstants], ipz[kMaxInstants], idt[kMaxInstants];
  for (int k = 0; k < K; ++k) {
    ipx[k] = hn::Set(d, in.px[k]);
    ipz[k] = hn::Set(d, in.pz[k]);
    idt[k] = hn::Set(d, in.dt[k]);
  }
  V gx[kMaxInstants], gz[kMaxInstants], hxx[kMaxInstants], hxz[kMaxInstants], hzz[kMaxInstants];
  for (int k = 0; k <= K; ++k)
    gx[k] = gz[k] = hxx[k] = hxz[k] = hzz[k] = zero;
  V mx = zero, mz = zero, cxx = zero, cxz = zero, czz = zero, any = zero;
  // kernel/ndf.glsl, box_cells_add: the smooth terms' cells.
  const int side = in.box_side;
  V bmx[kMaxBoxCells], bmz[kMaxBoxCells], bxx[kMaxBoxCells], bxz[kMaxBoxCells], bzz[kMaxBoxCells];
  for (int q = 0; q < kMaxBoxCells; ++q)
    bmx[q] = bmz[q] = bxx[q] = bxz[q] = bzz[q] = zero;
  const V inv_side = hn::Set(d, side > 0 ? T(1) / T(side) : T(0));
  const size_t n = size_t(w.count);  // the arrays' stride
  const size_t visit = size_t(in.count), alias_from = size_t(std::max(in.alias_from, 0));
  for (size_t i = 0; i < visit; i += N) {
    const V a = hn::LoadU(d, w.a + i), b = hn::LoadU(d, w.b + i);
    const V A = AmplitudesBelow(d, w.A, i, visit);
    const V th = Phase(d, a, b, hn::LoadU(d, w.theta0 + i), zero, x, z, zero);
    const V c = hn::Cos(d, th);
    const V s = (i < alias_from || side > 0) ? hn::Sin(d, th) : zero;
    // kernel/aliasing.glsl: the projected frequency and Eq. 20.
    const V fx = hn::Abs(hn::MulAdd(a, j00, hn::Mul(b, j01)));
    const V fy = hn::Abs(hn::MulAdd(a, j10, hn::Mul(b, j11)));
    // Under a moving camera the motion's phase change k . (p_K - p_0) is a third axis.
    const V km = moving ? hn::MulAdd(a, sweep_x, hn::Mul(b, sweep_z)) : zero;
    V rad;
    if (!moving) {
      rad = in.max_norm ? hn::Max(fx, fy) : hn::Sqrt(hn::MulAdd(fx, fx, hn::Mul(fy, fy)));
    } else {
      const V fm = hn::Abs(km);
      rad = in.max_norm ? hn::Max(hn::Max(fx, fy), fm)
                        : hn::Sqrt(hn::MulAdd(fx, fx, hn::MulAdd(fy, fy, hn::Mul(fm, fm))));
    }
    V alpha = hn::Min(one, hn::Max(zero, hn::Div(hn::Sub(hn::Mul(rad, inv_two_pi), start), width)));
    // kernel/ndf.glsl, footprint_half_width.
    const V kk = hn::MulAdd(a, a, hn::Mul(b, b));
    V D = zero;
    if (in.invertible) {
      const V qx = hn::Abs(hn::MulAdd(i00, a, hn::Mul(i10, b)));
      const V qy = hn::Abs(hn::MulAdd(i01, a, hn::Mul(i11, b)));
      D = hn::Div(hn::Mul(half, kk), hn::Max(hn::Max(qx, qy), hn::Set(d, T(1e-30))));
    }
    if (in.curvature) {
      const V dev = hn::Mul(hn::Mul(hn::LoadU(d, w.slope + i), D), D);
      alpha = hn::Max(alpha, hn::Min(one, hn::Max(zero, hn::Sub(hn::Div(dev, limit), one))));
    }
    if (i < alias_from) {
      const V resolved = hn::Mul(hn::Sub(one, alpha), A);
      const V rc = hn::Mul(resolved, c);
      gx[K] = hn::MulAdd(rc, a, gx[K]);
      gz[K] = hn::MulAdd(rc, b, gz[K]);
      const V aa = hn::Mul(a, a), ab = hn::Mul(a, b), bb = hn::Mul(b, b);
      if (!moving) {
        // kernel/staa.glsl, staa_path_add: the gradient and the Hessian at each instant.
        for (int k = 0; k < K; ++k) {
          const V rc = hn::LoadU(d, w.rot_c + k * n + i), rs = hn::LoadU(d, w.rot_s + k * n + i);
          const V ck = hn::MulAdd(c, rc, hn::Mul(s, rs));
          const V sk = hn::MulSub(s, rc, hn::Mul(c, rs));
          const V rk = hn::Mul(resolved, ck), hk = hn::Mul(resolved, sk);
          gx[k] = hn::MulAdd(rk, a, gx[k]);
          gz[k] = hn::MulAdd(rk, b, gz[k]);
          hxx[k] = hn::NegMulAdd(hk, aa, hxx[k]);
          hxz[k] = hn::NegMulAdd(hk, ab, hxz[k]);
          hzz[k] = hn::NegMulAdd(hk, bb, hzz[k]);
        }
      } else {
        // kernel/reflection_path.glsl, path_gradients_add_moving.
        const V theta0 = hn::LoadU(d, w.theta0 + i), cw = hn::LoadU(d, w.c + i);
        for (int k = 0; k < K; ++k) {
          const V thk = Phase(d, a, b, theta0, cw, ipx[k], ipz[k], idt[k]);
          const V rk = hn::Mul(resolved, hn::Cos(d, thk));
          gx[k] = hn::MulAdd(rk, a, gx[k]);
          gz[k] = hn::MulAdd(rk, b, gz[k]);
        }
      }
      const V rs = hn::Mul(resolved, s);
      hxx[K] = hn::NegMulAdd(rs, aa, hxx[K]);
      hxz[K] = hn::NegMulAdd(rs, ab, hxz[K]);
      hzz[K] = hn::NegMulAdd(rs, bb, hzz[K]);
    }
    if (side > 0) {
      // Half-phases along the pixel's edges, per cell: x = (k . J_0, k . J_1) / (2 n).
      const V x0 = hn::Mul(hn::Mul(half, hn::MulAdd(a, j00, hn::Mul(b, j01))), inv_side);
      const V x1 = hn::Mul(hn::Mul(half, hn::MulAdd(a, j10, hn::Mul(b, j11))), inv_side);
      // Reduced to [-pi, pi] before the sine and cosine (kernel/ndf.glsl, box_cells_add).
      const V rx0 = Wrap(d, x0), rx1 = Wrap(d, x1);
      const V cx0 = hn::Cos(d, rx0), sx0 = hn::Sin(d, rx0), cx1 = hn::Cos(d, rx1),
              sx1 = hn::Sin(d, rx1);
      const V f0 = SincFrom(d, x0, sx0), f1 = SincFrom(d, x1, sx1);
      const V g = hn::Mul(hn::Mul(f0, cx0), hn::Mul(f1, cx1));
      const V Af = hn::Mul(A, hn::Mul(f0, f1));
      const V J0 = hn::Mul(hn::Mul(half, A), A);
      const V kxx = hn::Mul(a, a), kxz = hn::Mul(a, b), kzz = hn::Mul(b, b);
      // box_offset_rotations: the first offset -(n - 1) x and the step 2 x.
      auto rotations = [&](V cx, V sx, V& fc, V& fs, V& c2, V& s2) {
        c2 = hn::MulSub(hn::Add(cx, cx), cx, one);
        s2 = hn::Mul(hn::Add(sx, sx), cx);
        fc = side == 1 ? one : (side == 2 ? cx : c2);
        fs = side == 1 ? zero : (side == 2 ? hn::Neg(sx) : hn::Neg(s2));
      };
      V ac, as, r0c, r0s, b0c, b0s, r1c, r1s;
      rotations(cx0, sx0, ac, as, r0c, r0s);
      rotations(cx1, sx1, b0c, b0s, r1c, r1s);
      for (int iu = 0; iu < side; ++iu) {
        V bc = b0c, bs = b0s;
        for (int iv = 0; iv < side; ++iv) {
          const V cab = hn::NegMulAdd(as, bs, hn::Mul(ac, bc));
          const V sab = hn::MulAdd(ac, bs, hn::Mul(as, bc));
          const V cp = hn::NegMulAdd(s, sab, hn::Mul(c, cab));
          const V Kc = hn::Mul(Af, cp);
          const V Jc = hn::Mul(J0, hn::MulAdd(hn::MulSub(hn::Add(cp, cp), cp, one), g, one));
          const V var = hn::NegMulAdd(Kc, Kc, Jc);
          const int q = iu * side + iv;
          bmx[q] = hn::NegMulAdd(Kc, a, bmx[q]);
          bmz[q] = hn::NegMulAdd(Kc, b, bmz[q]);
          bxx[q] = hn::MulAdd(var, kxx, bxx[q]);
          bxz[q] = hn::MulAdd(var, kxz, bxz[q]);
          bzz[q] = hn::MulAdd(var, kzz, bzz[q]);
          const V nbc = hn::NegMulAdd(bs, r1s, hn::Mul(bc, r1c));
          bs = hn::MulAdd(bc, r1s, hn::Mul(bs, r1c));
          bc = nbc;
        }
        const V nac = hn::NegMulAdd(as, r0s, hn::Mul(ac, r0c));
        as = hn::MulAdd(ac, r0s, hn::Mul(as, r0c));
        ac = nac;
      }
    }
    const V aliasing = hn::Mul(alpha, A);
    if (hn::AllFalse(d, hn::Gt(aliasing, zero))) continue;
    any = hn::Add(any, aliasing);
    V v;  // the wave's variance factor: J - K^2 (per pixel) or A^2 / 2 (uniform)
    if (in.per_pixel) {
      // kernel/ndf.glsl, wave_moment_factors (Eqs. 23-24); under a moving camera with the
      // swept half-width sqrt(D^2 + m^2), m = k . (p_K - p_0) / 2 (swept_half_width).
      V Dn = D;
      if (moving) {
        const V m = hn::Mul(half, km);
        Dn = hn::Sqrt(hn::MulAdd(D, D, hn::Mul(m, m)));
      }
      const V sd = hn::Sin(d, Dn), cd = hn::Cos(d, Dn);
      const V sinc1 = SincFrom(d, Dn, sd);
      const V sinc2 = hn::Mul(sinc1, cd);  // sinc(2 D) = sinc(D) cos(D)
      const V cos_2t = hn::MulSub(hn::Add(c, c), c, one);
      const V Kf = hn::Mul(hn::Mul(aliasing, c), sinc1);
      const V Jf =
          hn::Mul(hn::Mul(hn::Mul(half, aliasing), aliasing), hn::MulAdd(cos_2t, sinc2, one));
      mx = hn::NegMulAdd(Kf, a, mx);
      mz = hn::NegMulAdd(Kf, b, mz);
      v = hn::NegMulAdd(Kf, Kf, Jf);
    } else {
      v = hn::Mul(hn::Mul(half, aliasing), aliasing);
    }
    cxx = hn::MulAdd(v, hn::Mul(a, a), cxx);
    cxz = hn::MulAdd(v, hn::Mul(a, b), cxz);
    czz = hn::MulAdd(v, hn::Mul(b, b), czz);
  }
  auto sum = [&](V v) { return hn::GetLane(hn::SumOfLanes(d, v)); };
  for (int k = 0; k <= K; ++k) {
    out.gx[k] = sum(gx[k]);
    out.gz[k] = sum(gz[k]);
    out.hxx[k] = sum(hxx[k]);
    out.hxz[k] = sum(hxz[k]);
    out.hzz[k] = sum(hzz[k]);
  }
  out.mx = sum(mx);
  out.mz = sum(mz);
  out.cxx = sum(cxx);
  out.cxz = sum(cxz);
  out.czz = sum(czz);
  out.any = sum(any) > T(0);
  for (int q = 0; q < side * side; ++q) {
    out.bmx[q] = sum(bmx[q]);
    out.bmz[q] = sum(bmz[q]);
    out.bxx[q] = sum(bxx[q]);
    out.bxz[q] = sum(bxz[q]);
    out.bzz[q] = sum(bzz[q]);
  }
}

double HeightD(const Arrays<double>& w, int n, double x, double z, double dt) {
  return HeightT(w, n, x, z, dt);
}
float HeightF(const Arrays<float>& w, int n, float x, float z, float dt) {
  return HeightT(w, n, x, z, dt);
}
void HeightSlopeD(const Arrays<double>& w, int lo, int hi, double x, double z, double dt, double ux,
                  double uz, double& h, double& dh) {
  HeightSlopeT(w, lo, hi, x, z, dt, ux, uz, h, dh);
}
void HeightSlopeF(const Arrays<float>& w, int lo, int hi, float x, float z, float dt, float ux,
                  float uz, float& h, float& dh) {
  HeightSlopeT(w, lo, hi, x, z, dt, ux, uz, h, dh);
}
void GradientD(const Arrays<double>& w, double x, double z, double dt, double& gx, double& gz) {
  GradientT(w, x, z, dt, gx, gz);
}
void GradientF(const Arrays<float>& w, float x, float z, float dt, float& gx, float& gz) {
  GradientT(w, x, z, dt, gx, gz);
}
void PathD(const Arrays<double>& w, double x, double z, int K, double* gx, double* gz) {
  PathT(w, x, z, K, gx, gz);
}
void PathF(const Arrays<float>& w, float x, float z, int K, float* gx, float* gz) {
  PathT(w, x, z, K, gx, gz);
}
void PathMovingD(const Arrays<double>& w, const double* x, const double* z, const double* dt, int K,
                 double* gx, double* gz) {
  PathMovingT(w, x, z, dt, K, gx, gz);
}
void PathMovingF(const Arrays<float>& w, const float* x, const float* z, const float* dt, int K,
                 float* gx, float* gz) {
  PathMovingT(w, x, z, dt, K, gx, gz);
}
void PathDerivativesD(const Arrays<double>& w, double x, double z, double dt, int K, double* gx,
                      double* gz, double* dgx, double* dgz) {
  PathDerivativesT(w, x, z, dt, K, gx, gz, dgx, dgz);
}
void PathDerivativesF(const Arrays<float>& w, float x, float z, float dt, int K, float* gx,
                      float* gz, float* dgx, float* dgz) {
  PathDerivativesT(w, x, z, dt, K, gx, gz, dgx, dgz);
}
void StaaD(const Arrays<double>& w, const StaaPassIn<double>& in, StaaPassOut<double>& out) {
  StaaT(w, in, out);
}
void StaaF(const Arrays<float>& w, const StaaPassIn<float>& in, StaaPassOut<float>& out) {
  StaaT(w, in, out);
}

}  // namespace HWY_NAMESPACE
}  // namespace sg::wave_simd
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace sg::wave_simd {
HWY_EXPORT(HeightD);
HWY_EXPORT(HeightF);
HWY_EXPORT(HeightSlopeD);
HWY_EXPORT(HeightSlopeF);
HWY_EXPORT(GradientD);
HWY_EXPORT(GradientF);
HWY_EXPORT(PathD);
HWY_EXPORT(PathF);
HWY_EXPORT(PathMovingD);
HWY_EXPORT(PathMovingF);
HWY_EXPORT(PathDerivativesD);
HWY_EXPORT(PathDerivativesF);
HWY_EXPORT(StaaD);
HWY_EXPORT(StaaF);

double height(const Arrays<double>& w, int n, double x, double z, double dt) {
  return HWY_DYNAMIC_DISPATCH(HeightD)(w, n, x, z, dt);
}
float height(const Arrays<float>& w, int n, float x, float z, float dt) {
  return HWY_DYNAMIC_DISPATCH(HeightF)(w, n, x, z, dt);
}
void height_slope(const Arrays<double>& w, int lo, int hi, double x, double z, double dt, double ux,
                  double uz, double& h, double& dh) {
  HWY_DYNAMIC_DISPATCH(HeightSlopeD)(w, lo, hi, x, z, dt, ux, uz, h, dh);
}
void height_slope(const Arrays<float>& w, int lo, int hi, float x, float z, float dt, float ux,
                  float uz, float& h, float& dh) {
  HWY_DYNAMIC_DISPATCH(HeightSlopeF)(w, lo, hi, x, z, dt, ux, uz, h, dh);
}
void gradient(const Arrays<double>& w, double x, double z, double dt, double& gx, double& gz) {
  HWY_DYNAMIC_DISPATCH(GradientD)(w, x, z, dt, gx, gz);
}
void gradient(const Arrays<float>& w, float x, float z, float dt, float& gx, float& gz) {
  HWY_DYNAMIC_DISPATCH(GradientF)(w, x, z, dt, gx, gz);
}
void path(const Arrays<double>& w, double x, double z, int K, double* gx, double* gz) {
  HWY_DYNAMIC_DISPATCH(PathD)(w, x, z, K, gx, gz);
}
void path(const Arrays<float>& w, float x, float z, int K, float* gx, float* gz) {
  HWY_DYNAMIC_DISPATCH(PathF)(w, x, z, K, gx, gz);
}
void path_moving(const Arrays<double>& w, const double* x, const double* z, const double* dt, int K,
                 double* gx, double* gz) {
  HWY_DYNAMIC_DISPATCH(PathMovingD)(w, x, z, dt, K, gx, gz);
}
void path_moving(const Arrays<float>& w, const float* x, const float* z, const float* dt, int K,
                 float* gx, float* gz) {
  HWY_DYNAMIC_DISPATCH(PathMovingF)(w, x, z, dt, K, gx, gz);
}
void path_derivatives(const Arrays<double>& w, double x, double z, double dt, int K, double* gx,
                      double* gz, double* dgx, double* dgz) {
  HWY_DYNAMIC_DISPATCH(PathDerivativesD)(w, x, z, dt, K, gx, gz, dgx, dgz);
}
void path_derivatives(const Arrays<float>& w, float x, float z, float dt, int K, float* gx,
                      float* gz, float* dgx, float* dgz) {
  HWY_DYNAMIC_DISPATCH(PathDerivativesF)(w, x, z, dt, K, gx, gz, dgx, dgz);
}
void staa_pass(const Arrays<double>& w, const StaaPassIn<double>& in, StaaPassOut<double>& out) {
  HWY_DYNAMIC_DISPATCH(StaaD)(w, in, out);
}
void staa_pass(const Arrays<float>& w, const StaaPassIn<float>& in, StaaPassOut<float>& out) {
  HWY_DYNAMIC_DISPATCH(StaaF)(w, in, out);
}
const char* target() {
  const int64_t targets = hwy::SupportedTargets() & HWY_TARGETS;
  return targets ? hwy::TargetName(targets & -targets) : "none";
}
}  // namespace sg::wave_simd
#endif
