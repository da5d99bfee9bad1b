#!/bin/sh
# Issue #17's reproducers through the command line: each ends quickly with a
# message and exit status 1 (a result) or 2 (usage or tool error), never a
# signal, an abort or a hang; and `glslrun test`'s CI outputs.
#
#   tests/cli/hardening.sh SOURCE_DIR GLSLRUN
set -u
src=$1
glslrun=$2
. "$src/tests/cli/common.sh"

vs=$src/shaders/minimal.vert
fs=$src/shaders/minimal.frag
scene=$src/scenes/spot.toml
cd "$tmp" || exit 1


sed 's/^size = .*/size = [16384, 16384]/' "$scene" > big.toml
expect 1 "64M pixels at most" "$glslrun" "$vs" "$fs" big.toml -o big.png
sed 's/subdivisions = 10/subdivisions = 1024/' "$scene" > teapot.toml
expect 1 "must be in [1, 256]" "$glslrun" "$vs" "$fs" teapot.toml -o teapot.png
ln -s /dev/zero zero.frag
expect 1 "not a regular file" "$glslrun" "$vs" zero.frag
printf 'void main() { float a[1000000000]; a[1] = 1.0; gl_FragColor = vec4(a[1]); }\n' > array.frag
expect 1 "array.frag:1: error: 'a' : 1000000000 components" "$glslrun" "$vs" array.frag
# Macros that double one another 40 times (2^40 terms) stop at the token budget.
{ echo '#define A1 x+x'; for i in $(seq 2 40); do echo "#define A$i A$((i - 1))+A$((i - 1))"; done
  echo 'uniform float x; void main() { gl_FragColor = vec4(A40); }'; } > macros.frag
expect 1 "macros.frag: error: the source's macros expand past glslrun's limit" "$glslrun" "$vs" macros.frag
# A PNG of a few bytes whose header claims 16384x16384 pixels.
python3 -c "
import struct, zlib
def chunk(t, d): return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d))
ihdr = struct.pack('>IIBBBBB', 16384, 16384, 8, 6, 0, 0, 0)
open('huge.png', 'wb').write(b'\\x89PNG\\r\\n\\x1a\\n' + chunk(b'IHDR', ihdr) + chunk(b'IDAT', zlib.compress(b'\\0' * 10)))
"
expect 2 "more than its" "$glslrun" --compare huge.png huge.png
expect 2 "the path is empty" "$glslrun" "$vs" "$fs" "$scene" -o ''
# sscanf's %d wrapped 4294967360 to 64 and rendered a 64x64 image.
expect 2 "--size '4294967360x64' must be WxH" "$glslrun" "$vs" "$fs" "$scene" --size 4294967360x64 -o wrapped.png
[ ! -e wrapped.png ] || fail "--size 4294967360x64 wrote an image"
[ -z "$(ls ./*.png 2>/dev/null | grep -v huge.png)" ] || fail "a PNG was written: $(ls)"
"$glslrun" --dump-ir "$vs" "$fs" "$scene" > ir.txt || fail "--dump-ir with a scene failed"
[ -z "$(ls ./*.png 2>/dev/null | grep -v huge.png)" ] || fail "--dump-ir with a scene wrote a PNG: $(ls)"
# A call chain 1000 deep: minutes in LLVM, then "call depth exceeded (recursion?)" at run time.
{ echo 'uniform float u; float f0(float x) { return x * 1.5; }'
  for i in $(seq 1 999); do echo "float f$i(float x) { return f$((i - 1))(x) + 1.0; }"; done
  echo 'void main() { gl_FragColor = vec4(f999(u)); }'; } > chain.frag
expect 1 "chain.frag:745: error: 'f743' : calls nest 1000 deep from main, more than glslrun's limit of 256" \
    "$glslrun" "$vs" chain.frag
# A render's draws and frames together stop at --max-instructions: each frame's
# draws are within their own budget, the frames together are not.
printf 'uniform int n; void main() { float s = 0.0; for (int i = 0; i < n; ++i) s += float(i);\n gl_FragColor = vec4(s); }\n' > loop.frag
"$glslrun" "$vs" loop.frag "$scene" --size 32x32 --uniform n=500 --stats -o one.png > stats.txt || fail "loop.frag: $(cat stats.txt)"
per_frame=$(sed -n 's/^instructions \([0-9]*\).*/\1/p' stats.txt)
[ "${per_frame:-0}" -gt 10000 ] || fail "--stats printed no instruction count: $(cat stats.txt)"
expect 1 "the render executed more than $((3 * per_frame + 10)) instructions, its draws together" \
    "$glslrun" "$vs" loop.frag "$scene" --size 32x32 --uniform n=500 --frames 5 --max-instructions $((3 * per_frame + 10)) -o f.png
[ -e f.0002.png ] && [ ! -e f.0003.png ] || fail "--frames past --max-instructions: frames 0..2 should be written: $(ls)"
"$glslrun" "$vs" loop.frag "$scene" --size 32x32 --uniform n=500 --frames 3 --max-instructions $((3 * per_frame)) -o g.png \
    2> /dev/null || fail "three frames within --max-instructions failed"
expect 2 "--max-instructions" "$glslrun" "$vs" loop.frag "$scene" --max-instructions 0

# Output cut short by a full disk is an error, not a success.
if [ -w /dev/full ]; then
    "$glslrun" --dump-ir "$vs" "$fs" > /dev/full 2> err.txt
    [ $? = 2 ] && grep -q "cannot write standard output" err.txt || fail "--dump-ir > /dev/full: $(cat err.txt)"
fi

# -o goes through a temporary file: a failed write leaves nothing at the path.
mkdir ro && chmod 555 ro
if [ ! -w ro ]; then
    expect 2 "cannot open" "$glslrun" "$vs" "$fs" "$scene" -o ro/out.png
    [ -z "$(ls ro)" ] || fail "a failed write left $(ls ro)"
fi
"$glslrun" "$vs" "$fs" "$scene" --size 16x16 -o out.png || fail "rendering to out.png failed"
[ "$(ls | grep -c partial)" = 0 ] || fail "a temporary file was left: $(ls)"

# --compare's thresholds and exit status.
"$glslrun" "$vs" "$fs" "$scene" --size 16x16 -o other.png --precision fast || fail "second render failed"
"$glslrun" --compare out.png out.png > /dev/null || fail "an image differs from itself"
"$glslrun" --compare out.png other.png --tolerance 1 --min-fraction 0.999 --diff diff.png > /dev/null ||
    fail "fast vs precise minimal.frag differs by more than 1/255"
[ -s diff.png ] || fail "--diff wrote no image"
expect 2 "is not a number" "$glslrun" --compare out.png other.png --min-fraction nan

# glslrun test: exit statuses, --time-limit, shards and the CI reports.
mkdir empty
expect 2 "no tests found" "$glslrun" test empty
expect 2 "is not a number" "$glslrun" test --time-limit nan "$src/tests/extremes"
expect 2 "must be I/N" "$glslrun" test --shard 3/3 "$src/tests/extremes"
if [ -w /dev/full ]; then
    expect 2 "/dev/full: cannot write the TSV file" "$glslrun" test --tsv /dev/full "$src/tests/extremes"
    expect 2 "/dev/full: cannot write the JSON file" "$glslrun" test --json /dev/full "$src/tests/extremes"
fi
timeout 60 "$glslrun" test --no-isolate --time-limit 2 "$src/tests/hardening/slow_without_loops.shader_test" > slow.txt
[ $? = 1 ] || fail "the slow test did not fail with status 1 within its time limit"
grep -q "time limit ran out" slow.txt || fail "no time-limit message: $(cat slow.txt)"
"$glslrun" test --root "$src" tests/extremes --junit all.xml --json all.json > all.txt || fail "tests/extremes failed"
total=$(grep -c '"name"' all.json)
[ "$total" -gt 5 ] || fail "the JSON report lists $total tests"
[ "$(grep -c '<testcase' all.xml)" = "$total" ] || fail "the JUnit report does not list $total tests"
: > shards.txt
for i in 0 1 2; do
    "$glslrun" test --root "$src" tests/extremes --shard $i/3 --json shard$i.json > /dev/null || fail "shard $i failed"
    grep '"name"' shard$i.json | sed 's/", "result.*//' >> shards.txt
done
[ "$(sort shards.txt | uniq | wc -l)" = "$total" ] && [ "$(wc -l < shards.txt)" = "$total" ] ||
    fail "the three shards do not hold each test once"

# glslrun batch: many renders in one process; a failed job names its line.
printf '# two jobs\n%s %s %s b1.png\n%s %s missing.toml b2.png\n' "$vs" "$fs" "$scene" "$vs" "$fs" > jobs.txt
expect 1 "jobs.txt:3: error: job failed" "$glslrun" batch jobs.txt
[ -s b1.png ] && [ ! -e b2.png ] || fail "batch: b1.png should be written, b2.png not: $(ls)"
echo "$vs $fs" > bad_jobs.txt
expect 1 "bad_jobs.txt:1: error: a job is" "$glslrun" batch bad_jobs.txt
# A malformed line is reported with its number; the other jobs still run.
printf '%s %s %s b3.png\n%s %s %s b3.txt\n' "$vs" "$fs" "$scene" "$vs" "$fs" "$scene" > txt_jobs.txt
expect 1 "txt_jobs.txt:2: error: cannot write 'b3.txt'" "$glslrun" batch txt_jobs.txt
[ -e b3.png ] && [ ! -e b3.txt ] || fail "batch: the good job did not run, or the bad one did: $(ls)"

# Stippled lines past 2^20 dashes are refused before any dash is stored: a strip of 2400 diagonals of a
# 1024x1024 image with every other pixel set makes 1.2M (stored first, they took 300 MB).
{ printf '[output]\nsize = [1024, 1024]\n[camera]\northo = { left = 0, right = 1024, bottom = 0, top = 1024, '
  printf 'near = -1, far = 1 }\n[state]\nline_stipple = true\nline_stipple_pattern = 0x5555\n[[objects]]\n'
  printf 'mesh = "arrays"\nprimitive = "line_strip"\nvertices = ['
  for i in $(seq 1200); do printf '[0, 0], [1024, 1024], '; done; printf ']\n'; } > dashes.toml
if [ -x /usr/bin/time ]; then
    /usr/bin/time -f "%M" -o dashes.rss "$glslrun" "$vs" "$fs" dashes.toml -o dashes.png 2>dashes.err
    grep -q "stippled lines make more than 1048576 dashes" dashes.err || fail "2^20 dashes: $(cat dashes.err)"
    [ "$(tail -1 dashes.rss)" -lt 120000 ] || fail "the refused stippled draw peaked at $(tail -1 dashes.rss) KB"
fi

finish "hardening: every reproducer ends with a message and status 1 or 2"
