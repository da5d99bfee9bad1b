#!/bin/sh
# Reruns the extreme-value cases on Mesa llvmpipe (not part of ctest: it needs
# piglit's shader_runner and EGL). Two checks:
#  1. the same .shader_test files with llvmpipe's recorded results (the `mesa`
#     fields of cases.py) must pass on llvmpipe, so the table in
#     docs/extremes.md is still true;
#  2. with --compare, every case runs alone on glslrun and on llvmpipe and the
#     table of both results is printed (BUILD/glslrun must exist).
# Usage: tests/extremes/run_on_mesa.sh [--compare] [BUILD_DIR]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
compare=0
if [ "${1:-}" = "--compare" ]; then compare=1; shift; fi
build=${1:-$here/../../build}
runner=${SHADER_RUNNER:-/usr/lib/x86_64-linux-gnu/piglit/bin/shader_runner}
export LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe EGL_PLATFORM=surfaceless PIGLIT_PLATFORM=surfaceless_egl

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
python3 "$here/extremes.py" generate --mesa "$tmp"
status=0
for f in "$tmp"/*.shader_test; do
    out=$("$runner" "$f" -auto -fbo 2>&1) || true
    case "$out" in
        *'"result": "pass"'*) echo "pass  $(basename "$f")" ;;
        *) echo "FAIL  $(basename "$f") (llvmpipe no longer gives the recorded results)"; echo "$out" | tail -20; status=1 ;;
    esac
done
if [ $compare = 1 ]; then
    python3 "$here/extremes.py" compare --glslrun "$build/glslrun" --shader-runner "$runner" || status=1
fi
exit $status
