#!/bin/sh
# The JIT's code cache from the command line: a second render of the same
# program compiles nothing (--stats counts), its fused fragment pipeline
# included, and writes the same PNG as the first, the interpreter's and an
# uncached render; --no-cache and
# GLSLRUN_NO_CACHE write nothing; GLSLRUN_CACHE_DIR and --cache-dir choose
# the directory; an unwritable one is a warning, not an error; damaged
# entries are compiled and written again; the JIT's second tier is cached
# apart (--jit-tier).
#   tests/cli/code_cache.sh SOURCE_DIR GLSLRUN
set -u
src=$1
glslrun=$2
. "$src/tests/cli/common.sh"
cd "$tmp" || exit 2
spot="$src/shaders/spot_pix_fixed.vert $src/shaders/spot_pix_fixed.frag $src/scenes/spot.toml --size 64x64"
entries() { find "$1" -type f 2>/dev/null | wc -l; }
# render NAME [BACKEND] ARGS...: the PNG to NAME.png, --stats to NAME.txt (BACKEND: jit unless given)
render() {
    name=$1
    shift
    backend=jit
    case "${1:-}" in auto | interp) backend=$1; shift ;; esac
    # shellcheck disable=SC2086
    "$glslrun" $spot --backend $backend --stats -o "$name.png" "$@" >"$name.txt" 2>"$name.err" ||
        fail "render $name failed: $(head -c 300 "$name.err")"
}
unset GLSLRUN_NO_CACHE
export GLSLRUN_CACHE_DIR="$tmp/env-cache"

render cold --cache-dir "$tmp/cache"
grep -q "2 shaders compiled, 0 loaded from the code cache" cold.txt || fail "cold: $(grep backend cold.txt)"
[ "$(entries "$tmp/cache")" = 2 ] || fail "cold: $(entries "$tmp/cache") entries, not 2"
render warm --cache-dir "$tmp/cache"
grep -q "0 shaders compiled, 2 loaded from the code cache" warm.txt || fail "warm: $(grep backend warm.txt)"
# A one-frame render under auto never loads the JIT (runtime/jit_plugin.h), warm cache or not.
render auto auto --cache-dir "$tmp/cache"
grep -q "0 shaders compiled, 0 loaded" auto.txt || fail "auto, one frame, warm cache: $(grep backend auto.txt)"
render uncached --no-cache
grep -q "2 shaders compiled, 0 loaded" uncached.txt || fail "--no-cache: $(grep backend uncached.txt)"
render interp interp
for name in warm auto uncached interp; do
    cmp -s cold.png $name.png || fail "the $name image differs from the first render's"
done

# The JIT's second tier (--jit-tier) is cached under keys of its own; a tiered run loads it at the
# first draw where it is there (spot's vertex shader: quick in the first tier, so it has a second;
# its fragment shader has every optimization in the first already). The same images.
render tier_first --jit-tier first --cache-dir "$tmp/tier-cache"
grep -q "2 shaders compiled, 0 loaded from the code cache; 0 of them optimised" tier_first.txt ||
    fail "--jit-tier first: $(grep 'JIT code' tier_first.txt)"
render tier_optimised --jit-tier optimised --cache-dir "$tmp/tier-cache"
grep -q "2 shaders compiled, 0 loaded from the code cache; 2 of them optimised" tier_optimised.txt ||
    fail "--jit-tier optimised: $(grep 'JIT code' tier_optimised.txt)"
render tier_tiered --cache-dir "$tmp/tier-cache"
grep -q "0 shaders compiled, 2 loaded from the code cache; 1 of them optimised" tier_tiered.txt ||
    fail "tiered, warm: $(grep 'JIT code' tier_tiered.txt)"
for name in tier_first tier_optimised tier_tiered; do
    cmp -s cold.png $name.png || fail "the $name image differs from the first render's"
done
# shellcheck disable=SC2086
if "$glslrun" $spot --jit-tier fastest -o bad.png >bad.txt 2>&1; then fail "--jit-tier fastest was accepted"; fi
grep -q "unknown JIT tier 'fastest': use tiered, first or optimised" bad.txt || fail "--jit-tier fastest: $(cat bad.txt)"

# The fused fragment pipeline (compiled once a program has shaded 2^20
# fragments, raster/fused/pipeline.h: the sixth frame of this quad) is cached too.
quad="$src/shaders/colors.vert $src/shaders/colors.frag $src/scenes/quad.toml --size 1024x1024 --bench 5"
for name in fused_cold fused_warm; do
    # shellcheck disable=SC2086
    "$glslrun" $quad --backend jit --stats --cache-dir "$tmp/fused-cache" -o $name.png >$name.txt 2>$name.err ||
        fail "render $name failed: $(head -c 300 $name.err)"
    grep -q '^fused_fragments  *[1-9]' $name.txt || fail "$name: the fused pipeline drew no fragment"
done
grep -q "1 pipeline compiled, 0 loaded from the code cache" fused_cold.txt || fail "fused, cold: $(grep pipelines fused_cold.txt)"
grep -q "0 shaders compiled, 2 loaded" fused_warm.txt || fail "fused, warm: $(grep backend fused_warm.txt)"
grep -q "0 pipelines compiled, 1 loaded from the code cache" fused_warm.txt ||
    fail "fused, warm: the pipeline was not loaded: $(grep fragments fused_warm.txt)"
[ "$(entries "$tmp/fused-cache")" = 4 ] ||
    fail "fused: $(entries "$tmp/fused-cache") entries, not 4 (2 shaders, 1 pipeline: its inputs and the rest)"
# A cached pipeline costs no LLVM time: the first frame takes it, before 2^20 fragments
# (fused_fragments counts the last frame's: 0 on the C++ path).
# shellcheck disable=SC2086
"$glslrun" ${quad% --bench 5} --bench 1 --backend jit --stats --cache-dir "$tmp/fused-cache" -o fused_first.png \
    >fused_first.txt 2>&1 || fail "render fused_first failed: $(head -c 300 fused_first.txt)"
grep -q '^fused_fragments  *[1-9]' fused_first.txt ||
    fail "fused, warm: the first frame did not take the cached pipeline: $(grep fragments fused_first.txt)"
cmp -s fused_cold.png fused_first.png || fail "the first frame with the cached pipeline differs from the cold run's"
# shellcheck disable=SC2086
"$glslrun" $quad --backend interp -o fused_interp.png >/dev/null || fail "the quad did not render (interp)"
cmp -s fused_cold.png fused_warm.png || fail "the image with the cached pipeline differs from the first"
cmp -s fused_cold.png fused_interp.png || fail "the fused pipeline's image differs from the interpreter's"

# A program drawn with four states (stencil mark and test, colour mask,
# blending) has four pipelines that share one inputs function: 2 shaders,
# 1 inputs function and 4 pipelines' rest in the cache, all loaded again.
mirror="$src/bench/corpus/mirror.vert $src/bench/corpus/mirror.frag $src/bench/corpus/mirror.toml --size 1024x1024 --bench 2"
for name in mirror_cold mirror_warm; do
    # shellcheck disable=SC2086
    "$glslrun" $mirror --backend jit --stats --cache-dir "$tmp/mirror-cache" -o $name.png >$name.txt 2>$name.err ||
        fail "render $name failed: $(head -c 300 $name.err)"
done
grep -q "4 pipelines compiled, 0 loaded from the code cache" mirror_cold.txt ||
    fail "mirror, cold: $(grep pipelines mirror_cold.txt)"
grep -q "0 pipelines compiled, 4 loaded from the code cache" mirror_warm.txt ||
    fail "mirror, warm: $(grep pipelines mirror_warm.txt)"
[ "$(entries "$tmp/mirror-cache")" = 7 ] || fail "mirror: $(entries "$tmp/mirror-cache") entries, not 7"
cmp -s mirror_cold.png mirror_warm.png || fail "mirror: the image with the cached pipelines differs"

# The environment: GLSLRUN_CACHE_DIR, and GLSLRUN_NO_CACHE over it.
[ "$(entries "$tmp/env-cache")" = 0 ] || fail "--no-cache or --cache-dir wrote to GLSLRUN_CACHE_DIR"
render env
[ "$(entries "$tmp/env-cache")" = 2 ] || fail "GLSLRUN_CACHE_DIR: $(entries "$tmp/env-cache") entries, not 2"
GLSLRUN_NO_CACHE=1 render env_off --cache-dir "$tmp/off-cache"
[ "$(entries "$tmp/off-cache")" = 0 ] || fail "GLSLRUN_NO_CACHE=1 still wrote a cache"
grep -q "2 shaders compiled" env_off.txt || fail "GLSLRUN_NO_CACHE=1: $(grep backend env_off.txt)"

# A directory that cannot be made: a warning, the image all the same.
echo x >blocker
render blocked --cache-dir "$tmp/blocker/cache"
grep -q "warning: the code cache directory .* cannot be written" blocked.err ||
    fail "no warning for an unwritable cache: $(head -c 300 blocked.err)"
cmp -s cold.png blocked.png || fail "the image with an unwritable cache differs"

# A damaged entry: compiled again and written again, the same image.
for f in $(find "$tmp/cache" -type f); do printf 'garbage' >"$f"; done
render damaged --cache-dir "$tmp/cache"
grep -q "2 shaders compiled, 0 loaded" damaged.txt || fail "damaged entries: $(grep backend damaged.txt)"
cmp -s cold.png damaged.png || fail "the image after damaged entries differs"
render repaired --cache-dir "$tmp/cache"
grep -q "0 shaders compiled, 2 loaded" repaired.txt || fail "rewritten entries: $(grep backend repaired.txt)"
finish "code cache: a second run compiles nothing (shaders, the second tier and fused pipeline), the same images, unwritable and damaged caches handled"
