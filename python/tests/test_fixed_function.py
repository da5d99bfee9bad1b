"""Python's entry points with a stage left out, as the command line takes them: the stage is GL's
fixed function, generated from the scene; render("scene.toml") draws every object in fixed function."""
import os
import subprocess

import numpy as np
import pytest

import glslrun

SOURCE = os.environ.get("GLSLRUN_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
CLI = os.environ.get("GLSLRUN_CLI", "glslrun")


def path(*parts):
    return os.path.join(SOURCE, *parts)


FRAG = path("shaders", "minimal.frag")
VERT = path("shaders", "spot_pix_fixed.vert")
SPOT = path("scenes", "spot.toml")
FIXED = path("scenes", "fixed_function.toml")


def cli_image(tmp_path, *files):
    png = tmp_path / "cli.png"
    subprocess.run([CLI, *files, "-o", str(png)], check=True, capture_output=True)
    return glslrun.read_png(str(png))


def test_render_with_a_stage_left_out_equals_the_command_line(tmp_path):
    expected = cli_image(tmp_path, FRAG, SPOT)
    np.testing.assert_array_equal(glslrun.render(None, FRAG, SPOT), expected)
    np.testing.assert_array_equal(glslrun.render(FRAG, SPOT), expected)  # the files by their names
    np.testing.assert_array_equal(glslrun.render(fragment=FRAG, scene=SPOT), expected)
    program = glslrun.Program.from_files(None, FRAG)
    np.testing.assert_array_equal(program.render(glslrun.Scene.load(SPOT)), expected)
    program = glslrun.Program.compile(None, open(FRAG).read())
    np.testing.assert_array_equal(program.render(glslrun.Scene.load(SPOT)), expected)
    vertex_only = cli_image(tmp_path, VERT, SPOT)
    np.testing.assert_array_equal(glslrun.render(VERT, None, SPOT), vertex_only)


def test_render_without_shaders_equals_the_command_line(tmp_path):
    expected = cli_image(tmp_path, FIXED)
    image = glslrun.render(FIXED)
    assert len(np.unique(image.reshape(-1, 4), axis=0)) > 100  # lit, textured and fogged, not flat
    np.testing.assert_array_equal(image, expected)
    np.testing.assert_array_equal(glslrun.render(None, None, FIXED), expected)


def test_one_shader_in_the_reports():
    report = glslrun.error_report(FRAG, SPOT, mode="fast")
    assert "notes" in report and report["mode_image"].shape == (512, 512, 4)
    assert glslrun.check_undefined(None, FRAG, SPOT) == []


def test_messages_say_what_to_do():
    with pytest.warns(RuntimeWarning, match="no shaders were given, and the scene sets no fixed-function state"):
        glslrun.render(SPOT)  # unlit white: said, with what to give
    with pytest.raises(ValueError, match=r"needs a scene file \(\.toml\).*None\) is drawn with GL's fixed function"):
        glslrun.render(FRAG)
    with pytest.raises(ValueError, match="cannot tell what 'a.glsl' is from its name: pass render"):
        glslrun.render("a.glsl", SPOT)
    with pytest.raises(ValueError, match=r"a Program needs a vertex or a fragment shader.*glslrun.render"):
        glslrun.Program.compile(None, None)
    with pytest.raises(ValueError, match=r"error_report\(\) looks at your shaders.*render\(\"scene.toml\"\)"):
        glslrun.error_report(FIXED)
