#!/bin/sh
# The JIT computes the interpreter's bits: every case of the image-hash set
# (bench/precision.py's CASES, which cover every scene in scenes/), in
# Precise and Fast, at 1 and 2 threads, rendered by both backends, must give
# byte-identical PNGs; and the fused fragment pipeline's last frames of
# three scenes. Reference runs on the interpreter only (--help).
#   tests/cli/backend_identical.sh SOURCE_DIR GLSLRUN
set -u
src=$1
glslrun=$2
. "$src/tests/cli/common.sh"
cases=$(sed -n 's/^    ("\([a-z_]*\)", "\([a-z_]*\.toml\)", .*/\1 \2/p' "$src/bench/precision.py")
[ -n "$cases" ] || fail "no cases found in bench/precision.py"
compared=0
echo "$cases" > "$tmp/cases"
while read -r shader scene; do
    for precision in precise fast; do
        for threads in 1 2; do
            # At 1 thread the JIT also draws with the uniforms compiled in (specialized from the first draw).
            specialized=$([ $threads = 1 ] && echo jit_specialized)
            for backend in interp jit $specialized; do
                "$glslrun" "$src/shaders/$shader.vert" "$src/shaders/$shader.frag" "$src/scenes/$scene" \
                    --precision $precision --threads $threads --backend ${backend%_specialized} \
                    --specialize-after $([ $backend = jit_specialized ] && echo 1 || echo 0) \
                    -o "$tmp/$backend.png" >/dev/null ||
                    fail "$shader on $scene did not render ($precision, $backend)"
            done
            for backend in jit $specialized; do
                cmp -s "$tmp/interp.png" "$tmp/$backend.png" ||
                    fail "$shader on $scene ($precision, $threads threads): the $backend image differs from the interpreter's"
                compared=$((compared + 1))
            done
        done
    done
done < "$tmp/cases"
# The fused fragment pipeline: a program takes it once it has shaded 2^20
# fragments (raster/fused/pipeline.h), so several frames of three scenes,
# the last of which it must have drawn (multi_pass: its light passes blend);
# at 1, 2 and 3 threads (with 2 or 3, a large draw clears on a thread of its
# own while its vertices and setup run: raster/draw.cpp's ClearAhead).
for case in "spot_pix_fixed spot 1920x1080 6" "colors quad 1024x1024 8" "minimal multi_pass 1280x720 3"; do
    set -- $case
    for run in interp:1 jit:1 jit:2 jit:3; do
        backend=${run%:*} threads=${run#*:}
        "$glslrun" "$src/shaders/$1.vert" "$src/shaders/$1.frag" "$src/scenes/$2.toml" --size $3 --bench $4 \
            --backend $backend --threads $threads -o "$tmp/$backend$threads.png" > "$tmp/$backend$threads.txt" ||
            fail "$1 on $2 did not render ($backend, $threads threads)"
    done
    for threads in 1 2 3; do
        grep -q '^fused_fragments  *[1-9]' "$tmp/jit$threads.txt" ||
            fail "$1 on $2: the fused pipeline drew no fragment ($threads threads)"
        cmp -s "$tmp/interp1.png" "$tmp/jit$threads.png" ||
            fail "$1 on $2 at $3: the fused pipeline's image at $threads threads differs from the interpreter's at 1"
        compared=$((compared + 1))
    done
done
finish "$compared image pairs identical"
