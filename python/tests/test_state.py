"""A scene's GL state from Python (Scene.set_state, set_camera, set_light,
...): each setter gives the image that the same keys in the scene file give,
and a mistake changes nothing."""
import numpy as np
import pytest

import glslrun

VS = """varying vec4 lit;
void main() {
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
    vec3 n = normalize(gl_NormalMatrix * gl_Normal);
    vec3 l = normalize(gl_LightSource[1].position.xyz);
    lit = gl_FrontMaterial.emission + gl_LightModel.ambient * gl_FrontMaterial.ambient
        + gl_LightSource[1].diffuse * gl_FrontMaterial.diffuse * max(dot(n, l), 0.0);
    gl_TexCoord[0] = gl_TextureMatrix[0] * vec4(0.5, 0.25, 0.0, 1.0);
    gl_FogFragCoord = 0.5 + gl_FogCoord * 0.25;
}"""
FS = """varying vec4 lit;
void main() {
    float f = clamp((gl_Fog.end - gl_FogFragCoord) * gl_Fog.scale, 0.0, 1.0);
    gl_FragColor = vec4(mix(gl_Fog.color.rgb, lit.rgb, f), 0.5) + vec4(gl_TexCoord[0].xy, 0.0, 0.0) * 0.25;
}"""

# Two overlapping quads at different depths; the camera looks at them from z = 3.
BASE = """[output]
size = [24, 24]
clear_color = [0.1, 0.2, 0.3, 1.0]
[[objects]]
mesh = "quad"
[[objects]]
mesh = "quad"
transform = [{ translate = [0.3, 0.2, 0.4] }, { scale = [0.6, 0.6, 1] }]
"""

# Each setter, and the same keys as the file writes them.
SETTINGS = [
    ("set_state", (), {"depth_test": True, "depth_func": "less", "blend": True,
                       "blend_func": ["src_alpha", "one_minus_src_alpha"], "color_writemask": [True, False, True, True],
                       "scissor_test": True, "scissor_box": [2, 3, 18, 16], "stencil_test": True,
                       "stencil_func": "always", "stencil_ref": 1, "stencil_pass_depth_pass": "replace",
                       "alpha_test": True, "alpha_test_func": "greater", "alpha_test_ref": 0.25, "cull_face": "back"},
     '[state]\ndepth_test = true\ndepth_func = "less"\nblend = true\n'
     'blend_func = ["src_alpha", "one_minus_src_alpha"]\ncolor_writemask = [true, false, true, true]\n'
     'scissor_test = true\nscissor_box = [2, 3, 18, 16]\nstencil_test = true\nstencil_func = "always"\n'
     'stencil_ref = 1\nstencil_pass_depth_pass = "replace"\nalpha_test = true\nalpha_test_func = "greater"\n'
     'alpha_test_ref = 0.25\ncull_face = "back"\n'),
    ("set_camera", (), {"look_at": {"eye": [0.5, 0.5, 3], "center": [0, 0, 0], "up": [0, 1, 0]},
                        "perspective": {"fovy": 50, "near": 1, "far": 10}},
     '[camera]\nlook_at = { eye = [0.5, 0.5, 3], center = [0, 0, 0], up = [0, 1, 0] }\n'
     'perspective = { fovy = 50, near = 1, far = 10 }\n'),
    ("set_light", (1,), {"diffuse": np.array([1.0, 0.5, 0.25]), "position": [1, 2, 3, 0]},
     '[lights.1]\ndiffuse = [1.0, 0.5, 0.25]\nposition = [1, 2, 3, 0]\n'),
    ("set_light_model", (), {"ambient": [0.3, 0.1, 0.1, 1]}, '[light_model]\nambient = [0.3, 0.1, 0.1, 1]\n'),
    ("set_material", (), {"diffuse": [0.2, 0.9, 0.4], "emission": [0.1, 0.0, 0.2]},
     '[material]\ndiffuse = [0.2, 0.9, 0.4]\nemission = [0.1, 0.0, 0.2]\n'),
    ("set_material", ("front",), {"ambient": [1, 1, 0]}, '[front_material]\nambient = [1, 1, 0]\n'),
    ("set_fog", (), {"color": [0.9, 0.1, 0.1], "start": 0.0, "end": 1.0}, '[fog]\ncolor = [0.9, 0.1, 0.1]\nstart = 0.0\nend = 1.0\n'),
    ("set_texture_matrix", (0,), {"transform": [{"scale": [2, 3, 1]}]},
     '[texture_matrix.0]\ntransform = [{ scale = [2, 3, 1] }]\n'),
    ("set_current", (), {"fog_coord": 1.0}, '[current]\nfog_coord = 1.0\n'),  # the quads have colours of their own
    ("set_state", (), {"polygon_stipple": True, "polygon_stipple_pattern": [0xAAAAAAAA, 0x55555555]},
     '[state]\npolygon_stipple = true\npolygon_stipple_pattern = [0xAAAAAAAA, 0x55555555]\n'),
]


@pytest.fixture(scope="module")
def program():
    return glslrun.Program.compile(VS, FS)


@pytest.mark.parametrize("method,args,keys,toml", SETTINGS, ids=[s[0] + str(s[1]) for s in SETTINGS])
def test_a_setter_gives_the_image_of_the_same_keys_in_the_file(program, method, args, keys, toml):
    # The camera first, so that the quads are lit and seen at an angle (the light's position follows it).
    camera = SETTINGS[1][3]
    from_file = program.render(glslrun.Scene.parse(BASE + camera + (toml if method != "set_camera" else "")))
    scene = glslrun.Scene.parse(BASE + camera)
    before = program.render(scene)
    getattr(scene, method)(*args, **keys)
    after = program.render(scene)
    if method != "set_camera":
        assert not np.array_equal(before, after), f"{method} changed nothing"
    assert np.array_equal(after, from_file)


def test_setters_apply_to_a_scene_built_in_code(program):
    scene = glslrun.Scene()
    scene.resize(16, 16)
    quad = np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], np.float32)
    scene.add_mesh(quad, normals=np.tile([0, 0, 1], (4, 1)), primitive="quads")
    plain = program.render(scene)
    scene.set_material(diffuse=[0, 0, 0], emission=[1, 0, 0])
    assert not np.array_equal(plain, program.render(scene))
    scene.set_state(color_writemask=[False, False, False, False])
    empty = glslrun.Scene()
    empty.resize(16, 16)
    assert np.array_equal(program.render(scene), program.render(empty))  # the clear alone: nothing written


def test_a_mistake_raises_and_changes_nothing(program):
    scene = glslrun.Scene.parse(BASE)
    before = program.render(scene)
    with pytest.raises(glslrun.Error, match="did you mean 'depth_test'") as e:
        scene.set_state(blend=True, depth_tset=True)
    assert e.value.diagnostics[0][0] == "set_state"
    with pytest.raises(glslrun.Error, match="depth_func"):
        scene.set_state(blend=True, depth_func="sometimes")
    with pytest.raises(glslrun.Error):
        scene.set_light(0, diffuse=[float("nan"), 0, 0])
    with pytest.raises(ValueError, match="light 8 is not 0..7"):
        scene.set_light(8, diffuse=[1, 0, 0])
    with pytest.raises(ValueError, match="face 'side'"):
        scene.set_material("side", diffuse=[1, 0, 0])
    with pytest.raises(TypeError, match="blend: object is not a value"):
        scene.set_state(blend=object())
    assert np.array_equal(before, program.render(scene))  # blend=True of the failed calls never applied


def test_a_scene_whose_objects_have_their_own_state_refuses_state_setters():
    scene = glslrun.Scene.parse(BASE + '[[objects]]\nmesh = "quad"\nstate = { depth_test = true }\n')
    with pytest.raises(glslrun.Error, match="objects have state of their own"):
        scene.set_state(blend=True)
    scene.set_camera(perspective={"fovy": 40, "near": 1, "far": 5})  # the camera reaches every draw


def test_the_setters_have_docstrings():
    for name in ("set_state", "set_camera", "set_light", "set_light_model", "set_material", "set_fog",
                 "set_current", "set_texture_matrix"):
        doc = getattr(glslrun.Scene, name).__doc__
        assert doc and "scene file" in doc, name
    assert "stencil_func" in glslrun.Scene.set_state.__doc__
