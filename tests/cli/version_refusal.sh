#!/bin/sh
# Shaders of another GLSL version or profile never render: for #version 130,
# 140, 150, 330, 450 and 100 es (as the vertex or the fragment shader),
# glslrun prints `file:line: error:` naming the version and saying what it
# runs, exits nonzero and writes no image; `glslrun test` counts such a
# piglit test as a skip. 110 and 120 still render.
#
#   tests/cli/version_refusal.sh SOURCE_DIR GLSLRUN
set -u
src=$1
glslrun=$2
. "$src/tests/cli/common.sh"

scene=$src/scenes/quad.toml
vs=$src/shaders/minimal.vert
fs=$src/shaders/minimal.frag

# render VERTEX FRAGMENT OUT: exit status of a render into OUT, messages in OUT.log.
render() { "$glslrun" "$1" "$2" "$scene" --size 32x32 -o "$3" >"$3.log" 2>&1; }

for version in 130 140 150 330 450 "100 es"; do
    for stage in vert frag; do
        shader=$tmp/v$(echo "$version" | tr -d ' ').$stage
        { echo "#version $version"; cat "$src/shaders/minimal.$stage"; } >"$shader"
        out=$tmp/out.png
        rm -f "$out"
        if [ $stage = vert ]; then render "$shader" "$fs" "$out"; else render "$vs" "$shader" "$out"; fi
        status=$?
        [ $status != 0 ] || fail "#version $version ($stage): exit status 0"
        [ ! -e "$out" ] || fail "#version $version ($stage): an image was written"
        grep -q "^$shader:1: error: '#version $version' : .* is not supported: glslrun runs GLSL 1.10 and 1.20 only" \
            "$out.log" || fail "#version $version ($stage): message is '$(cat "$out.log")'"
    done
done

for version in 110 120; do
    shader=$tmp/ok$version.frag
    { echo "#version $version"; cat "$fs"; } >"$shader"
    render "$vs" "$shader" "$tmp/ok.png" || fail "#version $version does not render: $(cat "$tmp/ok.png.log")"
done

# A piglit test whose shader asks for GLSL 1.30 is a skip with the reason.
mkdir "$tmp/piglit"
cat >"$tmp/piglit/v130.shader_test" <<'TEST'
[require]
GLSL >= 1.10

[vertex shader passthrough]

[fragment shader]
#version 130
out vec4 color;
void main() { color = vec4(1.0); }

[test]
draw rect -1 -1 2 2
probe all rgba 1 1 1 1
TEST
"$glslrun" test --root "$tmp/piglit" "$tmp/piglit" >"$tmp/test.log" 2>&1 || fail "glslrun test: exit status $?"
grep -q "^skip  v130.shader_test: .*'#version 130' : GLSL 1.30 is not supported" "$tmp/test.log" ||
    fail "glslrun test: $(cat "$tmp/test.log")"

finish "version refusal: 6 versions x 2 stages refused, 110/120 render, piglit skip"
