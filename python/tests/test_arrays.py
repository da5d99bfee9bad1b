"""Scenes from numpy arrays (python/module_mesh.cpp): meshes and textures
without a scene file, checked against the same scene written as TOML."""
import numpy as np
import pytest

import glslrun

COLOR_VS = "void main() { gl_FrontColor = gl_Color; gl_Position = gl_Vertex; }\n"
COLOR_FS = "void main() { gl_FragColor = gl_Color; }\n"
TEX_VS = "void main() { gl_TexCoord[0] = gl_MultiTexCoord0; gl_Position = gl_Vertex; }\n"
TEX_FS = "uniform sampler2D t;\nvoid main() { gl_FragColor = texture2D(t, gl_TexCoord[0].st); }\n"

POSITIONS = np.array([[-1, -1, 0], [1, -1, 0], [-1, 1, 0], [1, 1, 0]], np.float32)
COLORS = np.array([[1, 0, 0, 1], [0, 1, 0, 1], [0, 0, 1, 1], [1, 1, 0, 1]], np.float32)


def test_a_mesh_from_arrays_equals_the_same_mesh_from_toml():
    program = glslrun.Program.compile(COLOR_VS, COLOR_FS)
    toml = glslrun.Scene.parse("""
[output]
size = [16, 16]
[[objects]]
mesh = "arrays"
primitive = "triangle_strip"
vertices = [[-1, -1, 0], [1, -1, 0], [-1, 1, 0], [1, 1, 0]]
colors = [[1, 0, 0, 1], [0, 1, 0, 1], [0, 0, 1, 1], [1, 1, 0, 1]]
""")
    scene = glslrun.Scene()
    scene.resize(16, 16)
    assert scene.add_mesh(POSITIONS, colors=COLORS, primitive="triangle_strip") == 0
    expected = program.render(toml)
    image = program.render(scene)
    assert image.any()
    np.testing.assert_array_equal(image, expected)
    # The same quad as indexed triangles.
    indexed = glslrun.Scene()
    indexed.resize(16, 16)
    indexed.add_mesh(POSITIONS, colors=COLORS, indices=np.array([0, 1, 2, 2, 1, 3]))
    np.testing.assert_array_equal(program.render(indexed), expected)


# Red, green over blue, white: row 0 is the top of the picture.
PICTURE = np.array([[[255, 0, 0, 255], [0, 255, 0, 255]],
                    [[0, 0, 255, 255], [255, 255, 255, 255]]], np.uint8)


def textured_square(fragment):
    """An 8x8 scene filled by a square with s, t over [0, 1], and its program."""
    scene = glslrun.Scene()
    scene.resize(8, 8)
    uv = (POSITIONS[:, :2] + 1) / 2
    scene.add_mesh(POSITIONS, texcoords=uv, primitive="triangle_strip", uniforms={"t": 0})
    return glslrun.Program.compile(TEX_VS, fragment), scene


def test_a_texture_from_an_array_is_upright():
    program, scene = textured_square(TEX_FS)
    picture = PICTURE
    scene.set_texture(0, picture, linear=False, mipmaps=False)
    image = program.render(scene)  # top row first, as the picture
    assert tuple(image[0, 0]) == (255, 0, 0, 255) and tuple(image[0, 7]) == (0, 255, 0, 255)
    assert tuple(image[7, 0]) == (0, 0, 255, 255) and tuple(image[7, 7]) == (255, 255, 255, 255)
    # Floats, with mipmaps (GL's default minifying filter needs them).
    scene.set_texture(0, picture.astype(np.float32) / 255)
    assert program.render(scene)[0, 0, 0] > 128


RECT_FS = """
uniform sampler2DRect t;
void main() { gl_FragColor = texture2DRect(t, gl_TexCoord[0].st * vec2(2.0)); }
"""


def test_a_rectangle_texture_is_addressed_in_texels():
    program, scene = textured_square(RECT_FS)
    picture = PICTURE
    # s, t in [0, 2]: texels, not [0, 1]; no mipmaps, clamp_to_edge (GL's rectangle defaults).
    scene.set_texture(0, picture, linear=False, target="rectangle")
    image = program.render(scene)
    assert tuple(image[0, 0]) == (255, 0, 0, 255) and tuple(image[7, 7]) == (255, 255, 255, 255)
    with pytest.raises(ValueError, match="no mipmaps"):
        scene.set_texture(0, picture, target="rectangle", mipmaps=True)
    with pytest.raises(ValueError, match="not repeat"):
        scene.set_texture(0, picture, target="rectangle", wrap="repeat")
    with pytest.raises(ValueError, match="target 'rect'"):
        scene.set_texture(0, picture, target="rect")


ARRAY2D_FS = """
#extension GL_EXT_texture_array : enable
uniform sampler2DArray t;
uniform float layer;
void main() { gl_FragColor = texture2DArray(t, vec3(gl_TexCoord[0].st, layer)); }
"""

ARRAY1D_FS = """
#extension GL_EXT_texture_array : enable
uniform sampler1DArray t;
uniform float layer;
void main() { gl_FragColor = texture1DArray(t, vec2(gl_TexCoord[0].s, layer)); }
"""


def test_array_textures_pick_their_layer():
    """EXT_texture_array from numpy: a leading axis of layers, each layer upright as a 2D picture."""
    program, scene = textured_square(ARRAY2D_FS)
    layers = np.stack([PICTURE, 255 - PICTURE[::-1]])  # layer 1: another picture
    layers[1, :, :, 3] = 255
    scene.set_texture(0, layers, linear=False, mipmaps=False, target="2d_array")
    for layer in (0, 1):
        image = program.render(scene, uniforms={"layer": layer})
        picture = layers[layer]
        assert tuple(image[0, 0]) == tuple(picture[0, 0]) and tuple(image[0, 7]) == tuple(picture[0, 1])
        assert tuple(image[7, 0]) == tuple(picture[1, 0]) and tuple(image[7, 7]) == tuple(picture[1, 1])
    # A list of images is the same array; with mipmaps, per layer (a layer's average stays its own).
    scene.set_texture(0, list(layers), target="2d_array")
    assert tuple(program.render(scene, uniforms={"layer": 1})[0, 0]) != tuple(
        program.render(scene, uniforms={"layer": 0})[0, 0])
    # 1D arrays: layer l is row l of the array, never flipped.
    program, scene = textured_square(ARRAY1D_FS)
    rows = np.array([[[255, 0, 0, 255], [0, 255, 0, 255]], [[0, 0, 255, 255], [255, 255, 255, 255]]], np.uint8)
    scene.set_texture(0, rows, linear=False, mipmaps=False, target="1d_array")
    for layer in (0, 1):
        image = program.render(scene, uniforms={"layer": layer})
        assert tuple(image[7, 0]) == tuple(rows[layer, 0]) and tuple(image[0, 7]) == tuple(rows[layer, 1])
    with pytest.raises(TypeError, match="L x H x W"):
        scene.set_texture(0, PICTURE[:, :, 0], target="2d_array")  # a picture without its axis of layers
    with pytest.raises(TypeError, match="layers 1..2048"):
        scene.set_texture(0, np.zeros((2049, 1, 1), np.uint8), target="2d_array")
    with pytest.raises(ValueError, match="at most 16777216 texels"):
        scene.set_texture(0, np.broadcast_to(np.uint8(0), (2048, 4096, 4096)), target="2d_array")


def test_array_mistakes_are_errors():
    scene = glslrun.Scene()
    with pytest.raises(ValueError, match="positions"):
        scene.add_mesh(np.ones((4, 5), np.float32))
    with pytest.raises(ValueError, match="normals must be an array of shape \\(4, 3\\)"):
        scene.add_mesh(POSITIONS, normals=np.ones((3, 3)))
    with pytest.raises(ValueError, match="indices\\[1\\] = 4 is not a vertex"):
        scene.add_mesh(POSITIONS, indices=[0, 4, 1])
    with pytest.raises(ValueError, match="primitive 'tris'"):
        scene.add_mesh(POSITIONS, primitive="tris")
    with pytest.raises(ValueError, match="texture units"):
        scene.set_texture(16, np.zeros((2, 2, 4), np.uint8))
    with pytest.raises(TypeError):
        scene.set_texture(0, np.zeros((2, 2, 2), np.uint8))
    with pytest.raises(ValueError, match="wrap 'loop'"):
        scene.set_texture(0, np.zeros((2, 2, 4), np.uint8), wrap="loop")
    assert scene.objects == 0
    passes = glslrun.Scene.parse('[[objects]]\nmesh = "quad"\n[[passes]]\nname = "one"\n')
    with pytest.raises(ValueError, match="passes"):
        passes.add_mesh(POSITIONS)
