#!/bin/sh
# Checks `glslrun trace`: --json is valid JSON with the text's content, every
# replay matches the render in all three precision modes and with an odd
# size, --vertex and --find-nan work from the command line, and bad input
# and bad arguments are clear errors with status 1 and 2.
#
#   tests/cli/trace.sh SOURCE_DIR GLSLRUN
set -u
src=$1
glslrun=$2
. "$src/tests/cli/common.sh"

vs=$src/shaders/spot_pix_oops.vert
fs=$src/shaders/spot_pix_oops.frag
scene=$src/scenes/spot.toml

"$glslrun" trace --pixel 240,172 --json "$vs" "$fs" "$scene" >"$tmp/trace.json" || fail "trace --json exited with $?"
python3 - "$tmp/trace.json" <<'PY' || fail "trace --json: wrong content"
import json, sys
t = json.load(open(sys.argv[1]))
assert t["pixel"] == [240, 172], t["pixel"]
f = t["fragments"]
assert [x["outcome"] for x in f] == ["written", "depth_failed"], [x["outcome"] for x in f]
assert all(x["matches_render"] for x in f)
assert f[0]["matches_render"] and f[0]["trace"]["outputs"][0]["name"] == "gl_FragColor"
steps = f[0]["trace"]["steps"]
assert any(s["kind"] == "assign" and s["name"] == "intensity" and s["value"] == [0] for s in steps)
assert any(s["kind"] == "branch" for s in steps)
# Each step's line, with its text.
assert any(s["where"].endswith("spot_pix_oops.frag:31") and s["text"] == "intensity = max(dot(lightDir,n),0.0);"
           for s in steps if s["kind"] == "statement"), "no text of line 31"

assert len(t["vertices"]) == 3 and all(v["matches_render"] for v in t["vertices"])
# A matrix's "value" lists its components column by column (GLSL's order); "rows" as the text prints it.
mv = [u for u in t["vertices"][0]["trace"]["uniforms"] if u["name"] == "gl_ModelViewMatrix"][0]
assert mv["rows"] == [[mv["value"][c * 4 + r] for c in range(4)] for r in range(4)], mv
assert mv["rows"][2][3] == -5, mv["rows"]
PY

# Each fragment's outcome is the test that stopped it, with the values compared
# (an RGBA8 buffer compares alpha as bytes: 64 of 255 against 128).
d=$src/tests/scene/data
"$glslrun" trace --pixel 16,16 --json "$src/shaders/colors.vert" "$d/fragment_tests.frag" "$d/fragment_tests.toml" \
    >"$tmp/tests.json" || fail "trace fragment_tests exited with $?"
python3 - "$tmp/tests.json" <<'PY' || fail "trace fragment_tests: wrong outcomes"
import json, sys
t = json.load(open(sys.argv[1]))
f = t["fragments"]
assert [x["outcome"] for x in f] == ["alpha_failed", "stencil_failed", "written", "depth_failed", "discarded"], f
a = f[0]["tests"]
assert a["alpha"]["result"] == "failed" and a["depth"]["result"] == "off", a
assert (a["alpha"]["alpha"], a["alpha"]["reference"], a["alpha"]["bytes"]) == (64, 128, True), a
s = f[1]["tests"]["stencil"]
assert (s["result"], s["func"], s["reference"], s["stored"]) == ("failed", "equal", 1, 0), s
d = f[3]["tests"]["depth"]
assert d["result"] == "failed" and d["stored"] == f[2]["depth"] and d["z"] > d["stored"], d
assert t["scissored"] == [4], t["scissored"]
assert all(x["matches_render"] for x in f)
PY

# Every pass's program is probed: the pixel history of a scene whose passes
# name their own shaders, in draw order, with the pass and program.
mp="$src/shaders/minimal.vert $src/shaders/minimal.frag $src/scenes/multi_pass.toml"
"$glslrun" trace --pixel 128,128 $mp >"$tmp/passes.txt" || fail "trace multi_pass exited with $?"
grep -q "no fragment" "$tmp/passes.txt" && fail "trace multi_pass: no fragment on a lit pixel"
grep -q "^fragment 0 at pixel 128,128: draw 0 (pass 'ambient', program .*/passes/ambient.vert + .*/passes/ambient.frag)" \
    "$tmp/passes.txt" || fail "trace multi_pass: the ambient pass is not first"
grep -q "^fragment .*(pass 'light 1', .*: written$" "$tmp/passes.txt" || fail "trace multi_pass: no light 1 fragment"
grep -q WARNING "$tmp/passes.txt" && fail "trace multi_pass: a replay differs from the render"
"$glslrun" trace --vertex 0 --draw 2 $mp >"$tmp/passes_vertex.txt" || fail "trace --vertex multi_pass exited with $?"
grep -q "^vertex 0 of draw 2 (pass 'light 0', program .*/passes/light.vert + .*/passes/light.frag):" \
    "$tmp/passes_vertex.txt" || fail "trace --vertex: draw 2 is not light 0's"
grep -q WARNING "$tmp/passes_vertex.txt" && fail "trace --vertex multi_pass: the replay differs from the render"
"$glslrun" trace --find-nan --colour-range $mp >"$tmp/passes_nan.txt" || fail "--find-nan multi_pass exited with $?"
grep -q "^no NaN or infinity" "$tmp/passes_nan.txt" || fail "--find-nan multi_pass: $(cat "$tmp/passes_nan.txt")"
# --target: a render target's pixel history; a name the scene lacks is refused with the names it has.
blur="$src/shaders/minimal.vert $src/shaders/minimal.frag $src/scenes/blur.toml"
"$glslrun" trace --pixel 64,64 --target image $blur >"$tmp/target.txt" || fail "trace --target exited with $?"
grep -q "^fragment 0 at render target 'image' pixel 64,64: draw 0 (pass 'scene', " "$tmp/target.txt" ||
    fail "trace --target image: not the scene pass's fragment"
grep -q "^  after:  colour 0 rgba8(" "$tmp/target.txt" || fail "trace --target: no framebuffer after the fragment"
"$glslrun" trace --pixel 64,64 --target nope $blur 2>"$tmp/target_err.txt" && fail "trace --target nope succeeded"
grep -q "no render target 'nope' (it has half, image)" "$tmp/target_err.txt" || fail "trace --target nope: $(cat "$tmp/target_err.txt")"
"$glslrun" trace --target image $blur 2>"$tmp/target_err.txt" && fail "trace --target without --pixel succeeded"
grep -q "render target of --pixel X,Y, which is missing" "$tmp/target_err.txt" || fail "trace --target alone: $(cat "$tmp/target_err.txt")"

# A stage left out is GL's fixed function, generated from the scene: the trace follows the generated
# source, names it as generated, and --dump-fixed-function writes the same text the trace shows.
"$glslrun" trace --pixel 240,172 "$src/shaders/minimal.frag" "$scene" >"$tmp/alone.txt" 2>&1 ||
    fail "trace of a fragment shader alone exited with $? ($(head -c 300 "$tmp/alone.txt"))"
grep -q "^fragment 0 at pixel 240,172: draw 0 (program (generated) fixed-function-1.vert + .*minimal.frag)" \
    "$tmp/alone.txt" || fail "trace of minimal.frag alone: no generated vertex stage in the header"
grep -q "^    (generated) fixed-function-1.vert:[0-9]*  gl_Position = " "$tmp/alone.txt" ||
    fail "trace of minimal.frag alone: no step in the generated vertex stage"
grep -q "^(generated) fixed-function-1.vert is GL's fixed-function vertex stage, generated .*--dump-fixed-function" \
    "$tmp/alone.txt" || fail "trace of minimal.frag alone: the generated stage is not explained"
grep -q WARNING "$tmp/alone.txt" && fail "trace of minimal.frag alone: a replay differs from the render"
ff=$src/scenes/fixed_function.toml
"$glslrun" trace --pixel 40,30 --size 128x96 --dump-fixed-function "$tmp/ffp" "$ff" >"$tmp/ffp.txt" 2>&1 ||
    fail "trace of a scene without shaders exited with $? ($(head -c 300 "$tmp/ffp.txt"))"
grep -q "^wrote $tmp/ffp/fixed-function-1.frag: GL's fixed-function fragment stage" "$tmp/ffp.txt" ||
    fail "--dump-fixed-function: $(head -c 300 "$tmp/ffp.txt")"
grep -q WARNING "$tmp/ffp.txt" && fail "trace of fixed_function.toml: a replay differs from the render"
# Each step's text is the dumped file's line.
step=$(grep -m1 "^    (generated) fixed-function-1.frag:[0-9]*  " "$tmp/ffp.txt")
line=$(echo "$step" | sed 's/^ *(generated) fixed-function-1.frag:\([0-9]*\) .*/\1/')
text=$(echo "$step" | sed 's/^ *(generated) fixed-function-1.frag:[0-9]*  //')
[ -n "$line" ] && [ "$(sed -n "${line}p" "$tmp/ffp/fixed-function-1.frag" | sed 's/^ *//')" = "$text" ] ||
    fail "--dump-fixed-function: line $line of the dump is not the trace's '$text'"
"$glslrun" "$ff" --size 128x96 -o "$tmp/ff.png" --dump-fixed-function "$tmp/ffp2" >/dev/null || fail "render --dump-fixed-function"
cmp -s "$tmp/ffp/fixed-function-1.vert" "$tmp/ffp2/fixed-function-1.vert" || fail "render and trace dump different stages"
"$glslrun" "$ff" -o - --dump-fixed-function "$tmp/ffp3" >/dev/null 2>&1 && fail "-o - took --dump-fixed-function"
# A fixed-function pass beside a shaded one: each draw replays its own program.
cat >"$tmp/beside.toml" <<'TOML'
[output]
size = [64, 32]
[camera]
perspective = { fovy = 40, near = 1, far = 30 }
[state]
depth_test = true
[fixed_function]
lighting = true
[lights.0]
position = [1, 1, 1, 0]
[[objects]]
name = "lit"
mesh = "cube"
transform = [ { translate = [-1.2, 0, -4] }, { rotate = [30, 1, 1, 0] } ]
[[objects]]
name = "shaded"
mesh = "cube"
transform = [ { translate = [1.2, 0, -4] }, { rotate = [30, 1, 1, 0] } ]
[[passes]]
name = "ffp"
objects = ["lit"]
program = "fixed"
[[passes]]
name = "mine"
objects = ["shaded"]
TOML
for px in 16,16 48,16; do
    "$glslrun" trace --pixel $px "$vs" "$fs" "$tmp/beside.toml" >"$tmp/beside-$px.txt" 2>&1 ||
        fail "trace of a fixed pass beside a shaded one at $px exited with $?"
    grep -q "^fragment 0 " "$tmp/beside-$px.txt" || fail "beside at $px: no fragment"
    grep -q WARNING "$tmp/beside-$px.txt" && fail "beside at $px: a replay differs from the render"
done
grep -q "(pass 'ffp', program (generated) fixed-function-1.vert + (generated) fixed-function-1.frag)" \
    "$tmp/beside-16,16.txt" || fail "beside: the fixed pass's program: $(head -c 300 "$tmp/beside-16,16.txt")"
grep -q "(pass 'mine', program .*spot_pix_oops.vert + .*spot_pix_oops.frag)" "$tmp/beside-48,16.txt" || fail "beside: the shaded pass"
"$glslrun" trace --find-nan "$src/shaders/minimal.frag" "$scene" --size 64x64 >"$tmp/alone-nan.txt" ||
    fail "--find-nan of minimal.frag alone exited with $?"
# A NaN made by a generated stage (GL_NORMALIZE of a zero normal) is said to be in GL's fixed function,
# not in the user's file.
cat >"$tmp/zero_normal.toml" <<'TOML'
[output]
size = [16, 16]
[fixed_function]
lighting = true
normalize = true
[current]
normal = [0, 0, 0]
[[objects]]
mesh = "arrays"
primitive = "triangles"
vertices = [[-1, -1], [1, -1], [0, 1]]
TOML
"$glslrun" trace --find-nan "$src/shaders/minimal.frag" "$tmp/zero_normal.toml" >"$tmp/ffp-nan.txt" ||
    fail "--find-nan in a generated stage exited with $?"
grep -q "^first NaN/Inf: vertex 0 of draw 0: (generated) fixed-function-1.vert:[0-9]*: " "$tmp/ffp-nan.txt" ||
    fail "--find-nan in a generated stage: $(cat "$tmp/ffp-nan.txt")"
grep -q "^(generated) fixed-function-1.vert is GL's fixed-function vertex stage, generated " "$tmp/ffp-nan.txt" ||
    fail "--find-nan in a generated stage does not say it is generated: $(cat "$tmp/ffp-nan.txt")"

# The replay equals the render whatever the mode, size and program (a loop and calls in multi_light).
for mode in precise fast reference; do
    for prog in spot_pix_fixed multi_light; do
        out=$tmp/$prog-$mode.txt
        "$glslrun" trace --pixel 45,25 --size 97x61 --precision $mode "$src/shaders/$prog.vert" "$src/shaders/$prog.frag" \
            "$src/scenes/$([ $prog = multi_light ] && echo multi_light || echo spot).toml" >"$out" ||
            fail "$prog $mode: trace exited with $?"
        grep -q "^fragment 0 at pixel 45,25" "$out" || fail "$prog $mode: no fragment at 45,25"
        grep -q WARNING "$out" && fail "$prog $mode: the replay differs from the render"
    done
done
grep -q "loop iteration 2" "$tmp/multi_light-precise.txt" || fail "multi_light: no third loop iteration"
grep -q "call light" "$tmp/multi_light-precise.txt" || fail "multi_light: no call of light()"

"$glslrun" trace --vertex 5 "$vs" "$fs" "$scene" >"$tmp/vertex.txt" || fail "trace --vertex exited with $?"
grep -q "^vertex 5 of draw 0:" "$tmp/vertex.txt" || fail "trace --vertex: no vertex 5"
grep -q "gl_Position = vec4(" "$tmp/vertex.txt" || fail "trace --vertex: gl_Position not assigned"
# A matrix prints as rows under its name, as --stats prints it.
grep -A4 "gl_ModelViewMatrix =$" "$tmp/vertex.txt" | grep -c "^ *|.* -5 |$" | grep -qx 1 || fail "trace: no modelview matrix rows"
grep -q "spot_pix_oops.vert:[0-9]*  gl_Position = ftransform();" "$tmp/vertex.txt" || fail "trace: no line text"

"$glslrun" trace --find-nan --size 64x64 "$vs" "$fs" "$scene" >"$tmp/nan.txt" || fail "--find-nan exited with $?"
grep -q "^no NaN or infinity" "$tmp/nan.txt" || fail "--find-nan found a NaN in the spot light"

# --stats: the built-in uniforms read, with values; a matrix as rows under its name.
COLUMNS=100 "$glslrun" "$vs" "$fs" "$scene" --size 64x64 -o "$tmp/s.png" --stats >"$tmp/stats.txt" || fail "--stats exited with $?"
grep -A4 "gl_ModelViewMatrix =$" "$tmp/stats.txt" | grep -c "^ *|.* -5 |$" | grep -qx 1 || fail "--stats: no modelview matrix rows"
grep -q "gl_LightSource\[0\].spotCosCutoff = 0.9396926$" "$tmp/stats.txt" || fail "--stats: no spotCosCutoff value"
awk 'length > 100 { exit 1 }' "$tmp/stats.txt" || fail "--stats: a line longer than 100 columns"

# Bad input: a message and status 1 (the scene, the shaders or the request do
# not fit); bad arguments: status 2 (docs/ci.md), CLI11's parse errors too.
expect_error() {
    want=$1
    shift
    "$glslrun" trace "$@" >"$tmp/err.out" 2>"$tmp/err.txt"
    got=$?
    [ $got = "$want" ] || fail "trace $*: exit status $got, not $want"
    [ -s "$tmp/err.txt" ] || fail "trace $*: no message"
}
expect_error 1 --pixel 600,10 "$vs" "$fs" "$scene"
expect_error 1 --vertex 999999 "$vs" "$fs" "$scene"
expect_error 1 --vertex 0 --draw 3 "$vs" "$fs" "$scene"
expect_error 1 --pixel 1,1 "$vs" "$src/shaders/missing.frag" "$scene"
expect_error 2 --check-undefined "$src/scenes/fixed_function.toml"
expect_error 2 --pixel 10 "$vs" "$fs" "$scene"
expect_error 2 --pixel 1,1x "$vs" "$fs" "$scene"
expect_error 2 --pixel 99999999999999,1 "$vs" "$fs" "$scene"
expect_error 2 --pixel " 1,1" "$vs" "$fs" "$scene"
expect_error 2 "$vs" "$fs" "$scene"
expect_error 2 --pixel 1,1 "$vs" "$fs"
expect_error 2 --pixel 1,1
expect_error 2 --no-such-option --pixel 1,1 "$vs" "$fs" "$scene"
expect_error 2 --vertex -3 "$vs" "$fs" "$scene"
expect_error 2 --precision exact --pixel 1,1 "$vs" "$fs" "$scene"
finish "trace: JSON, replays equal to the render, --vertex, --find-nan and errors"
