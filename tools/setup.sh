#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine (as root), builds glslrun, installs it
# under /usr/local (the glslrun command, the C++ libraries with their CMake
# and pkg-config files, the Python module), then either
#   demo: renders the lecture's per-pixel spot-light teapot to spot.png, or
#   test: runs every test (unit tests, example, package, Python, piglit conformance suite).
set -euo pipefail
mode=${1:-demo}
cd "$(dirname "$0")/.."

packages=(build-essential cmake ninja-build pkg-config glslang-dev glslang-tools libglm-dev
          libfmt-dev catch2 libpng-dev libcli11-dev libtomlplusplus-dev libstb-dev
          libtinyobjloader-dev libegl-dev libgl-dev libgl1-mesa-dri libgles-dev llvm-15-dev
          python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pytest  # the Python module
          nlohmann-json3-dev libpugixml-dev  # JSON (trace, serve, reports) and JUnit XML
          help2man  # the man page, from glslrun --help
          libcpp-httplib-dev  # glslrun serve's HTTP server
          ccache)  # the builds below (and CI's variants) reuse each other's object files
[ "$mode" = test ] && packages+=(piglit clang libclang-rt-14-dev  # clang: the sanitizer and fuzzer build
                                  python3-hypothesis  # the Python module's fuzz run (python/tests/test_fuzz.py)
                                  python3-jsonschema)  # the JSON reports against docs/schema (tests/cli/json_schema.py)
[ "$mode" = test ] && packages+=(chromium chromium-driver python3-selenium)  # glslrun serve's page in a browser (tests/cli/serve_test.py)
[ "$mode" = test ] && packages+=(zsh  # tests/package/consumer.sh tries the zsh completion
                                  python3-build python3-venv python3-mypy)  # the wheel, venv and type stub (tests/package/wheel.sh)
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# ccache keys on paths relative to the checkout, so the build variants of
# `test` and a later clone share their object files.
export CCACHE_BASEDIR=$PWD CCACHE_NOHASHDIR=1
launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# Debian's Python packages (numpy, pybind11) belong to /usr/bin/python3.
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPython3_EXECUTABLE=/usr/bin/python3 "${launcher[@]}" > /dev/null
cmake --build build -j "$(nproc)"
cmake --install build > /dev/null  # prefix /usr/local: glslrun is on PATH, `import glslrun` works
ldconfig

# A build whose output would drown the log: kept in DIR/build.log, and its end
# printed (with the free disk space, the usual cause on a shared machine) if it fails.
quiet_build() {
    local dir=$1; shift
    cmake --build "$dir" -j "$(nproc)" --target "$@" > "$dir/build.log" 2>&1 || {
        tail -n 40 "$dir/build.log" >&2
        df -h "$dir" >&2
        echo "the build in $dir failed (its whole output: $dir/build.log)" >&2
        exit 1
    }
}

case "$mode" in
demo)
    glslrun shaders/spot_pix_fixed.vert shaders/spot_pix_fixed.frag scenes/spot.toml -o spot.png --stats
    echo "wrote spot.png with $(command -v glslrun)"
    ;;
test)
    # This run's build trees and ccache take about 10 GB: a disk that fills up
    # shows as a failed build, so say so first.
    avail_kb=$(df -Pk . | awk 'NR == 2 {print $4}')
    [ "$avail_kb" -gt $((10 * 1024 * 1024)) ] || echo "warning: $((avail_kb / 1024)) MB free on $(pwd)'s disk; the builds below need about 10 GB" >&2
    # The IR verifier after every pass, in every run below (ctest sets it for its tests too).
    export GLSLRUN_VERIFY=1
    # The JIT's code cache of every run below: a directory of this run's own,
    # never the user's (ctest gives each of its tests one of its own).
    GLSLRUN_CACHE_DIR=$(mktemp -d "${TMPDIR:-/tmp}/glslrun-ci-cache.XXXXXX")
    export GLSLRUN_CACHE_DIR
    trap 'rm -rf "$GLSLRUN_CACHE_DIR"' EXIT
    (cd build && ctest --output-on-failure -j "$(nproc)")
    # Under the JIT (built in here): --backend auto would run most tests' few
    # draws on the interpreter while LLVM compiles (ctest runs the language
    # suite on both backends, and backend_identical compares their images).
    GLSLRUN=build/glslrun bash tools/piglit_suite.sh --backend jit
    # Again, every program's code now loaded from the code cache: the same results.
    GLSLRUN=build/glslrun bash tools/piglit_suite.sh --backend jit
    GLSLRUN=build/glslrun bash tools/piglit_suite.sh --backend interp
    # Images must not depend on the interpreter's batch width: build glslrun
    # with 8 and 64 lanes and compare every scene image in every mode.
    bash tools/image_hashes.sh build/glslrun > build/hashes-default.txt
    for lanes in 8 64; do
        # No debug information: these trees are only run, and -g made each of them about 1 GB.
        cmake -S . -B "build-lanes$lanes" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
              -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -DNDEBUG" -DGLSLRUN_LANES=$lanes "${launcher[@]}" > /dev/null
        quiet_build "build-lanes$lanes" glslrun test_fused test_runtime
        bash tools/image_hashes.sh "build-lanes$lanes/glslrun" > "build/hashes-$lanes.txt"
        diff build/hashes-default.txt "build/hashes-$lanes.txt" || { echo "images differ with $lanes lanes" >&2; exit 1; }
        echo "batch width $lanes: $(wc -l < build/hashes-default.txt) images identical to the default build (32 lanes)"
        # The JIT's vectors are kLanes wide too: its images against the interpreter's.
        sh tests/cli/backend_identical.sh . "build-lanes$lanes/glslrun"
        # The fused fragment pipeline (quad order within a batch) against the interpreter's path.
        "build-lanes$lanes/test_fused"
        # The JIT against the interpreter op by op: generated built-ins, gathers, NaN operands (not the
        # fuzz test: at 64 lanes LLVM takes minutes over its programs); the batched sampler, whose
        # blends take 4 or 8 lanes at a time, against the per-lane one (2 s).
        "build-lanes$lanes/test_runtime" "[jit_math],[jit_indexed],[nan],[batch]"
    done
    # ASan + UBSan over the unit tests of the library's inputs, the piglit suite and
    # the hostile-input reproducers, then each fuzzer for 20 s (docs/ci.md).
    bash tools/sanitize_and_fuzz.sh 20
    ;;
*)
    echo "usage: tools/setup.sh [demo|test]" >&2
    exit 2
    ;;
esac
