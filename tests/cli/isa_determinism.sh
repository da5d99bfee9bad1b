#!/bin/sh
# Images must not depend on the CPU: the interpreter picks AVX2 kernels where
# the CPU has them and the baseline x86-64 ones elsewhere (GLSLRUN_NO_AVX2=1
# forces the baseline). Renders the lecture and textured scenes both ways, and
# with 1 and 3 threads, and requires byte-identical PNGs.
#   tests/cli/isa_determinism.sh SOURCE_DIR GLSLRUN
set -u
src=$1
glslrun=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
render() {  # name program scene no_avx2 threads
    GLSLRUN_NO_AVX2=$4 "$glslrun" "$src/shaders/$2.vert" "$src/shaders/$2.frag" "$src/scenes/$3" \
        --size 160x120 --threads "$5" -o "$tmp/$1.png" >/dev/null ||
        { echo "FAIL: $2 on $3 did not render" >&2; failures=$((failures + 1)); }
}
for case in "spot_pix_fixed spot.toml" "dir_vert directional.toml" "two_side two_side.toml" \
            "textured_pix textured.toml" "cube_reflect cube_map.toml"; do
    set -- $case
    render avx2 "$1" "$2" "" 1
    render base "$1" "$2" 1 3
    if ! cmp -s "$tmp/avx2.png" "$tmp/base.png"; then
        echo "FAIL: $1 on $2 differs between the AVX2 and the baseline kernels" >&2
        failures=$((failures + 1))
    fi
done
[ $failures -eq 0 ] && echo "all images identical"
exit $((failures > 0))
