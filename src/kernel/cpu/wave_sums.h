// The CPU engine's vectorised sums over the waves: the same arithmetic as the kernel's
// loops (kernel/waves.glsl, wave_sum_height_first, wave_sum_height_slope and wave_sum_gradient;
// kernel/reflection_path.glsl, wave_sum_path and wave_sum_path_moving; kernel/staa.glsl,
// wave_sum_staa;
// kernel/reference.glsl, wave_sum_path_derivatives), run across
// the waves in SIMD lanes with Highway (sine and cosine: Highway's contrib math, 3 ULP)
// and dispatched at run time to the host's widest instruction set. The kernel's loops are
// the definition; kernel_wave_sums_test holds these equal to them (they differ only in
// rounding: the order of the sums and the sine's last bits).
//
// The kernel reaches them through its SG_CPU_WAVE_SUMS hooks (kernel/cpu/kernel_double.cpp,
// kernel/cpu/kernel_float.cpp); this interface has plain numbers only. The arrays are
// padded to a multiple of kLanePadding with waves of amplitude 0 (shading/kernel_frame.h),
// so the vectors need no tail; a sum over the first n waves masks the lanes past n in its
// last vector (amplitude 0), so that it equals the loop's.
#pragma once

#include "kernel/cpp_prelude.h"

namespace sg::wave_simd {

inline constexpr int kLanePadding = 16;
inline constexpr int kMaxInstants = SG_MAX_SEGMENTS + 1;

template <class T>
struct StaaPassIn {
  T x = 0, z = 0;                        // the point (camera-relative)
  T j00 = 0, j01 = 0, j10 = 0, j11 = 0;  // the footprint's Jacobian J, column-major
  T i00 = 0, i01 = 0, i10 = 0, i11 = 0;  // its inverse (0 when J is singular)
  bool invertible = false;
  T alias_start = 0, alias_end = 1;
  bool max_norm = true;
  bool per_pixel = true;
  bool curvature = false;
  T limit = 0;  // curvature limit times the light's radius
  int segments = 1;
  int count = 0;       // the waves visited: positions [0, count) (kernel/staa.glsl, remainder)
  int alias_from = 0;  // every wave from this position on aliases fully (resolved share 0)
  int box_side = 0;    // the smooth terms' cells per side (kernel/ndf.glsl, box_cells_add; 0: off)
  // A camera that moves over the shutter (kernel/reflection_path.glsl, PathViews): the
  // water point (px, pz) and dt of each instant k < segments, and the motion p_K - p_0
  // (sweep) over which Eq. 20 and Appendix A's half-width are taken.
  bool moving = false;
  T px[kMaxInstants] = {}, pz[kMaxInstants] = {}, dt[kMaxInstants] = {};
  T sweep_x = 0, sweep_z = 0;
};

inline constexpr int kMaxBoxCells = 9;

template <class T>
struct StaaPassOut {
  T gx[kMaxInstants], gz[kMaxInstants];  // resolved gradients at the instants
  // Resolved Hessians at the instants (under a moving camera only the last, the display
  // time's, is summed).
  T hxx[kMaxInstants], hxz[kMaxInstants], hzz[kMaxInstants];
  T mx = 0, mz = 0;             // NDF mean
  T cxx = 0, cxz = 0, czz = 0;  // NDF covariance
  bool any = false;
  // The cells' moments (box_side^2 of them, row-major): mean and covariance.
  T bmx[kMaxBoxCells], bmz[kMaxBoxCells], bxx[kMaxBoxCells], bxz[kMaxBoxCells], bzz[kMaxBoxCells];
};

// The height of the first n waves (n <= w.count).
double height(const Arrays<double>& w, int n, double x, double z, double dt);
float height(const Arrays<float>& w, int n, float x, float z, float dt);
// The height of waves lo <= i < hi and its derivative along (ux, uz).
void height_slope(const Arrays<double>& w, int lo, int hi, double x, double z, double dt, double ux,
                  double uz, double& h, double& dh);
void height_slope(const Arrays<float>& w, int lo, int hi, float x, float z, float dt, float ux,
                  float uz, float& h, float& dh);
void gradient(const Arrays<double>& w, double x, double z, double dt, double& gx, double& gz);
void gradient(const Arrays<float>& w, float x, float z, float dt, float& gx, float& gz);
// The gradients at the K + 1 instants of a path (every wave at full amplitude).
void path(const Arrays<double>& w, double x, double z, int segments, double* gx, double* gz);
void path(const Arrays<float>& w, float x, float z, int segments, float* gx, float* gz);
// The same under a moving camera: instant k at point (x[k], z[k]) and dt[k], the last
// (k = segments) at dt 0 (kernel/reflection_path.glsl, wave_sum_path_moving).
void path_moving(const Arrays<double>& w, const double* x, const double* z, const double* dt,
                 int segments, double* gx, double* gz);
void path_moving(const Arrays<float>& w, const float* x, const float* z, const float* dt,
                 int segments, float* gx, float* gz);
// The gradients and their time derivatives at the K + 1 instants of a path whose last
// instant is dt after the display time (kernel/reference.glsl, wave_sum_path_derivatives).
void path_derivatives(const Arrays<double>& w, double x, double z, double dt, int segments,
                      double* gx, double* gz, double* dgx, double* dgz);
void path_derivatives(const Arrays<float>& w, float x, float z, float dt, int segments, float* gx,
                      float* gz, float* dgx, float* dgz);
void staa_pass(const Arrays<double>& w, const StaaPassIn<double>& in, StaaPassOut<double>& out);
void staa_pass(const Arrays<float>& w, const StaaPassIn<float>& in, StaaPassOut<float>& out);

// The instruction set the sums run on, as Highway names it ("AVX3", "AVX2", ...).
const char* target();

}  // namespace sg::wave_simd
