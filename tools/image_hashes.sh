#!/usr/bin/env bash
# Prints the SHA-256 of every scene image glslrun renders (the cases of
# bench/precision.py) in each precision mode, one "mode shader scene hash"
# line each. Run it on two machines and diff the outputs: Precise images must
# be identical on every x86-64 machine (docs/precision.md, "Guarantees").
#
#   tools/image_hashes.sh GLSLRUN [MODES] [THREADS]
#   tools/image_hashes.sh build/glslrun "precise fast reference" 3
set -euo pipefail
glslrun=$1
modes=${2:-"precise fast reference"}
threads=${3:-2}
repo=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

cases=$(python3 -c "
import sys; sys.path.insert(0, '$repo/bench')
import precision
for shader, scene, _ in precision.CASES: print(shader, scene)" 2>/dev/null) || cases=$(
    sed -n 's/^    ("\([a-z_]*\)", "\([a-z_]*\.toml\)", .*/\1 \2/p' "$repo/bench/precision.py")
[ -n "$cases" ] || { echo "image_hashes.sh: no cases found in bench/precision.py" >&2; exit 1; }

while read -r shader scene; do
    for mode in $modes; do
        "$glslrun" "$repo/shaders/$shader.vert" "$repo/shaders/$shader.frag" "$repo/scenes/$scene" \
            --precision "$mode" --threads "$threads" -o "$tmp/out.png" > /dev/null
        echo "$mode $shader $scene $(sha256sum < "$tmp/out.png" | cut -d' ' -f1)"
    done
done <<< "$cases"
