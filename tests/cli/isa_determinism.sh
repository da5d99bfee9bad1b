#!/bin/sh
# Images must not depend on the CPU: the interpreter picks AVX2 kernels where
# the CPU has them and the baseline x86-64 ones elsewhere (GLSLRUN_NO_AVX2=1
# forces the baseline). Renders the lecture and textured scenes both ways, and
# with 1 and 3 threads, and requires byte-identical PNGs, in every precision
# mode (Fast has its own kernels; Reference has baseline ones only, so there
# it checks the thread counts). The JIT's code too: AVX-512 where the CPU has
# it and AVX2 (GLSLRUN_NO_AVX512=1) must draw the interpreter's image.
#   tests/cli/isa_determinism.sh SOURCE_DIR GLSLRUN
set -u
src=$1
glslrun=$2
. "$src/tests/cli/common.sh"
render() {  # name program scene no_avx2 threads precision [backend no_avx512]
    GLSLRUN_NO_AVX2=$4 GLSLRUN_NO_AVX512=${8:-} "$glslrun" "$src/shaders/$2.vert" "$src/shaders/$2.frag" \
        "$src/scenes/$3" --size 160x120 --threads "$5" --precision "$6" --backend "${7:-auto}" --no-cache \
        -o "$tmp/$1.png" >/dev/null ||
        fail "$2 on $3 did not render ($6)"
}
for precision in precise fast reference; do
    for case in "spot_pix_fixed spot.toml" "dir_vert directional.toml" "two_side two_side.toml" \
                "textured_pix textured.toml" "cube_reflect cube_map.toml"; do
        set -- $case
        render avx2 "$1" "$2" "" 1 $precision
        render base "$1" "$2" 1 3 $precision
        if ! cmp -s "$tmp/avx2.png" "$tmp/base.png"; then
            fail "$1 on $2 ($precision) differs between AVX2 and baseline kernels, 1 and 3 threads"
        fi
        [ $precision = reference ] && continue
        render jit512 "$1" "$2" "" 1 $precision jit ""
        render jit256 "$1" "$2" "" 3 $precision jit 1
        for isa in jit512 jit256; do
            cmp -s "$tmp/avx2.png" "$tmp/$isa.png" ||
                fail "$1 on $2 ($precision) differs between the interpreter and the JIT ($isa)"
        done
    done
done
finish "all images identical"
