#!/bin/sh
# The JIT as a plugin (runtime/jit_plugin.h): a one-frame render under the
# default backend never loads it (nor LLVM); --backend jit does, and renders
# the interpreter's bytes; a missing or foreign plugin is an error for
# --backend jit and no error for auto, which then runs the interpreter; nor
# does glslrun test under auto.
#
#   tests/cli/jit_plugin.sh SOURCE_DIR GLSLRUN
set -u
src=$1
glslrun=$2
. "$src/tests/cli/common.sh"
cd "$tmp"
demo="$src/shaders/spot_pix_fixed.vert $src/shaders/spot_pix_fixed.frag $src/scenes/spot.toml"

# The dynamic loader's own log of what it opened (LD_DEBUG=files, on stderr).
LD_DEBUG=files $glslrun $demo -o auto.png 2>loaded.txt || fail "the demo under auto failed"
grep -q "libglslrun-jit.so\|libLLVM" loaded.txt && fail "a one-frame render under auto loaded the JIT plugin or LLVM"
LD_DEBUG=files $glslrun --backend jit $demo -o jit.png 2>loaded.txt || fail "the demo under --backend jit failed"
grep -q "file=.*libglslrun-jit.so" loaded.txt || fail "--backend jit did not load libglslrun-jit.so"
grep -q "file=.*libLLVM" loaded.txt || fail "--backend jit did not load LLVM"
$glslrun --backend interp $demo -o interp.png || fail "the demo under --backend interp failed"
cmp -s jit.png interp.png || fail "the plugin's image differs from the interpreter's"
cmp -s auto.png interp.png || fail "auto's image differs from the interpreter's"

# glslrun test under auto: its short tests never compile, so neither the
# runner (before it forks a child per test) nor the children load the plugin
# (a parent with LLVM loaded made each fork dearer); --backend jit warms it up.
piglit="$src/tests/extremes/compare_branch.shader_test $src/tests/extremes/denormals.shader_test"
# shellcheck disable=SC2086
LD_DEBUG=files $glslrun test -q $piglit 2>loaded.txt >/dev/null || fail "glslrun test under auto failed"
grep -q "libglslrun-jit.so\|libLLVM" loaded.txt && fail "glslrun test under auto loaded the JIT plugin or LLVM"
# shellcheck disable=SC2086
LD_DEBUG=files $glslrun test -q --backend jit $piglit 2>loaded.txt >/dev/null || fail "glslrun test --backend jit failed"
grep -q "file=.*libglslrun-jit.so" loaded.txt || fail "glslrun test --backend jit did not load the plugin"

# A plugin that is not there, or not glslrun's.
GLSLRUN_JIT_PLUGIN=$tmp/none.so expect 2 "was not found" $glslrun --backend jit $demo -o none.png
: > empty.so
GLSLRUN_JIT_PLUGIN=$tmp/empty.so expect 2 "could not be loaded" $glslrun --backend jit $demo -o none.png
libpng=$(ldd "$glslrun" | grep -o '/[^ ]*libpng[^ ]*' | head -n 1)
if [ -n "$libpng" ]; then
    GLSLRUN_JIT_PLUGIN=$libpng expect 2 "is not glslrun's JIT plugin" $glslrun --backend jit $demo -o none.png
fi
GLSLRUN_JIT_PLUGIN=$tmp/none.so $glslrun $demo -o fallback.png || fail "auto without the plugin failed"
cmp -s fallback.png interp.png || fail "auto without the plugin: not the interpreter's image"
finish "jit plugin: loaded only when compiling, same bytes, missing or foreign plugins refused"
