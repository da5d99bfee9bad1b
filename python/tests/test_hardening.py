"""The Python module under abuse: arguments past every limit come back as
glslrun.Error or ValueError, never as a crash, MemoryError or a hang."""
import os
import sys
import time

import numpy as np
import pytest

import glslrun

SOURCE = os.environ.get("GLSLRUN_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))

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
    # Multiples of 4: a fragment count must be one (a quad is four fragments).
    for count in (2**32 - 4, (1 << 26) + 4):
        with pytest.raises(glslrun.Error, match="too many"):
            p.run_vertices({}, count=count)
        with pytest.raises(glslrun.Error, match="too many"):
            p.run_fragments({}, count=count)
    with pytest.raises(TypeError):
        p.run_vertices({}, count=-1)


def test_a_nul_byte_in_any_path_is_an_error(tmp_path):
    image = np.zeros((2, 2, 4), np.uint8)
    cut = tmp_path / "a"
    with pytest.raises(glslrun.Error, match="NUL byte"):
        glslrun.write_png(image, str(cut) + "\0.png")
    assert not cut.exists()  # the path was cut at the NUL: `a` was written
    glslrun.write_png(image, str(cut))
    with pytest.raises(glslrun.Error, match="NUL byte"):
        glslrun.read_png(str(cut) + "\0ignored")
    with pytest.raises(glslrun.Error, match="NUL byte"):
        glslrun.Scene.load(os.path.join(SOURCE, "scenes", "quad.toml") + "\0x")
    with pytest.raises(glslrun.Error, match="NUL byte"):
        glslrun.Program.from_files(os.path.join(SOURCE, "shaders", "colors.vert") + "\0x",
                                   os.path.join(SOURCE, "shaders", "colors.frag"))
    # A texture path inside a scene (TOML's \u0000) loaded another file.
    (tmp_path / "t.png").write_bytes(cut.read_bytes())
    with pytest.raises(glslrun.Error, match="NUL byte"):
        glslrun.Scene.parse('[output]\nsize = [4, 4]\n[textures.0]\nimage = "t.png\\u0000.jpg"\n'
                            '[[objects]]\nmesh = "quad"\n', str(tmp_path / "s.toml"))
    glslrun.Scene.parse('[output]\nsize = [4, 4]\n[textures.0]\nimage = "t.png"\n[[objects]]\nmesh = "quad"\n',
                        str(tmp_path / "s.toml"))


# A two-line shader whose loop stays under every per-batch cap: minutes at 512x512.
LONG_FS = ("uniform int n; void main() { float s = 0.0;"
           " for (int i = 0; i < n; ++i) s += sin(float(i)); gl_FragColor = vec4(s); }")
LONG_SCENE = '[output]\nsize = [512, 512]\n[uniforms]\nn = 4000000\n[[objects]]\nmesh = "quad"\n'


def test_a_time_limit_ends_a_long_render_with_an_error():
    p = glslrun.Program.compile(VS, LONG_FS)
    scene = glslrun.Scene.parse(LONG_SCENE, os.path.join(SOURCE, "scenes", "inline.toml"))
    with pytest.raises(glslrun.Error, match="time limit ran out"):
        p.render(scene, time_limit=0.3)


def test_ctrl_c_stops_a_long_render_within_a_second(tmp_path):
    import signal
    import subprocess
    import sys
    import time
    script = tmp_path / "long.py"
    script.write_text(f"""
import sys, time, glslrun
p = glslrun.Program.compile({VS!r}, {LONG_FS!r})
scene = glslrun.Scene.parse({LONG_SCENE!r}, {os.path.join(SOURCE, "scenes", "inline.toml")!r})
print("rendering", flush=True)
try:
    p.render(scene)
except KeyboardInterrupt:
    print("interrupted", flush=True)
    sys.exit(3)
""")
    child = subprocess.Popen([sys.executable, str(script)], stdout=subprocess.PIPE, text=True,
                             env=dict(os.environ))
    try:
        assert child.stdout.readline().strip() == "rendering"
        time.sleep(0.5)  # into the draw
        sent = time.monotonic()
        child.send_signal(signal.SIGINT)
        out, _ = child.communicate(timeout=30)
        elapsed = time.monotonic() - sent
    finally:
        child.kill()
    assert child.returncode == 3 and "interrupted" in out
    # Within a second on an idle machine (about 20 ms); some room for a loaded one.
    assert elapsed < 3, f"{elapsed:.2f} s from SIGINT to exit"


def test_a_render_of_many_draws_stops_at_its_instruction_budget():
    # Eight draws, each well within the draw's budget: together past the render's.
    objects = '[[objects]]\nmesh = "quad"\n' * 8
    scene = glslrun.Scene.parse("[output]\nsize = [64, 64]\n" + objects)
    p = glslrun.Program.compile(VS, "uniform int n; void main() { float s = 0.0; "
                                "for (int i = 0; i < n; ++i) s += float(i); gl_FragColor = vec4(s); }")
    p.set_uniform("n", 4000)
    assert p.max_draw_instructions == 2**32 and p.max_render_instructions == 2**36
    p.render(scene)
    p.max_draw_instructions = 2**23  # each draw takes 4.2M
    p.max_render_instructions = 2**23
    with pytest.raises(glslrun.Error, match="the render executed more than 8388608 instructions, its draws together"):
        p.render(scene)
    p.max_render_instructions = 2**36
    p.render(scene)
    p.max_draw_instructions = 2**16
    with pytest.raises(glslrun.Error, match="the draw executed more than 65536 instructions"):
        p.render(scene)


def test_a_scene_past_16_mib_is_refused_before_it_is_parsed(tmp_path):
    # 56 MB of numbers, under the 64 MiB text limit, needed 2.4 GB of TOML tree.
    text = "[output]\nsize = [4, 4]\n[uniforms]\nbig = [" + "0," * (8 << 20) + "0]\n"
    with pytest.raises(glslrun.Error, match="limit is 16 MiB"):
        glslrun.Scene.parse(text)
    big = tmp_path / "big.toml"
    big.write_text(text)
    with pytest.raises(glslrun.Error, match="limit is 16 MiB"):
        glslrun.Scene.load(str(big))


def texture_scene(image):
    path = os.path.join(SOURCE, "tests", "hardening", image)
    return glslrun.Scene.parse(f'[output]\nsize = [4, 4]\n[textures.0]\nimage = "{path}"\nmin_filter = "linear"\n'
                               '[[objects]]\nmesh = "quad"\n', os.path.join(SOURCE, "scenes", "inline.toml"))


def test_jpeg_decoding_is_bounded_by_its_scans_and_its_data(tmp_path):
    texture_scene("jpeg_progressive.jpg")  # 10 scans: read as before
    # The same file with one scan repeated 3000 times (100,000 took 110 s in stb_image).
    with pytest.raises(glslrun.Error, match="more than 500 scans"):
        texture_scene("jpeg_3000_scans.jpg")
    # The reproducer itself: one scan repeated 100,000 times (1.4 MB) ends at the scan limit, at once.
    sys.path.insert(0, os.path.join(SOURCE, "tests", "hardening"))
    import jpeg_scans
    base = jpeg_scans.progressive(16)
    path = tmp_path / "scans.jpg"
    path.write_bytes(jpeg_scans.repeat_scan(base, 1, 100_000))
    start = time.monotonic()
    with pytest.raises(glslrun.Error, match="more than 500 scans"):
        texture_scene(str(path))
    assert time.monotonic() - start < 2
    # Under the scan limit, the work: the largest texture's progressive file (6 scans of grey, 1.5M
    # block visits) decodes; the same with its last scan (a refinement) 70 times, 68 KB,
    # asks for 19.7M, past 2^24.
    big = jpeg_scans.progressive(4096, grey=True)
    path.write_bytes(big)
    assert texture_scene(str(path)).width == 4
    path.write_bytes(jpeg_scans.repeat_scan(big, 5, 70))
    start = time.monotonic()
    with pytest.raises(glslrun.Error, match="more than 16777216 block decodes"):
        texture_scene(str(path))
    assert time.monotonic() - start < 2
    # An 8x8 baseline JPEG whose header says 4000x4000: decoded as 16M grey texels before.
    with pytest.raises(glslrun.Error, match="header lies about the size"):
        texture_scene("jpeg_lying_size.jpg")
