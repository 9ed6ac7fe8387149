#!/usr/bin/env python3
"""Chebyshev coefficients of the kernel's erfc (src/kernel/special.glsl).

Following Shepherd and Laframboise (1981), "Chebyshev approximation of (1 + 2x) exp(x^2)
erfc x in 0 <= x < infinity", Math. Comp. 36(153), 249-253: the function
    y(x) = (1 + 2x) exp(x^2) erfc(x)
is smooth and bounded on [0, inf) (from 1 at x = 0 to 2 / sqrt(pi)), and so is its
expansion in Chebyshev polynomials of t = (x - K) / (x + K). erfc(x) = exp(-x^2) y(x) /
(1 + 2x) then costs one exponential and a Clenshaw sum, in GLSL as in C++.

y is evaluated here in 80-digit decimal arithmetic (the Taylor series of erf below x = 3,
the continued fraction of erfc above), the coefficients come from the discrete Chebyshev
transform on N nodes, and the expansion is truncated where its terms fall below 1e-18.
Run: python3 tools/erfc_chebyshev.py   (prints the GLSL constant array).
"""
from decimal import Decimal as D, getcontext

getcontext().prec = 80
K = D("3.75")
PI = D("3.14159265358979323846264338327950288419716939937510582097494459230781640628620899")
SQRT_PI = PI.sqrt()


def erfc_series(x):
    # erf(x) = 2/sqrt(pi) sum (-1)^n x^(2n+1) / (n! (2n+1))
    term = x
    s = x
    n = 0
    x2 = x * x
    while True:
        n += 1
        term = -term * x2 / n
        add = term / (2 * n + 1)
        s += add
        if abs(add) < D(10) ** -75:
            break
    return 1 - 2 / SQRT_PI * s


def cf_scaled(x):
    # exp(x^2) erfc(x) = 1/sqrt(pi) * 1/(x + (1/2)/(x + 1/(x + (3/2)/(x + 2/(x + ...)))))
    # evaluated bottom-up with enough terms.
    n = 400
    f = x
    for k in range(n, 0, -1):
        f = x + D(k) / 2 / f
    return 1 / (SQRT_PI * f)


def y(x):
    if x < 3:
        return (1 + 2 * x) * (x * x).exp() * erfc_series(x)
    return (1 + 2 * x) * cf_scaled(x)


def dcos(a):
    # cos in decimal arithmetic (Taylor series after reduction to [-pi, pi]).
    two_pi = 2 * PI
    a = a - two_pi * (a / two_pi).to_integral_value()
    term = D(1)
    s = D(1)
    n = 0
    while True:
        n += 2
        term = -term * a * a / (n * (n - 1))
        s += term
        if abs(term) < D(10) ** -78:
            return s


def coefficients(N=120):
    nodes = [dcos(PI * (j + D("0.5")) / N) for j in range(N)]
    vals = []
    for t in nodes:
        x = K * (1 + t) / (1 - t)
        vals.append(y(x))
    c = []
    for k in range(N):
        s = D(0)
        for j in range(N):
            s += vals[j] * dcos(PI * k * (j + D("0.5")) / N)
        c.append(2 * s / N)
    c[0] /= 2
    return c


if __name__ == "__main__":
    c = coefficients()
    last = max(k for k in range(len(c)) if abs(c[k]) > D("1e-18"))
    c = c[: last + 1]
    print(f"// {len(c)} coefficients, K = {K}")
    for v in c:
        print(f"    {float(v):.17g},")
