#!/usr/bin/python3
"""Every program of bench/corpus/ and every lecture scene against llvmpipe at 1920x1080.

Per program, glslrun's JIT (Precise) and llvmpipe (BUILD/glref, LP_NUM_THREADS) render the
program's scene with --bench FRAMES, at 1 and at 2 threads; Fast renders it at 1 thread. The
runs are interleaved (one run of every renderer on every program, then the next run), and
each number is the median over the runs of each run's median frame:
- CPU ms per frame (process CPU time) at 1 and 2 threads, and wall ms per frame at 2 threads;
- Fast's speed-up over Precise (Precise CPU / Fast CPU, 1 thread);
- LLVM's compile time for the program (llvm_compile_ms, both stages, every function: the JIT's first
  tier and the fused pipelines, what a first draw may wait for), the median over the runs (a run
  after the first loads the code cache's code); and the largest over the runs of the second tier's
  (llvm_optimise_ms: the hot stages compiled again in the background; 0 where none was).
The load average is read before and after each program's runs and reported with the table:
on a shared machine the CPU times are the numbers to trust, the wall times less so.

The lecture scenes are bench/precision.py's cases and the multi-pass scene (its passes name
their own programs), as bench/jit_bench.py --scenes draws them.

    /usr/bin/python3 bench/corpus_bench.py --build build [--runs 5] [--frames 10] [--only NAME,..]
        [--output table.md]
"""
import argparse
import os
import statistics
import sys

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CORPUS = os.path.join(REPO, "bench", "corpus")
sys.path.insert(0, os.path.join(REPO, "bench"))
import precision  # noqa: E402  (CASES: the lecture programs and their scenes)
from jit_bench import bench  # noqa: E402  (runs a --bench command, returns its key/value lines)

# (label, renderer, threads, extra glslrun arguments)
CONFIGS = [
    ("jit1", "glslrun", 1, ["--backend", "jit", "--precision", "precise"]),
    ("lp1", "llvmpipe", 1, []),
    ("fast1", "glslrun", 1, ["--backend", "jit", "--precision", "fast"]),
    ("jit2", "glslrun", 2, ["--backend", "jit", "--precision", "precise"]),
    ("lp2", "llvmpipe", 2, []),
]


def cases():
    """(set, name, vertex, fragment, scene): the corpus, then the lecture."""
    found = []
    for frag in sorted(f for f in os.listdir(CORPUS) if f.endswith(".frag")):
        stem = os.path.join(CORPUS, frag[:-5])
        found.append(("corpus", frag[:-5], stem + ".vert", stem + ".frag", stem + ".toml"))
    lecture = list(dict.fromkeys((p, s) for p, s, _ in precision.CASES)) + [("minimal", "multi_pass.toml")]
    for program, scene in lecture:
        stem = os.path.join(REPO, "shaders", program)
        found.append(("lecture", f"{program} ({scene[:-5]})", stem + ".vert", stem + ".frag",
                      os.path.join(REPO, "scenes", scene)))
    return found


def run_one(build, case, config, frames):
    _, _, vert, frag, scene = case
    _, renderer, threads, extra = config
    args = [vert, frag, scene, "--size", "1920x1080", "--bench", str(frames), "-o", "/tmp/corpus_bench.png"]
    if renderer == "llvmpipe":
        return bench([os.path.join(build, "glref"), "--driver", "llvmpipe", *args],
                     dict(os.environ, LP_NUM_THREADS=str(threads)))
    return bench([os.path.join(build, "glslrun"), *args, "--threads", str(threads), *extra])


def measure(args, selected):
    """Interleaved runs; returns {(case name, config label): [bench dicts]} and the loads seen."""
    runs = {(c[1], k[0]): [] for c in selected for k in CONFIGS}
    loads = []
    for _ in range(args.runs):
        for case in selected:
            loads.append(os.getloadavg()[0])
            for config in CONFIGS:
                runs[(case[1], config[0])].append(run_one(args.build, case, config, args.frames))
        loads.append(os.getloadavg()[0])
    return runs, loads


def table(selected, runs, loads, args):
    med = lambda name, label, key: statistics.median(float(x[key]) for x in runs[(name, label)])
    lines = [f"`bench/corpus_bench.py --runs {args.runs} --frames {args.frames}`, 1920x1080, glslrun's JIT "
             f"(Precise unless said) against llvmpipe; {os.cpu_count()} cores; load average (1 min) "
             f"{min(loads):.2f} to {max(loads):.2f} during the runs. CPU and wall ms per frame, medians.", "",
             "| set | program | jit CPU 1T | llvmpipe CPU 1T | ratio 1T | jit wall 2T | llvmpipe wall 2T | "
             "ratio wall 2T | ratio CPU 2T | Fast speed-up | LLVM compile ms | tier 2 LLVM ms |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    ratios = {}
    for case in selected:
        n = case[1]
        r1 = med(n, "jit1", "cpu_median_ms") / med(n, "lp1", "cpu_median_ms")
        r2w = med(n, "jit2", "median_ms") / med(n, "lp2", "median_ms")
        r2c = med(n, "jit2", "cpu_median_ms") / med(n, "lp2", "cpu_median_ms")
        fast = med(n, "jit1", "cpu_median_ms") / med(n, "fast1", "cpu_median_ms")
        ratios[n] = (case[0], r1)
        lines.append(f"| {case[0]} | {n} | {med(n, 'jit1', 'cpu_median_ms'):.2f} | "
                     f"{med(n, 'lp1', 'cpu_median_ms'):.2f} | {r1:.2f} | {med(n, 'jit2', 'median_ms'):.2f} | {med(n, 'lp2', 'median_ms'):.2f} | {r2w:.2f} | "
                     f"{r2c:.2f} | {fast:.2f}x | {med(n, 'jit1', 'llvm_compile_ms'):.1f} | "
                     f"{max(float(x.get('llvm_optimise_ms', 0)) for x in runs[(n, 'jit1')]):.1f} |")
    lines.append("")
    for group in ("corpus", "lecture"):
        values = sorted((r, n) for n, (g, r) in ratios.items() if g == group)
        if values:
            worst = ", ".join(f"{n} {r:.2f}" for r, n in reversed(values[-3:]))
            lines.append(f"- {group}: median ratio at 1 thread {statistics.median(r for r, _ in values):.2f} over "
                         f"{len(values)} programs; slowest relative to llvmpipe: {worst}.")
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", required=True)
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--frames", type=int, default=10)
    ap.add_argument("--only", default="", help="comma-separated program names (corpus names, or lecture programs)")
    ap.add_argument("--output", help="also write the markdown table to this file")
    args = ap.parse_args()
    selected = cases()
    if args.only:
        wanted = set(args.only.split(","))
        selected = [c for c in selected if c[1] in wanted or c[1].split(" ")[0] in wanted]
        missing = wanted - {c[1] for c in selected} - {c[1].split(" ")[0] for c in selected}
        if missing:
            sys.exit(f"corpus_bench.py: no such program: {', '.join(sorted(missing))}")
    runs, loads = measure(args, selected)
    text = table(selected, runs, loads, args)
    print(text)
    if args.output:
        with open(args.output, "w") as f:
            f.write(text + "\n")


if __name__ == "__main__":
    main()
