"""The polynomial coefficients of `crates/numeric/src/lane_power.rs`, fitted again.

Chebyshev interpolants (mpmath's `chebyfit`, 120-bit arithmetic; near-minimax) of the two
series' tails over the reduced ranges, rounded to doubles, with their largest error weighted
by the factor the code multiplies them with (s^3, r^3), on 3000 points:

* ln m = 2 atanh s = 2s + s^3 Q(s^2), Q(u) = 2 (atanh(sqrt u)/sqrt u - 1)/u (Abramowitz &
  Stegun 4.1.27 for the series), u in [0, 0.0294373] (s at m = sqrt 2: (sqrt2-1)/(sqrt2+1));
* e^r = 1 + r + r^2/2 + r^3 P(r), P(r) = (e^r - 1 - r - r^2/2)/r^3 (A&S 4.2.1), r in
  [-0.34658, 0.34658] (ln 2 / 2 and the rounding of n).

Run: python3 crates/numeric/tools/fit_lane_power.py (needs mpmath).
"""
from mpmath import mp, mpf, atanh, sqrt, exp, chebyfit, linspace

mp.prec = 120
U = mpf("0.0294373")
R = mpf("0.34658")


def q(u):
    if u == 0:
        return mpf(2) / 3
    s = sqrt(u)
    return 2 * (atanh(s) / s - 1) / u


def p(r):
    if abs(r) < mpf("1e-12"):
        return mpf(1) / 6 + r / 24
    return (exp(r) - 1 - r - r * r / 2) / r**3


def fit(name, f, a, b, n, weight):
    coeffs, _ = chebyfit(f, [a, b], n, error=True)
    doubles = [float(c) for c in coeffs]  # highest degree first
    worst = 0
    for x in linspace(a, b, 3000):
        v = mpf(0)
        for c in doubles:
            v = v * x + mpf(c)
        worst = max(worst, abs(v - f(x)) * weight(x))
    print(f"{name}: {n} coefficients, weighted error {float(worst):.3e}")
    for c in reversed(doubles):  # constant first, as the code's `horner` takes them
        print(f"    {c!r},")


fit("ln tail Q(u)", q, 0, U, 8, lambda u: sqrt(u) ** 3)
fit("exp tail P(r)", p, -R, R, 10, lambda r: abs(r) ** 3)
