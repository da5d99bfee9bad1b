#!/usr/bin/env python3
"""Fits the polynomials of ir/precise_math.h and ir/fast_math.h.

Chebyshev fits (mpmath.chebyfit, near-minimax) of smooth kernels on the
reduced ranges the functions use. Prints each polynomial's coefficients
(lowest degree first) as C++ double literals, and the fit's absolute error
(the kernels are close to 1 on their ranges, so it is also the relative one).
Run: python3 tools/mathfit/fit.py
"""
import mpmath as mp

mp.mp.dps = 40
TAN_PI_8 = mp.tan(mp.pi / 8)
S_MAX = 3 - 2 * mp.sqrt(2)  # |(m-1)/(m+1)| for m in [sqrt(2)/2, sqrt(2)]
MARGIN = mp.mpf("1.0001")  # the reduced argument may overshoot by a rounding


def safe(f, at_zero):
    return lambda z: at_zero if z == 0 else f(z)


KERNELS = {
    # 2^r on |r| <= 1/2 (exp2: x = k + r).
    "exp2": (lambda r: mp.power(2, r), [-0.5 * MARGIN, 0.5 * MARGIN], 9),
    # log2(m) = s * P(s^2), s = (m-1)/(m+1): P(z) = 2 atanh(sqrt z) / (sqrt z ln 2).
    "log2": (safe(lambda z: 2 * mp.atanh(mp.sqrt(z)) / (mp.sqrt(z) * mp.log(2)), 2 / mp.log(2)),
             [0, (S_MAX * MARGIN) ** 2], 6),
    # sin(r) = r * P(r^2) and cos(r) = P(r^2) on |r| <= pi/4.
    "sin": (safe(lambda z: mp.sin(mp.sqrt(z)) / mp.sqrt(z), 1), [0, (mp.pi / 4 * MARGIN) ** 2], 5),
    "cos": (lambda z: mp.cos(mp.sqrt(z)), [0, (mp.pi / 4 * MARGIN) ** 2], 6),
    # atan(u) = u * P(u^2) on |u| <= tan(pi/8).
    "atan": (safe(lambda z: mp.atan(mp.sqrt(z)) / mp.sqrt(z), 1), [0, (TAN_PI_8 * MARGIN) ** 2], 8),
}

FAST_KERNELS = {
    # float-only kernels for Fast mode: fewer terms, ~1e-7 relative.
    "fast_exp2": (lambda r: mp.power(2, r), [-0.5, 0.5], 5),
    "fast_log2": (safe(lambda z: 2 * mp.atanh(mp.sqrt(z)) / (mp.sqrt(z) * mp.log(2)), 2 / mp.log(2)),
                  [0, S_MAX ** 2], 3),
    "fast_sin": (safe(lambda z: mp.sin(mp.sqrt(z)) / mp.sqrt(z), 1), [0, (mp.pi / 4 * MARGIN) ** 2], 3),
    "fast_cos": (lambda z: mp.cos(mp.sqrt(z)), [0, (mp.pi / 4 * MARGIN) ** 2], 4),
}


def main():
    for table in (KERNELS, FAST_KERNELS):
        for name, (f, interval, degree) in table.items():
            poly, err = mp.chebyfit(f, interval, degree + 1, error=True)
            coeffs = list(reversed(poly))  # chebyfit gives the highest degree first
            print(f"// {name}: degree {degree}, max abs error {mp.nstr(err, 3)} (2^{mp.nstr(mp.log(err, 2), 4)})")
            print(", ".join(repr(float(c)) for c in coeffs))


if __name__ == "__main__":
    main()
