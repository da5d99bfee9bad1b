#!/usr/bin/env python3
"""Compiles every case of tests/spec/*.cases with Mesa (piglit's glslparsertest
on llvmpipe, EGL surfaceless) and prints the cases where Mesa's verdict is not
the case's: the Mesa column of docs/semantics.md ("Where the spec, Mesa and
glslang disagree") is re-measured this way. Not part of ctest (it needs piglit
and EGL); exits 0 either way.

  tests/spec/run_on_mesa.py [CASE_FILE...]
"""
import os
import pathlib
import subprocess
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
PARSER_TEST = os.environ.get("GLSLPARSERTEST", "/usr/lib/x86_64-linux-gnu/piglit/bin/glslparsertest")


def cases(path):
    """(header line, title, stage, version, verdict, body) for each case."""
    current = None
    for number, line in enumerate(path.read_text().splitlines(), 1):
        if line.startswith("== "):
            if current:
                yield current
            title, spec = line[3:].rsplit("|", 1)
            stage, version, verdict = spec.split()
            current = [f"{path.name}:{number}", title.strip(), stage, int(version), verdict, ""]
        elif current:
            current[5] += line + "\n"
    if current:
        yield current


def mesa_compiles(stage, version, body, tmp):
    shader = pathlib.Path(tmp) / f"case.{stage}"
    shader.write_text(body)
    env = dict(os.environ, PIGLIT_PLATFORM="surfaceless_egl", LIBGL_ALWAYS_SOFTWARE="1", GALLIUM_DRIVER="llvmpipe")
    run = subprocess.run([PARSER_TEST, str(shader), "pass", f"{version // 100}.{version % 100:02d}"],
                         capture_output=True, text=True, env=env, timeout=60)
    return '"result": "pass"' in run.stdout, (run.stdout + run.stderr).strip().splitlines()


def main():
    files = [pathlib.Path(f) for f in sys.argv[1:]] or sorted(HERE.glob("*.cases"))
    total = differ = 0
    with tempfile.TemporaryDirectory() as tmp:
        for path in files:
            for where, title, stage, version, verdict, body in cases(path):
                total += 1
                ok, log = mesa_compiles(stage, version, body, tmp)
                expected_ok = verdict in ("pass", "link-fail", "accepted-gap")
                if ok != expected_ok:
                    differ += 1
                    first = next((l for l in log if "error" in l.lower()), log[-1] if log else "")
                    print(f"{where}: {title}\n    case: {verdict}, Mesa: {'compiles' if ok else 'error'}  {first[:120]}")
    print(f"{differ} of {total} cases get another verdict from Mesa")


if __name__ == "__main__":
    main()
