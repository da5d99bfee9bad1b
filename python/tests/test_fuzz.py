"""A short fuzz run of the Python module with hypothesis (Debian's
python3-hypothesis): arbitrary arguments to every entry point must end in a
return or an ordinary exception (glslrun.Error, TypeError, ValueError,
IndexError, OverflowError), never a crash. Bounded to a few seconds: a fixed
number of examples, derandomized so that CI runs the same ones each time."""
import os

import numpy as np
import pytest

import glslrun

hypothesis = pytest.importorskip("hypothesis")
from hypothesis import HealthCheck, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402
from hypothesis.extra import numpy as hnp  # noqa: E402

SOURCE = os.environ.get("GLSLRUN_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
EXPECTED = (glslrun.Error, TypeError, ValueError, IndexError, OverflowError)
FUZZ = settings(max_examples=150, deadline=None, derandomize=True, database=None,
                suppress_health_check=list(HealthCheck))

VS = ("uniform mat4 m; uniform int k; attribute vec4 a;"
      " void main() { gl_Position = m * gl_Vertex + a * float(k); gl_TexCoord[0] = a; }")
FS = ("uniform float f[4]; uniform bool b; uniform sampler2D t;"
      " void main() { gl_FragColor = texture2D(t, gl_TexCoord[0].st) * f[1] + vec4(b); }")
PROGRAM = glslrun.Program.compile(VS, FS)

names = st.sampled_from(["m", "k", "f", "f[3]", "f[4]", "b", "t", "a", "gl_ModelViewMatrix", "", "m[0]", "x\0y"])
shapes = hnp.array_shapes(min_dims=0, max_dims=3, min_side=0, max_side=6)
dtypes = st.sampled_from([np.float32, np.float64, np.int32, np.int64, np.uint8, np.bool_, np.complex64])
arrays = st.one_of(hnp.arrays(dtypes, shapes, elements=None),
                   st.builds(lambda n: np.broadcast_to(np.float32(1), (n, 4)),
                             st.sampled_from([0, 1, 3, 2**26 + 1, 2**40])))
values = st.one_of(st.integers(), st.floats(allow_nan=True), st.lists(st.floats(), max_size=20), arrays,
                   st.text(max_size=4), st.none())


@FUZZ
@given(name=names, value=values)
def test_set_uniform(name, value):
    try:
        PROGRAM.set_uniform(name, value)
    except EXPECTED:
        pass


@FUZZ
@given(inputs=st.dictionaries(st.sampled_from(["gl_Vertex", "a", "gl_Color", "gl_FragCoord", "none"]), arrays,
                              max_size=3),
       count=st.one_of(st.just(0), st.integers(0, 300), st.sampled_from([2**32 - 1, 2**26 + 1, -1, 2**64])),
       vertices=st.booleans())
def test_run_batches(inputs, count, vertices):
    run = PROGRAM.run_vertices if vertices else PROGRAM.run_fragments
    try:
        out = run(inputs, count=count)
        assert all(isinstance(v, np.ndarray) for v in out.values())
    except EXPECTED:
        pass


images = st.one_of(hnp.arrays(st.sampled_from([np.uint8, np.float32, np.int16]), shapes),
                   st.builds(lambda h, w: np.broadcast_to(np.zeros(4, np.uint8), (h, w, 4)),
                             st.sampled_from([0, 1, 5, 16385, 2**20]), st.sampled_from([0, 2, 16384, 2**20])))


@FUZZ
@given(a=images, b=images, tolerance=st.integers(-3, 300))
def test_compare_images(a, b, tolerance):
    try:
        glslrun.compare_images(a, b, tolerance=tolerance)
    except EXPECTED:
        pass


@FUZZ
@given(text=st.text(max_size=200), size=st.tuples(st.integers(-2, 40), st.integers(-2, 40)))
def test_scene_parse_and_render(text, size):
    toml = '[output]\nsize = [8, 8]\n[[objects]]\nmesh = "quad"\n' + text
    try:
        scene = glslrun.Scene.parse(toml, os.path.join(SOURCE, "scenes", "inline.toml"))
        scene.resize(*size)
        PROGRAM.render(scene, time_limit=2)
    except EXPECTED:
        pass
