// The real roots in (0, 1) of a polynomial of degree 6 (step 3 of kernel/reference.glsl:
// where the reference's gradient path crosses the light's rim or the horizon): the roots
// are isolated by Bernstein subdivision (the coefficients' sign changes bound the roots in
// an interval: none, exactly one, or split; at most 24 halvings) and refined by Newton
// steps kept inside the bracket, to 1e-12 of the interval in double and 2e-6 in float.

// A polynomial of degree 6 in s, power basis: c[0] + c[1] s + ... + c[6] s^6.
struct Poly6 {
  real c[7];
};

SG_FN real poly6_eval(IN(Poly6) p, real s) {
  real r = p.c[6];
  for (int k = 5; k >= 0; --k)
    r = r * s + p.c[k];
  return r;
}

SG_FN real poly6_derivative(IN(Poly6) p, real s) {
  real r = 6.0 * p.c[6];
  for (int k = 5; k >= 1; --k)
    r = r * s + real(k) * p.c[k];
  return r;
}

// C(k, j) / C(6, j) for j <= k: power-basis to Bernstein coefficients of degree 6.
const real kPowerToBernstein6[49] =
    SG_ARRAY(real, 49,
             (1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,                                     //
              1.0, 1.0 / 6.0, 0.0, 0.0, 0.0, 0.0, 0.0,                               //
              1.0, 2.0 / 6.0, 1.0 / 15.0, 0.0, 0.0, 0.0, 0.0,                        //
              1.0, 3.0 / 6.0, 3.0 / 15.0, 1.0 / 20.0, 0.0, 0.0, 0.0,                 //
              1.0, 4.0 / 6.0, 6.0 / 15.0, 4.0 / 20.0, 1.0 / 15.0, 0.0, 0.0,          //
              1.0, 5.0 / 6.0, 10.0 / 15.0, 10.0 / 20.0, 5.0 / 15.0, 1.0 / 6.0, 0.0,  //
              1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0));

// The Bernstein coefficients of p restricted to [a, b] (p(a + (b - a) s), s in [0, 1]):
// a Taylor shift by a (repeated synthetic division), a scaling by b - a, then the basis
// change.
SG_FN Poly6 poly6_bernstein(IN(Poly6) p, real a, real b) {
  Poly6 q = p;
  for (int i = 0; i < 6; ++i) {
    for (int j = 5; j >= i; --j)
      q.c[j] += a * q.c[j + 1];
  }
  real w = b - a;
  real scale = 1.0;
  for (int j = 0; j <= 6; ++j) {
    q.c[j] *= scale;
    scale *= w;
  }
  Poly6 r;
  for (int k = 0; k <= 6; ++k) {
    real sum = 0.0;
    for (int j = 0; j <= k; ++j)
      sum += kPowerToBernstein6[k * 7 + j] * q.c[j];
    r.c[k] = sum;
  }
  return r;
}

// Sign changes of the coefficients (zero counted as positive).
SG_FN int sign_changes(IN(Poly6) b) {
  int n = 0;
  for (int k = 0; k < 6; ++k)
    n += (b.c[k] >= 0.0) != (b.c[k + 1] >= 0.0) ? 1 : 0;
  return n;
}

SG_FN real root_tolerance_s() {
  return kDoublePrecision ? 1e-12 : 2e-6;
}

// The root of p in [a, b], where p(a) and p(b) have opposite signs (fa = p(a)): Newton
// steps kept inside the shrinking bracket, bisection where a step leaves it.
SG_FN real poly6_refine(IN(Poly6) p, real a, real b, real fa) {
  real lo = a;
  real hi = b;
  bool lo_positive = fa >= 0.0;
  real x = 0.5 * (a + b);
  for (int it = 0; it < 64; ++it) {
    real fx = poly6_eval(p, x);
    if ((fx >= 0.0) == lo_positive) {
      lo = x;
    } else {
      hi = x;
    }
    real dfx = poly6_derivative(p, x);
    real next = dfx != 0.0 ? x - fx / dfx : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    real step = abs(next - x);
    x = next;
    if (step <= root_tolerance_s() || hi - lo <= root_tolerance_s()) break;
  }
  return x;
}

// The roots of p in (0, 1), increasing: Bernstein subdivision over the binary tree of
// dyadic intervals, depth first without a stack (interval index i at depth d is
// [i 2^-d, (i + 1) 2^-d]).
const int kMaxSubdivisionDepth = 24;
const int kMaxSubdivisionSteps = 512;

struct Roots6 {
  real s[6];
  int count;
};

SG_FN Roots6 poly6_roots(IN(Poly6) p) {
  Roots6 r;
  r.count = 0;
  for (int k = 0; k < 6; ++k)
    r.s[k] = 0.0;
  int d = 0;
  int i = 0;
  for (int step = 0; step < kMaxSubdivisionSteps; ++step) {
    real inv = 1.0 / real(1 << d);
    real a = real(i) * inv;
    real b = real(i + 1) * inv;
    Poly6 bz = poly6_bernstein(p, a, b);
    // The end coefficients are p(a) and p(b): evaluated as such, so that neighbouring
    // intervals agree on the sign at their shared end (a root there is counted once).
    bz.c[0] = poly6_eval(p, a);
    bz.c[6] = poly6_eval(p, b);
    int changes = sign_changes(bz);
    bool split = false;
    if (changes == 1 || (changes > 1 && d == kMaxSubdivisionDepth)) {
      // Exactly one root (one sign change); at the depth limit an odd number of sign
      // changes between the ends counts as one, an even number as none (a tangency).
      bool ends_differ = (bz.c[0] >= 0.0) != (bz.c[6] >= 0.0);
      if (ends_differ && r.count < 6) {
        r.s[r.count] = changes == 1 ? poly6_refine(p, a, b, bz.c[0])
                                    : a - bz.c[0] * (b - a) / (bz.c[6] - bz.c[0]);
        r.count += 1;
      }
    } else if (changes > 1) {
      split = true;
    }
    if (split) {
      d += 1;
      i *= 2;
      continue;
    }
    while (d > 0 && (i % 2) == 1) {
      i /= 2;
      d -= 1;
    }
    if (d == 0) break;
    i += 1;
  }
  return r;
}
