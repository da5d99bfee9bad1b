#!/usr/bin/python3
"""Tests `glslrun serve` (tools/glslrun/serve_command.cpp and its page).

  serve_test.py http    SOURCE_DIR GLSLRUN OUT_DIR   the server over HTTP: what it serves and refuses
  serve_test.py browser SOURCE_DIR GLSLRUN OUT_DIR   the page in headless chromium, driven by selenium
  serve_test.py docs    SOURCE_DIR GLSLRUN OUT_DIR   docs/debugging.md's screenshots of the "Ooops" walk-through

`browser` saves a screenshot of each step in OUT_DIR (step1-loaded.png, ...).
It is skipped (status 77) only when chromium or chromedriver is missing.
"""
import atexit
import hashlib
import http.client
import json
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import urllib.request

SKIP = 77
RUNNING = []  # servers not stopped yet: killed at exit, so that a failed check leaves none behind


@atexit.register
def kill_running():
    for proc in RUNNING:
        if proc.poll() is None:
            proc.kill()
            proc.wait()


def fail(message):
    print(f"FAIL: {message}", file=sys.stderr)
    sys.exit(1)


def check(condition, message):
    if not condition:
        fail(message)


class Server:
    """glslrun serve on a free port, with a TMPDIR of its own (its scratch directory goes there)."""

    def __init__(self, glslrun, files, out_dir, *options, cwd=None):
        self.tmp = tempfile.mkdtemp(prefix="tmp-", dir=out_dir)
        env = dict(os.environ, TMPDIR=self.tmp)
        self.proc = subprocess.Popen([glslrun, "serve", "--port", "0", *options, *files], env=env,
                                     stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=cwd)
        RUNNING.append(self.proc)
        line = self.proc.stdout.readline()
        m = re.match(r"glslrun serve: http://127\.0\.0\.1:(\d+)/ \(Ctrl-C stops\)$", line.strip())
        if not m:
            self.proc.kill()
            fail(f"serve printed {line!r}, stderr {self.proc.stderr.read()!r}")
        self.port = int(m.group(1))
        self.url = f"http://127.0.0.1:{self.port}/"

    def request(self, method, path, body=None, headers=None, timeout=60):
        """(status, body bytes) of a request sent as written: the path is not normalised."""
        conn = http.client.HTTPConnection("127.0.0.1", self.port, timeout=timeout)
        conn.putrequest(method, path, skip_host=True, skip_accept_encoding=True)
        headers = {"Host": f"127.0.0.1:{self.port}", **(headers or {})}
        if body is not None:
            headers["Content-Length"] = str(len(body))
        for k, v in headers.items():
            if v is not None:
                conn.putheader(k, v)
        conn.endheaders(body)
        res = conn.getresponse()
        data = res.read()
        conn.close()
        return res.status, data

    def json(self, method, path, body=None):
        status, data = self.request(method, path, body)
        check(status == 200, f"{method} {path}: status {status}")
        return json.loads(data)

    def stop(self, sig=signal.SIGTERM):
        """Stops it with `sig`: it must exit 0 within seconds and leave no scratch directory."""
        self.proc.send_signal(sig)
        try:
            status = self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            fail(f"serve did not stop on signal {sig}")
        RUNNING.remove(self.proc)
        check(status == 0, f"serve exited with {status} on signal {sig}: {self.proc.stderr.read()}")
        left = os.listdir(self.tmp)
        check(not left, f"the scratch directory was left behind: {left}")
        shutil.rmtree(self.tmp)


def digest(paths):
    return [hashlib.sha256(open(p, "rb").read()).hexdigest() for p in paths]


def spot_files(src):
    return [f"{src}/shaders/spot_pix_fixed.vert", f"{src}/shaders/spot_pix_fixed.frag", f"{src}/scenes/spot.toml"]


# ------------------------------------------------------------------- http ---
def test_http(src, glslrun, out):
    files = spot_files(src)
    before = digest(files)
    server = Server(glslrun, files, out, "--time-limit", "2")
    # The page's own files, and nothing else: no path leaves the page's directory.
    status, page = server.request("GET", "/")
    check(status == 200 and b"serve.js" in page, "GET / is not the page")
    for path in ["/serve.js", "/serve.css", "/index.html"]:
        check(server.request("GET", path)[0] == 200, f"GET {path} failed")
    for path in ["/../../../../etc/passwd", "/..%2f..%2f..%2fetc%2fpasswd", "/%2e%2e/%2e%2e/etc/passwd",
                 "/serve.js/../../serve_command.cpp", "//etc/passwd", "/etc/passwd", "/../serve_command.cpp",
                 "/..\\..\\etc\\passwd", "/serve.js%00.png", "/api/../../CMakeLists.txt"]:
        status, data = server.request("GET", path)
        check(status in (400, 404) and b"root:" not in data and b"#include" not in data,
              f"GET {path}: status {status}, {data[:60]!r}")
    # Only this page: another Host (DNS rebinding) or another Origin is refused.
    check(server.request("GET", "/api/files", headers={"Host": "evil.example:80"})[0] == 403, "a foreign Host passed")
    check(server.request("GET", "/api/files", headers={"Host": None})[0] == 403, "no Host passed")
    status, _ = server.request("POST", "/api/render", b"", headers={"Origin": "http://evil.example"})
    check(status == 403, f"a POST from another origin got {status}")
    files_json = server.json("GET", "/api/files")["files"]
    check([f["kind"] for f in files_json] == ["vert", "frag", "scene"], f"files: {files_json}")
    # A render, then an edit with an error: the diagnostic names the file and line.
    r = server.json("POST", "/api/render", b"")
    check(r["ok"] and r["width"] == 512 and "fragments" in r["stats"], f"render: {r}")
    frag = files_json[1]["text"]
    bad = frag.replace("spotAtt = pow(spotDot, gl_LightSource[0].spotExponent);",
                       "spotAtt = pow(spotDot, gl_LightSource[0].spotExponent)")
    check(bad != frag, "the edit did not apply")
    r = server.json("POST", "/api/files/1", bad.encode())
    check(not r["ok"] and any(d["index"] == 1 and d["line"] == 24 for d in r["diagnostics"]), f"bad edit: {r}")
    # A scene error at its line too.
    scene = files_json[2]["text"]
    r = server.json("POST", "/api/files/2", (scene + "\n[camera]\nfov = 3\n").encode())
    check(not r["ok"] and any(d["index"] == 2 and d["line"] > 0 for d in r["diagnostics"]), f"bad scene: {r}")
    r = server.json("POST", "/api/files/2", scene.encode())
    # A shader that never ends is stopped by the time limit, and the server answers on.
    # A loop under the per-batch cap, over minutes of work in all: the time limit (2 s) ends it.
    endless = frag.replace("gl_FragColor = color;", "float k = 0.0; for (int i = 0; i < 3000000; ++i) "
                           "k += sin(k); gl_FragColor = color + k;")
    start = time.monotonic()
    r = server.json("POST", "/api/files/1", endless.encode())
    check(not r["ok"] and "time limit" in r["diagnostics"][0]["message"] and time.monotonic() - start < 30,
          f"endless loop: {r}")
    start = time.monotonic()
    h = server.json("GET", "/api/heat")
    check("time limit" in h.get("error", "") and time.monotonic() - start < 30, f"endless loop's heat map: {h}")
    r = server.json("POST", "/api/files/1", frag.encode())
    check(r["ok"], f"after the endless loop: {r}")
    check(server.request("POST", "/api/files/9", b"x")[0] == 404, "an edit of file 9 was accepted")
    # The trace of a lit pixel, and an error for one outside the image.
    t = server.json("GET", "/api/trace?x=256&y=256")
    lines = [s.get("text", "") for s in t["fragments"][0]["trace"]["steps"]]
    check(any("spotAtt = pow(spotDot" in l for l in lines), "the trace lacks the spot factor's line")
    check("error" in server.json("GET", "/api/trace?x=9999&y=1"), "a pixel outside the image traced")
    check(server.request("GET", "/api/trace?x=a&y=1")[0] == 400, "a malformed pixel was accepted")
    # Findings: a division by zero makes a NaN/inf, found at a pixel.
    nan = frag.replace("gl_FragColor = color;", "gl_FragColor = color / (intensity - intensity);")
    check(server.json("POST", "/api/files/1", nan.encode())["ok"], "the NaN edit did not render")
    f = server.json("GET", "/api/findings")
    check(any(x["kind"] == "nan" and "fdiv" in x["op"] for x in f["findings"]), f"findings: {f}")
    # The same division by zero is an undefined operation (--check-undefined), at its source line.
    check(any(x["kind"] == "undefined" and "division" in x["op"] and x["where"].endswith(":" + str(
        frag.split("gl_FragColor = color;")[0].count("\n") + 1)) for x in f["findings"]), f"undefined: {f}")
    server.json("POST", "/api/files/1", frag.encode())
    h = server.json("GET", "/api/heat")
    check(h.get("ok") and "gl_FragColor" in h["output"], f"heat: {h}")
    status, png = server.request("GET", "/api/heat.png")
    check(status == 200 and png.startswith(b"\x89PNG"), "no heat map PNG")
    check(digest(files) == before, "the user's files changed")
    server.stop(signal.SIGINT)
    # A port in use is a clear error.
    # A comment in Latin-1 (not UTF-8) is shown with U+FFFD, not an error.
    latin1 = os.path.join(out, "latin1.frag")
    with open(latin1, "wb") as f:
        f.write(b"// ilumina\xe7\xe3o\n" + open(files[1], "rb").read())
    other = Server(glslrun, [files[0], latin1, files[2]], out)
    check("\ufffd" in other.json("GET", "/api/files")["files"][1]["text"], "the Latin-1 comment")
    check(other.json("POST", "/api/render", b"")["ok"], "the Latin-1 shader did not render")
    res = subprocess.run([glslrun, "serve", "--port", str(other.port), *files], capture_output=True, text=True,
                         timeout=30)
    check(res.returncode == 2 and "cannot listen" in res.stderr, f"a port in use: {res.returncode} {res.stderr}")
    other.stop(signal.SIGHUP)
    # Without a vertex shader, as `glslrun` renders: the note on a varying the fixed-function stage does not write.
    alone = Server(glslrun, files[1:], out)
    r = alone.json("POST", "/api/render", b"")
    check(not r["ok"] and "the vertex stage is GL's fixed function" in r["diagnostics"][0]["message"],
          f"no vertex shader: {r}")
    alone.stop()
    # A fragment shader alone draws with the generated fixed-function vertex stage: traced, its text sent.
    alone = Server(glslrun, [f"{src}/shaders/minimal.frag", files[2]], out)
    check(alone.json("POST", "/api/render", b"")["ok"], "minimal.frag alone did not render")
    t = alone.json("GET", "/api/trace?x=256&y=256")
    check("error" not in t and t["fragments"] and all(f["matches_render"] for f in t["fragments"]), f"trace: {t}")
    generated = [g for g in t["generated"] if g["name"] == "(generated) fixed-function-1.vert"]
    check(generated and "gl_Position" in generated[0]["text"], f"no generated vertex stage: {t['generated']}")
    check(any(s.get("where", "").startswith("(generated) fixed-function-1.vert:") for v in t["vertices"]
              for s in v["trace"]["steps"]), "the vertices' steps are not in the generated stage")
    alone.stop()
    # A vertex shader alone: the fragment stage is generated, and traced.
    alone = Server(glslrun, [files[0], files[2]], out)
    check(alone.json("POST", "/api/render", b"")["ok"], "spot_pix_fixed.vert alone did not render")
    t = alone.json("GET", "/api/trace?x=256&y=256")
    check("error" not in t and any(s.get("where", "").startswith("(generated) fixed-function-1.frag:")
                                   for s in t["fragments"][0]["trace"]["steps"]), f"vertex alone: {t}")
    alone.stop()
    # No shader at all: every draw is GL's fixed function, rendered, traced and searched for NaNs in the
    # generated stages; the heat map, which measures the user's shaders, says why there is none.
    fixed = Server(glslrun, [f"{src}/scenes/fixed_function.toml"], out)
    r = fixed.json("POST", "/api/render", b"")
    check(r["ok"] and r["width"] > 0, f"no shader: {r}")
    check([f["kind"] for f in fixed.json("GET", "/api/files")["files"]] == ["scene"], "no shader: the files")
    t = fixed.json("GET", f"/api/trace?x={r['width'] // 2}&y={r['height'] // 2}")
    check("error" not in t and t["fragments"] and all(f["matches_render"] for f in t["fragments"]),
          f"no shader, trace: {t}")
    check({g["name"] for g in t["generated"]} >= {"(generated) fixed-function-1.vert",
                                                    "(generated) fixed-function-1.frag"},
          f"no shader, generated stages: {t['generated']}")
    n = fixed.json("GET", "/api/findings")
    check("error" not in n and "no NaN or infinity" in n["summary"], f"no shader, findings: {n}")
    h = fixed.json("GET", "/api/heat")
    check("fixed function" in h.get("error", ""), f"no shader, heat map: {h}")
    fixed.stop()
    res = subprocess.run([glslrun, "serve", files[0]], capture_output=True, text=True, timeout=30)
    check(res.returncode == 2 and "serve needs" in res.stderr, f"no scene: {res.returncode} {res.stderr}")
    print("serve over HTTP: page files only, Host/Origin checked, errors at their lines, time limit, clean stop")


# ---------------------------------------------------------------- browser ---
def browser_driver(size="1600,1000"):
    chromium = shutil.which("chromium")
    chromedriver = shutil.which("chromedriver")
    if not chromium or not chromedriver:
        print("SKIP: chromium or chromedriver is not installed (Debian's chromium and chromium-driver; "
              "tools/setup.sh test installs them)")
        sys.exit(SKIP)
    from selenium import webdriver  # python3-selenium: a missing one is a failure, not a skip
    from selenium.webdriver.chrome.service import Service
    options = webdriver.ChromeOptions()
    options.binary_location = chromium
    for arg in ["--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                f"--window-size={size}", "--force-device-scale-factor=1"]:
        options.add_argument(arg)
    return webdriver.Chrome(service=Service(chromedriver), options=options)


def wait_for(driver, condition, what, timeout=30):
    from selenium.webdriver.support.ui import WebDriverWait
    try:
        return WebDriverWait(driver, timeout, poll_frequency=0.05).until(lambda d: condition(d))
    except Exception:
        driver.save_screenshot(os.path.join(OUT, "failed.png"))
        fail(f"timed out waiting for {what} (screenshot: {OUT}/failed.png)")


def rendered(driver, generation):
    return driver.execute_script(
        "return document.body.dataset.renderOk === 'true' && Number(document.body.dataset.generation) > arguments[0]"
        " && document.getElementById('image').complete", generation)


def click_pixel(driver, x, y):
    """Clicks image pixel x,y where the page shows it, and waits for its trace."""
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.by import By
    image = driver.find_element(By.ID, "image")
    w, h = image.size["width"], image.size["height"]
    scale = w / driver.execute_script("return arguments[0].naturalWidth", image)
    driver.execute_script("document.getElementById('trace').dataset.state = ''")
    # Offsets from the element's centre, in whole CSS pixels: the pixel's middle, rounded down.
    ActionChains(driver).move_to_element_with_offset(image, math.floor((x + 0.5) * scale - w // 2),
                                                     math.floor((y + 0.5) * scale - h // 2)).click().perform()
    wait_for(driver, lambda d: d.find_element(By.ID, "trace").get_attribute("data-state") == "done", "the trace")
    info = driver.find_element(By.ID, "pixel-info").text
    check(info.startswith(f"pixel {x},{y}"), f"clicked {info!r}, not pixel {x},{y}")


def trace_row(driver, line):
    """The first traced fragment's listing row of `line`: (row, source text, values)."""
    from selenium.webdriver.common.by import By
    row = driver.find_element(By.CSS_SELECTOR, f"details[open] table.listing tr[data-line='{line}']")
    cells = row.find_elements(By.TAG_NAME, "td")
    return row, cells[1].text, cells[2].text


def test_browser(src, glslrun, out):
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys
    files = spot_files(src)
    before = digest(files)
    driver = browser_driver()
    server = Server(glslrun, files, out)
    try:
        start = time.monotonic()
        driver.get(server.url)
        wait_for(driver, lambda d: rendered(d, 0), "the first image")
        first_png = server.request("GET", "/api/image.png")[1]
        generation = int(driver.execute_script("return document.body.dataset.generation"))
        driver.save_screenshot(f"{out}/step1-loaded.png")
        # Click the lit pixel 256,256 (the spot's centre) where the image is shown.
        click_pixel(driver, 256, 256)
        row, source, values = trace_row(driver, 24)
        check("ran" in row.get_attribute("class"), "line 24 is not marked as run")
        check("spotAtt = pow(spotDot, gl_LightSource[0].spotExponent);" in source, f"line 24: {source}")
        check(re.match(r"spotAtt = 0\.\d+", values), f"line 24's value: {values!r}")
        check(trace_row(driver, 21)[2] == "=> if: false, else-branch", "line 21's decision (file:line:column) is not shown")
        driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", row)
        driver.save_screenshot(f"{out}/step2-trace.png")
        # A click on a line of the trace selects that line in the editor.
        row.click()
        selected = driver.execute_script("const t = document.getElementById('text');"
                                         "return t.value.slice(t.selectionStart, t.selectionEnd)")
        check(selected.strip() == "spotAtt = pow(spotDot, gl_LightSource[0].spotExponent);", f"selected {selected!r}")
        # Fields the page does not know (a newer trace's) are shown, not dropped: the same trace with two added.
        shown = driver.execute_async_script("""
            const done = arguments[arguments.length - 1];
            fetch('/api/trace?x=256&y=256').then((r) => r.json()).then((t) => {
              t.fragments[0].colour_after = [1, 0.5, 0, 1];
              t.fragments[0].trace.steps.find((s) => s.kind === 'assign').lookup = {lod: 1.5};
              showTrace(t);
              done([document.querySelector("details[open] .extra[data-key='colour_after']")?.textContent,
                    document.querySelector("details[open] table.listing tr[data-line='11'] td.values")?.textContent]);
            });""")
        check(shown[0] and "colour_after" in shown[0] and "0.5" in shown[0], f"an unknown fragment field: {shown}")
        check(shown[1] and 'lookup: {"lod":1.5}' in shown[1], f"an unknown step field: {shown}")
        # Delete the ';' that ends line 24, typing into the editor.
        text = driver.find_element(By.ID, "text")
        text.click()
        driver.execute_script("const t = arguments[0], at = t.value.indexOf('spotExponent);') + 13;"
                              "t.focus(); t.setSelectionRange(at, at + 1);", text)
        text.send_keys(Keys.DELETE)
        wait_for(driver, lambda d: d.execute_script("return document.body.dataset.renderOk") == "false",
                 "the compile error")
        marked = [e.text for e in driver.find_elements(By.CSS_SELECTOR, "#gutter div.error")]
        check(marked == ["24"], f"lines marked as errors: {marked}")
        # The margin's line 24 is beside the text's line 24 (the mark drawn over the text), scrolled as it is.
        tops = driver.execute_script("return [document.getElementById('line-24').getBoundingClientRect().top,"
                                     "document.querySelector('#marks div.error').getBoundingClientRect().top]")
        check(abs(tops[0] - tops[1]) < 2, f"the margin is not beside the text: line 24 at {tops[0]}, its mark at {tops[1]}")
        messages = [e.text for e in driver.find_elements(By.CSS_SELECTOR, "#diagnostics li.error")]
        check(any(":24: error:" in m and "spot_pix_fixed.frag" in m for m in messages), f"diagnostics: {messages}")
        check(driver.find_element(By.ID, "no-image").is_displayed(), "the stale image is not marked")
        driver.save_screenshot(f"{out}/step3-error.png")
        # Type the ';' back: the image comes back, the same bytes as at first.
        text.send_keys(";")
        wait_for(driver, lambda d: rendered(d, generation), "the image after the fix")
        check(not driver.find_elements(By.CSS_SELECTOR, "#gutter div.error"), "an error mark is left")
        check(not driver.find_element(By.ID, "no-image").is_displayed(), "the image is still marked stale")
        check(server.request("GET", "/api/image.png")[1] == first_png, "the fixed image differs from the first")
        driver.save_screenshot(f"{out}/step4-fixed.png")
        # Tab indents in the editor rather than moving the focus away.
        generation = int(driver.execute_script("return document.body.dataset.generation"))
        text.send_keys(Keys.TAB)
        check(driver.execute_script("return document.activeElement.id") == "text", "Tab left the editor")
        check("spotExponent);    \n" in text.get_attribute("value"), "Tab did not insert four spaces")
        wait_for(driver, lambda d: rendered(d, generation), "the image after the Tab")
        # The findings overlay: the first colour outside [0, 1] is marked.
        driver.find_element(By.ID, "show-findings").click()
        wait_for(driver, lambda d: d.find_elements(By.CSS_SELECTOR, "#findings .finding"), "the findings")
        driver.save_screenshot(f"{out}/step5-findings.png")
        # The heat map of the error against reference, over the image.
        driver.find_element(By.ID, "show-heat").click()
        wait_for(driver, lambda d: d.execute_script("const h = document.getElementById('heat');"
                                                    "return !h.hidden && h.complete && h.naturalWidth === 512"),
                 "the heat map")
        driver.save_screenshot(f"{out}/step6-heat.png")
        elapsed = time.monotonic() - start
        errors = [e for e in driver.get_log("browser") if e["level"] == "SEVERE"]
        check(not errors, f"the page logged errors: {errors}")
    finally:
        driver.quit()
    server.stop()
    check(digest(files) == before, "the user's files changed")
    print(f"serve in chromium: loaded, traced 256,256 (line 24), error at line 24, fixed, findings, heat map; "
          f"{elapsed:.1f} s; screenshots in {out}")


# ------------------------------------------------------------------- docs ---
def make_docs(src, glslrun, out):
    """docs/serve_oops.png and docs/serve_fixed.png: the lecture's "Ooops" at pixel 240,172, and the fix typed in."""
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys
    files = ["shaders/spot_pix_oops.vert", "shaders/spot_pix_oops.frag", "scenes/spot.toml"]
    driver = browser_driver("1600,900")
    server = Server(glslrun, files, out, cwd=src)
    try:
        driver.get(server.url)
        wait_for(driver, lambda d: rendered(d, 0), "the first image")
        click_pixel(driver, 240, 172)
        row, source, values = trace_row(driver, 32)
        check(source.strip().startswith("color = (ambient + diffuse*intensity) * att;"), source)
        check(trace_row(driver, 31)[2] == "intensity = 0", "intensity is not 0 on line 31")
        driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", row)
        driver.save_screenshot(f"{out}/serve_oops.png")
        generation = int(driver.execute_script("return document.body.dataset.generation"))
        text = driver.find_element(By.ID, "text")
        text.click()
        driver.execute_script("const t = arguments[0], old = 'color = (ambient + diffuse*intensity) * att;',"
                              "at = t.value.indexOf(old); t.focus(); t.setSelectionRange(at, at + old.length);"
                              "t.scrollTop = 20 * 17;", text)
        text.send_keys("color = (diffuse*intensity)*att;\n    if ((intensity > 0.0) && (spotAtt != 0.0))\n"
                       "        color += ambient;")
        wait_for(driver, lambda d: rendered(d, generation), "the fixed image")
        click_pixel(driver, 240, 172)
        row, source, values = trace_row(driver, 33)
        check(values == "=> if: false, else-branch\n=> if: false, else-branch", f"line 33: {values!r}")
        driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", row)
        driver.save_screenshot(f"{out}/serve_fixed.png")
    finally:
        driver.quit()
    server.stop()
    print(f"wrote {out}/serve_oops.png and {out}/serve_fixed.png")


if __name__ == "__main__":
    if len(sys.argv) != 5 or sys.argv[1] not in ("http", "browser", "docs"):
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    mode, source, binary, OUT = sys.argv[1:]
    OUT = os.path.abspath(OUT)
    if mode != "docs":
        shutil.rmtree(OUT, ignore_errors=True)  # no screenshot of an earlier run
    os.makedirs(OUT, exist_ok=True)
    {"http": test_http, "browser": test_browser, "docs": make_docs}[mode](source, os.path.abspath(binary), OUT)
