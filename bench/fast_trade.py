#!/usr/bin/python3
"""What Fast buys and what it costs, per program: every program of bench/corpus/ and the lecture.

Per program (bench/corpus_bench.py's cases, 1920x1080, glslrun's JIT, 1 thread), Precise and Fast
render the program's scene with --bench FRAMES; the runs are interleaved (Precise then Fast, then
Fast then Precise on the next run, every program in turn) and each number is the median over the
runs of a run's median frame (CPU ms of the process per frame). Then:
- buys: Precise CPU ms / Fast CPU ms;
- costs: Fast's image against Precise's: the pixels whose RGBA bytes differ, the largest byte
  difference, and the mean byte difference over all channels of all pixels;
- the built-ins Fast approximates, counted in the program's source (pow, exp, exp2, log, log2,
  sin, cos, inversesqrt, normalize; calls in a loop count once), and its texture lookups (Fast
  filters them as NVIDIA's GPU does, docs/precision.md); docs/precision_measured.md holds the table.
The load average is read before every program's runs; on a shared machine the CPU times are the
numbers to trust.

--synthetic measures, instead, programs whose frame is mostly math: a full-screen quad whose
fragment shader runs one built-in 16 times in a loop (`s += pow(x + 0.01, y * 4.0)`, and so on,
the loop's own work a fract and two adds), and the loop alone ("none").

    /usr/bin/python3 bench/fast_trade.py --build build [--runs 3] [--frames 8] [--only NAME,..]
        [--synthetic] [--output table.md]
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile

import numpy as np
from PIL import Image

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from corpus_bench import cases  # noqa: E402  (the corpus, then the lecture)
from jit_bench import bench  # noqa: E402

APPROXIMATED = ("pow", "exp2", "exp", "log2", "log", "sin", "cos", "inversesqrt", "normalize")


def approximated_calls(case):
    """'pow 2, normalize 5' from the program's source; textures as 'tex N'."""
    text = ""
    for path in case[2:4]:
        with open(path) as f:
            text += re.sub(r"//[^\n]*", "", f.read())
    counts = [(name, len(re.findall(r"\b" + name + r"\s*\(", text))) for name in APPROXIMATED]
    parts = [f"{name} {n}" for name, n in counts if n]
    textures = len(re.findall(r"\b(?:texture|shadow)\w*\s*\(", text))
    if textures:
        parts.append(f"tex {textures}")
    return ", ".join(parts) or "none"


SYNTHETIC = [("none", "x * y"), ("pow", "pow(x + 0.01, y * 4.0)"), ("exp2", "exp2(x * 8.0 - y)"),
             ("exp", "exp(x * 3.0 - y)"), ("log2", "log2(x + y + 0.001)"), ("log", "log(x + y + 0.001)"),
             ("sin", "sin(x * 20.0 + y)"), ("cos", "cos(x * 20.0 + y)"),
             ("inversesqrt", "inversesqrt(x + y + 0.001)"), ("normalize", "normalize(vec3(x, y, 0.5)).x"),
             ("sqrt", "sqrt(x + y)"), ("division", "1.0 / (x + y + 0.01)")]


def synthetic_cases(directory):
    """(set, name, vertex, fragment, scene) for every SYNTHETIC program, written into `directory`."""
    vert, scene = os.path.join(directory, "quad.vert"), os.path.join(directory, "quad.toml")
    with open(vert, "w") as f:
        f.write("varying vec2 c;\nvoid main() { c = gl_Vertex.xy * 0.5 + 0.5; gl_Position = gl_Vertex; }\n")
    with open(scene, "w") as f:
        f.write('[output]\nsize = [1920, 1080]\n[[objects]]\nmesh = "quad"\n')
    found = []
    for name, expr in SYNTHETIC:
        frag = os.path.join(directory, name + ".frag")
        with open(frag, "w") as f:
            f.write("varying vec2 c;\nvoid main() {\n    float x = c.x, y = c.y, s = 0.0;\n"
                    f"    for (int i = 0; i < 16; ++i) {{ s += {expr}; x = fract(x + 0.137); y = fract(y + 0.311); }}\n"
                    "    gl_FragColor = vec4(fract(s), 0.0, 0.0, 1.0);\n}\n")
        found.append(("synthetic", name, vert, frag, scene))
    return found


def run_one(build, case, precision, frames, image):
    _, _, vert, frag, scene = case
    return bench([os.path.join(build, "glslrun"), vert, frag, scene, "--size", "1920x1080", "--bench", str(frames),
                  "-o", image, "--threads", "1", "--backend", "jit", "--precision", precision])


def image_cost(precise_png, fast_png):
    """(pixels differing, max byte difference, mean byte difference) of Fast's image against Precise's."""
    a = np.asarray(Image.open(precise_png).convert("RGBA"), dtype=np.int16)
    b = np.asarray(Image.open(fast_png).convert("RGBA"), dtype=np.int16)
    diff = np.abs(a - b)
    return int(np.count_nonzero(diff.max(axis=2))), int(diff.max()), float(diff.mean()), a.shape[0] * a.shape[1]


def measure(args, selected, tmp):
    """Interleaved runs: {(name, precision): [CPU ms]}, {(name, precision): last image}, loads seen."""
    cpu = {(c[1], p): [] for c in selected for p in ("precise", "fast")}
    images, loads = {}, []
    for run in range(args.runs):
        for i, case in enumerate(selected):
            loads.append(os.getloadavg()[0])
            for precision in ("precise", "fast") if run % 2 == 0 else ("fast", "precise"):
                image = images[(case[1], precision)] = os.path.join(tmp, f"{i}-{precision}.png")
                try:
                    result = run_one(args.build, case, precision, args.frames, image)
                except subprocess.CalledProcessError as e:
                    sys.exit(f"fast_trade.py: {case[1]} in {precision} failed: {e.stderr.strip()}")
                cpu[(case[1], precision)].append(float(result["cpu_median_ms"]))
        print(f"run {run + 1} of {args.runs} done (load {os.getloadavg()[0]:.2f})", file=sys.stderr, flush=True)
    return cpu, images, loads


def table(args, selected, cpu, images, loads):
    lines = [f"`bench/fast_trade.py --runs {args.runs} --frames {args.frames}`, 1920x1080, JIT, 1 thread; "
             f"{os.cpu_count()} cores; load average (1 min) {min(loads):.2f} to {max(loads):.2f} during the runs.", "",
             "| set | program | approximated calls (source) | Precise CPU ms | Fast CPU ms | Fast speed-up | "
             "pixels differing from Precise | max byte diff | mean byte diff |",
             "|---|---|---|---:|---:|---:|---:|---:|---:|"]
    for case in selected:
        n = case[1]
        p, f = statistics.median(cpu[(n, "precise")]), statistics.median(cpu[(n, "fast")])
        differing, worst, mean, pixels = image_cost(images[(n, "precise")], images[(n, "fast")])
        lines.append(f"| {case[0]} | {n} | {approximated_calls(case)} | {p:.2f} | {f:.2f} | {p / f:.2f}x | "
                     f"{differing} ({100.0 * differing / pixels:.2f}%) | {worst} | {mean:.4f} |")
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", required=True)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--frames", type=int, default=8)
    ap.add_argument("--only", default="", help="comma-separated program names (corpus names, or lecture programs)")
    ap.add_argument("--synthetic", action="store_true", help="the loops of one built-in instead of the programs")
    ap.add_argument("--output", help="also write the markdown table to this file")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        selected = synthetic_cases(tmp) if args.synthetic else cases()
        if args.only:
            wanted = set(args.only.split(","))
            selected = [c for c in selected if c[1] in wanted or c[1].split(" ")[0] in wanted]
            if not selected:
                sys.exit(f"fast_trade.py: no such program: {args.only}")
        text = table(args, selected, *measure(args, selected, tmp))
    print(text)
    if args.output:
        with open(args.output, "w") as out:
            out.write(text + "\n")


if __name__ == "__main__":
    main()
