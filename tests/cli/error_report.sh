#!/bin/sh
# Checks `glslrun --error-report DIR`: reference against reference is exact
# (every max_ulp, max_8bit and differing_pixels is 0), every mode writes its
# files and its `key value` lines with numbers, the images it writes equal
# plain renders' PNGs byte for byte, and bad arguments are clear errors.
#
#   tests/cli/error_report.sh SOURCE_DIR GLSLRUN
set -u
src=$1
glslrun=$2
. "$src/tests/cli/common.sh"

vs=$src/shaders/spot_pix_fixed.vert
fs=$src/shaders/spot_pix_fixed.frag
scene=$src/scenes/spot.toml
size=96x64

# value KEY FILE: the value of a `key value` line.
value() { sed -n "s/^$1  *//p" "$2"; }

# report MODE: the report of MODE into $tmp/MODE, its output in $tmp/MODE.out.
report() {
    "$glslrun" "$vs" "$fs" "$scene" --size $size --precision "$1" --error-report "$tmp/$1" >"$tmp/$1.out" ||
        fail "--error-report with --precision $1 exited with $?"
}

for mode in reference precise fast; do
    report $mode
    out=$tmp/$mode.out
    [ "$(value mode "$out")" = $mode ] || fail "$mode: the mode line is '$(value mode "$out")'"
    [ "$(value size "$out")" = $size ] || fail "$mode: size is not $size"
    for key in reference_ms mode_ms frag.gl_FragColor.max_ulp frag.gl_FragColor.mean_ulp frag.gl_FragColor.max_abs \
               frag.gl_FragColor.r.max_ulp frag.gl_FragColor.a.mean_8bit frag.gl_FragColor.max_8bit \
               frag.gl_FragColor.mean_8bit frag.gl_FragColor.differing_pixels frag.gl_FragColor.covered_both \
               frag.gl_FragColor.covered_one frag.depth.max_ulp vertex.gl_Position.max_ulp vertex.normal.mean_ulp; do
        n=$(grep -c "^$key " "$out")
        [ "$n" = 1 ] || fail "$mode: key '$key' appears $n times"
        value "$key" "$out" | grep -Eq '^[0-9]+(\.[0-9]+)?(e[-+][0-9]+)?$' || fail "$mode: '$key' is not a number"
    done
    value frag.gl_FragColor.worst_ulp_xy "$out" | grep -Eq '^(none|[0-9]+ [0-9]+)$' || fail "$mode: worst_ulp_xy"
    [ "$(value frag.gl_FragColor.covered_both "$out")" -gt 500 ] || fail "$mode: the teapot covers too few pixels"
    for f in reference.png actual-$mode.png gl_FragColor_ulp.png gl_FragColor_diff8.png depth_ulp.png \
             heat_legend.png report.txt report.keys; do
        [ -s "$tmp/$mode/$f" ] || fail "$mode: $f was not written"
    done
    grep -q 'log2 scale' "$out" || fail "$mode: the heat maps' colour scale is not explained"
    # The table and the key lines in DIR are those printed.
    grep -q "^mode  *$mode" "$tmp/$mode/report.keys" || fail "$mode: report.keys has no mode line"
    grep -q "error report: $mode against reference" "$tmp/$mode/report.txt" || fail "$mode: report.txt has no table"
    # The report's images are the PNGs a plain render in that mode writes.
    "$glslrun" "$vs" "$fs" "$scene" --size $size --precision $mode -o "$tmp/plain-$mode.png" >/dev/null ||
        fail "plain render with --precision $mode"
    cmp -s "$tmp/plain-$mode.png" "$tmp/$mode/actual-$mode.png" || fail "$mode: actual-$mode.png is not the plain render"
    cmp -s "$tmp/plain-reference.png" "$tmp/$mode/reference.png" || fail "$mode: reference.png is not the plain render"
done

# Reference against reference: exactly 0 everywhere.
out=$tmp/reference.out
grep -E '\.(max_ulp|max_8bit|differing_pixels|covered_one|nan_mismatches) ' "$out" | grep -Ev ' 0$' &&
    fail "reference against reference is not exact"
[ "$(value frag.gl_FragColor.worst_ulp_xy "$out")" = none ] || fail "reference against itself has a worst pixel"

# The thread count changes nothing.
"$glslrun" "$vs" "$fs" "$scene" --size $size --precision fast --threads 3 --error-report "$tmp/t3" >"$tmp/t3.out" ||
    fail "--threads 3"
grep -v '_ms ' "$tmp/t3.out" | grep -v "^files:" | sed "s#$tmp/t3#DIR#g" >"$tmp/a"
grep -v '_ms ' "$tmp/fast.out" | grep -v "^files:" | sed "s#$tmp/fast#DIR#g" >"$tmp/b"
grep -v '^time ' "$tmp/a" >"$tmp/a2"; grep -v '^time ' "$tmp/b" >"$tmp/b2"
cmp -s "$tmp/a2" "$tmp/b2" || fail "--threads 3 changed the report"

# Errors: clear messages and a nonzero status, never a crash.
expect_error() {  # WORDS_IN_MESSAGE ARGS...
    words=$1
    shift
    "$glslrun" "$@" >/dev/null 2>"$tmp/err"
    rc=$?
    [ $rc -gt 0 ] && [ $rc -lt 128 ] || fail "$*: exit status $rc"
    grep -q -- "$words" "$tmp/err" || fail "$*: the error does not say '$words': $(cat "$tmp/err")"
}
expect_error "precise or fast" "$vs" "$fs" "$scene" --size 8x8 --precision exact --error-report "$tmp/x"
touch "$tmp/file"
expect_error "not a directory" "$vs" "$fs" "$scene" --size 8x8 --error-report "$tmp/file"
expect_error "cannot create" "$vs" "$fs" "$scene" --size 8x8 --error-report "$tmp/file/sub"
expect_error "needs a scene" "$vs" "$fs" --error-report "$tmp/x"
expect_error "does not combine" "$vs" "$fs" "$scene" --size 8x8 --error-report "$tmp/x" --bench 2
expect_error "does not combine" "$vs" "$fs" "$scene" --size 8x8 --error-report "$tmp/x" -o "$tmp/x.png"
expect_error "does not combine" "$vs" "$fs" "$scene" --size 8x8 --error-report "$tmp/x" --stats
# --time-limit bounds the report's renders (reference is the slow one): a shader that loops
# for minutes ends with the time limit's error.
sed 's/gl_FragColor = color;/float k = 0.0; for (int i = 0; i < 3000000; ++i) k += sin(k); gl_FragColor = color + k;/' \
    "$fs" > "$tmp/slow.frag"
grep -q 3000000 "$tmp/slow.frag" || fail "the slow shader was not made"
expect_error "time limit" "$vs" "$tmp/slow.frag" "$scene" --error-report "$tmp/slow" --time-limit 1

finish "error report: all checks passed"
