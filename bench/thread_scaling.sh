#!/usr/bin/env bash
# Thread scaling of glslrun alone (no Mesa, so it runs on machines without it,
# such as the 16-core device machine): the lecture's spot-light teapot at
# 1920x1080, subdivisions 10 and 64, and the vertex-bound directional and
# minimal programs at subdivision 64, for each thread count. Prints one TSV row
# per case and count (median ms per frame and speed-up over 1 thread), and
# fails if any image differs from the 1-thread image.
#
#   bench/thread_scaling.sh GLSLRUN [THREAD_COUNTS] [FRAMES]
#   bench/thread_scaling.sh build/glslrun "1 2 4 8 16" 20
set -euo pipefail
glslrun=$1
counts=${2:-"1 2"}
frames=${3:-20}
repo=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

echo -e "case\tthreads\tmedian_ms\tvertex_ms\traster_ms\tfragment_ms\tspeedup"
# name, program (shaders/NAME.vert and .frag), scene, subdivisions
cases=("spot sub 10|spot_pix_fixed|spot.toml|10" "spot sub 64|spot_pix_fixed|spot.toml|64"
       "directional sub 64|dir_vert|directional.toml|64" "minimal sub 64|minimal|directional.toml|64")
for c in "${cases[@]}"; do
    IFS='|' read -r name program scene_file sub <<< "$c"
    scene=$tmp/$program-sub$sub.toml
    sed -E "s/^subdivisions *= *[0-9]+/subdivisions = $sub/" "$repo/scenes/$scene_file" > "$scene"
    base=""
    for t in $counts; do
        out=$("$glslrun" "$repo/shaders/$program.vert" "$repo/shaders/$program.frag" "$scene" \
              --size 1920x1080 --threads "$t" --bench "$frames" -o "$tmp/t$t.png")
        value() { awk -v k="$1" '$1 == k { print $2 }' <<< "$out"; }
        ms=$(value median_ms)
        [ -z "$base" ] && base=$ms
        speedup=$(awk -v b="$base" -v m="$ms" 'BEGIN { printf "%.2f", b / m }')
        echo -e "$name\t$t\t$ms\t$(value vertex_ms)\t$(value raster_ms)\t$(value fragment_ms)\t$speedup"
        first=$(echo $counts | cut -d' ' -f1)
        if ! cmp -s "$tmp/t$first.png" "$tmp/t$t.png"; then
            echo "thread_scaling.sh: the image with $t threads differs from the one with $first" >&2
            exit 1
        fi
    done
done
