# The type stub of `import glslrun` (python/module.cpp, python/module_scene.cpp),
# installed as glslrun/__init__.pyi with py.typed. CI checks it with
# mypy.stubtest against the built module and `mypy --strict` over
# examples/render.py and python/tests/typed_use.py.
from typing import Any, Sequence, Union

import numpy as np
import numpy.typing as npt

__version__: str

# A number, a sequence of numbers (nested as deep as wanted) or a numpy array.
_Numbers = Union[float, int, bool, Sequence[Any], npt.NDArray[Any]]
_Image = npt.NDArray[np.uint8]  # H x W x 4 RGBA8, top row first
_Outputs = dict[str, npt.NDArray[np.float32]]  # name -> (count, components)
# A value of a scene file's key (docs/scene-format.md): number, bool, string,
# list, numpy array or table.
_SceneValue = Union[float, int, bool, str, Sequence[Any], dict[str, Any], npt.NDArray[Any]]

class Error(RuntimeError):
    # (file, line, message, warning) per diagnostic.
    diagnostics: list[tuple[str, int, str, bool]]

class Scene:
    def __init__(self) -> None: ...
    @staticmethod
    def load(path: str) -> Scene: ...
    @staticmethod
    def parse(toml: str, path: str = "<string>") -> Scene: ...
    @property
    def path(self) -> str: ...
    @property
    def width(self) -> int: ...
    @property
    def height(self) -> int: ...
    @property
    def objects(self) -> int: ...
    @property
    def warnings(self) -> list[str]: ...
    def resize(self, width: int, height: int) -> None: ...
    def add_mesh(
        self,
        positions: _Numbers,
        *,
        normals: _Numbers | None = None,
        texcoords: _Numbers | None = None,
        colors: _Numbers | None = None,
        indices: _Numbers | None = None,
        primitive: str = "triangles",
        uniforms: dict[str, _Numbers] | None = None,
    ) -> int: ...
    def set_texture(
        self,
        unit: int,
        image: _Numbers,
        *,
        linear: bool = True,
        wrap: str | None = None,
        mipmaps: bool | None = None,
        top_down: bool = False,
        target: str = "2d",
    ) -> None: ...
    # The GL state of the scene file's sections, keyword by keyword.
    def set_state(self, **kwargs: _SceneValue) -> None: ...
    def set_camera(self, **kwargs: _SceneValue) -> None: ...
    def set_light(self, light: int, **kwargs: _SceneValue) -> None: ...
    def set_light_model(self, **kwargs: _SceneValue) -> None: ...
    def set_material(self, face: str = "front_and_back", **kwargs: _SceneValue) -> None: ...
    def set_fog(self, **kwargs: _SceneValue) -> None: ...
    def set_current(self, **kwargs: _SceneValue) -> None: ...
    def set_texture_matrix(self, unit: int, **kwargs: _SceneValue) -> None: ...

class Program:
    @staticmethod
    def compile(
        vertex: Union[str, Sequence[tuple[str, str]], None],
        fragment: Union[str, Sequence[tuple[str, str]], None],
        default_version: int = 110,
        optimize: bool = True,
        *,
        include_dirs: Sequence[str] = ...,
    ) -> Program: ...
    @staticmethod
    def from_files(
        vertex: Union[str, Sequence[str], None],
        fragment: Union[str, Sequence[str], None],
        default_version: int = 110,
        optimize: bool = True,
        *,
        include_dirs: Sequence[str] = ...,
    ) -> Program: ...
    def set_uniform(self, name: str, value: _Numbers) -> None: ...
    def has_uniform(self, name: str) -> bool: ...
    @property
    def uniforms(self) -> list[dict[str, Any]]: ...
    threads: int
    precision: str
    backend: str
    jit_tier: str
    cache_dir: str
    cache: bool
    @property
    def jit_compiles(self) -> dict[str, int]: ...
    max_loop_iterations: int
    max_draw_instructions: int
    max_render_instructions: int
    def dump_ir(self) -> str: ...
    def run_vertices(
        self, inputs: dict[str, _Numbers], count: int = 0, scene: Scene | None = None, object: int = 0
    ) -> _Outputs: ...
    def run_fragments(
        self, inputs: dict[str, _Numbers], count: int = 0, scene: Scene | None = None, object: int = 0
    ) -> _Outputs: ...
    def render(
        self, scene: Scene, *, uniforms: dict[str, _Numbers] | None = None, time_limit: float = 0.0
    ) -> _Image: ...

def render(
    vertex: str | None = None,
    fragment: str | None = None,
    scene: str | None = None,
    threads: int = 0,
    precision: str = "precise",
    *,
    uniforms: dict[str, _Numbers] | None = None,
    backend: str = "auto",
    time_limit: float = 0.0,
    cache_dir: str = "",
    cache: bool = True,
    include_dirs: Sequence[str] = ...,
) -> _Image: ...
def jit_available() -> bool: ...
def read_png(path: str) -> _Image: ...
def write_png(image: _Image, path: str) -> None: ...
def compare_images(reference: _Image, actual: _Image, tolerance: int = 1) -> dict[str, Any]: ...
def error_report(
    vertex: str | None = None,
    fragment: str | None = None,
    scene: str | None = None,
    mode: str = "fast",
    threads: int = 0,
    *,
    include_dirs: Sequence[str] = ...,
) -> dict[str, Any]: ...
def check_undefined(
    vertex: str | None = None,
    fragment: str | None = None,
    scene: str | None = None,
    precision: str = "precise",
    *,
    backend: str = "auto",
    include_dirs: Sequence[str] = ...,
) -> list[dict[str, Any]]: ...
