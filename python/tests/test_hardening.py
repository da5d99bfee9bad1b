"""The Python module under abuse: arguments past every limit come back as
glslrun.Error or ValueError, never as a crash, MemoryError or a hang."""
import os

import numpy as np
import pytest

import glslrun

VS = "void main() { gl_Position = gl_Vertex; }"
FS = "void main() { gl_FragColor = vec4(1.0); }"


def program():
    return glslrun.Program.compile(VS, FS)


def test_image_helpers_check_a_huge_broadcast_array_before_copying_it(tmp_path):
    # 2^40 pixels as a view of one; the copy used to fail and its null result was used.
    huge = np.broadcast_to(np.zeros(4, np.uint8), (1 << 20, 1 << 20, 4))
    small = np.zeros((2, 2, 4), np.uint8)
    with pytest.raises(ValueError, match="each side"):
        glslrun.compare_images(huge, small)
    with pytest.raises(ValueError, match="each side"):
        glslrun.compare_images(small, huge)
    with pytest.raises(ValueError, match="each side"):
        glslrun.write_png(huge, str(tmp_path / "a.png"))
    with pytest.raises(ValueError, match="each side"):
        glslrun.write_png(np.zeros((0, 4, 4), np.uint8), str(tmp_path / "b.png"))
    # A broadcast view within the sides is copied and works.
    view = np.broadcast_to(np.array([1, 2, 3, 255], np.uint8), (3, 5, 4))
    assert glslrun.compare_images(view, np.ascontiguousarray(view))["passed"]


def test_batch_inputs_check_a_huge_broadcast_array_before_copying_it():
    p = program()
    huge = np.broadcast_to(np.zeros(4, np.float32), (1 << 40, 4))
    with pytest.raises(ValueError, match="count at most"):
        p.run_vertices({"gl_Vertex": huge})
    with pytest.raises(ValueError, match="components 1..16"):
        p.run_vertices({"gl_Vertex": np.zeros((3, 17), np.float32)})
    with pytest.raises(glslrun.Error, match="more values than any uniform"):
        q = glslrun.Program.compile(VS, "uniform vec4 c; void main() { gl_FragColor = c; }")
        q.set_uniform("c", np.broadcast_to(np.float32(1), (1 << 40,)))


def test_counts_past_the_limits_are_errors():
    p = program()
    for count in (2**32 - 1, (1 << 26) + 1):
        with pytest.raises(glslrun.Error, match="too many"):
            p.run_vertices({}, count=count)
        with pytest.raises(glslrun.Error, match="too many"):
            p.run_fragments({}, count=count)
    with pytest.raises(TypeError):
        p.run_vertices({}, count=-1)
