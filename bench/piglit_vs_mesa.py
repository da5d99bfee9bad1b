#!/usr/bin/python3
"""The piglit .shader_test files: glslrun (one `glslrun test` process, each test in
its own forked child) against Mesa's shader_runner on llvmpipe (one process per
test, as piglit runs it), with the same number of tests at a time. Issue #6.

    /usr/bin/python3 bench/piglit_vs_mesa.py --build build [--every 10] [--runs 3] [--jobs 2]

--every K takes every K-th test of the sorted list (1: all 3146); the times are also
scaled up to the whole list. Runs are interleaved. Builds nothing; the load average
is printed with every timing, since the machine is shared.
"""
import argparse
import concurrent.futures
import os
import statistics
import subprocess
import sys
import time

PIGLIT = os.environ.get("PIGLIT_ROOT", "/usr/lib/x86_64-linux-gnu/piglit")
# The directories of tools/piglit_suite.sh.
DIRS = ["tests/spec/glsl-1.10", "generated_tests/spec/glsl-1.10", "tests/spec/glsl-1.20",
        "generated_tests/spec/glsl-1.20", "tests/shaders"]
MESA_ENV = {"LIBGL_ALWAYS_SOFTWARE": "1", "GALLIUM_DRIVER": "llvmpipe", "EGL_PLATFORM": "surfaceless",
            "PIGLIT_PLATFORM": "surfaceless_egl"}


def shader_tests():
    found = []
    for d in DIRS:
        for root, _, files in os.walk(os.path.join(PIGLIT, d)):
            found += [os.path.relpath(os.path.join(root, f), PIGLIT) for f in files if f.endswith(".shader_test")]
    return sorted(found)


def load():
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def run_glslrun(build, tests, jobs):
    start = time.monotonic()
    p = subprocess.run([os.path.join(build, "glslrun"), "test", "--root", PIGLIT, "-j", str(jobs), *tests],
                       capture_output=True, text=True)
    seconds = time.monotonic() - start
    passed = sum(line.startswith("pass") for line in p.stdout.splitlines())
    return seconds, passed


def shader_runner(test):
    env = dict(os.environ, **MESA_ENV)
    try:
        p = subprocess.run([os.path.join(PIGLIT, "bin", "shader_runner"), os.path.join(PIGLIT, test), "-auto",
                            "-fbo"], env=env, capture_output=True, text=True, timeout=120)
    except subprocess.TimeoutExpired:
        return False
    return '"result": "pass"' in p.stdout


def run_mesa(tests, jobs):
    start = time.monotonic()
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        passed = sum(pool.map(shader_runner, tests))
    return time.monotonic() - start, passed


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", required=True, help="build directory with glslrun")
    ap.add_argument("--every", type=int, default=10, help="take every K-th test (default 10)")
    ap.add_argument("--runs", type=int, default=3, help="interleaved runs (default 3)")
    ap.add_argument("--jobs", type=int, default=os.cpu_count(), help="tests at a time (default: cores)")
    args = ap.parse_args()
    if args.every < 1 or args.runs < 1 or args.jobs < 1:
        ap.error("--every, --runs and --jobs must be at least 1")
    if not os.path.isfile(os.path.join(PIGLIT, "bin", "shader_runner")):
        sys.exit(f"no shader_runner under {PIGLIT}/bin; set PIGLIT_ROOT")
    everything = shader_tests()
    tests = everything[::args.every]
    scale = len(everything) / len(tests)
    print(f"{len(tests)} of {len(everything)} .shader_test files, {args.jobs} at a time, {args.runs} runs; "
          f"{os.cpu_count()} cores; {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}", flush=True)
    times = {"glslrun": [], "llvmpipe": []}
    for run in range(args.runs):
        for name in times:
            before = load()
            seconds, passed = run_glslrun(args.build, tests, args.jobs) if name == "glslrun" else \
                run_mesa(tests, args.jobs)
            times[name].append(seconds)
            print(f"run {run + 1} {name:8}: {seconds:7.2f} s, {passed} passed (load before {before}, after {load()})",
                  flush=True)
    g, m = statistics.median(times["glslrun"]), statistics.median(times["llvmpipe"])
    print(f"median: glslrun {g:.2f} s, llvmpipe shader_runner {m:.2f} s; llvmpipe / glslrun = {m / g:.1f}")
    print(f"scaled to all {len(everything)}: glslrun {g * scale:.1f} s, llvmpipe {m * scale:.1f} s")


if __name__ == "__main__":
    main()
