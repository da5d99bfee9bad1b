#!/usr/bin/python3
"""The JIT against the interpreter and llvmpipe (issue #12), and LLVM's compile time.

frames: the 1080p spot-light teapot (scenes/spot.toml, spot_pix_fixed) rendered by
glslrun --backend interp, glslrun --backend jit and llvmpipe (BUILD/glref), interleaved
(one run of each, then the next run); per renderer the median over the runs of each
run's median frame (wall and process CPU time).
compile: glslrun --backend jit --bench 1 on every lecture program of bench/precision.py
(its own scene and size), printing llvm_compile_ms (both stages, both functions each).
fast: Fast against Precise under the JIT on the per-pixel lecture scenes of
bench/precision.py at 1920x1080 and 1 thread, interleaved; per mode the median over the runs
of each run's median frame CPU time (the #12 target: Fast >= 1.5x Precise).

    /usr/bin/python3 bench/jit_bench.py --build build [--runs 5] [--frames 10] [--threads 1,2]
"""
import argparse
import os
import statistics
import subprocess
import sys

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(REPO, "bench"))
import precision  # noqa: E402  (CASES: the lecture programs and their scenes)


def bench(cmd, env=None):
    out = subprocess.run(cmd, capture_output=True, text=True, check=True, env=env).stdout
    return {k: v for k, v in (line.split(None, 1) for line in out.splitlines() if " " in line)}


def spot(build, renderer, threads, frames):
    stem = os.path.join(REPO, "shaders", "spot_pix_fixed")
    args = [stem + ".vert", stem + ".frag", os.path.join(REPO, "scenes", "spot.toml"), "--size", "1920x1080",
            "--bench", str(frames), "-o", "/tmp/jit_bench.png"]
    if renderer == "llvmpipe":
        env = dict(os.environ, LP_NUM_THREADS=str(threads))
        return bench([os.path.join(build, "glref"), "--driver", "llvmpipe", *args], env)
    return bench([os.path.join(build, "glslrun"), *args, "--threads", str(threads), "--backend", renderer])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", required=True)
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--frames", type=int, default=10)
    ap.add_argument("--threads", default="1,2")
    args = ap.parse_args()
    print(f"load average at start: {os.getloadavg()[0]:.2f}; {os.cpu_count()} cores")
    renderers = ["interp", "jit"] + (["llvmpipe"] if os.access(os.path.join(args.build, "glref"), os.X_OK) else [])
    print("| threads | renderer | frame ms | CPU ms | fragment ms | first frame ms | LLVM compile ms |")
    print("|---|---|---|---|---|---|---|")
    for threads in (int(t) for t in args.threads.split(",")):
        runs = {r: [] for r in renderers}
        for _ in range(args.runs):
            for r in renderers:
                runs[r].append(spot(args.build, r, threads, args.frames))
        for r in renderers:
            med = lambda key: statistics.median(float(x.get(key, "nan")) for x in runs[r])
            print(f"| {threads} | {r} | {med('median_ms'):.2f} | {med('cpu_median_ms'):.2f} | "
                  f"{med('fragment_ms'):.2f} | {med('first_frame_ms'):.1f} | {med('llvm_compile_ms'):.1f} |")
    print(f"load average at end: {os.getloadavg()[0]:.2f}\n")
    print("| program | scene | LLVM compile ms |")
    print("|---|---|---|")
    for program, scene, _ in precision.CASES:
        stem = os.path.join(REPO, "shaders", program)
        times = [float(bench([os.path.join(args.build, "glslrun"), stem + ".vert", stem + ".frag",
                              os.path.join(REPO, "scenes", scene), "--bench", "1", "--backend", "jit",
                              "-o", "/tmp/jit_bench.png"])["llvm_compile_ms"]) for _ in range(3)]
        print(f"| {program} | {scene} | {statistics.median(times):.1f} |")
    fast_against_precise(args)


def fast_against_precise(args):
    print(f"\nload average at start: {os.getloadavg()[0]:.2f}")
    print("| program | scene | precise CPU ms | fast CPU ms | fast speed-up |")
    print("|---|---|---|---|---|")
    for program, scene, kind in precision.CASES:
        if "pixel" not in kind:
            continue
        stem = os.path.join(REPO, "shaders", program)
        cmd = [os.path.join(args.build, "glslrun"), stem + ".vert", stem + ".frag", os.path.join(REPO, "scenes", scene),
               "--size", "1920x1080", "--threads", "1", "--backend", "jit", "--bench", str(args.frames),
               "-o", "/tmp/jit_bench.png"]
        runs = {mode: [] for mode in ("precise", "fast")}
        for _ in range(args.runs):
            for mode in runs:
                runs[mode].append(float(bench(cmd + ["--precision", mode])["cpu_median_ms"]))
        precise, fast = (statistics.median(runs[m]) for m in ("precise", "fast"))
        print(f"| {program} | {scene} | {precise:.2f} | {fast:.2f} | {precise / fast:.2f}x |")
    print(f"load average at end: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
