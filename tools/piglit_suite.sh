#!/bin/sh
# Runs glslrun's piglit conformance suite (GLSL 1.10/1.20 execution and compiler
# tests, and the GLSL 1.10 ones of the extensions glslrun enables) against
# tests/piglit-expectations.txt. Exit status: nonzero on any regression or
# unexpected pass.
#
#   tools/piglit_suite.sh [--tsv results.tsv] [more glslrun test options]
#
# GLSLRUN: the glslrun binary (default: build/glslrun, else the first found in build*/).
# PIGLIT_ROOT: piglit's install directory (default: Debian's).
set -eu
repo=$(cd "$(dirname "$0")/.." && pwd)
root=${PIGLIT_ROOT:-/usr/lib/x86_64-linux-gnu/piglit}
glslrun=${GLSLRUN:-}
if [ -z "$glslrun" ]; then
    for candidate in "$repo"/build/glslrun "$repo"/build*/glslrun; do
        if [ -x "$candidate" ]; then glslrun=$candidate; break; fi
    done
fi
if [ -z "$glslrun" ] || [ ! -x "$glslrun" ]; then
    echo "piglit_suite.sh: no glslrun binary found; build it or set GLSLRUN" >&2
    exit 2
fi
if [ ! -d "$root/tests/spec" ]; then
    echo "piglit_suite.sh: piglit not found at $root; set PIGLIT_ROOT" >&2
    exit 2
fi
jobs=$(nproc 2>/dev/null || echo 1)
exec "$glslrun" test --root "$root" --expect "$repo/tests/piglit-expectations.txt" -j "$jobs" "$@" \
    tests/spec/glsl-1.10 \
    generated_tests/spec/glsl-1.10 \
    tests/spec/glsl-1.20 \
    generated_tests/spec/glsl-1.20 \
    tests/shaders \
    tests/spec/arb_texture_rectangle \
    tests/spec/arb_shader_texture_lod \
    tests/spec/ext_texture_array \
    generated_tests/spec/arb_draw_buffers/preprocessor/enabled-compat.vert \
    generated_tests/spec/arb_draw_buffers/preprocessor/enabled-compat.frag \
    generated_tests/spec/arb_draw_buffers/preprocessor/disabled-defined-compat.vert \
    generated_tests/spec/arb_draw_buffers/preprocessor/disabled-defined-compat.frag \
    generated_tests/spec/arb_draw_buffers/preprocessor/disabled-undefined-compat.vert \
    generated_tests/spec/arb_draw_buffers/preprocessor/disabled-undefined-compat.frag \
    generated_tests/spec/arb_texture_rectangle/preprocessor/enabled-compat.vert \
    generated_tests/spec/arb_texture_rectangle/preprocessor/enabled-compat.frag \
    generated_tests/spec/arb_texture_rectangle/preprocessor/disabled-defined-compat.vert \
    generated_tests/spec/arb_texture_rectangle/preprocessor/disabled-defined-compat.frag \
    generated_tests/spec/arb_texture_rectangle/preprocessor/disabled-undefined-compat.vert \
    generated_tests/spec/arb_texture_rectangle/preprocessor/disabled-undefined-compat.frag \
    generated_tests/spec/arb_shader_texture_lod/preprocessor/enabled-compat.vert \
    generated_tests/spec/arb_shader_texture_lod/preprocessor/enabled-compat.frag \
    generated_tests/spec/arb_shader_texture_lod/preprocessor/disabled-defined-compat.vert \
    generated_tests/spec/arb_shader_texture_lod/preprocessor/disabled-defined-compat.frag \
    generated_tests/spec/arb_shader_texture_lod/preprocessor/disabled-undefined-compat.vert \
    generated_tests/spec/arb_shader_texture_lod/preprocessor/disabled-undefined-compat.frag \
    generated_tests/spec/ext_texture_array/preprocessor/enabled-compat.vert \
    generated_tests/spec/ext_texture_array/preprocessor/enabled-compat.frag \
    generated_tests/spec/ext_texture_array/preprocessor/disabled-defined-compat.vert \
    generated_tests/spec/ext_texture_array/preprocessor/disabled-defined-compat.frag \
    generated_tests/spec/ext_texture_array/preprocessor/disabled-undefined-compat.vert \
    generated_tests/spec/ext_texture_array/preprocessor/disabled-undefined-compat.frag
