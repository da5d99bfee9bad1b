#!/usr/bin/env python3
"""Decode fma.frag: which multiply-adds a renderer fused into one rounding, per band.

usage: decode_fma.py [fma2] LABEL=IMG.png ...   (fma.frag's image, or fma2.frag's)
For every band, each candidate model's result is computed exactly (every value here is exact in
float64, so float64 arithmetic rounded once to float32 is the fused operation) and compared with the
image's r * 2^24 mod 65536 (mod 256 in band 3) on the samples where the candidates differ.
Needs numpy and PIL (Debian 12: python3-numpy, python3-pil).
"""
import sys

import numpy as np
from PIL import Image

f32, f64 = np.float32, np.float64


def load(path):
    a = np.asarray(Image.open(path).convert("RGBA"), dtype=np.int64)
    n = np.rint(a[::-1] / 17.0).astype(np.int64)  # row index = floor(gl_FragCoord.y)
    return n


def r32(x):
    """One rounding to float32 (x exact in float64)."""
    return np.asarray(x, dtype=f64).astype(f32).astype(f64)


def inputs():
    u = np.tile(np.arange(256, dtype=f64), (32, 1))
    v = (1 + 8 * np.arange(32, dtype=f64))[:, None] + 0 * u
    s = 2.0 ** -12
    return u, v, 1 + u * s, 1 + v * s, 1 + (u + v) * s, s


def candidates(band):
    """{model: r} for one band; 'fused' is one rounding of each multiply-add the band names."""
    u, v, a, b, P, s = inputs()
    ab = a * b  # exact in float64
    if band in (0, 1, 3, 4, 5, 6, 7, 8, 9, 10, 12):
        return {"fused": r32(ab - P), "unfused": r32(r32(ab) - P)}
    if band == 2:
        return {"fused": r32(P - ab), "unfused": r32(P - r32(ab))}
    if band == 11:  # mix(x, y, t) with x = -P, y = a - P, t = b
        x, y, t = -P, a - P, b
        return {"x+(y-x)*t fused": r32(x + (y - x) * t), "x+(y-x)*t unfused": r32(x + r32((y - x) * t)),
                "x*(1-t)+y*t": r32(r32(x * (1 - t)) + r32(y * t))}
    if band in (13, 14):
        cx, cy = -(u - v) * 2 * s, -2 * P
        if band == 14:
            return {"fused": r32(2 * ab + cy), "unfused": r32(r32(2 * ab) + cy)}
        xx, yy = a * a, b * b
        return {"fma(x,x,-y*y)": r32(r32(xx - r32(yy)) + cx), "fma(-y,y,x*x)": r32(r32(r32(xx) - yy) + cx),
                "unfused": r32(r32(r32(xx) - r32(yy)) + cx)}
    a2, b2 = -(1 + (u + 1) * s), b  # a*b exact where u is even, a2*b2 where u is odd
    p, q = a * b, a2 * b2
    return {"fma(a,b,a2*b2)": r32(p + r32(q)), "fma(a2,b2,a*b)": r32(r32(p) + q), "unfused": r32(r32(p) + r32(q)),
            "(a+a2)*b": r32((a + a2) * b)}


def candidates2(band):
    """fma2.frag's bands: {model: r}, or a pair of such for the two-result bands 0-3."""
    u, v, a, b, P, s = inputs()
    ab, Q = a * b, P + s
    fu = {"fused": r32(ab - P), "unfused": r32(r32(ab) - P)}
    if band in (0, 1):
        return [fu, {"fused": r32(ab - Q), "unfused": r32(r32(ab) - Q)}]
    if band == 2:
        return [fu, {"fused": r32(ab - P), "unfused": r32(r32(ab) - P)}]
    if band == 3:
        return [fu, {"q*2 fused": r32(ab - P), "unfused": r32(r32(ab) - P)}]
    if band in (4, 5, 11, 15):
        return fu
    if band in (6, 7, 8):
        return {"fused": r32(2 * ab - 2 * P), "unfused": r32(r32(2 * ab) - 2 * P)}
    if band == 9:
        return {"fused": 2 * r32(0.5 * ab - 0.5 * P), "unfused": 2 * r32(r32(0.5 * ab) - 0.5 * P)}
    if band == 10:
        return {"fused": r32(3 * ab - 3 * P), "unfused": r32(r32(3 * ab) - 3 * P), "(a*b)*3": r32(r32(3 * r32(ab)) - 3 * P)}
    if band == 12:
        return {"fused": r32(2 * (ab - P)), "unfused": r32(2 * (r32(ab) - P))}
    return {"fused": r32(P - ab), "unfused": r32(P - r32(ab))}


NAMES2 = ["two subtractions", "two subtractions, other order", "p - P and (p - 1) - (u+v)/4096",
          "p - P and (p*0.5)*2 - P", "compare first, then p - P", "a*b - P inside one block", "t = 2a; t*b - 2P",
          "a*(2b) - 2P", "(a*b)*2 - 2P", "(a/2)*b - P/2", "(3a)*b - 3P", "x*y - z in a function",
          "(a*b - P) * 2", "-(a*b) + P", "a*(-b) + P", "a*b - P (control)"]

NAMES = ["a*b - c", "a*b + c", "c - a*b", "one product, two adds", "an add and a compare",
         "the add in another block", "dot2, product first", "dot2, product second", "dot3, product last",
         "dot4, product first", "mat2 * vec2", "mix(x, y, t)", "vec3 mul + add", "mandelbrot x*x - y*y + cx",
         "mandelbrot 2*x*y + cy", "a*b + a2*b2"]


def report(band, name, got, cands, mod, tag):
    cands = {k: np.mod(np.rint(r * 2.0 ** 24).astype(np.int64), mod) for k, r in cands.items()}
    vals = list(cands.values())
    differ = np.zeros(got.shape, bool)
    for w in vals[1:]:
        differ |= w != vals[0]
    shares = ", ".join(f"{k} {100 * np.mean(w[differ] == got[differ]):.1f}%" for k, w in cands.items())
    print(f"  {band:2d} {name}{tag}: {shares} of {differ.sum()} samples where they differ")


def decode(path, second):
    n = load(path)
    for band, name in enumerate(NAMES2 if second else NAMES):
        rows = n[32 * band: 32 * band + 32]
        cands = candidates2(band) if second else candidates(band)
        if isinstance(cands, list) or band == 3:
            pairs = cands if isinstance(cands, list) else [cands, cands]
            for i, c in enumerate(pairs):
                got = (rows[..., 2 * i] << 4) | rows[..., 2 * i + 1]
                report(band, name, got, c, 256, f" (result {i + 1})")
        else:
            got = (rows[..., 0] << 12) | (rows[..., 1] << 8) | (rows[..., 2] << 4) | rows[..., 3]
            report(band, name, got, cands, 65536, "")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    second = sys.argv[1] == "fma2"
    for arg in sys.argv[1 + second:]:
        label, path = arg.split("=", 1)
        print(f"{'fma2' if second else 'fma'} {label}:")
        decode(path, second)
