#!/bin/sh
# Checks the output format of `glslrun --bench N` (and `glref --bench N` when
# a glref binary is given): every key, numbers where numbers belong, the frame
# count, the range of N, and the combinations with other options. No timing
# is asserted.
#
#   tests/cli/bench_format.sh SOURCE_DIR GLSLRUN [GLREF]
set -u
src=$1
glslrun=$2
glref=${3:-}
. "$src/tests/cli/common.sh"

vs=$src/shaders/spot_pix_fixed.vert
fs=$src/shaders/spot_pix_fixed.frag
scene=$src/scenes/spot.toml

# value KEY FILE: the value of a `key value` line (the rest of the line).
value() { sed -n "s/^$1 *//p" "$2"; }

# check_keys FILE FRAMES KEY...: each key once, with a non-negative number.
check_keys() {
    file=$1 frames=$2
    shift 2
    [ "$(value frames "$file")" = "$frames" ] || fail "$file: frames is not $frames"
    for key in "$@"; do
        n=$(grep -c "^$key " "$file")
        [ "$n" = 1 ] || fail "$file: key '$key' appears $n times"
        value "$key" "$file" | grep -Eq '^[0-9]+(\.[0-9]+)?$' || fail "$file: '$key' is not a number"
    done
}
times="compile_ms first_draw_ms first_frame_ms median_ms min_ms fps cpu_median_ms"

# glslrun: every key, and the image equals a single frame's (frames reuse the framebuffer).
"$glslrun" "$vs" "$fs" "$scene" --size 64x48 -o "$tmp/one.png" >/dev/null || fail "glslrun without --bench"
"$glslrun" "$vs" "$fs" "$scene" --size 64x48 -o "$tmp/bench.png" --bench 3 --threads 2 >"$tmp/out" ||
    fail "glslrun --bench 3 exited with $?"
check_keys "$tmp/out" 3 $times vertex_ms raster_ms fragment_ms output_ms vertices triangles fragments
[ "$(value renderer "$tmp/out")" = glslrun ] || fail "renderer is not glslrun"
[ "$(value size "$tmp/out")" = 64x48 ] || fail "size is not 64x48"
[ "$(value threads "$tmp/out")" = 2 ] || fail "threads is not 2"
[ "$(value precision "$tmp/out")" = precise ] || fail "precision is not the default, precise"
[ "$(value triangles "$tmp/out")" = 6400 ] || fail "triangles is not one frame's 6400 (32 patches, 10x10, 2 each)"
"$glslrun" --compare "$tmp/one.png" "$tmp/bench.png" >/dev/null || fail "--bench changed the image"
# Nor does the thread count (none of the runs above or below may differ by a bit).
"$glslrun" "$vs" "$fs" "$scene" --size 64x48 -o "$tmp/t64.png" --bench 2 --threads 64 >/dev/null ||
    fail "--threads 64 --bench 2 failed"
"$glslrun" --compare "$tmp/one.png" "$tmp/t64.png" >/dev/null || fail "--threads 64 changed the image"

# --bench with --compare and --stats: both still work, and the exit status is the comparison's.
"$glslrun" "$vs" "$fs" "$scene" --size 64x48 -o "$tmp/c.png" --bench 1 --stats --compare "$tmp/one.png" \
    >"$tmp/out" || fail "--bench --compare against the same image failed"
check_keys "$tmp/out" 1 $times
grep -q '^fragments    ' "$tmp/out" || fail "--stats output missing with --bench"
grep -q 'pixels' "$tmp/out" || fail "--compare summary missing with --bench"
grep -q '^textures     none$' "$tmp/out" || fail "--stats must say that no texture is bound"
# --stats lists the bound textures.
"$glslrun" "$src/shaders/textured_pix.vert" "$src/shaders/textured_pix.frag" "$src/scenes/textured.toml" \
    --size 32x32 -o "$tmp/tex.png" --stats >"$tmp/out" || fail "the textured scene failed"
grep -Eq '^textures     unit 0: 2D [0-9]+x[0-9]+ RGBA8, [0-9]+ levels$' "$tmp/out" ||
    fail "--stats does not list the textured scene's texture: $(grep '^textures' "$tmp/out")"

# --precision: named by --bench and --stats; a bad name is a usage error that names the option.
for mode in reference fast; do
    "$glslrun" "$vs" "$fs" "$scene" --size 32x24 -o "$tmp/p.png" --bench 1 --stats --precision $mode >"$tmp/out" ||
        fail "--precision $mode failed"
    grep -q "^precision        $mode$" "$tmp/out" || fail "--bench does not say precision $mode"
    grep -q "^precision    $mode$" "$tmp/out" || fail "--stats does not say precision $mode"
done
"$glslrun" "$vs" "$fs" "$scene" --size 8x8 -o "$tmp/x.png" --precision double >/dev/null 2>"$tmp/err"
rc=$?
[ $rc -gt 0 ] && [ $rc -lt 128 ] || fail "--precision double: exit status $rc"
grep -q -- "--precision: unknown precision 'double'" "$tmp/err" || fail "--precision double: $(cat "$tmp/err")"
if "$glslrun" test --precision exact "$src/tests/extremes" >/dev/null 2>&1; then
    fail "glslrun test --precision exact was accepted"
fi

# The range of N, and --bench without a scene or with images only: errors, not crashes.
for n in 0 -1 100001 abc; do
    "$glslrun" "$vs" "$fs" "$scene" --size 8x8 -o "$tmp/x.png" --bench "$n" >/dev/null 2>"$tmp/err"
    rc=$?
    [ $rc -gt 0 ] && [ $rc -lt 128 ] || fail "--bench $n: exit status $rc"
    grep -q -- --bench "$tmp/err" || fail "--bench $n: the error does not name the option"
done
if "$glslrun" "$vs" "$fs" --bench 2 >/dev/null 2>&1; then fail "--bench without a scene was accepted"; fi
if "$glslrun" --compare "$tmp/one.png" "$tmp/one.png" --bench 2 >/dev/null 2>&1; then
    fail "--bench with two images was accepted"
fi

# glref: the same keys (no per-stage times: Mesa does not report them).
if [ -n "$glref" ]; then
    "$glref" --driver softpipe "$vs" "$fs" "$scene" --size 64x48 -o "$tmp/mesa.png" --bench 2 >"$tmp/mesa" ||
        fail "glref --bench 2 exited with $?"
    check_keys "$tmp/mesa" 2 $times
    [ "$(value threads "$tmp/mesa")" = 1 ] || fail "softpipe's threads is not 1"
    if "$glref" "$vs" "$fs" "$scene" --bench 0 >/dev/null 2>&1; then fail "glref --bench 0 was accepted"; fi
fi

finish "bench format: all checks passed"
