"""glslrun test's reports against their formats: --json validated against
docs/schema/glslrun.schema.json (python3-jsonschema), --junit parsed as XML,
--tsv read back field by field, for a suite whose names and messages hold
quotes, markup, tabs, newlines, control bytes and invalid UTF-8.

    python3 tests/cli/json_schema.py SOURCE_DIR GLSLRUN
"""
import json
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import jsonschema

src, glslrun = sys.argv[1], sys.argv[2]
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what, file=sys.stderr)


def tsv_field(text):
    """docs/ci.md's escaping undone."""
    out, i = "", 0
    while i < len(text):
        if text[i] == "\\" and i + 1 < len(text):
            out += {"\\": "\\", "t": "\t", "n": "\n", "r": "\r"}[text[i + 1]]
            i += 2
        else:
            out += text[i]
            i += 1
    return out


with open(os.path.join(src, "docs", "schema", "glslrun.schema.json")) as f:
    schema = json.load(f)
jsonschema.Draft202012Validator.check_schema(schema)

with tempfile.TemporaryDirectory() as d:
    # A failing test whose name has quotes and markup, and whose message quotes
    # source bytes: a tab, a control byte and invalid UTF-8.
    name = os.path.join(d, 'q"<&>.shader_test')
    with open(name, "wb") as f:
        f.write(b"[require]\nGLSL >= 1.10\n[vertex shader passthrough]\n[fragment shader]\n"
                b"void main() { gl_FragColor = vec4(\xff\xfe\x01\tbad); }\n[test]\ndraw rect -1 -1 2 2\n")
    with open(os.path.join(d, "ok.shader_test"), "w") as f:
        f.write("[require]\nGLSL >= 1.10\n[vertex shader passthrough]\n[fragment shader]\n"
                "void main() { gl_FragColor = vec4(0.0, 1.0, 0.0, 1.0); }\n[test]\ndraw rect -1 -1 2 2\n"
                "probe all rgba 0.0 1.0 0.0 1.0\n")
    out = {k: os.path.join(d, "report." + k) for k in ("json", "xml", "tsv")}
    run = subprocess.run([glslrun, "test", "--root", d, d, "--json", out["json"], "--junit", out["xml"],
                          "--tsv", out["tsv"]], capture_output=True)
    check(run.returncode == 1, f"exit status {run.returncode}, not 1 (one test fails): {run.stderr[-300:]!r}")
    with open(out["json"], "rb") as f:
        raw = f.read()
    report = json.loads(raw.decode("utf-8"))  # strict UTF-8: a raw invalid byte fails here
    jsonschema.validate(report, schema)
    jsonschema.validate(report, {"$ref": "#/$defs/test_report", "$defs": schema["$defs"]})
    check([t["result"] for t in report] == ["pass", "fail"], f"results: {report}")
    check(report[1]["name"] == 'q"<&>.shader_test', f"name: {report[1]['name']!r}")
    check("\ufffd" in report[1]["message"], f"message: {report[1]['message']!r}")
    check(raw.count(b"\n") == len(report) + 2, "not one test's object a line")
    suite = ET.parse(out["xml"]).getroot()  # expat refuses control characters and invalid UTF-8
    cases = suite.findall("testcase")
    check(suite.get("tests") == "2" and suite.get("failures") == "1", f"testsuite: {suite.attrib}")
    check([c.get("name") for c in cases] == ["ok.shader_test", 'q"<&>.shader_test'], "JUnit names")
    check(cases[1].find("failure") is not None, "no <failure>")
    with open(out["tsv"], encoding="utf-8", errors="surrogateescape") as f:
        rows = [line.rstrip("\n").split("\t") for line in f]
    check(rows[0] == ["path", "result", "seconds", "message"], f"TSV header: {rows[0]}")
    check(all(len(r) == 4 for r in rows), "a TSV row without 4 fields")
    check(tsv_field(rows[2][0]) == 'q"<&>.shader_test' and rows[2][1] == "fail", f"TSV row: {rows[2]}")

    # A suite that passes: the reports of every file of tests/extremes.
    run = subprocess.run([glslrun, "test", "--root", src, "tests/extremes", "--json", out["json"]],
                         capture_output=True, cwd=src)
    with open(out["json"]) as f:
        jsonschema.validate(json.load(f), schema)

if failures:
    sys.exit(1)
print("json_schema: glslrun test's JSON follows docs/schema/glslrun.schema.json; its JUnit and TSV read back")
