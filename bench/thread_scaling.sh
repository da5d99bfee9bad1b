#!/usr/bin/env bash
# Thread scaling of glslrun alone (no Mesa, so it runs on machines without it,
# such as the 16-core device machine): the lecture's spot-light teapot at
# 1920x1080, subdivisions 10 and 64, for each thread count. Prints one TSV row
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
for sub in 10 64; do
    scene=$tmp/spot-sub$sub.toml
    sed -E "s/^subdivisions *= *[0-9]+/subdivisions = $sub/" "$repo/scenes/spot.toml" > "$scene"
    base=""
    for t in $counts; do
        out=$("$glslrun" "$repo/shaders/spot_pix_fixed.vert" "$repo/shaders/spot_pix_fixed.frag" "$scene" \
              --size 1920x1080 --threads "$t" --bench "$frames" -o "$tmp/t$t.png")
        value() { awk -v k="$1" '$1 == k { print $2 }' <<< "$out"; }
        ms=$(value median_ms)
        [ -z "$base" ] && base=$ms
        speedup=$(awk -v b="$base" -v m="$ms" 'BEGIN { printf "%.2f", b / m }')
        echo -e "spot sub $sub\t$t\t$ms\t$(value vertex_ms)\t$(value raster_ms)\t$(value fragment_ms)\t$speedup"
        first=$(echo $counts | cut -d' ' -f1)
        if ! cmp -s "$tmp/t$first.png" "$tmp/t$t.png"; then
            echo "thread_scaling.sh: the image with $t threads differs from the one with $first" >&2
            exit 1
        fi
    done
done
