#!/bin/sh
# Python as Python users install it, offline: the wheel built by Debian's
# python3-build through pyproject.toml's backend (from this build's objects),
# installed into a fresh venv (--system-site-packages for numpy), imported
# and rendered with there; then `pip install .` the same way; the type stub
# checked against the module (mypy.stubtest) and the examples with
# `mypy --strict`; help() shows the docstrings.
#   wheel.sh SOURCE_DIR BUILD_DIR [PYTHON]
set -eu
src=$1 build=$2 python=${3:-/usr/bin/python3}
out=$build/wheel-test
rm -rf "$out"
mkdir -p "$out"
start=$(date +%s)
log() { echo "$1 ($(($(date +%s) - start)) s)"; }

"$python" -m build --no-isolation --wheel --outdir "$out/dist" --config-setting=build-dir="$build" "$src" \
    > "$out/build.log" 2>&1 || { cat "$out/build.log"; exit 1; }
wheel=$(ls "$out"/dist/glslrun-*.whl)
log "built $(basename "$wheel")"
"$python" - "$wheel" <<'PY'
import sys, zipfile
names = zipfile.ZipFile(sys.argv[1]).namelist()
for want in ("glslrun/__init__.pyi", "glslrun/py.typed", "glslrun/libglslrun-jit.so", ".dist-info/LICENSE", ".dist-info/RECORD"):
    assert any(n.endswith(want) for n in names), (want, names)
assert any(n.startswith("glslrun/__init__.cpython") and n.endswith(".so") for n in names), names
PY

"$python" -m venv --system-site-packages "$out/venv"
venv_python=$out/venv/bin/python
cd "$out"  # not the source or build tree: glslrun must come from the venv
check_import() {
    "$venv_python" - "$src" "$out/venv" <<'PY'
import os, sys
import glslrun
src, venv = sys.argv[1], os.path.realpath(sys.argv[2])
assert os.path.realpath(glslrun.__file__).startswith(venv), glslrun.__file__
image = glslrun.render(f"{src}/shaders/minimal.vert", f"{src}/shaders/minimal.frag", f"{src}/scenes/quad.toml")
assert image.shape == (512, 512, 4) and image.dtype.name == "uint8" and image.any(), image.shape
assert "override" in glslrun.Program.render.__doc__
assert glslrun.jit_available(), "the wheel's JIT plugin did not load"
print("  import glslrun from", os.path.dirname(glslrun.__file__), "-> render", image.shape)
PY
}
"$out/venv/bin/pip" install --no-index --no-deps -q "$wheel"
check_import
log "pip install the wheel into a fresh venv"

"$out/venv/bin/pip" uninstall -y -q glslrun
"$out/venv/bin/pip" install --no-index --no-deps -q --config-settings build-dir="$build" "$src" > "$out/pip.log" 2>&1 ||
    { cat "$out/pip.log"; exit 1; }
check_import
log "pip install . (build isolation, offline)"

"$venv_python" -m mypy.stubtest glslrun --allowlist "$src/python/stubtest-allowlist.txt" > "$out/stubtest.log" 2>&1 || { cat "$out/stubtest.log"; exit 1; }
"$venv_python" -m mypy --strict --cache-dir "$out/mypy-cache" "$src/examples/render.py" "$src/examples/program.py"
log "mypy.stubtest glslrun, mypy --strict examples/*.py"
