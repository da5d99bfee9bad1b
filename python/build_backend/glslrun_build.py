"""glslrun's PEP 517 build backend (pyproject.toml): drives the project's own
CMake build and packs its `python` install component into a wheel.

Standard library only, so that `pip install .` works offline in a fresh venv
with build isolation (nothing to download); cmake, a C++ compiler, pybind11
and the other build dependencies come from the system (tools/setup.sh).

config settings (`pip install . -C build-dir=DIR`, `python3 -m build -C ...`):
  build-dir   the CMake build directory (default: build/wheel-<python tag>
              under the source). An already configured one is built as it
              is: CI passes its own build, so the wheel costs one install.
Environment: CMAKE_ARGS (extra configure arguments, split on spaces),
CMAKE_BUILD_PARALLEL_LEVEL (as for cmake --build).
"""
import base64
import hashlib
import io
import os
import re
import shutil
import subprocess
import sys
import sysconfig
import tarfile
import tempfile
import zipfile

SOURCE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
NAME = "glslrun"


def _version():
    with open(os.path.join(SOURCE, "CMakeLists.txt"), encoding="utf-8") as f:
        match = re.search(r"project\(glslrun\s+VERSION\s+([0-9.]+)", f.read())
    if not match:
        raise RuntimeError("no `project(glslrun VERSION x.y.z)` in CMakeLists.txt")
    return match.group(1)


def _tag():
    python = f"cp{sys.version_info.major}{sys.version_info.minor}"
    platform = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return f"{python}-{python}-{platform}"


def _metadata():
    with open(os.path.join(SOURCE, "README.md"), encoding="utf-8") as f:
        readme = f.read()
    return (
        "Metadata-Version: 2.1\n"
        f"Name: {NAME}\n"
        f"Version: {_version()}\n"
        "Summary: Legacy GLSL (1.10/1.20) on the CPU: render scenes and run shaders headless\n"
        "License: MIT\n"
        "Requires-Python: >=3.9\n"
        "Requires-Dist: numpy\n"
        "Description-Content-Type: text/markdown\n"
        "\n" + readme
    )


def _run(command):
    print("+", " ".join(command), flush=True)
    subprocess.run(command, check=True, stdout=sys.stderr)


def _build(build_dir, staging):
    """Configures (unless build_dir already is a build), builds the Python
    module and installs the `python` component into staging."""
    if not os.path.exists(os.path.join(build_dir, "CMakeCache.txt")):
        configure = ["cmake", "-S", SOURCE, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release",
                     f"-DPython3_EXECUTABLE={sys.executable}", "-DGLSLRUN_BUILD_TESTS=OFF"]
        if shutil.which("ninja"):
            configure += ["-G", "Ninja"]
        if shutil.which("ccache"):
            configure += ["-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"]
        configure += os.environ.get("CMAKE_ARGS", "").split()
        _run(configure)
    _run(["cmake", "--build", build_dir, "--target", "glslrun_python"])
    _run(["cmake", "--install", build_dir, "--component", "python", "--strip", "--prefix", staging])
    packages = []
    for root, dirs, _ in os.walk(staging):
        if NAME in dirs and os.path.exists(os.path.join(root, NAME, "py.typed")):
            packages.append(os.path.join(root, NAME))
    if len(packages) != 1:
        raise RuntimeError(f"the python component installed {len(packages)} glslrun packages under {staging}")
    package = packages[0]
    suffix = sysconfig.get_config_var("EXT_SUFFIX")
    if not os.path.exists(os.path.join(package, "__init__" + suffix)):
        raise RuntimeError(f"{build_dir} builds the module for another Python than {sys.executable} "
                           f"(no __init__{suffix} in {package}): pass another build-dir")
    return package


def _record_line(name, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{name},sha256={digest},{len(data)}"


def _write_wheel(path, package):
    dist_info = f"{NAME}-{_version()}.dist-info"
    files = []
    for root, _, names in os.walk(package):
        for n in sorted(names):
            full = os.path.join(root, n)
            with open(full, "rb") as f:
                files.append((f"{NAME}/{os.path.relpath(full, package)}", f.read()))
    with open(os.path.join(SOURCE, "LICENSE"), "rb") as f:
        files.append((f"{dist_info}/LICENSE", f.read()))
    files.append((f"{dist_info}/METADATA", _metadata().encode()))
    wheel = f"Wheel-Version: 1.0\nGenerator: glslrun_build\nRoot-Is-Purelib: false\nTag: {_tag()}\n"
    files.append((f"{dist_info}/WHEEL", wheel.encode()))
    record = [_record_line(name, data) for name, data in files] + [f"{dist_info}/RECORD,,"]
    files.append((f"{dist_info}/RECORD", ("\n".join(record) + "\n").encode()))
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as z:
        for name, data in files:
            info = zipfile.ZipInfo(name, date_time=(2026, 1, 1, 0, 0, 0))
            info.external_attr = (0o755 if name.endswith(".so") else 0o644) << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            z.writestr(info, data)


# ---------------------------------------------------------------- PEP 517 ---

def get_requires_for_build_wheel(config_settings=None):
    return []


def get_requires_for_build_sdist(config_settings=None):
    return []


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    settings = config_settings or {}
    build_dir = settings.get("build-dir") or os.path.join(SOURCE, "build", "wheel-" + _tag().split("-")[0])
    build_dir = os.path.abspath(build_dir)
    name = f"{NAME}-{_version()}-{_tag()}.whl"
    with tempfile.TemporaryDirectory() as staging:
        package = _build(build_dir, staging)
        _write_wheel(os.path.join(wheel_directory, name), package)
    return name


def build_sdist(sdist_directory, config_settings=None):
    """The tracked source files (git ls-files), which build_wheel builds."""
    base = f"{NAME}-{_version()}"
    listed = subprocess.run(["git", "-C", SOURCE, "ls-files", "-z"], check=True, capture_output=True).stdout
    name = base + ".tar.gz"
    with tarfile.open(os.path.join(sdist_directory, name), "w:gz", format=tarfile.PAX_FORMAT) as tar:
        for path in sorted(p for p in listed.decode().split("\0") if p):
            if os.path.isfile(os.path.join(SOURCE, path)):
                tar.add(os.path.join(SOURCE, path), arcname=f"{base}/{path}", recursive=False)
        info = tarfile.TarInfo(f"{base}/PKG-INFO")
        data = _metadata().encode()
        info.size = len(data)
        tar.addfile(info, io.BytesIO(data))
    return name
