#!/bin/sh
# Checks the command line's outputs: -o - writes the PNG to standard output
# (the same bytes as the file), a name that is not .png is an error,
# draw_buffers = 2 writes out.png and out.1.png, --uniform overrides the
# scene's value (bad ones are errors), and --frames N writes N images that
# follow `uniform float time`.
#
#   tests/cli/outputs.sh SOURCE_DIR GLSLRUN
set -u
src=$1
glslrun=$2
. "$src/tests/cli/common.sh"

cat >"$tmp/a.vert" <<'GLSL'
void main() { gl_Position = ftransform(); }
GLSL
cat >"$tmp/a.frag" <<'GLSL'
uniform float time;
uniform vec3 tint;
void main() {
    gl_FragData[0] = vec4(tint, 1.0);
    gl_FragData[1] = vec4(fract(time), 0.0, 1.0, 1.0);
}
GLSL
cat >"$tmp/s.toml" <<'TOML'
[output]
size = [16, 16]
[state]
draw_buffers = 2
[uniforms]
tint = [1, 0, 0]
time = 0.0
[[objects]]
mesh = "quad"
TOML
run() { "$glslrun" "$tmp/a.vert" "$tmp/a.frag" "$tmp/s.toml" "$@"; }

run -o "$tmp/out.png" >/dev/null || fail "plain render exited with $?"
[ -s "$tmp/out.png" ] && [ -s "$tmp/out.1.png" ] || fail "draw_buffers = 2 did not write out.png and out.1.png"
cmp -s "$tmp/out.png" "$tmp/out.1.png" && fail "the two draw buffers' images are the same"

# --uniform: the image changes to the given colour, and back with the scene's value.
run -o "$tmp/green.png" --uniform 'tint=[0, 1, 0]' >/dev/null || fail "--uniform exited with $?"
cmp -s "$tmp/out.png" "$tmp/green.png" && fail "--uniform tint did not change the image"
run -o "$tmp/red.png" --uniform 'tint=[0, 1, 0]' --uniform 'tint=[1, 0, 0]' >/dev/null || fail "two --uniform exited with $?"
cmp -s "$tmp/out.png" "$tmp/red.png" || fail "the last --uniform does not win"
for bad in 'tint' 'tint=[0, 1]' 'nosuch=1.0' 'tint=red'; do
    if run -o "$tmp/bad.png" --uniform "$bad" >/dev/null 2>"$tmp/err"; then fail "--uniform '$bad' was accepted"; fi
    grep -q -e "--uniform" "$tmp/err" || fail "--uniform '$bad': the error does not name the option: $(cat "$tmp/err")"
done

# -o - : PNG bytes on standard output, and nothing else there; one buffer only.
sed 's/draw_buffers = 2/draw_buffers = 1/' "$tmp/s.toml" >"$tmp/one.toml"
"$glslrun" "$tmp/a.vert" "$tmp/a.frag" "$tmp/one.toml" -o - >"$tmp/stdout.png" || fail "-o - exited with $?"
"$glslrun" "$tmp/a.vert" "$tmp/a.frag" "$tmp/one.toml" -o "$tmp/file.png" >/dev/null || fail "-o file exited with $?"
cmp -s "$tmp/stdout.png" "$tmp/file.png" || fail "-o - did not write the same PNG as -o file.png"
[ -e ./- ] && fail "-o - created a file named '-'"
if run -o - >/dev/null 2>"$tmp/err"; then fail "-o - with two draw buffers was accepted"; fi

# Output names: .png, .jpg/.jpeg, .bmp and .tga; nothing else.
for name in x.gif x.PNGX x; do
    if run -o "$tmp/$name" >/dev/null 2>"$tmp/err"; then fail "-o $name was accepted"; fi
    grep -q "chosen by the name's ending" "$tmp/err" || fail "-o $name: unclear error: $(cat "$tmp/err")"
    [ -e "$tmp/$name" ] && fail "-o $name wrote a file"
done
run -o "$tmp/upper.PNG" >/dev/null || fail "-o upper.PNG was refused"

# --frames 3: out.0000.png .. out.0002.png (and their second buffers); time changes the second buffer.
run -o "$tmp/f.png" --frames 3 >/dev/null || fail "--frames exited with $?"
for i in 0000 0001 0002; do
    [ -s "$tmp/f.$i.png" ] && [ -s "$tmp/f.$i.1.png" ] || fail "--frames 3 did not write f.$i.png and f.$i.1.png"
done
cmp -s "$tmp/f.0000.1.png" "$tmp/f.0001.1.png" && fail "frames 0 and 1 are the same: time did not advance"
cmp -s "$tmp/f.0000.png" "$tmp/f.0001.png" || fail "buffer 0 does not read time, yet frames 0 and 1 differ"
[ -e "$tmp/f.0003.png" ] && fail "--frames 3 wrote a fourth frame"

# The time uniform's name and rate: --time-uniform and --fps, or the scene's [animation].
cat >"$tmp/t.frag" <<'GLSL'
uniform float t;
void main() { gl_FragColor = vec4(fract(t), 0.0, 1.0, 1.0); }
GLSL
printf '[output]\nsize = [8, 8]\n[uniforms]\nt = 0.0\n[[objects]]\nmesh = "quad"\n' >"$tmp/t.toml"
trun() { "$glslrun" "$tmp/a.vert" "$tmp/t.frag" "$@"; }
trun "$tmp/t.toml" -o "$tmp/half.png" --uniform 't=0.5' >/dev/null || fail "--uniform t=0.5 exited with $?"
trun "$tmp/t.toml" -o "$tmp/cli.png" --frames 2 --time-uniform t --fps 2 >/dev/null || fail "--time-uniform/--fps exited with $?"
cmp -s "$tmp/cli.0001.png" "$tmp/half.png" || fail "frame 1 at --fps 2 is not t = 0.5"
cmp -s "$tmp/cli.0000.png" "$tmp/half.png" && fail "frame 0 at --fps 2 is t = 0.5"
{ cat "$tmp/t.toml"; printf '[animation]\ntime_uniform = "t"\nframes_per_second = 2\n'; } >"$tmp/anim.toml"
trun "$tmp/anim.toml" -o "$tmp/anim.png" --frames 2 >/dev/null || fail "[animation] exited with $?"
cmp -s "$tmp/anim.0001.png" "$tmp/half.png" || fail "[animation] frames_per_second = 2: frame 1 is not t = 0.5"
if trun "$tmp/t.toml" -o "$tmp/x.png" --fps 2 >/dev/null 2>"$tmp/err"; then fail "--fps without --frames was accepted"; fi
grep -q "give --frames" "$tmp/err" || fail "--fps without --frames: unclear error: $(cat "$tmp/err")"
{ cat "$tmp/t.toml"; printf '[animation]\nframes_per_second = 0\n'; } >"$tmp/bad.toml"
if trun "$tmp/bad.toml" -o "$tmp/x.png" --frames 1 >/dev/null 2>"$tmp/err"; then fail "frames_per_second = 0 was accepted"; fi
grep -q "bad.toml:8: error: .*frames_per_second" "$tmp/err" || fail "frames_per_second = 0: no file:line error: $(cat "$tmp/err")"

finish "cli outputs: -o -, extensions, draw buffers, --uniform and --frames behave"
