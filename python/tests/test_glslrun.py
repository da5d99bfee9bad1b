"""The Python module `glslrun` (python/module.cpp): run by ctest's `python` test.

GLSLRUN_SOURCE_DIR is the checkout, GLSLRUN_CLI the command-line binary whose
PNG the module's images must equal byte for byte.
"""
import os
import struct
import subprocess
import sys
import zlib

import numpy as np
import pytest

import glslrun

SOURCE = os.environ.get("GLSLRUN_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
CLI = os.environ.get("GLSLRUN_CLI", "glslrun")


def path(*parts):
    return os.path.join(SOURCE, *parts)


def decode_png(data):
    """An RGBA8 PNG as glslrun writes it, decoded with zlib alone (no
    glslrun code), so the comparison does not depend on glslrun's reader."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, width, height = 8, b"", 0, 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, color, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert (depth, color, interlace) == (8, 6, 0)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = width * 4
    rows = np.zeros((height, stride), dtype=np.int64)
    prior = np.zeros(stride, dtype=np.int64)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = np.frombuffer(raw, np.uint8, stride, y * (stride + 1) + 1).astype(np.int64)
        if kind == 0:
            out = line
        elif kind == 1:  # sub: a running sum per channel (glslrun's filter)
            out = line.reshape(-1, 4).cumsum(axis=0).reshape(-1) & 0xFF
        elif kind == 2:
            out = (line + prior) & 0xFF
        else:  # average, Paeth: byte by byte
            out = [0] * stride
            for x in range(stride):
                left = out[x - 4] if x >= 4 else 0
                up, corner = int(prior[x]), (int(prior[x - 4]) if x >= 4 else 0)
                if kind == 3:
                    pred = (left + up) // 2
                else:
                    p = left + up - corner
                    pa, pb, pc = abs(p - left), abs(p - up), abs(p - corner)
                    pred = left if pa <= pb and pa <= pc else up if pb <= pc else corner
                out[x] = (int(line[x]) + pred) & 0xFF
            out = np.array(out, dtype=np.int64)
        rows[y], prior = out, out
    return rows.astype(np.uint8).reshape(height, width, 4)


SPOT = (path("shaders", "spot_pix_fixed.vert"), path("shaders", "spot_pix_fixed.frag"), path("scenes", "spot.toml"))


def test_render_equals_the_command_lines_png(tmp_path):
    png = tmp_path / "spot.png"
    subprocess.run([CLI, *SPOT, "-o", str(png)], check=True, capture_output=True)
    expected = decode_png(png.read_bytes())
    image = glslrun.render(*SPOT)
    assert image.shape == (512, 512, 4) and image.dtype == np.uint8
    assert len(np.unique(image.reshape(-1, 4), axis=0)) > 1000  # a lit teapot, not a flat image
    np.testing.assert_array_equal(image, expected)
    # The library's own reader agrees, and threads do not change a pixel.
    np.testing.assert_array_equal(glslrun.read_png(str(png)), expected)
    np.testing.assert_array_equal(glslrun.render(*SPOT, threads=1), expected)


def test_program_render_and_scene_in_code():
    program = glslrun.Program.from_files(path("shaders", "colors.vert"), path("shaders", "colors.frag"))
    scene = glslrun.Scene.parse("""
[output]
size = [64, 32]
clear_color = [0, 0, 1, 1]
[[objects]]
mesh = "quad"
""", path("scenes", "inline.toml"))
    image = program.render(scene)
    assert image.shape == (32, 64, 4)
    # Identity matrices: the quad covers the whole viewport, so no pixel keeps the clear colour.
    assert not np.any(np.all(image == [0, 0, 255, 255], axis=2))
    scene.resize(16, 8)
    assert program.render(scene).shape == (8, 16, 4)


VS = """
uniform float scale;
uniform vec3 offset;
uniform mat4 m;
attribute float weight;
varying float v_weight;
void main() {
    v_weight = weight * scale;
    gl_Position = m * gl_Vertex + vec4(offset, 0.0);
}
"""
FS = """
uniform int mode;
uniform bool flip;
uniform float table[3];
varying float v_weight;
void main() {
    if (v_weight < 0.0) discard;
    float t = table[mode];
    gl_FragColor = vec4(v_weight, t, flip ? 1.0 : 0.0, 1.0);
}
"""


def test_uniforms_and_vertex_batches():
    program = glslrun.Program.compile(VS, FS)
    program.set_uniform("scale", 2)  # a Python int sets a float uniform
    program.set_uniform("offset", [1.0, -2.0, 0.5])
    m = np.diag([2.0, 3.0, 4.0, 1.0]).astype(np.float32)
    m[0, 3] = 10.0  # a translation in x: row-major numpy, so GL's column order is m.T
    program.set_uniform("m", m.T)
    vertices = np.arange(12, dtype=np.float32).reshape(3, 4) + 1.0
    vertices[:, 3] = 1.0
    out = program.run_vertices({"gl_Vertex": vertices, "weight": np.array([1.0, -1.0, 0.25])})
    expected = vertices @ m.T + np.array([1.0, -2.0, 0.5, 0.0], dtype=np.float32)
    np.testing.assert_allclose(out["gl_Position"], expected, rtol=1e-6)
    np.testing.assert_allclose(out["v_weight"][:, 0], [2.0, -2.0, 0.5])


def test_vertex_batches_in_a_scenes_state():
    program = glslrun.Program.from_files(path("shaders", "colors.vert"), path("shaders", "colors.frag"))
    points = np.array([[0, 0, 0, 1], [1, 1, 0, 1], [0, 0, -1, 1]], dtype=np.float32)
    plain = program.run_vertices({"gl_Vertex": points})
    np.testing.assert_array_equal(plain["gl_Position"], points)  # GL's identity matrices
    # scenes/quad.toml: gluLookAt from (0, 0, 5), gluPerspective(45, 1, 1, 100).
    scene = glslrun.Scene.load(path("scenes", "quad.toml"))
    clip = program.run_vertices({"gl_Vertex": points}, scene=scene)["gl_Position"]
    f = 1 / np.tan(np.radians(22.5))
    eye_z = np.array([-5.0, -5.0, -6.0])
    np.testing.assert_allclose(clip[:, 3], -eye_z, rtol=1e-6)  # w = -z in eye space
    np.testing.assert_allclose(clip[:, 0], f * points[:, 0], rtol=1e-6, atol=1e-6)
    np.testing.assert_allclose(clip[:, 2], (101 * eye_z + 200) / -99, rtol=1e-5)
    with pytest.raises(IndexError):
        program.run_vertices({"gl_Vertex": points}, scene=scene, object=1)


def test_fragment_batches_with_int_bool_and_array_uniforms():
    program = glslrun.Program.compile(VS, FS)
    program.set_uniform("table", np.array([0.25, 0.5, 0.75]))
    program.set_uniform("table[2]", 0.875)
    program.set_uniform("mode", 2)
    program.set_uniform("flip", True)
    weights = np.array([0.1, -1.0, 0.3, 0.4, 0.5, 0.6, -0.5, 0.8], dtype=np.float32)
    out = program.run_fragments({"v_weight": weights})
    np.testing.assert_array_equal(out["discarded"][:, 0], weights < 0)
    kept = weights >= 0
    color = out["gl_FragColor"]
    np.testing.assert_allclose(color[kept, 0], weights[kept])
    np.testing.assert_array_equal(color[kept, 1:], np.tile([0.875, 1.0, 1.0], (kept.sum(), 1)))
    types = {u["name"]: u["type"] for u in program.uniforms}
    assert types["table"] == "float" and types["mode"] == "int" and types["m"] == "mat4"


def test_uniform_mistakes_are_errors():
    program = glslrun.Program.compile(VS, FS)
    with pytest.raises(glslrun.Error, match="no active uniform named 'nope'"):
        program.set_uniform("nope", 1.0)
    with pytest.raises(glslrun.Error, match="components"):
        program.set_uniform("offset", [1.0, 2.0])
    with pytest.raises(glslrun.Error, match="1.5 is not a 32-bit integer"):
        program.set_uniform("mode", 1.5)
    with pytest.raises(glslrun.Error, match="not a 32-bit integer"):
        program.set_uniform("mode", 2**31)
    with pytest.raises(glslrun.Error, match="precision"):
        program.precision = "exact"
    program.precision = "fast"
    assert program.precision == "fast"


def test_compile_errors_carry_file_and_line():
    with pytest.raises(glslrun.Error) as caught:
        glslrun.Program.compile("void main() { gl_Position = vec4(0.0); }\n",
                                [("lit.frag", "void main() {\n  gl_FragColor = undefined_thing;\n}\n")])
    assert "lit.frag:2: error:" in str(caught.value)
    file, line, message, warning = caught.value.diagnostics[0]
    assert (file, line, warning) == ("lit.frag", 2, False) and "undefined_thing" in message


def test_missing_files_are_errors():
    with pytest.raises(glslrun.Error, match="missing.vert"):
        glslrun.render(path("missing.vert"), SPOT[1], SPOT[2])
    with pytest.raises(glslrun.Error, match="nowhere.toml"):
        glslrun.Scene.load(path("nowhere.toml"))


def test_images_compare_and_round_trip(tmp_path):
    image = glslrun.render(path("shaders", "colors.vert"), path("shaders", "colors.frag"), path("scenes", "quad.toml"))
    glslrun.write_png(image, str(tmp_path / "quad.png"))
    np.testing.assert_array_equal(decode_png((tmp_path / "quad.png").read_bytes()), image)
    other = image.copy()
    other[10, 20] = [0, 0, 0, 0]
    stats = glslrun.compare_images(image, other, tolerance=1)
    assert not stats["passed"] and stats["differing"] == 1 and stats["worst"] == (20, 10)
    assert glslrun.compare_images(image, image)["passed"]


def test_bad_image_arrays_are_errors(tmp_path):
    out = str(tmp_path / "bad.png")
    # Issue #17: floats were cast (300 -> 44, NaN -> anything), and a side
    # past 2^31 narrowed to a negative int in the message.
    with pytest.raises(TypeError, match="H x W x 4 uint8 array"):
        glslrun.write_png(np.full((2, 2, 4), 300.0), out)
    with pytest.raises(ValueError, match="each side at most 16384"):
        glslrun.write_png(np.zeros((3000000000, 0, 4), np.uint8), out)
    with pytest.raises(ValueError, match="each side at most 16384"):
        glslrun.compare_images(np.zeros((0, 4294967297, 4), np.uint8), np.zeros((0, 1, 4), np.uint8))
    with pytest.raises(ValueError, match="H x W x 4"):
        glslrun.write_png(np.zeros((2, 2, 3), np.uint8), out)
    glslrun.write_png(np.zeros((2, 2, 4), np.uint8)[:, ::-1], out)  # any strides: copied


def test_error_report_as_a_dict():
    report = glslrun.error_report(path("shaders", "colors.vert"), path("shaders", "colors.frag"),
                                  path("scenes", "quad.toml"), mode="fast")
    assert report["mode"] == "fast" and report["size"] == "512x512"
    assert report["reference_image"].shape == (512, 512, 4)
    assert any(key.startswith("ablation.") for key in report)


def test_example_script(tmp_path):
    out = tmp_path / "spot.png"
    subprocess.run([sys.executable, path("examples", "render.py"), *SPOT, str(out)], check=True,
                   capture_output=True, env=dict(os.environ))
    np.testing.assert_array_equal(decode_png(out.read_bytes()), glslrun.render(*SPOT))


def test_check_undefined_as_dicts():
    # pow(t, 2.0) with t = x - 4 < 0 in the 8x8 image's left half (tests/undefined/pow.frag).
    findings = glslrun.check_undefined(path("tests", "undefined", "quad.vert"), path("tests", "undefined", "pow.frag"),
                                       path("tests", "undefined", "undefined.toml"), backend="interp")
    assert len(findings) == 1
    f = findings[0]
    assert (f["op"], f["stage"], f["line"], f["text"], f["count"]) == ("pow", "fragment", 5, "r = pow(t, 2.0);", 32)
    assert f["file"].endswith("pow.frag")
    assert f["first"]["pixel"] == (0, 7) and f["first"]["operands"] == [-4.0, 2.0]
    assert (f["reference"], f["precise"]) == (16.0, 16.0) and f["fast"] != f["fast"]  # Fast: NaN
    assert "NaN" in f["gpu"] and "measured" in f["gpu"]
    clean = glslrun.check_undefined(path("tests", "undefined", "quad.vert"), path("tests", "undefined", "none.frag"),
                                    path("tests", "undefined", "undefined.toml"))
    assert clean == []


def test_code_cache(tmp_path):
    """The JIT's code cache: a second program compiles nothing and renders the same bits;
    an unwritable directory is a RuntimeWarning, not an error."""
    if not glslrun.jit_available():
        # ctest says when the build has the JIT: then its plugin must load (no silent skip).
        assert not os.environ.get("GLSLRUN_TEST_JIT_BUILT"), "the JIT plugin did not load"
        pytest.skip("built without the JIT")
    scene = glslrun.Scene.parse("[output]\nsize = [32, 32]\n[[objects]]\nmesh = \"quad\"\n",
                                path("scenes", "inline.toml"))
    images, counts = [], []
    for _ in range(2):
        program = glslrun.Program.from_files(path("shaders", "colors.vert"), path("shaders", "colors.frag"))
        program.backend = "jit"
        program.cache_dir = str(tmp_path / "cache")
        assert program.cache
        images.append(program.render(scene))
        counts.append(program.jit_compiles)
    assert counts[0]["compiled"] > 0 and counts[0]["loaded"] == 0
    assert counts[1] == {"compiled": 0, "loaded": counts[0]["compiled"], "optimised": 0}
    np.testing.assert_array_equal(images[0], images[1])
    blocker = tmp_path / "file"
    blocker.write_text("not a directory")
    with pytest.warns(RuntimeWarning, match="cannot be written"):
        image = glslrun.render(*SPOT, backend="jit", cache_dir=str(blocker / "cache"))
    np.testing.assert_array_equal(image, glslrun.render(*SPOT, backend="interp", cache=False))


def test_jit_tiers(tmp_path):
    """The JIT's tiers: the first tier's code and the second's draw the interpreter's bits."""
    if not glslrun.jit_available():
        assert not os.environ.get("GLSLRUN_TEST_JIT_BUILT"), "the JIT plugin did not load"
        pytest.skip("built without the JIT")
    scene = glslrun.Scene.parse("[output]\nsize = [32, 32]\n[[objects]]\nmesh = \"quad\"\n",
                                path("scenes", "inline.toml"))
    images = {}
    for backend, tier in (("interp", "tiered"), ("jit", "first"), ("jit", "optimised")):
        program = glslrun.Program.from_files(path("shaders", "colors.vert"), path("shaders", "colors.frag"))
        program.backend = backend
        program.jit_tier = tier
        assert program.jit_tier == tier
        program.cache = False
        images[tier] = program.render(scene)
        if tier == "optimised":
            assert program.jit_compiles["optimised"] == 2
    np.testing.assert_array_equal(images["first"], images["tiered"])
    np.testing.assert_array_equal(images["optimised"], images["tiered"])
    with pytest.raises(ValueError, match="unknown JIT tier 'fastest'"):
        program.jit_tier = "fastest"


def test_include_dirs(tmp_path):
    # As the command line's -I: `#include` looks beside the including file, then in include_dirs.
    lib = tmp_path / "lib"
    lib.mkdir()
    (lib / "colour.glsl").write_text("vec4 colour() { return vec4(0.5, 1.0, 0.0, 1.0); }\n")
    main = tmp_path / "main.frag"
    main.write_text('#extension GL_GOOGLE_include_directive : require\n#include "colour.glsl"\n'
                    "void main() { gl_FragColor = colour(); }\n")
    flat = tmp_path / "flat.frag"
    flat.write_text("void main() { gl_FragColor = vec4(0.5, 1.0, 0.0, 1.0); }\n")
    vert, scene = path("shaders", "colors.vert"), path("scenes", "quad.toml")
    with pytest.raises(glslrun.Error, match="colour.glsl"):
        glslrun.Program.from_files(vert, str(main))
    glslrun.Program.from_files(vert, str(main), include_dirs=[str(lib)])
    glslrun.Program.compile(open(vert).read(), [(str(main), main.read_text())], include_dirs=[str(lib)])
    expected = glslrun.render(vert, str(flat), scene, backend="interp")
    np.testing.assert_array_equal(glslrun.render(vert, str(main), scene, backend="interp", include_dirs=[str(lib)]),
                                  expected)
    assert glslrun.check_undefined(vert, str(main), scene, backend="interp", include_dirs=[str(lib)]) == []
    report = glslrun.error_report(vert, str(main), scene, mode="fast", include_dirs=[str(lib)])
    assert report["mode"] == "fast"
