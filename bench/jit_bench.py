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

--rows: the other rows of issue #12's table, 1 thread, glslrun --backend jit against
llvmpipe, interleaved, medians of CPU ms per frame:
- extra lit fragments, Mfrag/s per core: the spot teapot at 1920x1080 against 960x540
  (same triangles, 4x the pixels): the extra fragments (glslrun's count of fragments
  written, which llvmpipe's coverage rules match) over the extra CPU time;
- ns per triangle at subdivision 64: the spot teapot at 1920x1080, subdivision 64 against
  10 (262,144 against 6,400 triangles, about the same lit pixels): the extra CPU time
  over the extra triangles;
- the first 512x512 spot frame, compile included, default backend (auto), 1 thread,
  a fresh process each run (first_frame_ms).

--scenes: every lecture program on its scene (bench/precision.py's cases) and the
multi-pass scene (blending), 1920x1080, 1 thread, glslrun --backend jit against llvmpipe,
interleaved, medians of CPU ms per frame over --frames frames (the fused pipeline takes
over after 2^20 fragments: give it 30 or more).

    /usr/bin/python3 bench/jit_bench.py --build build [--runs 5] [--frames 10] [--threads 1,2] [--rows | --scenes]
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(REPO, "bench"))
import precision  # noqa: E402  (CASES: the lecture programs and their scenes)


def bench(cmd, env=None):
    out = subprocess.run(cmd, capture_output=True, text=True, check=True, env=env).stdout
    return {k: v for k, v in (line.split(None, 1) for line in out.splitlines() if " " in line)}


def spot(build, renderer, threads, frames, size="1920x1080", scene=None):
    stem = os.path.join(REPO, "shaders", "spot_pix_fixed")
    args = [stem + ".vert", stem + ".frag", scene or os.path.join(REPO, "scenes", "spot.toml"), "--size", size,
            "--bench", str(frames), "-o", "/tmp/jit_bench.png"]
    if renderer == "llvmpipe":
        env = dict(os.environ, LP_NUM_THREADS=str(threads))
        return bench([os.path.join(build, "glref"), "--driver", "llvmpipe", *args], env)
    return bench([os.path.join(build, "glslrun"), *args, "--threads", str(threads), "--backend", renderer])


def spot_sub64():
    """scenes/spot.toml with the teapot at subdivision 64, in a temporary file."""
    with open(os.path.join(REPO, "scenes", "spot.toml")) as f:
        text = f.read()
    text, n = re.subn(r"(?m)^subdivisions\s*=\s*\d+", "subdivisions = 64", text)
    assert n == 1, "scenes/spot.toml: one `subdivisions = N` line expected"
    fd, path = tempfile.mkstemp(suffix=".toml")  # the teapot is built in: nothing relative to the scene
    with os.fdopen(fd, "w") as f:
        f.write(text)
    return path


def rows(args):
    """The marginal rows of issue #12's table (see the module's text)."""
    renderers = ["jit", "llvmpipe"]
    sub64 = spot_sub64()
    try:
        # (name, size, scene, frames): the fused pipeline takes over after 2^20 fragments,
        # about 20 frames at 960x540, so the small frame runs 60 frames.
        variants = [("1080", "1920x1080", None, 3 * args.frames), ("540", "960x540", None, 6 * args.frames),
                    ("sub64", "1920x1080", sub64, args.frames)]
        runs = {(r, v[0]): [] for r in renderers for v in variants}
        first = {r: [] for r in ["auto", "llvmpipe"]}
        for _ in range(args.runs):
            for name, size, scene, frames in variants:
                for r in renderers:
                    runs[(r, name)].append(spot(args.build, r, 1, frames, size, scene))
            for r in first:
                first[r].append(float(spot(args.build, r, 1, 1, "512x512")["first_frame_ms"]))
    finally:
        os.remove(sub64)
    cpu = {k: statistics.median(float(x["cpu_median_ms"]) for x in v) for k, v in runs.items()}
    count = lambda name, key: statistics.median(float(x[key]) for x in runs[("jit", name)])
    extra_fragments = count("1080", "fragments") - count("540", "fragments")
    extra_triangles = count("sub64", "triangles") - count("1080", "triangles")
    print("| row | jit | llvmpipe | jit / llvmpipe |")
    print("|---|---|---|---|")
    for r in renderers:
        cpu[(r, "mfrag")] = extra_fragments / (cpu[(r, "1080")] - cpu[(r, "540")]) / 1000.0
        cpu[(r, "ns")] = (cpu[(r, "sub64")] - cpu[(r, "1080")]) * 1e6 / extra_triangles
    for label, key in (("1080p spot frame, CPU ms", "1080"), ("540p spot frame, CPU ms", "540"),
                       ("1080p spot, subdivision 64, CPU ms", "sub64"),
                       (f"extra lit fragments ({extra_fragments:.0f}), Mfrag/s per core", "mfrag"),
                       (f"ns per extra triangle ({extra_triangles:.0f})", "ns")):
        print(f"| {label} | {cpu[('jit', key)]:.2f} | {cpu[('llvmpipe', key)]:.2f} | "
              f"{cpu[('jit', key)] / cpu[('llvmpipe', key)]:.2f} |")
    print(f"| first 512x512 frame, compile included, ms (auto, processes: {args.runs}) | "
          f"{statistics.median(first['auto']):.2f} | {statistics.median(first['llvmpipe']):.2f} | "
          f"{statistics.median(first['auto']) / statistics.median(first['llvmpipe']):.2f} |")


def scenes(args):
    """Each lecture scene and the multi-pass one against llvmpipe (see the module's text)."""
    cases = list(dict.fromkeys((program, scene) for program, scene, _ in precision.CASES))
    cases.append(("minimal", "multi_pass.toml"))  # its passes name their own programs
    runs = {(c, r): [] for c in cases for r in ("jit", "llvmpipe")}
    for _ in range(args.runs):
        for program, scene in cases:
            stem = os.path.join(REPO, "shaders", program)
            common = [stem + ".vert", stem + ".frag", os.path.join(REPO, "scenes", scene), "--size", "1920x1080",
                      "--bench", str(args.frames), "-o", "/tmp/jit_bench.png"]
            runs[((program, scene), "jit")].append(
                bench([os.path.join(args.build, "glslrun"), *common, "--threads", "1", "--backend", "jit"]))
            runs[((program, scene), "llvmpipe")].append(
                bench([os.path.join(args.build, "glref"), "--driver", "llvmpipe", *common],
                      dict(os.environ, LP_NUM_THREADS="1")))
    print("| program | scene | jit CPU ms | llvmpipe CPU ms | jit / llvmpipe |")
    print("|---|---|---|---|---|")
    for program, scene in cases:
        jit, lp = (statistics.median(float(x["cpu_median_ms"]) for x in runs[((program, scene), r)])
                   for r in ("jit", "llvmpipe"))
        print(f"| {program} | {scene} | {jit:.2f} | {lp:.2f} | {jit / lp:.2f} |")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", required=True)
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--frames", type=int, default=10)
    ap.add_argument("--threads", default="1,2")
    ap.add_argument("--rows", action="store_true", help="the marginal rows and the first frame instead")
    ap.add_argument("--scenes", action="store_true", help="every lecture scene and multi_pass against llvmpipe instead")
    args = ap.parse_args()
    print(f"load average at start: {os.getloadavg()[0]:.2f}; {os.cpu_count()} cores")
    if args.rows or args.scenes:
        (rows if args.rows else scenes)(args)
        print(f"load average at end: {os.getloadavg()[0]:.2f}")
        return
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
