#!/usr/bin/env bash
# Sanitizers and fuzzers (docs/ci.md; meant as a step of `tools/setup.sh test`): one clang build
# with AddressSanitizer + UBSan and libFuzzer's coverage (build-asan), of only
# the targets it runs: the unit tests that cover the library's inputs, the
# command line for the piglit suite and tests/cli/hardening.sh, and the four
# fuzzers, each given a short bounded run from its seed corpus (the API
# fuzzer, fuzz/fuzz_api.cpp, a quarter of the time: its inputs are calls, not
# a language to explore).
#
#   tools/sanitize_and_fuzz.sh [FUZZ_SECONDS]   (default 20 per fuzzer)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-20}
# No leak check: glslang keeps process-wide tables that are never freed.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# -g1: line tables are all a sanitizer's report needs (full debug information made this tree 1.1 GB).
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" -DGLSLRUN_SANITIZE=ON -DGLSLRUN_FUZZ=ON "${launcher[@]}" > /dev/null
tests=(test_frontend test_runtime test_api test_raster test_piglit)
cmake --build build-asan -j "$(nproc)" --target glslrun "${tests[@]}" fuzz_compile fuzz_scene fuzz_piglit fuzz_api
(cd build-asan && ctest --output-on-failure -j "$(nproc)" -R '^(frontend|runtime|api|raster|piglit|cli_hardening)$')
# Isolated, as users run it: each test in a child forked from the runner's
# only thread (tools/glslrun/piglit_isolate.h says why that matters under ASan).
GLSLRUN=build-asan/glslrun bash tools/piglit_suite.sh
for fuzzer in compile scene piglit api; do
    budget=$seconds dict=(-dict="fuzz/$fuzzer.dict")
    case $fuzzer in
    compile) seeds=(fuzz/corpus/compile shaders) ;;
    scene) seeds=(fuzz/corpus/scene scenes) ;;
    piglit) seeds=(fuzz/corpus/piglit tests/extremes) ;;
    api) seeds=(fuzz/corpus/api) budget=$(( (seconds + 3) / 4 )) dict=() ;;
    esac
    # A fresh directory first: new inputs go there, the repo's seeds stay as they are.
    work=build-asan/corpus-$fuzzer
    mkdir -p "$work"
    # Slow inputs (a teapot of 256 subdivisions takes a second) get less of the
    # time; inputs stay under 4 KB (the piglit seeds' 15 KB made its runs 2.4
    # times slower); one process has no other's corpus to reload.
    "build-asan/fuzz_$fuzzer" "${dict[@]}" -max_total_time="$budget" -timeout=10 -rss_limit_mb=4096 \
        -entropic_scale_per_exec_time=1 -max_len=4096 -reload=0 \
        -print_final_stats=1 "$work" "${seeds[@]}" 2>&1 | grep -E '^(stat::number_of_executed_units|==.*ERROR|SUMMARY)' || true
    [ "${PIPESTATUS[0]}" = 0 ] || { echo "fuzz_$fuzzer found a crash (see above)" >&2; exit 1; }
done
