#!/usr/bin/python3
"""Decodes undefined.frag's results: each pixel column's 32 bits (R, G, B, A = bytes 0..3) as the
float or int result of the case of cases.txt, printed as `x | expression | value (bits)` per input.
An input is an image of the shader (glref's PNG, 40x1) or gpu_probe's output ("x 0xBITS" lines,
nvidia_h200.txt).
usage: decode.py [LABEL=]FILE ..."""
import math
import struct
import sys
from pathlib import Path

from PIL import Image


def cases():
    for line in (Path(__file__).parent / "cases.txt").read_text().splitlines():
        if line.strip() and not line.startswith("#"):
            x, expr, kind = line.split("|")
            yield int(x), expr, kind.strip()


def value(bits, kind):
    if kind == "i":
        return str(struct.unpack("<i", struct.pack("<I", bits))[0])
    f = struct.unpack("<f", struct.pack("<I", bits))[0]
    if math.isnan(f):
        return "NaN" if not bits >> 31 else "-NaN"
    return repr(f)


def read_bits(path):
    """Column x -> its 32 bits."""
    if path.endswith(".txt"):
        return {int(x): int(bits, 16) for x, bits in (line.split() for line in open(path) if line.strip())}
    img = Image.open(path).convert("RGBA")
    out = {}
    for x in range(img.width):
        r, g, b, a = img.getpixel((x, 0))
        out[x] = r | g << 8 | b << 16 | a << 24
    return out


def main():
    inputs = []
    for arg in sys.argv[1:]:
        label, _, path = arg.rpartition("=")
        inputs.append((label or path, read_bits(path)))
    if not inputs:
        sys.exit(__doc__)
    print("x | expression | " + " | ".join(label for label, _ in inputs))
    for x, expr, kind in cases():
        cells = []
        for _, bits_of in inputs:
            bits = bits_of[x]
            cells.append(f"{value(bits, kind)} (0x{bits:08x})")
        print(f"{x} | {expr} | " + " | ".join(cells))


if __name__ == "__main__":
    main()
