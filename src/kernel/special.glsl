// Special functions the kernel needs and GLSL lacks, written once for both languages.
//
// erfc: the Chebyshev expansion of Shepherd and Laframboise (1981), "Chebyshev
// approximation of (1 + 2x) exp(x^2) erfc x in 0 <= x < infinity", Math. Comp. 36(153),
// 249-253: y(x) = (1 + 2x) exp(x^2) erfc(x) is smooth and bounded on [0, inf), and so is
// its expansion in Chebyshev polynomials of t = (x - K) / (x + K), K = 3.75; then
// erfc(x) = exp(-x^2) y(x) / (1 + 2x), and erfc(-x) = 2 - erfc(x). The 27 coefficients
// were computed in 80-digit arithmetic by tools/erfc_chebyshev.py (truncated below 1e-18).
// Measured against std::erfc (kernel/special_test.cpp): in double, relative error below
// 6e-14 on [-6, 26], where the rounding of x^2 inside exp(-x^2) dominates; in float,
// relative error below 6e-7 on [-6, 3] and absolute error below 4e-7 everywhere. The float
// builds (the GL and web programs, the CPU's float kernel) sum the first 14 terms only:
// the rest add up to 8.6e-10 of y (about 1.2), 70 times below float's resolution, and the
// shorter sum made llvmpipe's `staa` program compile in 11.8 s instead of 17.5 s and its
// frames 12-19% faster (docs/benchmarks.md).
const real kErfcCheb[27] =
    SG_ARRAY(real, 27,
             (1.1775789345674017, -0.0045900545806464776, -0.084249133366517917,
              0.059209939998191893, -0.026658668435305753, 0.0090749976707052652,
              -0.0024131635404176081, 0.00049077583652580863, -6.916973302501207e-05,
              4.1390279860730102e-06, 7.7403830661984903e-07, -2.1886401049234397e-07,
              1.076499946567091e-08, 4.5219598112182866e-09, -7.7544002088313509e-10,
              -6.3180883408866841e-11, 2.8687950109306699e-11, 1.9455868545777347e-13,
              -9.6546967484334393e-13, 3.2525481481487401e-14, 3.3478119482868056e-14,
              -1.864562880419313e-15, -1.2507950530688648e-15, 7.4182352566240441e-17,
              5.068148904796111e-17, -2.2370566594359995e-18, -2.1873429443030178e-18));
const real kErfcK = 3.75;

SG_FN real sqr(real x) {
  return x * x;
}

// erfc(x) for finite x (above: the bound).
SG_FN real erfc(real x) {
  real ax = abs(x);
  real r = 0.0;
  if (ax < 27.0) {
    real t = (ax - kErfcK) / (ax + kErfcK);
    // Clenshaw's recurrence for sum c_k T_k(t).
    real b1 = 0.0;
    real b2 = 0.0;
    for (int k = kDoublePrecision ? 26 : 13; k >= 1; --k) {
      real b0 = 2.0 * t * b1 - b2 + kErfcCheb[k];
      b2 = b1;
      b1 = b0;
    }
    real y = t * b1 - b2 + kErfcCheb[0];
    r = exp(-ax * ax) * y / (1.0 + 2.0 * ax);
  }
  return x < 0.0 ? 2.0 - r : r;
}

// The standard normal CDF Phi(x).
SG_FN real normal_cdf(real x) {
  return 0.5 * erfc(-x * kInvSqrtTwo);
}

// Phi(-|z|), the normal's upper tail beyond |z|; beyond 9 standard deviations, below
// 1.2e-19, 0 without an erfc (the quadratures that call this spend most points there).
SG_FN real normal_upper_tail(real z) {
  real t = abs(z);
  return t >= 9.0 ? 0.0 : 0.5 * erfc(t * kInvSqrtTwo);
}

// Phi(b) - Phi(a) for a <= b from the two tails qa = Phi(-|a|) and qb = Phi(-|b|),
// accurate in both tails (each difference is taken where both terms are small).
SG_FN real normal_mass_of_tails(real a, real b, real qa, real qb) {
  if (a >= 0.0) return qa - qb;
  if (b <= 0.0) return qb - qa;
  return 1.0 - qa - qb;
}

// Phi(b) - Phi(a) for a <= b (normal_mass_of_tails).
SG_FN real normal_mass(real a, real b) {
  if (a >= 9.0 || b <= -9.0) return 0.0;
  if (a <= -9.0 && b >= 9.0) return 1.0;
  return normal_mass_of_tails(a, b, normal_upper_tail(a), normal_upper_tail(b));
}

// P(lo <= X <= hi) for X ~ N(0, s^2), s >= 0 (a step for s = 0).
SG_FN real normal_interval(real lo, real hi, real s) {
  if (hi <= lo) return 0.0;
  if (s <= 0.0) return (lo <= 0.0 && 0.0 <= hi) ? 1.0 : 0.0;
  return normal_mass(lo / s, hi / s);
}

// sin(x) / x, accurate near 0.
SG_FN real sinc(real x) {
  return sinc_from(x, sin(x));
}

// e^u - 1 without the cancellation of exp(u) - 1 near u = 0 (GLSL has no expm1): for
// |u| < 1/4 the Taylor series to degree 12 in Horner's form, whose first term left out,
// u^13 / 13!, is below 2.5e-18 of the sum (under double's rounding); beyond, exp(u) - 1,
// which loses no digits there (|e^u - 1| > 0.22). Unlike Kahan's (e^u - 1) u / log(e^u),
// it needs no log accurate to the last bit near 1, which GPUs do not give (Vulkan allows
// log an absolute error of 2^-21 on [0.5, 2]).
SG_FN real exp_minus_one(real u) {
  if (!(abs(u) < 0.25)) return exp(u) - 1.0;
  real p = 1.0 + u * (1.0 / 13.0);
  p = 1.0 + u * (1.0 / 12.0) * p;
  p = 1.0 + u * (1.0 / 11.0) * p;
  p = 1.0 + u * (1.0 / 10.0) * p;
  p = 1.0 + u * (1.0 / 9.0) * p;
  p = 1.0 + u * (1.0 / 8.0) * p;
  p = 1.0 + u * (1.0 / 7.0) * p;
  p = 1.0 + u * (1.0 / 6.0) * p;
  p = 1.0 + u * (1.0 / 5.0) * p;
  p = 1.0 + u * (1.0 / 4.0) * p;
  p = 1.0 + u * (1.0 / 3.0) * p;
  p = 1.0 + u * 0.5 * p;
  return u * p;
}

// The standard normal quantile Phi^-1(p), 0 < p < 1: P. J. Acklam's rational
// approximations (2003, "An algorithm for computing the inverse normal cumulative
// distribution function"), one for the centre |p - 1/2| <= 0.47575 and one in
// q = sqrt(-2 log p) for each tail; relative error below 1.15e-9 (measured against
// normal_cdf in kernel/special_test.cpp). The lower tail takes log(p) directly, so small p
// keep their digits.
SG_FN real normal_quantile(real p) {
  real pc = clamp(p, 1e-37, 1.0);  // 1e-37: u = -12.9, a normal float
  if (pc < 0.02425 || pc > 0.97575) {
    real q = sqrt(-2.0 * log(pc < 0.5 ? pc : 1.0 - pc));
    real num =
        ((((-7.784894002430293e-03 * q - 3.223964580411365e-01) * q - 2.400758277161838e+00) * q -
          2.549732539343734e+00) *
             q +
         4.374664141464968e+00) *
            q +
        2.938163982698783e+00;
    real den =
        (((7.784695709041462e-03 * q + 3.224671290700398e-01) * q + 2.445134137142996e+00) * q +
         3.754408661907416e+00) *
            q +
        1.0;
    return pc < 0.5 ? num / den : -num / den;
  }
  real q = pc - 0.5;
  real r = q * q;
  real num =
      (((((-3.969683028665376e+01 * r + 2.209460984245205e+02) * r - 2.759285104469687e+02) * r +
         1.383577518672690e+02) *
            r -
        3.066479806614716e+01) *
           r +
       2.506628277459239e+00) *
      q;
  real den =
      ((((-5.447609879822406e+01 * r + 1.615858368580409e+02) * r - 1.556989798598866e+02) * r +
        6.680131188771972e+01) *
           r -
       1.328068155288572e+01) *
          r +
      1.0;
  return num / den;
}
