#!/bin/sh
# Checks `glslrun --check-undefined` (docs/debugging.md): each shader of
# tests/undefined/ computes one operation that GLSL leaves undefined, and its
# report (the line, the count, the first invocation, the operands, what each
# mode and the GPU return) must equal tests/undefined/expected/NAME.txt in
# every precision mode and on both backends: the findings do not depend on
# them. The image must not change with the checks. A program whose every
# operation is defined, and every lecture program with its scene, report
# nothing. `trace --check-undefined` prints the same report, and
# `trace --find-nan` points to it when it finds nothing.
#
#   tests/cli/check_undefined.sh SOURCE_DIR GLSLRUN     (GLSLRUN_UPDATE_GOLDEN=1: rewrite the expected reports)
set -u
src=$1
glslrun=$2
. "$src/tests/cli/common.sh"
cd "$src" || exit 1  # the reports name the files as given: relative to the checkout
d=tests/undefined
scene=$d/undefined.toml

check() {  # name vertex fragment
    name=$1 vs=$2 fs=$3
    expected=$d/expected/$name.txt
    "$glslrun" --check-undefined "$vs" "$fs" "$scene" -o "$tmp/$name.png" >"$tmp/$name.txt" 2>"$tmp/err.txt" ||
        { fail "$name: exit status $? ($(head -c 300 "$tmp/err.txt"))"; return; }
    if [ "${GLSLRUN_UPDATE_GOLDEN:-0}" = 1 ]; then cp "$tmp/$name.txt" "$expected"; fi
    cmp -s "$tmp/$name.txt" "$expected" || fail "$name: the report differs from $expected: $(diff "$expected" "$tmp/$name.txt" | head -20)"
    "$glslrun" "$vs" "$fs" "$scene" -o "$tmp/plain.png" || fail "$name: the render without checks failed"
    cmp -s "$tmp/$name.png" "$tmp/plain.png" || fail "$name: the checks changed the image"
    for mode in precise fast reference; do
        for backend in interp jit; do
            "$glslrun" --check-undefined --precision $mode --backend $backend "$vs" "$fs" "$scene" >"$tmp/other.txt" 2>&1 ||
                fail "$name --precision $mode --backend $backend: exit status $?"
            cmp -s "$tmp/other.txt" "$expected" ||
                fail "$name --precision $mode --backend $backend: another report: $(diff "$expected" "$tmp/other.txt" | head -10)"
        done
    done
}

for fs in $d/*.frag; do
    name=$(basename "$fs" .frag)
    [ "$name" = vertex ] && continue
    check "$name" $d/quad.vert "$fs"
done
check vertex $d/vertex.vert $d/vertex.frag
# Every op of ir/undefined.h has its shader (none.frag and vertex: the two more).
ops=$(ls $d/expected | wc -l)
[ "$ops" = 21 ] || fail "expected 21 reports (19 operations, vertex, none), found $ops"

# The lecture's programs with their scenes: nothing is undefined there (their
# pow and division guard their operands with max() and a positive constant).
while read -r lvs lfs lscene; do
    "$glslrun" --check-undefined "shaders/$lvs" "shaders/$lfs" "scenes/$lscene" >"$tmp/lecture.txt" 2>&1 ||
        fail "$lfs: exit status $?"
    grep -q "^no operation that GLSL leaves undefined" "$tmp/lecture.txt" || fail "$lfs: $(head -c 400 "$tmp/lecture.txt")"
done <<'EOF_LIST'
minimal.vert minimal.frag teapot.toml
matamb.vert matamb.frag teapot.toml
colors.vert colors.frag quad.toml
dir_vert_diffuse.vert dir_vert_diffuse.frag directional.toml
dir_vert_global.vert dir_vert_global.frag directional.toml
dir_vert.vert dir_vert.frag directional.toml
dir_pix.vert dir_pix.frag directional.toml
pos_pix.vert pos_pix.frag positional.toml
spot_pix_oops.vert spot_pix_oops.frag spot.toml
spot_pix_fixed.vert spot_pix_fixed.frag spot.toml
multi_light.vert multi_light.frag multi_light.toml
textured_pix.vert textured_pix.frag textured.toml
back_material.vert back_material.frag back_material.toml
two_side.vert two_side.frag two_side.toml
cube_reflect.vert cube_reflect.frag cube_map.toml
minimal.vert minimal.frag multi_pass.toml
EOF_LIST

# The trace command prints the same report; --find-nan, finding nothing, points to it.
"$glslrun" trace --check-undefined $d/quad.vert $d/pow.frag "$scene" >"$tmp/trace.txt" 2>&1 || fail "trace --check-undefined: exit $?"
cmp -s "$tmp/trace.txt" $d/expected/pow.txt || fail "trace --check-undefined: $(diff $d/expected/pow.txt "$tmp/trace.txt" | head)"
"$glslrun" trace --find-nan $d/quad.vert $d/none.frag "$scene" >"$tmp/nan.txt" 2>&1 || fail "trace --find-nan: exit $?"
grep -q -- "--check-undefined" "$tmp/nan.txt" || fail "trace --find-nan does not mention --check-undefined: $(cat "$tmp/nan.txt")"

# Without the option no check is compiled: the IR holds no check_undef.
"$glslrun" --dump-ir $d/quad.vert $d/pow.frag >"$tmp/ir.txt" || fail "--dump-ir: exit $?"
grep -q check_undef "$tmp/ir.txt" && fail "the IR has check_undef without --check-undefined"

cd "$tmp" || exit 1
expect 2 "does not combine" "$glslrun" --check-undefined --stats "$src/$d/quad.vert" "$src/$d/pow.frag" "$src/$scene"
finish "check_undefined: 21 reports equal in 3 modes x 2 backends, lecture programs clean"
