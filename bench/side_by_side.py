#!/usr/bin/python3
"""glslrun and Mesa (llvmpipe, softpipe) side by side on the lecture's scenes (issue #6).

Builds nothing: it runs BUILD/glslrun --bench and BUILD/glref --bench, interleaved
(one run of every renderer of a case, then the next run), and prints per case the
medians over the runs and the ratios. Both tools print the same `key value` lines
(scene/bench_report.h); this script only parses them.

    /usr/bin/python3 bench/side_by_side.py --build build [--runs 5] [--plot perf.png] [--only spot] [--first-threads 1,2]
    /usr/bin/python3 bench/side_by_side.py --build build --threads 1,2,4,8,16 --only "spot pixel"
    /usr/bin/python3 bench/side_by_side.py --build build --from-json rows.json --plot perf.png

Scene variants (teapot subdivision) are written to a temporary directory from the
scene files in scenes/; the image size is given with --size. Thread counts: glslrun
--threads N, llvmpipe LP_NUM_THREADS=N; softpipe always uses one. The plot needs
Debian's python3-matplotlib; without it the table is still printed.
"""
import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# program: shaders/<stem>.vert and .frag, and its scene in scenes/
PROGRAMS = {
    "spot": ("spot_pix_fixed", "spot.toml"),
    "directional": ("dir_vert", "directional.toml"),
    "minimal": ("minimal", "directional.toml"),
}


def case(name, program, subdivisions, size, threads, renderers, kind="frames"):
    return dict(name=name, program=program, subdivisions=subdivisions, size=size,
                threads=threads, renderers=renderers, kind=kind)


def cases(thread_counts, first_thread_counts):
    """The cases of issue #6: the frame time at 1080p, then the first frame at 512x512."""
    out = []
    for sub in (10, 64):
        for threads in thread_counts:
            mesa = ["llvmpipe", "softpipe"] if threads == 1 else ["llvmpipe"]
            out.append(case(f"spot pixel, sub {sub}", "spot", sub, "1920x1080", threads, mesa))
    for program in ("directional", "minimal"):
        for threads in thread_counts:
            out.append(case(f"{program} vertex-bound, sub 64", program, 64, "1920x1080", threads,
                            ["llvmpipe"]))
    for threads in first_thread_counts:
        for program in PROGRAMS:
            out.append(case(f"{program} first frame", program, 10, "512x512", threads,
                            ["llvmpipe", "softpipe"], kind="first"))
    return out


def scene_variant(tmp, program, subdivisions):
    """The program's scene file with the teapot's subdivisions replaced."""
    scene = os.path.join(REPO, "scenes", PROGRAMS[program][1])
    with open(scene) as f:
        text = f.read()
    text, n = re.subn(r"(?m)^subdivisions\s*=\s*\d+", f"subdivisions = {subdivisions}", text)
    if n != 1:
        sys.exit(f"{scene}: expected one `subdivisions = N` line, found {n}")
    path = os.path.join(tmp, f"{program}-sub{subdivisions}.toml")
    with open(path, "w") as f:
        f.write(text)
    return path


def parse_bench(text):
    """The `key value` lines of --bench (and --error-report) as a dict; numbers as floats."""
    values = {}
    for line in text.splitlines():
        m = re.match(r"^([A-Za-z0-9_.\[\]]+)\s+(.*)$", line)
        if not m:
            continue
        key, value = m.groups()
        try:
            values[key] = float(value)
        except ValueError:
            values[key] = value
    return values


def command(build, renderer, c, scene, frames, tmp):
    shader = os.path.join(REPO, "shaders", PROGRAMS[c["program"]][0])
    args = [shader + ".vert", shader + ".frag", scene, "--size", c["size"], "--bench", str(frames),
            "-o", os.path.join(tmp, f"{renderer}.png")]
    env = dict(os.environ)
    if renderer == "glslrun":
        return [os.path.join(build, "glslrun"), *args, "--threads", str(c["threads"])], env
    env["LP_NUM_THREADS"] = str(c["threads"])
    return [os.path.join(build, "glref"), "--driver", renderer, *args], env


def run_once(build, renderer, c, scene, frames, tmp):
    cmd, env = command(build, renderer, c, scene, frames, tmp)
    p = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=600)
    if p.returncode != 0:
        sys.exit(f"failed ({p.returncode}): {' '.join(cmd)}\n{p.stderr}")
    values = parse_bench(p.stdout)
    for key in ("median_ms", "first_frame_ms", "compile_ms"):
        if not isinstance(values.get(key), float):
            sys.exit(f"no {key} in the output of {' '.join(cmd)}:\n{p.stdout}")
    return values


def frames_for(renderer, c, args):
    if c["kind"] == "first":
        return 1  # only the first frame counts; a fresh process each run
    return args.softpipe_frames if renderer == "softpipe" else args.frames


def measure(c, args, tmp):
    """Runs every renderer of the case `args.runs` times, interleaved; the runs' values per renderer."""
    scene = scene_variant(tmp, c["program"], c["subdivisions"])
    renderers = ["glslrun", *c["renderers"]]
    runs = {r: [] for r in renderers}
    for _ in range(args.runs):
        for r in renderers:
            runs[r].append(run_once(args.build, r, c, scene, frames_for(r, c, args), tmp))
    return runs


def summarize(c, runs):
    key = "first_frame_ms" if c["kind"] == "first" else "median_ms"
    row = {"case": c["name"], "size": c["size"], "threads": c["threads"], "metric": key}
    for r, values in runs.items():
        row[r] = statistics.median(v[key] for v in values)
        row[r + "_cpu_ms"] = statistics.median(v.get("cpu_median_ms", 0.0) for v in values)
        if r == "glslrun":
            for k in ("compile_ms", "first_draw_ms", "vertex_ms", "raster_ms", "fragment_ms"):
                row["glslrun_" + k] = statistics.median(v.get(k, 0.0) for v in values)
        else:
            row[r + "_compile_ms"] = statistics.median(v["compile_ms"] for v in values)
    return row


def fmt_ms(v):
    return "-" if v is None else f"{v:.1f}" if v >= 10 else f"{v:.2f}"


def fmt_ratio(a, b):
    return "-" if a is None or b is None or b == 0 else f"{a / b:.2f}"


def table(rows):
    lines = ["| case | size | threads | glslrun ms | llvmpipe ms | softpipe ms | glslrun / llvmpipe "
             "| softpipe / glslrun | same, CPU time | glslrun vertex / raster / fragment ms |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        g, lp, sp = r.get("glslrun"), r.get("llvmpipe"), r.get("softpipe")
        stages = (f"{fmt_ms(r['glslrun_vertex_ms'])} / {fmt_ms(r['glslrun_raster_ms'])} / "
                  f"{fmt_ms(r['glslrun_fragment_ms'])}" if r["metric"] == "median_ms" else
                  f"compile {fmt_ms(r['glslrun_compile_ms'])}, draw {fmt_ms(r['glslrun_first_draw_ms'])}")
        what = r["case"] + (" (first frame incl. compile)" if r["metric"] == "first_frame_ms" else "")
        cpu = "-"
        if r["metric"] == "median_ms":  # per-frame CPU time of the process, all threads
            g_cpu, lp_cpu, sp_cpu = (r.get(k + "_cpu_ms") for k in ("glslrun", "llvmpipe", "softpipe"))
            cpu = f"{fmt_ratio(g_cpu, lp_cpu)}, {fmt_ratio(sp_cpu, g_cpu)}"
        lines.append(f"| {what} | {r['size']} | {r['threads']} | {fmt_ms(g)} | {fmt_ms(lp)} | {fmt_ms(sp)} "
                     f"| {fmt_ratio(g, lp)} | {fmt_ratio(sp, g)} | {cpu} | {stages} |")
    return "\n".join(lines)


def plot(rows, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print(f"no plot: matplotlib is missing (Debian: python3-matplotlib); {path} not written",
              file=sys.stderr)
        return
    labels = [f"{r['case']}\n{r['threads']}t" for r in rows]
    fig, ax = plt.subplots(figsize=(12, 5))
    width = 0.27
    for i, renderer in enumerate(("glslrun", "llvmpipe", "softpipe")):
        xs = [j + (i - 1) * width for j in range(len(rows))]
        ax.bar(xs, [r.get(renderer) or 0 for r in rows], width, label=renderer)
    ax.set_yscale("log")
    ax.set_ylabel("ms per frame (first frame: incl. compile)")
    ax.set_xticks(range(len(rows)))
    ax.set_xticklabels(labels, rotation=30, ha="right", fontsize=8)
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    print(f"plot: {path}")


def load():
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def parse_counts(ap, option, text):
    """A comma-separated list of thread counts 1..256, or an argparse error."""
    try:
        counts = [int(t) for t in text.split(",")]
    except ValueError:
        counts = []
    if not counts or not all(1 <= t <= 256 for t in counts):
        ap.error(f"{option} '{text}': a comma-separated list of counts 1..256")
    return counts


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", required=True, help="build directory with glslrun and glref")
    ap.add_argument("--runs", type=int, default=5, help="interleaved runs per case (default 5)")
    ap.add_argument("--frames", type=int, default=10, help="--bench N for glslrun and llvmpipe (default 10)")
    ap.add_argument("--softpipe-frames", type=int, default=3, help="--bench N for softpipe (default 3)")
    ap.add_argument("--threads", default="1,2",
                    help="thread counts of the 1080p cases, e.g. 1,2,4,8,16 for a scaling run (default 1,2)")
    ap.add_argument("--first-threads", default="1",
                    help="thread counts of the first-frame cases (default 1; softpipe always uses one)")
    ap.add_argument("--only", default="", help="run only cases whose name contains this text")
    ap.add_argument("--plot", help="write a bar chart (PNG) here; needs python3-matplotlib")
    ap.add_argument("--json", help="write the rows as JSON here")
    ap.add_argument("--from-json", help="run nothing: print the table (and --plot) of rows saved by --json")
    args = ap.parse_args()
    if args.from_json:
        with open(args.from_json) as f:
            rows = json.load(f)
        print(table(rows))
        if args.plot:
            plot(rows, args.plot)
        return
    if args.runs < 1 or args.frames < 1 or args.softpipe_frames < 1:
        ap.error("--runs, --frames and --softpipe-frames must be at least 1")
    thread_counts = parse_counts(ap, "--threads", args.threads)
    first_thread_counts = parse_counts(ap, "--first-threads", args.first_threads)
    for tool in ("glslrun", "glref"):
        if not os.access(os.path.join(args.build, tool), os.X_OK):
            ap.error(f"{args.build}/{tool} not found: build the glslrun and glref targets")
    chosen = [c for c in cases(thread_counts, first_thread_counts) if args.only in c["name"]]
    print(f"load average at start: {load()}; {os.cpu_count()} cores; {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}", flush=True)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for c in chosen:
            rows.append(summarize(c, measure(c, args, tmp)))
            print(f"  {c['name']}, {c['threads']} thread(s): done (load {load()})", file=sys.stderr, flush=True)
    print(f"load average at end: {load()}")
    print(f"medians of {args.runs} interleaved runs; frames: median ms per frame of {args.frames} "
          f"(softpipe {args.softpipe_frames}) after the first\n")
    print(table(rows))
    if args.json:
        with open(args.json, "w") as f:
            json.dump(rows, f, indent=1)
    if args.plot:
        plot(rows, args.plot)


if __name__ == "__main__":
    main()
