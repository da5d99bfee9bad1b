"""Uniforms the user sets override a scene's [uniforms], and batch inputs are
checked: mistakes that used to give wrong numbers with no error."""
import os

import numpy as np
import pytest

import glslrun

VS = "void main() { gl_Position = ftransform(); }\n"
FS = "uniform vec4 tint;\nvoid main() { gl_FragColor = tint; }\n"
# A full-screen plane (identity camera), drawn in the scene's tint.
SCENE = """
[output]
size = [8, 8]
[uniforms]
tint = [0.5, 0.5, 0.5, 1]
[[objects]]
mesh = "arrays"
primitive = "triangle_strip"
vertices = [[-1, -1, 0], [1, -1, 0], [-1, 1, 0], [1, 1, 0]]
"""


def centre(image):
    return tuple(int(c) for c in image[4, 4])


def test_set_uniform_overrides_the_scenes_uniforms_on_every_render():
    program = glslrun.Program.compile(VS, FS)
    scene = glslrun.Scene.parse(SCENE)
    assert centre(program.render(scene)) == (128, 128, 128, 255)  # the scene's value
    seen = set()
    for red in range(0, 100):
        program.set_uniform("tint", [red / 255, 0, 0, 1])
        image = program.render(scene)
        assert centre(image) == (red, 0, 0, 255)
        seen.add(image.tobytes())
    assert len(seen) == 100


def test_uniforms_the_scene_leaves_alone_keep_their_values():
    # No clash with the scene's [uniforms]: rendered without a copy of the scene.
    program = glslrun.Program.compile(VS, FS)
    plain = glslrun.Scene.parse(SCENE.replace("[uniforms]\ntint = [0.5, 0.5, 0.5, 1]\n", ""))
    program.set_uniform("tint", [0, 0, 1, 1])
    assert centre(program.render(plain)) == (0, 0, 255, 255)
    assert centre(program.render(glslrun.Scene.parse(SCENE))) == (0, 0, 255, 255)
    assert centre(program.render(plain)) == (0, 0, 255, 255)
    assert centre(program.render(plain, uniforms={"tint": [1, 0, 0, 1]})) == (255, 0, 0, 255)
    assert centre(program.render(plain)) == (0, 0, 255, 255)  # set_uniform's value again


def test_render_takes_uniforms_that_override_the_scene(tmp_path):
    program = glslrun.Program.compile(VS, FS)
    scene = glslrun.Scene.parse(SCENE)
    assert centre(program.render(scene, uniforms={"tint": [0, 1, 0, 1]})) == (0, 255, 0, 255)
    # The keyword wins over set_uniform too, for that render only.
    program.set_uniform("tint", [0, 0, 1, 1])
    assert centre(program.render(scene, uniforms={"tint": np.array([1, 0, 0, 1])})) == (255, 0, 0, 255)
    assert centre(program.render(scene)) == (0, 0, 255, 255)
    # glslrun.render, from files, as --uniform.
    for name, text in (("a.vert", VS), ("a.frag", FS), ("s.toml", SCENE)):
        (tmp_path / name).write_text(text)
    files = [str(tmp_path / n) for n in ("a.vert", "a.frag", "s.toml")]
    assert centre(glslrun.render(*files)) == (128, 128, 128, 255)
    assert centre(glslrun.render(*files, uniforms={"tint": [1, 1, 0, 1]})) == (255, 255, 0, 255)
    with pytest.raises(glslrun.Error, match="no active uniform 'tnit'"):
        glslrun.render(*files, uniforms={"tnit": [1, 1, 0, 1]})
    with pytest.raises(TypeError):
        program.render(scene, uniforms={"tint": None})


def test_user_uniforms_win_in_a_scenes_batches_too():
    program = glslrun.Program.compile(VS, FS)
    scene = glslrun.Scene.parse(SCENE)
    np.testing.assert_allclose(program.run_fragments({}, count=4, scene=scene)["gl_FragColor"][0], [0.5, 0.5, 0.5, 1])
    program.set_uniform("tint", [0.25, 0, 0, 1])
    np.testing.assert_allclose(program.run_fragments({}, count=4, scene=scene)["gl_FragColor"][0], [0.25, 0, 0, 1])


def test_the_backend_option_gives_the_same_bits(tmp_path):
    for name, text in (("a.vert", VS), ("a.frag", FS), ("s.toml", SCENE)):
        (tmp_path / name).write_text(text)
    files = [str(tmp_path / n) for n in ("a.vert", "a.frag", "s.toml")]
    interp = glslrun.render(*files, backend="interp")
    np.testing.assert_array_equal(glslrun.render(*files, backend="jit"), interp)
    program = glslrun.Program.compile(VS, FS)
    program.backend = "interp"
    assert program.backend == "interp"
    with pytest.raises(glslrun.Error):
        program.backend = "gpu"


def test_a_uniform_value_must_be_numbers():
    program = glslrun.Program.compile(VS, FS)
    for bad in (None, [1, None, 0, 1], "red", [[1, 2], "x"]):
        with pytest.raises(TypeError, match="takes numbers"):
            program.set_uniform("tint", bad)


BATCH_VS = "attribute float weight;\nvarying float v;\nvoid main() { v = weight; gl_Position = gl_Vertex; }\n"
BATCH_FS = "varying float v;\nvoid main() { gl_FragColor = vec4(v); }\n"


def test_batch_inputs_are_checked():
    program = glslrun.Program.compile(BATCH_VS, BATCH_FS)
    vertices = np.ones((4, 4), np.float32)
    with pytest.raises(ValueError, match="reads no input 'wieght'.*gl_Vertex, weight|reads no input 'wieght'.*weight, gl_Vertex"):
        program.run_vertices({"gl_Vertex": vertices, "wieght": np.ones(4)})
    with pytest.raises(ValueError, match="'gl_Vertex' has 5 components"):
        program.run_vertices({"gl_Vertex": np.ones((4, 5), np.float32)})
    with pytest.raises(ValueError, match="multiple of 4"):
        program.run_fragments({"v": np.ones(6, np.float32)})
    with pytest.raises(ValueError, match="reads no input 'vv'"):
        program.run_fragments({"vv": np.ones(4, np.float32)})
    # What is right still runs.
    out = program.run_fragments({"v": np.full(8, 0.5, np.float32)})
    np.testing.assert_allclose(out["gl_FragColor"], 0.5)
    out = program.run_vertices({"gl_Vertex": vertices, "weight": np.arange(4)})
    np.testing.assert_allclose(out["v"][:, 0], [0, 1, 2, 3])


def test_a_scene_uniform_that_no_program_uses_is_a_warning(tmp_path):
    # GL ignores glUniform at location -1: the scene renders; the entry's line and the name meant are named.
    text = SCENE.replace("tint = [0.5, 0.5, 0.5, 1]\n", "tint = [0.5, 0.5, 0.5, 1]\ntnit = [1, 0, 0, 1]\n")
    program = glslrun.Program.compile(VS, FS)
    meant = r":6: warning: the program has no active uniform 'tnit'.*did you mean 'tint'\?"
    with pytest.warns(RuntimeWarning, match=meant):
        assert centre(program.render(glslrun.Scene.parse(text))) == (128, 128, 128, 255)
    for name, source in (("a.vert", VS), ("a.frag", FS), ("s.toml", text)):
        (tmp_path / name).write_text(source)
    with pytest.warns(RuntimeWarning, match=meant):
        image = glslrun.render(*(str(tmp_path / n) for n in ("a.vert", "a.frag", "s.toml")))
    assert centre(image) == (128, 128, 128, 255)
    # The scene's state for one object, as run_fragments applies it: the entry is skipped there too.
    out = program.run_fragments({}, count=4, scene=glslrun.Scene.parse(text))
    np.testing.assert_allclose(out["gl_FragColor"][0], [0.5, 0.5, 0.5, 1])
