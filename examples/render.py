#!/usr/bin/env python3
"""A scene rendered from Python, as `glslrun a.vert a.frag scene.toml -o out.png`:

    python3 examples/render.py shaders/spot_pix_fixed.vert shaders/spot_pix_fixed.frag scenes/spot.toml spot.png

The image is a numpy array (height x width x 4, uint8, top row first); the
script prints how much of it the scene covers and writes it as a PNG.
"""
import sys

import numpy as np

import glslrun


def main(argv: list[str]) -> int:
    if len(argv) != 5:
        print(__doc__, file=sys.stderr)
        return 2
    vert, frag, scene_path, out = argv[1:]
    try:
        image = glslrun.render(vert, frag, scene_path)
    except glslrun.Error as e:  # "file:line: error: ..." as the command line prints it
        print(e, file=sys.stderr)
        return 1
    scene = glslrun.Scene.load(scene_path)
    background = np.all(image == image[0, 0], axis=2)
    print(f"{scene_path}: {image.shape[1]}x{image.shape[0]}, {100 * (1 - background.mean()):.1f}% covered")
    glslrun.write_png(image, out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
