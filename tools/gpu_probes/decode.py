#!/usr/bin/env python3
"""Decode the GPU probes of this folder (rendered by run_gpu.sh, or by glslrun/glref on the CPU).

usage: decode.py texfilter|lod|lodrand|lod3d|texkinds|tex3dw|blendover|mipgen|cube|funcs2 LABEL=IMG.png ...
       decode.py textured LABEL=DIR   (textured_texel, _lod, _s, _t from run_gpu.sh in DIR)
       decode.py trilin|trimp LABEL=DIR   (trilin_w, _1 .. _4 / trimp_l*_m*_w* from run_gpu.sh in DIR)
       decode.py trigrad LABEL=IMG.png
Needs numpy and PIL (Debian 12: python3-numpy, python3-pil).
"""
import sys

import numpy as np
from PIL import Image

HERE = __file__.rsplit("/", 1)[0] if "/" in __file__ else "."
f32 = np.float32


def load(path):
    a = np.asarray(Image.open(path).convert("RGBA"), dtype=np.int64)
    return a[::-1]  # row index = floor(gl_FragCoord.y)


def dec16(a):
    n = np.rint(a / 17.0).astype(np.int64)
    return (n[..., 0] << 12) | (n[..., 1] << 8) | (n[..., 2] << 4) | n[..., 3]


def band(a, b):
    return a[64 * b: 64 * b + 64].reshape(-1)  # sample i = (y mod 64) * 512 + x


I = np.arange(32768)


def steps(x, w):
    """Where w (the measured weight in 1/65536) changes as x (the exact position) grows: the thresholds."""
    ch = np.nonzero(np.diff(w))[0]
    return [(float(x[c + 1]), int(w[c]), int(w[c + 1])) for c in ch]


def weight_rule(x, w, label):
    """x: exact fraction in texels (float64), w: measured weight * 65536. Fit w = q(x * 256) / 256."""
    x256 = x * 256.0
    models = {
        "exact": np.rint(x * 65536),
        "floor8": np.floor(x256) * 256,
        "round8": np.floor(x256 + 0.5) * 256,
        "round8_tiesdown": np.ceil(x256 - 0.5) * 256,
        "floor9": np.floor(x * 512) * 128,
    }
    res = ", ".join(f"{k} {100 * np.mean(v == w):.2f}%" for k, v in models.items())
    print(f"  {label}: weights {len(np.unique(w))} distinct; {res}")
    st = steps(x, w)
    print(f"    first steps (x where the weight changes, old, new): {st[:4]} ... {st[-2:]}")


def texfilter(images):
    for label, path in images:
        a = dec16(load(path))
        print(f"texfilter {label}:")
        weight_rule(I / 32768.0, band(a, 0), "2x1 along s (u = 0.5 + i/32768)")
        weight_rule(I / 32768.0, 65536 - band(a, 1), "64x1 (u = 31.5 + i/32768)")
        s = ((f32(2047.5) + (I / 32768.0).astype(f32)).astype(f32) / f32(4096)).astype(f32)
        u = s.astype(np.float64) * 4096
        weight_rule(u - 2047.5, 65536 - band(a, 2), "4096x1 (u = 2047.5 + i/32768, rounded)")
        weight_rule(I / 32768.0, band(a, 6), "1x2 along t")
        # NEAREST: which texel at u = 128 + (i - 16384) / 65536
        u = 128 + (I - 16384) / 65536.0
        k = np.rint(band(a, 3) * 255 / 65536.0)
        low = u[k == 128].min() if (k == 128).any() else None
        print(f"  NEAREST 256x1: texel 128 from u = {low!r} (floor(u): from 128.0); texels seen {np.unique(k)}")
        # band 7: u = -0.5 + i/16384 on 2 texels, CLAMP_TO_EDGE: the weight of texel 1 is clamp(u, 0.5, 1.5) - 0.5
        u = -0.5 + I / 16384.0
        w = band(a, 7)
        x = np.clip(u, 0.5, 1.5) - 0.5
        weight_rule(x, w, "2x1 CLAMP_TO_EDGE over u in [-0.5, 1.5)")


def quads(a, b):
    """Band b's quads: the four pixels' values, shape (8192, 4), q = (yb / 2) * 256 + x / 2."""
    blk = a[64 * b: 64 * b + 64].reshape(32, 2, 256, 2).transpose(0, 2, 1, 3).reshape(8192, 4)
    return blk


Q = np.arange(8192)


def lod_report(lam, f, label):
    """lam: the exact lambda (float64), f: the measured blend (15 v): its fraction against frac(lambda)."""
    fr = lam - np.floor(lam)
    err = f - fr
    print(f"  {label}: measured - exact frac(lambda): mean {err.mean():+.5f}, min {err.min():+.5f}, max {err.max():+.5f}; "
          f"distinct blends {len(np.unique(np.round(f * 65536)))}")
    for name, m in [("floor8", np.floor(fr * 256) / 256), ("round8", np.floor(fr * 256 + 0.5) / 256)]:
        print(f"    {name}(frac lambda): {100 * np.mean(np.abs(f - m) < 1.01 / 65536):.2f}% within 1/65536")
    st = steps(lam, np.round(f * 65536).astype(np.int64))
    print(f"    first steps (lambda where the blend changes, old, new /65536): {st[:5]}")


def classify(v15):
    return np.where(np.abs(v15 - 7.5) < 0.01, "mag", np.where(np.abs(v15) < 0.01, "L0", np.where(np.abs(v15 - 1) < 0.01, "L1", "mix")))


def lod(images):
    for label, path in images:
        img = load(path)
        a = dec16(img) * 15 / 65536.0
        g = dec16(img) / 65536.0
        print(f"lod {label}:")
        x = 1 + Q / 8192.0
        for b, m, extra, what in [(0, 1, 0, "LINEAR_MIPMAP_LINEAR, rho = 256 a"), (1, 2, 0, "the same, rho in [2, 4)"),
                                  (2, 1, 0.5, "s and t step along x (sqrt 2 * rho if the spec's length)"),
                                  (3, 1, 0, "t steps 3/4 a along y (max of the two lengths)")]:
            qv = quads(g, b)
            same = np.all(qv == qv[:, :1], axis=1).mean()
            lam = np.log2(x * m) + extra
            odd = np.floor(lam) % 2 == 1  # level k's green is k mod 2: the blend from k to k + 1 falls there
            lod_report(lam, np.where(odd, 1 - qv[:, 0], qv[:, 0]), f"band {b}, {what} (quads with 4 equal pixels: {100 * same:.1f}%)")
        qv = quads(g, 4)  # pixels (0,0), (1,0), (0,1), (1,1) of each quad
        lam0 = np.log2(x)
        for p, extra in enumerate([0, 0, 1, 1]):
            lam = lam0 + extra
            odd = np.floor(lam) % 2 == 1
            lod_report(lam, np.where(odd, 1 - qv[:, p], qv[:, p]), f"band 4, quad pixel {p}: fine derivatives give lambda + {extra}")
        for b, what in [(5, "NEAREST_MIPMAP_NEAREST, mag LINEAR, lambda in [0, 1)"),
                        (6, "NEAREST_MIPMAP_LINEAR, mag LINEAR, lambda in [0, 1)"), (7, "LINEAR_MIPMAP_NEAREST, lambda in [0, 1)")]:
            lam = np.log2(x * (0.5 if b == 4 else 1))
            c = classify(quads(a, b)[:, 0])
            runs = []
            for k in range(len(c)):
                if not runs or runs[-1][0] != c[k]:
                    runs.append([c[k], lam[k], lam[k]])
                runs[-1][2] = lam[k]
            print(f"  band {b}, {what}: " + "; ".join(f"{r[0]} lambda {r[1]:.6f}..{r[2]:.6f}" for r in runs[:8])
                  + (" ..." if len(runs) > 8 else ""))


def gpu_unorm8(v):
    """NVIDIA's float-to-UNORM8 store (docs/precision.md): 12 fraction bits, then nearest, ties down."""
    t = np.floor(v.astype(np.float64) * 4096)
    return np.ceil(t * 255 / 4096 - 0.5)


def texture_levels(img, rows, n):
    """The levels a mipgen image shows for one texture of size n: {L: array (w, w, 4)}, t up."""
    out = {}
    L, w = 1, n // 2
    while w >= 1:
        x0 = n - 2 * w
        out[L] = img[rows: rows + w, x0: x0 + w]
        L, w = L + 1, w // 2
    return out


def mip_models(above):
    """Candidate rules for one 2x2 box step: above (2w, 2w, 4) bytes -> (w, w, 4)."""
    s = above[0::2, 0::2] + above[1::2, 0::2] + above[0::2, 1::2] + above[1::2, 1::2]
    mean = s / 4.0
    f32mean = ((above[0::2, 0::2] / 255.0 + above[1::2, 0::2] / 255.0 + above[0::2, 1::2] / 255.0
                + above[1::2, 1::2] / 255.0) / 4).astype(np.float32)
    return {
        "round half even (glslrun)": np.rint(mean),
        "round half up": np.floor(mean + 0.5),
        "round half down": np.ceil(mean - 0.5),
        "truncate": np.floor(mean),
        "gpu_unorm8(mean / 255)": gpu_unorm8(f32mean),
        "two linear steps, gpu_unorm8": None,
    }


def mipgen(images):
    from PIL import Image as _I
    here = HERE
    base = {"rand128": (0, 128, np.asarray(_I.open(f"{here}/rand128.png").convert("RGBA"), dtype=np.int64)[::-1]),
            "wood": (64, 64, np.asarray(_I.open(f"{here}/../../scenes/textures/wood.png").convert("RGBA"), dtype=np.int64)[::-1])}
    for label, path in images:
        img = load(path)
        print(f"mipgen {label}:")
        for name, (rows, n, lvl0) in base.items():
            lv = texture_levels(img, rows, n)
            lv[0] = lvl0
            for L in sorted(k for k in lv if k >= 1):
                above, got = lv[L - 1], lv[L]
                if above.shape[0] < 2:
                    continue
                ms = mip_models(above)
                res = []
                for k, m in ms.items():
                    if m is None:
                        continue
                    res.append(f"{k} {100 * np.mean(m == got):.2f}%")
                print(f"  {name} level {L} ({got.shape[0]}x{got.shape[1]}) from the measured level {L - 1}: " + ", ".join(res))
                if L == 1:
                    s = (above[0::2, 0::2] + above[1::2, 0::2] + above[0::2, 1::2] + above[1::2, 1::2])
                    for r in range(4):
                        m = (s % 4) == r
                        d = got[m] - np.floor(s[m] / 4)
                        print(f"    sum mod 4 = {r}: byte - floor(sum/4): " + ", ".join(
                            f"{int(x)}: {int(c)}" for x, c in zip(*np.unique(d, return_counts=True))))


F2 = [("sin(x), x in [0.5, 1.5)", np.sin, lambda i: 0.5 + i / 32768.0),
      ("cos(x), x in [0, 1)", np.cos, lambda i: i / 32768.0),
      ("sin(x), x in [2, 3)", np.sin, lambda i: 2.0 + i / 32768.0),
      ("cos(x), x in [4, 6)", np.cos, lambda i: 4.0 + i / 16384.0),
      ("exp(x), x in (-1, 0]", np.exp, lambda i: -i / 32768.0),
      ("log(x), x in [1.75, 2.75)", np.log, lambda i: 1.75 + i / 32768.0),
      ("sin(x), x in [64, 192)", np.sin, lambda i: 64.0 + i / 256.0),
      ("cos(x), x in (-192, -64]", np.cos, lambda i: -64.0 - i / 256.0)]


def funcs2(images):
    """The absolute error in units of 2^-24, from the low 12 bits of y * 2^24 (mod 4096)."""
    for label, path in images:
        img = load(path)
        n = np.rint(img / 17.0).astype(np.int64)
        got = (n[..., 2] << 8) | (n[..., 1] << 4) | n[..., 0]  # bits 2^-13 .. 2^-24 of y
        print(f"funcs2 {label}: absolute error in units of 2^-24 (mean, min, max)")
        for b, (name, fn, arg) in enumerate(F2):
            x = arg(I.astype(np.float64)).astype(np.float32).astype(np.float64)
            want = np.floor(np.mod(fn(x) * 2.0 ** 24, 4096.0))
            e = np.mod(band(got[..., None], b)[:, 0] if False else got[64 * b: 64 * b + 64].reshape(-1) - want + 2048, 4096) - 2048
            print(f"  {name}: {e.mean():+.2f}, {int(e.min()):+d}, {int(e.max()):+d}")


QUANT = {
    "exact": lambda a: a,
    "floor8": lambda a: np.floor(a * 256) / 256,
    "round8": lambda a: np.floor(a * 256 + 0.5) / 256,
}


def lin_axis_repeat(s, n, q):
    """LINEAR under REPEAT: indices and the weight, with the weight rule q (QUANT)."""
    s = s.astype(np.float32)
    u = ((s - np.floor(s)) * np.float32(n) - np.float32(0.5)).astype(np.float32)
    i0 = np.floor(u).astype(np.int64)
    a = (u - np.floor(u)).astype(np.float32)
    a = q(a.astype(np.float64)).astype(np.float32)
    return i0 % n, (i0 + 1) % n, a


def mix32(x, y, a):
    x = x.astype(np.float32); y = y.astype(np.float32); a = a.astype(np.float32)
    return (x * (np.float32(1) - a) + y * a).astype(np.float32)


def bilinear_band(img, band_index, channel, label):
    """Bands 4, 5 of texfilter: the 16x16 random texture at exact (s, t), models of the blend."""
    tex = np.asarray(Image.open(f"{HERE}/rand16.png").convert("RGBA"), dtype=np.int64)[::-1]  # row j = t
    texf = (tex[..., channel] / 255.0).astype(np.float32)
    X = np.tile(np.arange(512), 64); yb = np.repeat(np.arange(64), 512)
    s = (X / 512.0 + yb / 32768.0).astype(np.float32)
    t = (yb / 64.0 + X / 16384.0).astype(np.float32)
    got = band(img, band_index)
    res = []
    for name, q in QUANT.items():
        x0, x1, ax = lin_axis_repeat(s, 16, q)
        y0, y1, ay = lin_axis_repeat(t, 16, q)
        r0 = mix32(texf[y0, x0], texf[y0, x1], ax)
        r1 = mix32(texf[y1, x0], texf[y1, x1], ax)
        v = mix32(r0, r1, ay)
        e = np.mod(np.floor(v.astype(np.float64) * 65536 + 0.5), 65536)
        diff = (got - e + 32768) % 65536 - 32768
        res.append(f"{name}: {100 * np.mean(diff == 0):.2f}% exact, |d| <= 1: {100 * np.mean(np.abs(diff) <= 1):.2f}%, max |d| {np.abs(diff).max()}")
        if name != "exact":
            # fixed point: the four texels' bytes times the 8-bit weights, exact
            wx = np.rint(ax.astype(np.float64) * 256); wy = np.rint(ay.astype(np.float64) * 256)
            tb = tex[..., channel]
            acc = (tb[y0, x0] * (256 - wx) + tb[y0, x1] * wx) * (256 - wy) + (tb[y1, x0] * (256 - wx) + tb[y1, x1] * wx) * wy
            vf = acc / (65536.0 * 255.0)
            e2 = np.mod(np.floor(vf * 65536 + 0.5), 65536)
            d2 = (got - e2 + 32768) % 65536 - 32768
            res.append(f"{name} exact products: {100 * np.mean(d2 == 0):.2f}% exact, max |d| {np.abs(d2).max()}")
    print(f"  {label}:\n    " + "\n    ".join(res))


def texfilter2d(images):
    for label, path in images:
        a = dec16(load(path))
        print(f"texfilter 2D {label}:")
        bilinear_band(a, 4, 0, "16x16 random, red")
        bilinear_band(a, 5, 1, "16x16 random, green")


def cube(images):
    """The +X face's weight of the white column, against s = (sc / ma + 1) / 2 computed in float."""
    mas = [1.0, 3.0, 5.0, 7.0, 11.0, 13.0, 0.75, 2.0]
    for label, path in images:
        a = dec16(load(path))
        print(f"cube {label}: per |ma|, the measured weight against models of s (the weight rule applied to each)")
        for b, ma in enumerate(mas):
            ma32 = np.float32(ma)
            sc = (ma32 * (I / 32768.0).astype(np.float32) - ma32 * np.float32(0.5)).astype(np.float32)
            got = band(a, b)
            res = []
            for sname, s in [("div", (np.float32(0.5) * ((sc / ma32).astype(np.float32) + np.float32(1))).astype(np.float32)),
                             ("rcp", (np.float32(0.5) * ((sc * (np.float32(1) / ma32)).astype(np.float32) + np.float32(1))).astype(np.float32)),
                             ("rcp/2", ((sc * (np.float32(0.5) / ma32)).astype(np.float32) + np.float32(0.5)).astype(np.float32))]:
                u = (s * np.float32(2) - np.float32(0.5)).astype(np.float32)
                x = np.clip(u.astype(np.float64), 0.0, 1.0)
                for qn in ("exact", "floor8", "round8"):
                    w = np.rint(QUANT[qn](x) * 65536)
                    res.append(f"{sname}/{qn} {100 * np.mean(w == got):.2f}%")
            print(f"  |ma| = {ma}: " + ", ".join(res))


# 256 * frac(lambda) for a significand 1 + k/256 of rho (runtime/sampling_gpu.h's kLog2Fraction).
def log2_fraction_table():
    src = open(HERE + "/../../runtime/sampling_gpu.h").read()
    body = src.split("kLog2Fraction[256] = {", 1)[1].split("};", 1)[0]
    return np.array([int(v) for v in body.replace("\n", " ").split(",") if v.strip()])


def lambda_of_rho(rho, table):
    bits = np.asarray(rho, dtype=f32).view(np.uint32).astype(np.int64)
    return ((bits >> 23) - 127) + table[(bits >> 15) & 255] / 256.0


def quad_lambdas(img):
    """lodnorm/lodrand/lod3d encoding: the lambda of each quad's first pixel (level pair in red, blend in G, B, A)."""
    n = np.rint(img[..., 1:4] / 17.0).astype(np.int64)
    g = ((n[..., 0] << 8) | (n[..., 1] << 4) | n[..., 2])[0::2, 0::2] / 4096.0
    k = np.floor(img[0::2, 0::2, 0] / 17.0 + 1e-9)
    f = np.where(k % 2 == 1, (1 - g) % 1.0, g)  # level k's green is k mod 2
    return k + np.round(f * 256) / 256


def gpu_length(a, b):
    a, b = np.abs(a).astype(f32), np.abs(b).astype(f32)
    return (np.maximum(a, b) + f32(0.34375) * np.minimum(a, b)).astype(f32)


def lodrand(images):
    """Each quad's lambda against models of rho: the fraction of quads (lambda in (0, 8)) they give exactly."""
    table = log2_fraction_table()
    qy, qx = np.mgrid[0:256, 0:512]
    q = qy * 256 + qx % 256
    m = np.where(qx < 256, 1.0, 1.375)
    ux, vx, uy, vy = [((q // 16 ** j) % 16 - 7.5) * m for j in range(4)]
    models = {
        "exact: max(|J x|, |J y|)": np.maximum(np.hypot(ux, vx), np.hypot(uy, vy)),
        "max(|J x|, |J y|), |(a, b)| = max + 11/32 min": np.maximum(gpu_length(ux, vx), gpu_length(uy, vy)),
        "the same and 11/16 |J (x +- y)| (sampling_gpu.h)": np.maximum(
            np.maximum(gpu_length(ux, vx), gpu_length(uy, vy)),
            f32(0.6875) * np.maximum(gpu_length(ux + uy, vx + vy), gpu_length(ux - uy, vx - vy))),
    }
    for label, path in images:
        lam = quad_lambdas(load(path))
        valid = (lam > 0.001) & (lam < 7.99)
        print(f"lodrand {label}: quads with lambda in (0, 8): {valid.sum()}")
        for name, rho in models.items():
            ok = np.abs(lambda_of_rho(rho.astype(f32), table) - lam) < 1e-6
            print(f"  {name}: half texels {100 * ok[valid & (qx < 256)].mean():.2f}%, "
                  f"steps of 11/16 {100 * ok[valid & (qx >= 256)].mean():.2f}%")


def lod3d(images):
    """lod3d.frag: each quad's lambda against 3D models of rho (the fraction of quads with lambda in (0, 6))."""
    table = log2_fraction_table()
    qy, qx = np.mgrid[0:256, 0:512]
    q = qy * 512 + qx
    ux, vx, wx, uy, vy, wy = [((q // 7 ** j) % 7 - 3) * 1.5 for j in range(6)]

    def length3(a, b, c, mid, low):
        m = np.sort(np.abs(np.stack([a, b, c])), axis=0)
        return m[2] + mid * m[1] + low * m[0]

    def rho(mid, low, diagonals):
        axes = np.maximum(length3(ux, vx, wx, mid, low), length3(uy, vy, wy, mid, low))
        if not diagonals:
            return axes
        return np.maximum(axes, 0.6875 * np.maximum(length3(ux + uy, vx + vy, wx + wy, mid, low),
                                                    length3(ux - uy, vx - vy, wx - wy, mid, low)))
    exact = np.maximum(np.sqrt(ux ** 2 + vx ** 2 + wx ** 2), np.sqrt(uy ** 2 + vy ** 2 + wy ** 2))
    models = {"exact: max(|J x|, |J y|)": exact,
              "max + 11/32 (mid + min), axes only": rho(0.34375, 0.34375, False),
              "max + 11/32 mid + 1/4 min, with 11/16 |J (x +- y)|": rho(0.34375, 0.25, True)}
    for label, path in images:
        lam = quad_lambdas(load(path))
        valid = (q < 7 ** 6) & (lam > 0.001) & (lam < 5.99)
        print(f"lod3d {label}: quads with lambda in (0, 6): {valid.sum()}")
        for name, r in models.items():
            ok = np.abs(lambda_of_rho(np.asarray(r, dtype=f32), table) - lam) < 1e-6
            print(f"  {name}: {100 * ok[valid].mean():.2f}%")


def texkinds(images):
    """texkinds.frag: the LINEAR weights of 3D, float and depth textures (8-bit weight w: v = w / 256)."""
    x = np.arange(32768) / 32768.0
    w8 = np.floor(x * 256 + 0.5)
    unorm16 = np.floor(np.floor((65535 * w8 + 128) / 256) / 65535 * 65536 + 0.5) % 65536
    float8 = np.floor(w8 / 256 * 65536 + 0.5) % 65536
    for label, path in images:
        e = dec16(load(path))
        band32 = lambda b: e[32 * b: 32 * b + 32].reshape(-1)
        print(f"texkinds {label}:")
        for b, what in [(0, "3D along s"), (1, "3D along r"), (2, "RGBA32F along s"), (4, "depth along s"),
                        (6, "depth compared (r = 1/2) along s")]:
            v = band32(b)
            print(f"  {what}: 16-bit blend of 8-bit weights {100 * np.mean(v == unorm16):.2f}%, "
                  f"w / 256 in float {100 * np.mean(v == float8):.2f}%, exact weight "
                  f"{100 * np.mean(v == np.floor(x * 65536 + 0.5)):.2f}%")
        for b, what in [(3, "RGBA32F"), (5, "depth"), (7, "RGBA32F (1/4 | 3/4)")]:
            print(f"  {what}: bits below 2^-16 zero in {100 * np.mean(band32(b) == 0):.2f}% of the samples")
        # Band 8 (high 16 bits) and 9 (the next 16): the random RGBA32F texture's red, against its
        # texels blended with the RGBA8 rule's integer weights (w11 = round(wx wy / 256), ...) in float.
        hi, lo = e[256:288].astype(np.float64), e[288:320].astype(np.float64) / 65536.0
        v = (hi - (lo >= 0.5) + lo) / 65536.0
        texels = np.asarray(Image.open(HERE + "/rand16.png").convert("RGBA"), dtype=np.int64)[::-1, :, 0]
        texels = (texels.astype(f32) / f32(255)).astype(f32)
        yb, xx = np.mgrid[0:32, 0:1024]

        def axis(c):
            u = ((c - np.floor(c)) * f32(16) - f32(0.5)).astype(f32)
            i0 = np.floor(u).astype(np.int64)
            return i0 % 16, (i0 + 1) % 16, np.floor((u - np.floor(u)).astype(np.float64) * 256 + 0.5).astype(np.int64)
        x0, x1, wx = axis((xx / 1024.0 + yb / 32768.0).astype(f32))
        y0, y1, wy = axis((yb / 32.0 + xx / 32768.0).astype(f32))
        w11 = (wx * wy + 128) >> 8
        terms = [texels[y0, x0] * (256 - wx - wy + w11), texels[y0, x1] * (wx - w11), texels[y1, x0] * (wy - w11),
                 texels[y1, x1] * w11]
        model = ((terms[0] + terms[1]).astype(f32) + (terms[2] + terms[3]).astype(f32)).astype(f32) / f32(256)
        d = np.abs(model.astype(np.float64) - v)
        print(f"  RGBA32F 16x16 random, red: integer weights summed in float: exact (2^-31) {100 * np.mean(d < 2 ** -31):.2f}%, "
              f"within 2^-16 {100 * np.mean(d < 2 ** -16):.2f}%, largest difference {d.max():.3g}")


def textured_levels():
    """scenes/textures/wood.png and its generated levels by the GPU's rule (runtime/mipmap_gpu.cpp), bytes."""
    a = np.asarray(Image.open(HERE + "/../../scenes/textures/wood.png").convert("RGBA"), dtype=np.int64)[::-1]
    levels = [a]
    while levels[-1].shape[0] > 1:
        b = levels[-1]
        r16 = (257 * (b[0::2, 0::2] + b[1::2, 0::2] + b[0::2, 1::2] + b[1::2, 1::2]) * 64 + 128) >> 8
        t = np.floor((r16.astype(f32) / f32(65535)) * f32(4096)).astype(np.int64)
        levels.append((t * 510 + 4095) >> 13)
    return levels


def textured_bilinear(level, s, t):
    """One level's 16-bit bilinear result (red, green) under REPEAT: 8-bit weights, texels as 257 b."""
    h, w = level.shape[:2]
    u = (s - np.floor(s)).astype(f32) * f32(w) - f32(0.5)
    v = (t - np.floor(t)).astype(f32) * f32(h) - f32(0.5)
    i0, j0 = np.floor(u).astype(np.int64), np.floor(v).astype(np.int64)
    wx, wy = (QUANT["round8"](u - np.floor(u)) * 256).astype(np.int64), (QUANT["round8"](v - np.floor(v)) * 256).astype(np.int64)
    w11 = (wx * wy + 128) >> 8
    tex = lambda j, i: 257 * level[j % h, i % w][..., :2]
    total = (tex(j0, i0) * (256 - wx - wy + w11)[..., None] + tex(j0, i0 + 1) * (wx - w11)[..., None]
             + tex(j0 + 1, i0) * (wy - w11)[..., None] + tex(j0 + 1, i0 + 1) * w11[..., None])
    return (total + 128) >> 8


def textured(images):
    """textured_texel/_lod/_s/_t (one folder: LABEL=DIR): the GPU's 16-bit texels of textured_pix's trilinear
    lookup against its bilinear levels at the GPU's own coordinates and lambda (textureQueryLod)."""
    for label, d in images:
        def img(name):
            return load(f"{d}/textured_{name}.png")
        def bits(a):
            return ((a[..., 0] << 24) | (a[..., 1] << 16) | (a[..., 2] << 8) | a[..., 3]).astype(np.uint32).view(f32)
        tex, lod, s, t = img("texel"), img("lod"), bits(img("s")), bits(img("t"))
        cov = (img("s")[..., :3] != 0).any(-1)
        got = np.stack([tex[..., 0] * 256 + tex[..., 1], tex[..., 2] * 256 + tex[..., 3]], -1)[cov]
        lam = (lod[..., 0] * 256 + lod[..., 1] - 32768)[cov] / 256.0
        s, t = s[cov], t[cov]
        levels = [textured_bilinear(lv, s, t) for lv in textured_levels()]
        q = len(levels) - 1
        whole = np.clip(np.floor(lam), 0, q).astype(np.int64)
        w = ((lam - np.floor(lam)) * 256).astype(np.int64)
        stack = np.stack(levels)
        idx = np.arange(len(lam))
        first, second = stack[whole, idx], stack[np.minimum(whole + 1, q), idx]
        blend = (first * (256 - w)[:, None] + second * w[:, None] + 128) >> 8
        model = np.where((lam <= 0)[:, None], stack[0, idx], np.where((w == 0)[:, None], first, blend))
        ok = (model == got).all(-1)
        print(f"textured {label}: {cov.sum()} covered pixels")
        for name, k in (("magnified (lambda <= 0)", lam <= 0), ("one level (lambda a whole number)", (lam > 0) & (w == 0)),
                        ("trilinear blend", (lam > 0) & (w > 0))):
            print(f"  {name}: {k.sum()} pixels, the model's 16-bit texel {100 * ok[k].mean():.2f}%")
        # Is a trilinear texel a blend of two adjacent levels' results by any one weight (both channels)?
        tri = (lam > 0) & (w > 0)
        fits = np.zeros(tri.sum(), bool)
        for d1 in range(q):
            a, b = stack[d1][tri].astype(float), stack[d1 + 1][tri].astype(float)
            lo, hi = np.zeros(len(a)), np.ones(len(a))
            for c in range(2):
                diff, g = b[:, c] - a[:, c], got[tri][:, c] - a[:, c]
                with np.errstate(divide="ignore", invalid="ignore"):
                    l1, h1 = (g - 0.5) / diff, (g + 0.5) / diff
                flat = diff == 0
                lo = np.maximum(lo, np.where(flat, np.where(np.abs(g) <= 0.5, 0, 2), np.minimum(l1, h1)))
                hi = np.minimum(hi, np.where(flat, np.where(np.abs(g) <= 0.5, 1, -1), np.maximum(l1, h1)))
            fits |= lo <= hi
        print(f"  trilinear texels that any weight of two adjacent levels gives: {100 * fits.mean():.2f}%")


def floatbits(a):
    """trilin.frag / textured_raw.frag: a float's bits as four bytes, most significant first."""
    return ((a[..., 0] << 24) | (a[..., 1] << 16) | (a[..., 2] << 8) | a[..., 3]).astype(np.uint32).view(f32)


def pcg_hash(h):
    """trilin.frag's and trimp.frag's hash in uint32 arithmetic."""
    h = (h.astype(np.uint64) * 747796405 + 2891336453) & 0xFFFFFFFF
    h = (((h >> ((h >> 28) + 4)) ^ h) * 277803737) & 0xFFFFFFFF
    return ((h >> 22) ^ h) & 0xFFFFFFFF


def level_weights(wx, wy, share):
    """runtime/sampling_gpu.h's level_weights(): a level's 2x2 texel weights when it weighs `share` of 256."""
    x1 = (wx * share + 128) >> 8
    x0 = share - x1
    w11 = (x1 * wy + np.where(wx == 256, 127, 128)) >> 8
    w10 = (x0 * wy + 127) >> 8
    return [(0, 0, x0 - w10), (0, 1, x1 - w11), (1, 0, w10), (1, 1, w11)]  # (row, column, weight)


def level_taps(n, s, t, share):
    """Texel rows, columns (REPEAT) and weights of an n x n level at (s, t): the GPU's 8-bit weights."""
    u = (s - np.floor(s)).astype(f32) * f32(n) - f32(0.5)
    v = (t - np.floor(t)).astype(f32) * f32(n) - f32(0.5)
    i0, j0 = np.floor(u).astype(np.int64), np.floor(v).astype(np.int64)
    wx = np.where(u - np.floor(u) > 0, (np.minimum(u - np.floor(u), f32(1)) * f32(256) + f32(0.5)).astype(np.int64), 0)
    wy = np.where(v - np.floor(v) > 0, (np.minimum(v - np.floor(v), f32(1)) * f32(256) + f32(0.5)).astype(np.int64), 0)
    return [((j0 + dj) % n, (i0 + di) % n, w) for dj, di, w in level_weights(wx, wy, share)], i0, j0


def trilinear16(levels, s, t, lam):
    """The GPU's 16-bit result of a LINEAR_MIPMAP_LINEAR lookup at lambda (every level square, REPEAT)."""
    q = len(levels) - 1
    lam = np.floor(np.asarray(lam) * 256) / 256  # 8 fraction bits, truncated
    d = np.clip(np.floor(lam), 0, q).astype(np.int64)
    w = np.where((lam > 0) & (lam < q), np.round((lam - np.floor(lam)) * 256), 0).astype(np.int64)
    total = np.zeros(len(s), np.int64)
    for lv in range(q + 1):
        for near, share in ((d == lv, 256 - w), ((d + 1 == lv) & (w > 0), w)):
            taps, _, _ = level_taps(levels[lv].shape[0], s, t, share)
            for j, i, wt in taps:
                total += np.where(near, wt * 257 * levels[lv][j, i], 0)
    return (total + 128) >> 8


def trilin(images):
    """trilin_w, trilin_1 .. _4 in DIR: textureLod's level weight of lambda, and the eight-texel rule on random levels."""
    for label, d in images:
        i = np.arange(512 * 512, dtype=np.int64)
        v = np.rint(floatbits(load(f"{d}/trilin_w.png")).ravel().astype(np.float64) * 65535).astype(np.int64)
        lam = i / 65536.0 - 0.5
        up = np.floor(np.maximum(lam, 0)) % 2 == 0  # blending from a level of 0 towards one of 1
        w = np.floor((np.maximum(lam, 0) % 1) * 256).astype(np.int64)
        want = (65535 * np.where(up, w, 256 - w) + 128) >> 8
        inner = (lam > 0) & (lam < 3)
        print(f"trilin {label}: mode 0, weight floor(256 frac(lambda)): {100 * np.mean((want == v)[inner]):.3f}% "
              f"of {inner.sum()} lambdas in (0, 3)")
        levels = [np.asarray(Image.open(f"{HERE}/rand_l{n}.png").convert("RGBA"), dtype=np.int64)[::-1, :, 0]
                  for n in (8, 4, 2, 1)]
        table = log2_fraction_table()
        for mode in (1, 2, 3):
            x, y = i % 512, i // 512
            key = (x >> 1) + 256 * (y >> 1) if mode == 3 else i
            h1 = pcg_hash(key)
            h2 = pcg_hash(h1 ^ 0x5BD1E995)
            h3 = pcg_hash(h2 ^ 0x1B873593)
            s = ((h1 & 0xFFFF) / 65536.0).astype(f32)
            t = ((h1 >> 16) / 65536.0).astype(f32)
            g = ((1024 + (h3 & 1023)) / 1024.0 * 2.0 ** (((h3 >> 10) & 3) - 1.0) / 8).astype(f32)
            if mode == 3:
                s, t = (s + (x & 1).astype(f32) * g).astype(f32), (t + (y & 1).astype(f32) * g).astype(f32)
            lam = (h2 & 4095) / 1024.0 - 0.5 if mode == 1 else lambda_of_rho(g * f32(8), table)
            got = np.rint(floatbits(load(f"{d}/trilin_{mode}.png")).ravel().astype(np.float64) * 65535)
            blend = (lam > 0) & (lam < 3) & (np.floor(lam * 256) % 256 != 0)
            ok = trilinear16(levels, s, t, lam) == got
            print(f"  mode {mode}: the eight-texel rule {100 * ok.mean():.3f}% of all, {100 * ok[blend].mean():.3f}% "
                  f"of the {blend.sum()} blends")
        q = floatbits(load(f"{d}/trilin_4.png")).ravel()
        print(f"  mode 4: textureQueryLod = the table's lambda at {100 * np.mean(q == lam):.3f}% of the pixels")


def trimp(images):
    """trimp_l{0,1}_m{0,1,2}_w{0,1} in DIR: each texel's weight of a two-level lookup against level_weights()."""
    table = log2_fraction_table()
    for label, d in images:
        i = np.arange(512 * 512, dtype=np.int64)
        x, y = i % 512, i // 512
        for mode in (0, 1, 2):
            cols = []
            for lv in (0, 1):
                for which in (0, 1):
                    a = load(f"{d}/trimp_l{lv}_m{mode}_w{which}.png").reshape(-1, 4)
                    cols += [a[:, 0] * 256 + a[:, 1], a[:, 2] * 256 + a[:, 3]]
            got = np.rint(np.stack(cols, 1) * 256 / 65535).astype(np.int64)  # 8-bit weights, 65535 w / 256 read back
            key = (x >> 1) + 256 * (y >> 1) if mode == 2 else i
            h1 = pcg_hash(key)
            h2 = pcg_hash(h1 ^ 0x5BD1E995)
            s = (0.375 + (h1 & 0x3FFF) / 65536.0).astype(f32)
            t = (0.375 + ((h1 >> 16) & 0x3FFF) / 65536.0).astype(f32)
            g = ((1024 + (h2 & 1023)) / 4096.0).astype(f32)
            if mode == 2:
                s, t = (s + (x & 1).astype(f32) * g).astype(f32), (t + (y & 1).astype(f32) * g).astype(f32)
            lam = (h2 >> 20) / 4096.0 if mode == 0 else lambda_of_rho(g * f32(4), table)
            w = np.floor(np.clip(lam, 0, 1) * 256).astype(np.int64)
            t0, i0, j0 = level_taps(4, s, t, 256 - w)
            t1, k0, l0 = level_taps(2, s, t, w)
            want = np.stack([wt for _, _, wt in t0] + [wt for _, _, wt in t1], 1)
            inside = (i0 == 1) & (j0 == 1) & (k0 == 0) & (l0 == 0) & (lam > 0) & (lam < 1)
            ok = (want == got).all(1)
            print(f"trimp {label} mode {mode}: all eight weights as level_weights() at "
                  f"{100 * ok[inside].mean():.3f}% of {inside.sum()} samples")


def trigrad(images):
    """trigrad.frag: textureGrad's lambda for random derivative vectors against gpu_rho()'s rule and the table."""
    table = log2_fraction_table()
    i = np.arange(512 * 512, dtype=np.int64)
    hs = [pcg_hash(i)]
    for salt in (0x5BD1E995, 0x1B873593, 0x85EBCA6B):
        hs.append(pcg_hash(hs[-1] ^ salt))

    def component(h):  # in texels of level 0 (256 wide)
        v = ((1024 + ((h >> 2) & 1023)) / 1024.0 * 2.0 ** (((h >> 12) & 7) - 1.0) / 256).astype(f32)
        return np.where(h & 3 == 0, f32(0), np.where((h >> 15) & 1 == 1, -v, v)).astype(f32) * f32(256)

    ux, vx, uy, vy = (component(h) for h in hs)
    axes = np.maximum(gpu_length(ux, vx), gpu_length(uy, vy))
    diag = np.maximum(gpu_length(ux + uy, vx + vy), gpu_length(ux - uy, vx - vy))
    rho = np.maximum(axes, f32(0.6875) * diag)
    model = np.clip(lambda_of_rho(np.maximum(rho, f32(1e-30)), table), 0, 8)
    nonzero = sum((c != 0).astype(int) for c in (ux, vx, uy, vy))
    for label, path in images:
        a = load(path).reshape(-1, 4)
        got = np.rint((a[:, 0] * 256 + a[:, 1]) / (257 * 28 / 256.0)) / 256  # level + 8-bit weight
        inner = (model > 0.01) & (model < 7.99)
        steps = np.rint((model - got) * 256)
        print(f"trigrad {label}: the rule's lambda {100 * np.mean(steps[inner] == 0):.2f}% of {inner.sum()} lookups, "
              f"within one table step {100 * np.mean(np.abs(steps[inner]) <= 1):.2f}%, one step high "
              f"{100 * np.mean(steps[inner] == 1):.2f}%")
        for k in range(1, 5):
            sel = inner & (nonzero == k)
            print(f"  {k} nonzero derivative components: {100 * np.mean(steps[sel] == 0):.2f}% of {sel.sum()}")


def level_weights(wx, wy, share):
    """runtime/sampling_gpu.h's split of a share among a plane's 2x2 texels: w00, w01, w10, w11."""
    x1 = (wx * share + 128) >> 8
    x0 = share - x1
    w11 = (x1 * wy + np.where(wx == 256, 127, 128)) >> 8
    w10 = (x0 * wy + 127) >> 8
    return x0 - w10, x1 - w11, w10, w11


def tex3dw(images):
    """tex3dw.frag: each texel's weight of a 3D LINEAR lookup, against the GPU's rule (two planes weighing
    256 - wz and wz, each split as a mipmap level's share) and the 2D weights split along z."""
    yb, x = np.mgrid[0:64, 0:1024].astype(np.float64)
    fr = lambda k: (k % 65536) / 65536
    w8 = [np.floor(f * 256 + 0.5).astype(np.int64) for f in
          (fr(x * 193 + yb * 811 + 7), fr(x * 1709 + yb * 47 + 12345), fr(x * 29 + yb * 2903 + 777))]
    wx, wy, wz = w8
    texels = [(i, j, k) for i in (0, 1) for j in (0, 1) for k in (0, 1)]
    rule, split = {}, {}
    for k, share in ((0, 256 - wz), (1, wz)):
        for (i, j), w in zip(((0, 0), (1, 0), (0, 1), (1, 1)), level_weights(wx, wy, share)):
            rule[(i, j, k)] = w
    for (i, j), w in zip(((0, 0), (1, 0), (0, 1), (1, 1)), level_weights(wx, wy, np.full_like(wx, 256))):
        hi = (w * wz + 128) >> 8
        split[(i, j, 0)], split[(i, j, 1)] = w - hi, hi
    patterns = [(1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 0), (1, 0, 1), (0, 1, 1), (1, 1, 1)]
    for label, path in images:
        e = dec16(load(path))
        print(f"tex3dw {label}:")
        for name, model in (("the GPU's rule", rule), ("2D weights split along z", split)):
            ok = []
            for b in range(8):
                pat, lo, hi = (patterns[b], 0, 255) if b < 7 else (patterns[6], 51, 217)
                total = sum(257 * (hi if sum(p * t for p, t in zip(pat, v)) % 2 else lo) * model[v] for v in texels)
                r = (total + 128) >> 8
                ok.append(np.mean(np.where(r >= 32768, r + 1, r) % 65536 == e[64 * b: 64 * b + 64]))
            print(f"  {name}: " + " ".join(f"{100 * v:.2f}%" for v in ok) + " (bands 0-7)")


def blendover(images):
    """blendover.frag: SRC_ALPHA over ONE_MINUS_SRC_ALPHA into RGBA8, against the exact products of the bytes
    rounded to nearest and stored by the GPU's UNORM8 rule."""
    for label, path in images:
        g = load(path)
        y, x = np.mgrid[0:g.shape[0], 0:g.shape[1]].astype(np.float64)
        fr = lambda k: (k % 65536) / 65536
        d = np.stack([x % 256, (7 * x + 3 * y) % 256, (11 * x + 5 * y + 17) % 256, (3 * x + y + 101) % 256], -1)
        src = np.stack([fr(x * 1709 + y * 47 + 12345), fr(x * 29 + y * 2903 + 777), fr(x * 631 + y * 1303 + 4242),
                        fr(x * 193 + y * 811 + 7)], -1)
        s8 = (np.floor(src * 4096).astype(np.int64) * 510 + 4095) >> 13  # the GPU's UNORM8 store
        c = s8 * s8[..., 3:] + d.astype(np.int64) * (255 - s8[..., 3:])
        near = (c + 127) // 255
        store = ((c * 4096 // 65025) * 510 + 4095) >> 13
        print(f"blendover {label}: to nearest {100 * np.mean(near == g):.3f}%, the GPU's store rule "
              f"{100 * np.mean(store == g):.3f}% of {g.size} channels")


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    what = sys.argv[1]
    imgs = [tuple(arg.split("=", 1)) for arg in sys.argv[2:]]
    globals()[what](imgs)
