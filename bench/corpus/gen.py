#!/usr/bin/python3
"""Writes the corpus's generated inputs: the PNG textures under textures/ and the two
scenes too long to write by hand (skinning.toml: a skinned tube's vertex arrays;
many_draws.toml: 240 small objects; volume.toml: 48 slices). Deterministic: running it again gives the same bytes.

    /usr/bin/python3 bench/corpus/gen.py
"""
import math
import os
import struct
import zlib

import lightmath  # beside this file

HERE = os.path.dirname(os.path.abspath(__file__))


def write_png(path, width, height, pixel, channels=3):
    """pixel(x, y) -> tuple of floats in [0, 1], (x, y) from the top-left corner."""
    rows = bytearray()
    for y in range(height):
        rows.append(0)
        for x in range(width):
            for c in pixel(x, y)[:channels]:
                rows.append(max(0, min(255, int(round(c * 255)))))
    colour_type = {1: 0, 3: 2, 4: 6}[channels]
    chunk = lambda tag, data: (struct.pack(">I", len(data)) + tag + data +
                               struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF))
    png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, colour_type, 0, 0, 0)) +
           chunk(b"IDAT", zlib.compress(bytes(rows), 9)) + chunk(b"IEND", b""))
    with open(os.path.join(HERE, "textures", path), "wb") as f:
        f.write(png)


def mix(a, b, t):
    return tuple(x + (y - x) * t for x, y in zip(a, b))


def smooth(t):
    t = max(0.0, min(1.0, t))
    return t * t * (3 - 2 * t)


def stone(x, y):
    """Smooth, tileable sandstone: sums of sines over a 256 period."""
    u, v = 2 * math.pi * (x + 0.5) / 256, 2 * math.pi * (y + 0.5) / 256
    f = 0.5 + 0.25 * math.sin(3 * u + 1.3 * math.sin(2 * v)) + 0.15 * math.sin(5 * v + 0.7 * math.cos(3 * u))
    f += 0.1 * math.sin(7 * u + 9 * v)
    return mix((0.45, 0.38, 0.30), (0.85, 0.78, 0.62), max(0.0, min(1.0, f)))


def decal(x, y):
    """A soft-edged emblem with alpha: a ring and a bar, transparent elsewhere."""
    cx, cy = (x + 0.5) / 128 - 0.5, (y + 0.5) / 128 - 0.5
    r = math.hypot(cx, cy)
    ring = smooth(1 - abs(r - 0.32) / 0.06)
    bar = smooth(1 - abs(cy) / 0.05) * smooth(1 - (abs(cx) - 0.25) / 0.04)
    a = max(ring, bar)
    return (0.85, 0.15 + 0.5 * smooth(0.5 - cy), 0.1, a)


def photo(x, y):
    """A picture with hard edges for the post-process: discs, stripes and a gradient sky."""
    u, v = (x + 0.5) / 512, (y + 0.5) / 512
    c = mix((0.35, 0.55, 0.85), (0.9, 0.85, 0.7), v)
    if v > 0.7:
        c = (0.25, 0.45, 0.2) if int(u * 16) % 2 == 0 else (0.3, 0.55, 0.25)
    for (px, py, r, col) in ((0.3, 0.35, 0.15, (0.9, 0.2, 0.15)), (0.7, 0.4, 0.1, (0.95, 0.9, 0.2)),
                             (0.55, 0.2, 0.07, (0.2, 0.3, 0.8))):
        if math.hypot(u - px, v - py) < r:
            c = col
    if 0.45 < u < 0.5 and v > 0.55:
        c = (0.1, 0.1, 0.1)
    return c


def normal_map(x, y):
    """Hemispherical bumps, 4x4 per texture, as a tangent-space normal map (smooth)."""
    u, v = ((x + 0.5) / 128 * 4) % 1 - 0.5, ((y + 0.5) / 128 * 4) % 1 - 0.5
    r2 = u * u + v * v
    if r2 < 0.16:
        h = math.sqrt(0.16 - r2)
        n = (u, -v, h)  # the image's y points down: t points up
    else:
        n = (0.0, 0.0, 1.0)
    length = math.sqrt(sum(c * c for c in n))
    return tuple(0.5 + 0.5 * c / length for c in n)


def slide(x, y):
    """A projector slide: a window of four panes with a frame, slightly blurred corners."""
    u, v = (x + 0.5) / 128, (y + 0.5) / 128
    frame = u < 0.08 or u > 0.92 or v < 0.08 or v > 0.92 or abs(u - 0.5) < 0.04 or abs(v - 0.5) < 0.04
    if frame:
        return (0.05, 0.05, 0.05)
    return mix((1.0, 0.95, 0.7), (0.7, 0.85, 1.0), v)


SHADOW_EYE, SHADOW_EXTENT, SHADOW_NEAR, SHADOW_FAR = [2.5, 5.0, 1.5], 3.5, 1.0, 10.0


def shadow_matrix():
    """World to shadow-map coordinates: bias * glOrtho * gluLookAt from the light."""
    view = lightmath.look_at(SHADOW_EYE, [0, 0, 0], [0, 1, 0])
    e = SHADOW_EXTENT
    return lightmath.mul(lightmath.BIAS, lightmath.mul(lightmath.ortho(-e, e, -e, e, SHADOW_NEAR, SHADOW_FAR), view))


def shadow_depth(x, y):
    """The depth map the light would render of shadow.toml's scene (a unit sphere at the origin
    over the floor y = -1), traced analytically: what a depth-only pass would leave."""
    view = lightmath.look_at(SHADOW_EYE, [0, 0, 0], [0, 1, 0])
    inv = lightmath.inverse_rigid(view)
    e = SHADOW_EXTENT
    lx, ly = -e + 2 * e * (x + 0.5) / 256, e - 2 * e * (y + 0.5) / 256
    origin = lightmath.apply(inv, [lx, ly, 0, 1])[:3]
    direction = [-inv[i][2] for i in range(3)]  # the light looks down its -z
    # the sphere: |o + d t|^2 = 1
    b = sum(o * d for o, d in zip(origin, direction))
    c = sum(o * o for o in origin) - 1
    hits = []
    if b * b - c >= 0:
        hits.append(-b - math.sqrt(b * b - c))
    t_floor = (-1 - origin[1]) / direction[1]
    px, pz = origin[0] + direction[0] * t_floor, origin[2] + direction[2] * t_floor
    if abs(px) <= 4 and abs(pz) <= 4:
        hits.append(t_floor)
    depth = (min(hits) - SHADOW_NEAR) / (SHADOW_FAR - SHADOW_NEAR) if hits else 1.0
    return (depth,)


def palette(x, _y):
    t = (x + 0.5) / 256
    return (0.5 + 0.5 * math.cos(2 * math.pi * (t + 0.0)), 0.5 + 0.5 * math.cos(2 * math.pi * (t + 0.33)),
            0.5 + 0.5 * math.cos(2 * math.pi * (t + 0.67)))


def toon_ramp(x, _y):
    return ((0.25, 0.2, 0.35), (0.55, 0.45, 0.6), (0.85, 0.75, 0.8), (1.0, 1.0, 1.0))[x]


def write_scene(name, comment, body):
    """NAME.toml: the comment, NAME.head.toml (the hand-written state), then the generated lines."""
    head = open(os.path.join(HERE, name + ".head.toml")).read().rstrip("\n")
    with open(os.path.join(HERE, name + ".toml"), "w") as f:
        f.write("\n".join(comment + [head] + body) + "\n")


def fmt(v):
    return "[" + ", ".join(f"{c:.4g}" for c in v) + "]"


def bone_matrices():
    """Bone k rotates by 30k degrees about z around the joint at x = -2 + 4k/3 (the bones chained)."""
    bones = [[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]]
    for k in range(1, 4):
        a, jx = math.radians(30), -2 + 4 * k / 3
        c, s = math.cos(a), math.sin(a)
        local = [[c, -s, 0, jx - c * jx], [s, c, 0, -s * jx], [0, 0, 1, 0], [0, 0, 0, 1]]
        bones.append(lightmath.mul(bones[-1], local))
    return bones


def skinning():
    """A tube along x in 3 segments bent by 4 bones; each vertex has 2 weights."""
    sides, rings, length, radius = 32, 128, 4.0, 0.35
    verts, normals, weights, bones, tex = [], [], [], [], []
    for i in range(rings + 1):
        s = i / rings
        x = -length / 2 + length * s
        seg = s * 3  # bones at s = 0, 1/3, 2/3, 1
        b0 = min(int(seg), 2)
        t = smooth(seg - b0)
        for j in range(sides):
            a = 2 * math.pi * j / sides
            pinch = 1 + 0.15 * math.cos(6 * math.pi * s)
            verts.append((x, radius * pinch * math.cos(a), radius * pinch * math.sin(a)))
            normals.append((0, math.cos(a), math.sin(a)))
            weights.append((1 - t, t))
            bones.append((b0, b0 + 1))
            tex.append((s * 6, j / sides))
    indices = []
    for i in range(rings):
        for j in range(sides):
            a, b = i * sides + j, i * sides + (j + 1) % sides
            c, d = a + sides, b + sides
            indices += [a, b, c, b, d, c]  # counter-clockwise seen from outside
    lines = ["\n[uniforms]\nbones = [" + ", ".join(lightmath.columns(b) for b in bone_matrices()) + "]"]
    lines.append("\n[[objects]]\nname = \"tube\"\nmesh = \"arrays\"")
    lines.append("vertices = [" + ", ".join(fmt(v) for v in verts) + "]")
    lines.append("normals = [" + ", ".join(fmt(v) for v in normals) + "]")
    lines.append("tex_coords = [" + ", ".join(fmt(v) for v in tex) + "]")
    lines.append("indices = [" + ", ".join(str(i) for i in indices) + "]")
    lines.append("attributes = { weights = [" + ", ".join(fmt(v) for v in weights) + "], bone_index = [" +
                 ", ".join(fmt(v) for v in bones) + "] }")
    write_scene("skinning", ["# Generated by gen.py: a tube of 32 x 129 vertices bent by four bones (uniform mat4 "
                             "bones[4]),", "# two weights and two bone indices per vertex as attributes."], lines)


def many_draws():
    """240 small objects (spheres, cubes, tori) on a 20 x 12 grid, each with its own colour uniform."""
    lines = []
    meshes = ('mesh = "sphere"\nradius = 0.3\nslices = 12\nstacks = 6', 'mesh = "cube"\nsize = 0.45',
              'mesh = "torus"\ninner_radius = 0.08\nouter_radius = 0.25\nsides = 8\nrings = 12')
    for k in range(240):
        i, j = k % 20, k // 20
        x, y = -9.5 + i, -5.5 + j
        h = (k * 37) % 240 / 240.0
        colour = (0.5 + 0.5 * math.cos(2 * math.pi * h), 0.5 + 0.5 * math.cos(2 * math.pi * (h + 0.33)),
                  0.5 + 0.5 * math.cos(2 * math.pi * (h + 0.67)))
        lines.append(f"\n[[objects]]\n{meshes[k % 3]}")
        lines.append(f"transform = [ {{ translate = [{x}, {y}, 0] }}, {{ rotate = [{(k * 23) % 360}, 1, 1, 0] }} ]")
        lines.append(f"uniforms = {{ tint = {fmt(colour)}, phase = {k * 0.1:.1f} }}")
    write_scene("many_draws", ["# Generated by gen.py: 240 small draws, each with its own transform and uniform."],
                lines)


def volume():
    """48 slice quads from back (r = 0) to front (r = 1), each its own draw with its r."""
    lines = []
    for k in range(48):
        r = (k + 0.5) / 48
        lines.append(f"\n[[objects]]\nmesh = \"quad\"")
        lines.append(f"transform = [ {{ rotate = [25, 1, 1, 0] }}, {{ translate = [0, 0, {2 * r - 1:.5f}] }} ]")
        lines.append(f"uniforms = {{ slice_r = {r:.5f} }}")
    write_scene("volume", ["# Generated by gen.py: the slices of a volume, back to front."], lines)


def main():
    write_png("stone.png", 256, 256, stone)
    write_png("decal.png", 128, 128, decal, 4)
    write_png("photo.png", 512, 512, photo)
    write_png("normal.png", 128, 128, normal_map)
    write_png("slide.png", 128, 128, slide)
    write_png("palette.png", 256, 1, palette)
    write_png("toon_ramp.png", 4, 1, toon_ramp)
    write_png("shadow_depth.png", 256, 256, shadow_depth, 1)
    print("shadow.toml's light_matrix:", lightmath.columns(shadow_matrix()))
    skinning()
    many_draws()
    volume()


if __name__ == "__main__":
    main()
