#!/usr/bin/env python3
"""A program and a scene step by step: compile, load, resize, render, and
run the vertex shader alone on a numpy array in the scene's state.

    python3 examples/program.py shaders/spot_pix_fixed.vert shaders/spot_pix_fixed.frag scenes/spot.toml

Uniforms set with `program.set_uniform` (or passed as `render(scene,
uniforms={...})`) override the scene's [uniforms] on every render, as the
command line's --uniform does. CI type-checks it with `mypy --strict`
against the installed stub.
"""
import sys

import numpy as np
import numpy.typing as npt

import glslrun


def covered(image: npt.NDArray[np.uint8]) -> float:
    """The fraction of pixels that differ from the top-left one."""
    background = np.all(image == image[0, 0], axis=2)
    return float(1 - background.mean())


def main(argv: list[str]) -> int:
    if len(argv) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    vert, frag, scene_path = argv[1:]
    try:
        program = glslrun.Program.from_files(vert, frag)
        scene = glslrun.Scene.load(scene_path)
    except glslrun.Error as e:
        print(e, file=sys.stderr)
        return 1
    scene.resize(128, 128)
    program.threads = 2
    print(f"{scene_path}: {scene.width}x{scene.height}, {scene.objects} objects; uniforms:",
          ", ".join(u["name"] for u in program.uniforms if not u["builtin"]) or "none")
    images = [program.render(scene)]
    print(f"  as the scene gives it: {100 * covered(images[0]):.1f}% covered")
    corners = np.array([[-1, -1, 0, 1], [1, -1, 0, 1], [1, 1, 0, 1], [-1, 1, 0, 1]], dtype=np.float32)
    clip = program.run_vertices({"gl_Vertex": corners}, scene=scene)["gl_Position"]
    print("  the unit square's corners in clip space:", np.round(clip, 3).tolist())
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
