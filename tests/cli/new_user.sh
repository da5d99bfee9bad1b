#!/bin/sh
# The command line as a new user meets it, and its input hardening: no
# output over an input, NUL bytes in paths, FIFOs, exit statuses as
# docs/ci.md states them, CR-only sources, --help, mistyped commands and
# uniforms, .glsl with --stage, `glslrun check`, image formats,
# --error-report's files, --compare's coverage, batch's format, the command
# line's program in a scene whose passes all name their own.
#
#   tests/cli/new_user.sh SOURCE_DIR GLSLRUN
set -u
src=$1
glslrun=$2
. "$src/tests/cli/common.sh"

vs=$src/shaders/minimal.vert
fs=$src/shaders/minimal.frag
scene=$src/scenes/spot.toml
cd "$tmp" || exit 1

same() { cmp -s "$1" "$2" || fail "$3"; }

# ---- Inputs are never overwritten: by name, symbolic or hard link.
cp -r "$src/scenes/textures" . && cp "$src/scenes/textured.toml" .
cp textures/wood.png wood.orig
tvs=$src/shaders/textured_pix.vert
tfs=$src/shaders/textured_pix.frag
expect 2 "is an input" "$glslrun" "$tvs" "$tfs" textured.toml --size 8x8 -o textures/wood.png
same textures/wood.png wood.orig "-o over the scene's texture changed it"
ln -s textures/wood.png wood_link.png
expect 2 "is an input" "$glslrun" "$tvs" "$tfs" textured.toml --size 8x8 -o wood_link.png
same textures/wood.png wood.orig "-o over a symbolic link to the texture changed it"
"$glslrun" "$vs" "$fs" "$scene" --size 8x8 -o ref.png || fail "render ref.png"
cp ref.png ref.orig
ln ref.png ref_hard.png
expect 2 "is an input" "$glslrun" --compare ref.png ref.png --diff ref.png
expect 2 "is an input" "$glslrun" --compare ref.png ref.png --diff ref_hard.png
expect 2 "is an input" "$glslrun" "$vs" "$fs" "$scene" --size 8x8 --compare ref.png --diff ref.png
same ref.png ref.orig "--diff over the reference changed it"
mkdir rep && cp "$scene" rep_scene.toml && ln rep_scene.toml rep/reference.png
expect 2 "is an input" "$glslrun" "$vs" "$fs" rep_scene.toml --size 8x8 --error-report rep
cmp -s rep_scene.toml "$scene" || fail "--error-report wrote over the scene through a hard link"

# ---- NUL bytes in paths, FIFOs, exit statuses.
printf '%s %s %s a\000b.png\n' "$vs" "$fs" "$scene" > nul.jobs
expect 1 "nul.jobs:1: error: a NUL byte" "$glslrun" batch nul.jobs
[ ! -e a ] || fail "a job with a NUL in its output wrote 'a'"
sed 's|^image = .*|image = "textures/wood.png\\u0000.txt"|' textured.toml > nul_texture.toml
expect 1 "holds a NUL byte" "$glslrun" "$tvs" "$tfs" nul_texture.toml --size 8x8 -o nul.png
mkfifo fifo.png
expect 2 "not a regular file" "$glslrun" --compare ref.png fifo.png
expect 2 "not a regular file" "$glslrun" --compare fifo.png ref.png
printf 'not a png' > notpng.txt
expect 2 "PNG images only" "$glslrun" --compare ref.png notpng.txt
grep -q "shader" err.txt && fail "--compare of a non-PNG speaks of shaders: $(cat err.txt)"
if [ -w /dev/full ]; then
    "$glslrun" "$vs" "$fs" "$scene" --size 8x8 -o - > /dev/full 2>err.txt
    [ $? = 2 ] || fail "-o - > /dev/full: exit status is not 2 ($(cat err.txt))"
fi
expect 2 "--size '300' must be WxH" "$glslrun" "$vs" "$fs" "$scene" --size 300

# ---- Sources: CR-only line ends, #line past INT_MAX.
printf '#version 110\r// a comment\rvoid main() {\r    gl_FragColor = vec4(1.0);\r}\r' > cr.frag
"$glslrun" check cr.frag 2>err.txt || fail "a CR-only shader is refused: $(cat err.txt)"
printf '#version 110\r\rvoid main() {\r    gl_FragColor = vec4(1.0)\r}\r' > cr_bad.frag
expect 1 "cr_bad.frag:4: error:" "$glslrun" check cr_bad.frag
printf '#line 4294967295 4294967295\nvoid main() { gl_FragColor = vec4(1.0) }\n' > line.frag
expect 1 "line.frag: error:" "$glslrun" check line.frag
grep -q '^-1' err.txt && fail "#line 4294967295: $(cat err.txt)"

# ---- --help, mistyped commands and uniforms, --uniform values.
"$glslrun" --help > help.txt || fail "--help failed"
for word in "glslrun trace" "glslrun batch" "glslrun check" "glslrun test" "--quiet" "Exit status" "Documentation: /"; do
    grep -qF -- "$word" help.txt || fail "--help does not mention '$word'"
done
expect 2 "did you mean 'glslrun trace'?" "$glslrun" trac
expect 2 "did you mean 'glslrun batch'?" "$glslrun" bach
# A misspelt option names the one meant (CLI11 alone says "was not expected").
expect 2 "glslrun: error: unknown option '--treads'; did you mean '--threads'?" "$glslrun" "$vs" "$fs" "$scene" --treads 2
expect 2 "unknown option '--pixle'; did you mean '--pixel'?" "$glslrun" trace --pixle=1,1 "$vs" "$fs" "$scene"
printf 'uniform vec3 baseColor;\nvoid main() { gl_FragColor = vec4(baseColor, 1.0); }\n' > base.frag
expect 1 "did you mean 'baseColor'?" "$glslrun" "$vs" base.frag "$scene" --size 8x8 --uniform basecolor=1,0,0 -o u.png
"$glslrun" "$vs" base.frag "$scene" --size 8x8 --uniform baseColor=1,0,0 -o list.png 2>err.txt ||
    fail "--uniform baseColor=1,0,0: $(cat err.txt)"
"$glslrun" "$vs" base.frag "$scene" --size 8x8 --uniform 'baseColor=[1, 0, 0]' -o array.png || fail "[1, 0, 0]"
same list.png array.png "--uniform 1,0,0 and [1, 0, 0] differ"
expect 2 "is not a value" "$glslrun" "$vs" base.frag "$scene" --uniform 'baseColor=1,,0'
grep -qi "toml\|expected" err.txt && fail "--uniform's message is toml++'s: $(cat err.txt)"
# A [uniforms] entry no program has is what GL ignores (location -1): the scene renders, with a warning at
# the entry's line naming the uniform the program does have.
printf '[output]\nsize = [8, 8]\n[uniforms]\nbaseColor = [1, 0, 0]\nbasecolour = [0, 1, 0]\n[[objects]]\nmesh = "quad"\n' > unused.toml
"$glslrun" "$vs" base.frag unused.toml -o unused.png 2>err.txt || fail "an unused [uniforms] entry: $(cat err.txt)"
grep -qF "unused.toml:5: warning: the program has no active uniform 'basecolour': the entry is ignored, as GL ignores glUniform at location -1; did you mean 'baseColor'?" err.txt ||
    fail "an unused [uniforms] entry's warning: $(cat err.txt)"
"$glslrun" trace --pixel 4,4 "$vs" base.frag unused.toml >/dev/null 2>err.txt || fail "trace, unused entry: $(cat err.txt)"
grep -qF "unused.toml:5: warning: the program has no active uniform 'basecolour'" err.txt ||
    fail "trace does not warn of an unused [uniforms] entry: $(cat err.txt)"
"$glslrun" "$vs" base.frag unused.toml --check-undefined >/dev/null 2>err.txt || fail "--check-undefined, unused entry: $(cat err.txt)"
grep -qF "unused.toml:5: warning: the program has no active uniform 'basecolour'" err.txt ||
    fail "--check-undefined does not warn of an unused [uniforms] entry: $(cat err.txt)"
"$glslrun" "$vs" base.frag unused.toml --error-report er_unused >/dev/null 2>err.txt || fail "--error-report, unused entry: $(cat err.txt)"
grep -qF "unused.toml:5: warning: the program has no active uniform 'basecolour'" err.txt ||
    fail "--error-report does not warn of an unused [uniforms] entry: $(cat err.txt)"

# ---- .glsl and --stage, glslrun check, the pass-through vertex shader.
cp "$fs" plain.glsl
expect 2 "give --stage vert or --stage frag" "$glslrun" plain.glsl "$scene" -o g.png
"$glslrun" --stage frag plain.glsl "$scene" --size 8x8 -o g.png || fail "--stage frag plain.glsl"
"$glslrun" "$fs" "$scene" --size 8x8 -o f.png || fail "minimal.frag alone"
# No shader at all: GL's fixed function for every draw; what needs a program of the user's says so.
"$glslrun" "$scene" --size 8x8 -o n.png || fail "a scene alone (fixed function)"
[ -s n.png ] || fail "a scene alone wrote no image"
expect 2 "need a program of yours" "$glslrun" "$scene" --stats
same g.png f.png "a .glsl fragment shader renders differently"
cp "$fs" named.frag.glsl
"$glslrun" check named.frag.glsl || fail "check a.frag.glsl"
"$glslrun" check -S frag plain.glsl || fail "check -S frag"
"$glslrun" check "$vs" "$fs" || fail "check of the minimal shaders"
expect 1 "plain.glsl:" "$glslrun" check -S vert plain.glsl
printf 'varying vec3 n;\nvoid main() { gl_FragColor = vec4(n, 1.0); }\n' > varying.frag
expect 1 "no vertex shader was given" "$glslrun" varying.frag

# ---- -D NAME[=VALUE], as glslangValidator's: line numbers unchanged.
printf '#version 110\nvoid main() {\n    gl_FragColor = vec4(COLOR);\n}\n' > defined.frag
"$glslrun" check -D COLOR=1.0,0.0,0.0,1.0 defined.frag || fail "check -D COLOR=..."
expect 1 "defined.frag:3: error:" "$glslrun" check defined.frag
"$glslrun" -D 'COLOR=0.0,1.0,0.0,1.0' "$vs" defined.frag "$scene" --size 8x8 -o defined.png || fail "render -D"
printf 'void main() {\n#ifdef GREEN\n    gl_FragColor = vec4(0.0, 1.0, 0.0, 1.0);\n#else\n    gl_FragColor = vec4(1.0);\n#endif\n}\n' > ifdef.frag
"$glslrun" -D GREEN "$vs" ifdef.frag "$scene" --size 8x8 -o ifdef.png || fail "render -D GREEN"
same defined.png ifdef.png "-D NAME and -D NAME=VALUE render differently"
expect 2 "must be an identifier" "$glslrun" check -D 1X=2 defined.frag
expect 2 "reserved" "$glslrun" check -D GL_FOO defined.frag

# ---- Image formats by name; PNG stays lossless.
"$glslrun" "$vs" "$fs" "$scene" --size 16x16 -o out.jpg || fail "-o out.jpg"
head -c 3 out.jpg | od -An -tx1 | grep -q "ff d8 ff" || fail "out.jpg is not a JPEG"
"$glslrun" "$vs" "$fs" "$scene" --size 16x16 -o out.bmp && [ "$(head -c 2 out.bmp)" = BM ] || fail "-o out.bmp"
"$glslrun" "$vs" "$fs" "$scene" --size 16x16 -o out.tga && [ -s out.tga ] || fail "-o out.tga"
expect 2 "chosen by the name" "$glslrun" "$vs" "$fs" "$scene" -o out.gif

# ---- --error-report writes its table and key lines into DIR, and says so.
"$glslrun" "$vs" "$fs" "$scene" --size 16x16 --precision fast --error-report er > er.out || fail "--error-report"
[ -s er/report.txt ] && [ -s er/report.keys ] || fail "--error-report wrote no report.txt or report.keys: $(ls er)"
grep -q "er/report.txt" er.out || fail "--error-report does not say where the table is"

# ---- --compare's coverage: background pixels are not covered.
"$glslrun" --compare ref.png ref.png > cmp.txt || fail "--compare of an image with itself"
grep -q " of 64 covered" cmp.txt && fail "--compare counted every pixel as covered: $(cat cmp.txt)"
grep -q "^covered: pixels that differ from 0,0,0,255" cmp.txt || fail "--compare: no background line: $(cat cmp.txt)"
"$glslrun" --compare ref.png ref.png --background none | grep -q " of 64 covered" || fail "--background none"
expect 2 "--background" "$glslrun" --compare ref.png ref.png --background 1,2,3

# ---- batch: malformed lines, quoted paths, each program compiled once.
mkdir "with space"
cat > jobs.txt <<JOBS
# a comment
$vs $fs $scene one.png
$vs $fs
"$vs" '$fs' "$scene" "with space/two.png"  # quoted
$vs $fs $scene 'unterminated.png
$vs $fs $scene three.png
JOBS
expect 1 "jobs.txt:3: error: a job is" "$glslrun" batch jobs.txt
grep -qF "jobs.txt:5: error: the quote ' opened" err.txt || fail "batch: no error for line 5: $(cat err.txt)"
[ -s one.png ] && [ -s "with space/two.png" ] && [ -s three.png ] || fail "batch did not run the good jobs: $(ls)"
grep -q "3 jobs, 3 rendered, 0 failed, 2 malformed lines; 1 program compiled" out.txt ||
    fail "batch summary: $(cat out.txt)"
# A compiled program is shared, its uniforms are not: each job renders as alone.
printf '[uniforms]\nbaseColor = [0, 1, 0]\n' > green_uniform.toml
sed -n '/^\[uniforms\]/q;p' "$scene" > scene_head.toml
cat scene_head.toml green_uniform.toml > green.toml
printf '%s %s %s %s\n' "$vs" base.frag green.toml b1.png "$vs" base.frag "$scene" b2.png > uniforms.jobs
"$glslrun" batch uniforms.jobs > /dev/null 2>err.txt || fail "batch uniforms.jobs: $(cat err.txt)"
"$glslrun" "$vs" base.frag "$scene" -o b2_alone.png 2>/dev/null || fail "render b2 alone"
same b2.png b2_alone.png "a batch job saw the previous job's uniform"

# Jobs of one shader or none draw the missing stages with GL's fixed function, as `glslrun` does;
# one shader's stage comes from its name.
ff=$src/scenes/fixed_function.toml
cp "$fs" stage.glsl
printf '%s %s alone.png\n%s fixed.png\nstage.glsl %s x.png\n' "$fs" "$scene" "$ff" "$scene" > fixed.jobs
expect 1 "fixed.jobs:3: error: 'stage.glsl': a job of one shader takes its stage from the name" \
    "$glslrun" batch fixed.jobs
grep -q "2 jobs, 2 rendered, 0 failed, 1 malformed line; 2 programs compiled" out.txt ||
    fail "batch fixed.jobs summary: $(cat out.txt)"
"$glslrun" "$fs" "$scene" -o alone_cli.png 2>/dev/null || fail "render minimal.frag alone"
"$glslrun" "$ff" -o fixed_cli.png 2>/dev/null || fail "render fixed_function.toml"
same alone.png alone_cli.png "batch: a job of a fragment shader alone differs from glslrun's image"
same fixed.png fixed_cli.png "batch: a job without shaders differs from glslrun's image"

# docs/scene-format.md's fixed-function example renders as given, and its unit 1 (a combiner) has a texture to
# be on: without [textures.1] the image is the same.
awk '/^A whole scene .*toon\.frag/ { found = 1 } found && /^```$/ { exit } found && on { print }
     found && /^```toml$/ { on = 1 }' "$src/docs/scene-format.md" > doc_fixed.toml
grep -q '^fragment = "toon.frag"' doc_fixed.toml || fail "the fixed-function example was not found in docs/scene-format.md"
printf 'void main() { gl_FragColor = floor(gl_Color * 4.0) / 4.0; }\n' > toon.frag
"$glslrun" doc_fixed.toml --size 128x96 -o doc_fixed.png 2>err.txt || fail "the docs' fixed-function example: $(cat err.txt)"
sed '/^\[textures.1\]/,/^$/d' doc_fixed.toml > doc_fixed_no1.toml
"$glslrun" doc_fixed_no1.toml --size 128x96 -o doc_fixed_no1.png 2>err.txt || fail "the example without unit 1"
cmp -s doc_fixed.png doc_fixed_no1.png && fail "the docs' example: texture unit 1's combiner changes nothing"

# A scene without shaders and without fixed-function state would be unlit white: said, with what to give.
"$glslrun" "$scene" --size 32x32 -o white.png 2>err.txt || fail "spot.toml without shaders: $(cat err.txt)"
grep -q "no shaders were given, and the scene sets no fixed-function state.*give the program's shaders" err.txt ||
    fail "no warning for a scene without shaders or state: $(cat err.txt)"
"$glslrun" "$src/scenes/fixed_function.toml" --size 32x32 -o lit.png 2>err.txt || fail "fixed_function.toml"
[ -s err.txt ] && fail "fixed_function.toml warned: $(cat err.txt)"

# ---- Progress on a terminal (script gives the command one).
if command -v script > /dev/null; then
    script -qec "$glslrun $vs $fs $scene --size 8x8 --frames 3 -o fr.png" /dev/null > tty.txt 2>&1
    grep -q "3/3 frames" tty.txt || fail "--frames shows no progress on a terminal: $(cat tty.txt)"
    "$glslrun" "$vs" "$fs" "$scene" --size 8x8 --frames 3 -o fr.png 2> notty.txt
    grep -q "/3 frames" notty.txt && fail "--frames prints progress into a pipe: $(cat notty.txt)"
    script -qec "$glslrun $vs $fs $scene --size 8x8 --bench 3 -o fr.png" /dev/null > tty.txt 2>&1
    grep -q "3/3 bench frames" tty.txt || fail "--bench shows no progress on a terminal: $(cat tty.txt)"
fi

# ---- #include with -I DIR (GL_GOOGLE_include_directive, as glslangValidator's -I).
mkdir -p inc/lib inc/other
printf '#extension GL_GOOGLE_include_directive : require\n#include "colour.glsl"\nvoid main() { gl_FragColor = colour(); }\n' > inc/main.frag
printf '#include "helpers/scale.glsl"\nvec4 colour() { return vec4(scale(0.25), 1.0, 0.0, 1.0); }\n' > inc/lib/colour.glsl
mkdir -p inc/lib/helpers
printf 'float scale(float x) { return x * 2.0; }\n' > inc/lib/helpers/scale.glsl
expect 1 "inc/main.frag:2: error: '#include' : 'colour.glsl' is in none of inc (-I DIR adds a directory)" \
    "$glslrun" check inc/main.frag
"$glslrun" check -I inc/other -I inc/lib inc/main.frag > out.txt 2> err.txt || fail "check -I: $(cat err.txt)"
"$glslrun" "$vs" inc/main.frag "$scene" -I inc/lib --size 4x4 -o inc.png 2> err.txt || fail "render -I: $(cat err.txt)"
printf 'void main() { gl_FragColor = vec4(0.5, 1.0, 0.0, 1.0); }\n' > inc/flat.frag
"$glslrun" "$vs" inc/flat.frag "$scene" --size 4x4 -o flat.png 2> /dev/null || fail "render flat.frag"
same inc.png flat.png "the included function's colour"
# Every command that compiles the shaders takes -I and -D: the debugger, the
# error report, --check-undefined, and a pass that names its own shaders.
"$glslrun" trace --pixel 2,2 -I inc/lib "$vs" inc/main.frag "$scene" --size 4x4 > tr.txt 2> err.txt ||
    fail "trace -I: $(cat err.txt)"
grep -q "colour.glsl" tr.txt || fail "trace -I: the included file's lines are not in the trace: $(cat tr.txt)"
"$glslrun" trace --find-nan -I inc/lib "$vs" inc/main.frag "$scene" --size 4x4 > /dev/null 2> err.txt ||
    fail "trace --find-nan -I: $(cat err.txt)"
"$glslrun" "$vs" inc/main.frag "$scene" -I inc/lib --size 4x4 --check-undefined > /dev/null 2> err.txt ||
    fail "--check-undefined -I: $(cat err.txt)"
"$glslrun" "$vs" inc/main.frag "$scene" -I inc/lib --size 4x4 --error-report er_inc > /dev/null 2> err.txt ||
    fail "--error-report -I: $(cat err.txt)"
printf '#ifndef GREEN\n#error GREEN is not defined\n#endif\nvoid main() { gl_FragColor = vec4(0.5, GREEN, 0.0, 1.0); }\n' \
    > inc/defined.frag
"$glslrun" "$vs" inc/defined.frag "$scene" -D GREEN=1.0 --size 4x4 --error-report er_d > /dev/null 2> err.txt ||
    fail "--error-report -D: $(cat err.txt)"
"$glslrun" trace --pixel 2,2 -D GREEN=1.0 "$vs" inc/defined.frag "$scene" --size 4x4 > /dev/null 2> err.txt ||
    fail "trace -D: $(cat err.txt)"
{ cat "$scene"; printf '\n[[passes]]\nvertex = "%s"\nfragment = "inc/main.frag"\n' "$vs"; } > inc_pass.toml
"$glslrun" "$vs" inc/main.frag inc_pass.toml -I inc/lib --size 4x4 -o inc_pass.png 2> err.txt ||
    fail "a pass's own shaders with -I: $(cat err.txt)"
same inc_pass.png flat.png "a pass's own shader with -I: the included function's colour"
# An error inside an included file names that file and its own line.
printf 'float scale(float x) {\n    return x * undefined_thing;\n}\n' > inc/lib/helpers/scale.glsl
expect 1 "inc/lib/helpers/scale.glsl:2: error: 'undefined_thing' : undeclared identifier" \
    "$glslrun" check -I inc/lib inc/main.frag
expect 2 "--include-dir: Directory does not exist: inc/missing" "$glslrun" check -I inc/missing inc/main.frag
# A file that includes itself ends at the depth limit.
printf '#extension GL_GOOGLE_include_directive : require\n#include "self.frag"\nvoid main() {}\n' > inc/self.frag
expect 1 "#include nests more than 32 deep" "$glslrun" check inc/self.frag

# ---- --stats names a rectangle texture (scenes/rectangle.toml).
"$glslrun" "$src/shaders/rect_post.vert" "$src/shaders/rect_post.frag" "$src/scenes/rectangle.toml" --size 8x8 \
    --stats -o rect.png > rect_stats.txt 2> rect_err.txt || fail "rect_post did not render: $(cat rect_err.txt)"
grep -q "unit 0: rectangle 64x64 RGBA8, 1 level" rect_stats.txt || fail "--stats: no rectangle texture in $(cat rect_stats.txt)"

# ---- The command line's program compiles and links even where every pass
# names its own shaders (multi_pass.toml): its errors are reported, with no image.
printf 'void main() { gl_FragColor = vec4(undefined_name); }\n' > broken.frag
printf 'varying vec3 v;\nvoid main() { gl_FragColor = vec4(v, 1.0); }\n' > unlinked.frag
for mode in "-o passes.png" "--frames 2 -o passes.png" "--bench 1 -o passes.png" "--error-report er"; do
    # shellcheck disable=SC2086
    expect 1 "broken.frag:1: error: 'undefined_name'" "$glslrun" "$vs" broken.frag "$src/scenes/multi_pass.toml" \
        --size 8x8 $mode
    ls passes*.png er/*.png > /dev/null 2>&1 && fail "an image was written for a program that does not compile ($mode)"
done
expect 1 "varying 'v' is read by the fragment shader but not written" "$glslrun" "$vs" unlinked.frag \
    "$src/scenes/multi_pass.toml" --size 8x8 -o passes.png
expect 1 "broken.frag:1: error" "$glslrun" trace --pixel 1,1 "$vs" broken.frag "$src/scenes/multi_pass.toml"
printf '%s broken.frag %s passes.png\n' "$vs" "$src/scenes/multi_pass.toml" > passes.jobs
expect 1 "broken.frag:1: error" "$glslrun" batch passes.jobs

finish "new-user CLI: inputs protected, NUL paths, exit statuses, help, check, formats, reports, batch"
