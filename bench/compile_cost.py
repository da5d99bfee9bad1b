#!/usr/bin/python3
"""Compile cost against source size: programs of growing size in every shape, each
compiled by `glslrun --backend interp --stats` on a 1x1 quad (so that LLVM is out of it
and the draw is one fragment): the process's CPU time (user + system, /usr/bin/time: the
compile is nearly all of it, and CPU time holds up on a loaded machine where wall time
does not), the compile time glslrun reports (wall: glslang, lowering and the IR passes)
and the process's peak memory (max RSS). The growth exponent is the least-squares slope
of log(CPU time) against log(source bytes) over the runs of 0.1 s or more (1.0: linear;
2.0: quadratic). One column runs `--backend jit` for information, up to --jit-max-kib
of source: its whole process's wall time, LLVM included.

    /usr/bin/python3 bench/compile_cost.py --build build [--max-kib 1024] [--shapes a,b] [--jit-max-kib 32]

Every shape's sources grow by doubling up to --max-kib of source. A run that takes
longer than --timeout seconds is reported as a timeout. Prints a Markdown table.
"""
import argparse
import math
import os
import re
import subprocess
import sys
import tempfile
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
VS = "void main() { gl_Position = ftransform(); }\n"
HEAD = "uniform float u;\n"
TAIL = "    gl_FragColor = vec4(x);\n}\n"


def straight(n):
    body = "".join(f"    x = x * 1.0001 + {k % 7}.5;\n" for k in range(n))
    return HEAD + "void main() {\n    float x = u;\n" + body + TAIL


def if_chain(n):
    body = "".join(f"    if (x > {k % 5}.5) x = x * 0.5; else x = x + 1.0;\n" for k in range(n))
    return HEAD + "void main() {\n    float x = u;\n" + body + TAIL


def nested_ifs(n):
    opens = "".join(f"    if (x > {k % 5}.5) {{ x = x + 1.0;\n" for k in range(n))
    return HEAD + "void main() {\n    float x = u;\n" + opens + "    }" * n + "\n" + TAIL


def nested_loops(n):
    opens = "".join(f"    for (int i{k} = 0; i{k} < 1; ++i{k}) {{ x = x + 1.0;\n" for k in range(n))
    return HEAD + "void main() {\n    float x = u;\n" + opens + "    }" * n + "\n" + TAIL


def call_chain(n):
    fns = "float f0(float x) { return x * 1.0001 + 0.5; }\n"
    fns += "".join(f"float f{k}(float x) {{ return f{k - 1}(x) * 1.0001 + 0.5; }}\n" for k in range(1, n))
    return HEAD + fns + f"void main() {{\n    float x = f{n - 1}(u);\n" + TAIL


def many_functions(n):
    fns = "".join(f"float g{k}(float x) {{ return x * {k}.0 + 0.5; }}\n" for k in range(n))
    calls = "".join(f"    x = g{k}(x);\n" for k in range(n))
    return HEAD + fns + "void main() {\n    float x = u;\n" + calls + TAIL


def structs(n):
    decls = "".join(f"struct S{k} {{ float a; vec2 b; }};\n" for k in range(n))
    uses = "".join(f"    S{k} v{k}; v{k}.a = x; v{k}.b = vec2(x); x = v{k}.a + v{k}.b.y;\n" for k in range(n))
    return HEAD + decls + "void main() {\n    float x = u;\n" + uses + TAIL


def nested_structs(n):
    # A chain n deep (n is at most glslrun's struct member limit), one variable of the deepest.
    decls = "struct S0 { float a; };\n"
    decls += "".join(f"struct S{k} {{ S{k - 1} s; float a; }};\n" for k in range(1, n))
    return (HEAD + decls + f"void main() {{\n    float x = u;\n    S{n - 1} v;\n    v.a = x;\n    x = v.a;\n" +
            TAIL)


def arrays(n):
    # Dynamically indexed arrays of 64 elements each.
    decls = "".join(f"    float a{k}[64]; a{k}[i] = x; x = x + a{k}[j];\n" for k in range(n))
    return (HEAD + "uniform int i, j;\nvoid main() {\n    float x = u;\n" + decls + TAIL)


def const_arrays(n):
    # One GLSL 1.20 constant array of n elements, read at a dynamic index.
    values = ", ".join(f"{k % 97}.25" for k in range(n))
    return ("#version 120\n" + HEAD + "uniform int i;\n" + f"const float c[{n}] = float[{n}]({values});\n" +
            "void main() {\n    float x = u + c[i];\n" + TAIL)


def uniforms(n):
    decls = "".join(f"uniform float u{k};\n" for k in range(n))
    sums = "".join(f"    x = x + u{k};\n" for k in range(n))
    return HEAD + decls + "void main() {\n    float x = u;\n" + sums + TAIL


SHAPES = {
    "straight": (straight, 32),
    "if_chain": (if_chain, 32),
    "nested_ifs": (nested_ifs, 16),
    "nested_loops": (nested_loops, 16),
    "call_chain": (call_chain, 16),
    "many_functions": (many_functions, 32),
    "structs": (structs, 16),
    "nested_structs": (nested_structs, 16),
    "arrays": (arrays, 8),
    "const_arrays": (const_arrays, 256),
    "uniforms": (uniforms, 32),
}


def run(build, vs, fs, backend, timeout):
    """(compile ms reported by glslrun or None, wall s, CPU s, max RSS MiB, first error line)."""
    cmd = ["/usr/bin/time", "-f", "maxrss_kb %M cpu %U %S", os.path.join(build, "glslrun"), vs, fs,
           os.path.join(REPO, "scenes", "quad.toml"), "--size", "1x1", "--backend", backend, "--stats",
           "-o", os.path.join(os.path.dirname(fs), "out.png")]
    start = time.monotonic()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, timeout, None, None, "timeout"
    wall = time.monotonic() - start
    out = p.stdout + p.stderr
    compile_ms = re.search(r"compile ([0-9.]+)", out)
    rss = re.search(r"maxrss_kb (\d+) cpu ([0-9.]+) ([0-9.]+)", out)
    error = "" if p.returncode == 0 else next((l for l in out.splitlines() if "error" in l), "exit %d" % p.returncode)
    return (float(compile_ms.group(1)) if compile_ms else None, wall,
            float(rss.group(2)) + float(rss.group(3)) if rss else None,
            int(rss.group(1)) / 1024 if rss else None, error)


def slope(points):
    """Least-squares slope of log(CPU s) against log(bytes) over the points of 0.1 s or more."""
    pts = [(math.log(b), math.log(t)) for b, t in points if t and t >= 0.1]
    if len(pts) < 2:
        return None
    mx = sum(x for x, _ in pts) / len(pts)
    my = sum(y for _, y in pts) / len(pts)
    den = sum((x - mx) ** 2 for x, _ in pts)
    return sum((x - mx) * (y - my) for x, y in pts) / den if den else None


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(REPO, "build"))
    ap.add_argument("--max-kib", type=int, default=1024)
    ap.add_argument("--shapes", default=",".join(SHAPES))
    ap.add_argument("--timeout", type=float, default=60)
    ap.add_argument("--jit-max-kib", type=float, default=32, help="0: no JIT column")
    args = ap.parse_args()
    print(f"load average {os.getloadavg()[0]:.2f}; glslrun {args.build}\n")
    print("| shape | source KiB | CPU s (interp) | compile ms (wall) | peak MiB | jit process s | result |")
    print("|---|---:|---:|---:|---:|---:|---|")
    summary = []
    with tempfile.TemporaryDirectory() as tmp:
        vs = os.path.join(tmp, "t.vert")
        with open(vs, "w") as f:
            f.write(VS)
        for name in args.shapes.split(","):
            make, n = SHAPES[name]
            points = []
            while True:
                src = make(n)
                if len(src) > args.max_kib * 1024:
                    break
                fs = os.path.join(tmp, f"{name}.frag")
                with open(fs, "w") as f:
                    f.write(src)
                ms, wall, cpu, rss, error = run(args.build, vs, fs, "interp", args.timeout)
                jit = ""
                if len(src) <= args.jit_max_kib * 1024:
                    jit_run = run(args.build, vs, fs, "jit", 20)
                    jit = "over 20" if jit_run[4] == "timeout" else "%.2f" % jit_run[1]
                if not error:
                    points.append((len(src), cpu))
                print(f"| {name} | {len(src) / 1024:.1f} | {'%.2f' % cpu if cpu is not None else '-'} | "
                      f"{'%.0f' % ms if ms is not None else '-'} | {'%.0f' % rss if rss else '-'} | {jit} | "
                      f"{error.replace(tmp + '/', '')[:80] or 'ok'} |", flush=True)
                if error == "timeout":
                    break
                n *= 2
            largest = max(points, default=(0, 0))
            summary.append((name, slope(points), largest))
    print("\n| shape | growth exponent (CPU time against bytes) | largest source compiled, KiB | its CPU s |")
    print("|---|---:|---:|---:|")
    for name, s, (b, t) in summary:
        print(f"| {name} | {'%.2f' % s if s is not None else '-'} | {b / 1024:.0f} | {t or 0:.2f} |")


if __name__ == "__main__":
    sys.exit(main())
