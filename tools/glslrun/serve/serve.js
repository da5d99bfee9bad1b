// glslrun serve's page: edits go to the server (kept in its memory), each
// edit re-renders; a click traces a pixel; the toggles overlay the NaN/inf
// findings and the error heat map. The trace JSON is debug::format_json's;
// fields this page does not know are shown as they are, so that additions
// to the trace appear without a change here.
"use strict";

const $ = (id) => document.getElementById(id);
const state = { files: [], current: 0, diagnostics: [], generation: 0, pixel: null, timer: null, edits: 0 };
const FINDING_COLOURS = { nan: "#ff00ff", colour_range: "#ff9800", undefined: "#00e5ff" };
const PALETTE = ["#76ff03", "#ffea00", "#ff1744"];
const MAX_NOTES = 24;  // values shown beside one line of the trace

function setStatus(text, kind) {
  const s = $("status");
  s.textContent = text;
  s.className = kind || "";
}

function el(tag, attrs, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) {
    if (k === "class") e.className = v;
    else if (k.startsWith("on")) e.addEventListener(k.slice(2), v);
    else e.setAttribute(k, v);
  }
  for (const c of children) e.append(c instanceof Node ? c : String(c));
  return e;
}

async function getJson(url, options) {
  const res = await fetch(url, options);
  if (!res.ok) throw new Error(`${url}: HTTP ${res.status}`);
  return res.json();
}

// ----------------------------------------------------------------- editor ---
function lineCount(text) { return text.split("\n").length; }

function showFile(index) {
  state.current = index;
  $("text").value = state.files[index].text;
  $("text").scrollTop = 0;
  drawTabs();
  drawGutter();
}

function drawTabs() {
  const tabs = $("tabs");
  tabs.replaceChildren();
  state.files.forEach((f, i) => {
    const errors = state.diagnostics.some((d) => d.index === i && !d.warning);
    const b = el("button", { class: (i === state.current ? "active " : "") + (errors ? "has-error" : ""),
                             title: f.name, "data-index": i, onclick: () => showFile(i) },
                 f.name.split("/").pop());
    tabs.append(b);
  });
}

// Line numbers beside the text, and a mark on each line with a diagnostic.
function drawGutter() {
  const text = $("text");
  const gutter = $("gutter"), marks = $("marks");
  gutter.replaceChildren();
  marks.replaceChildren();
  const lineHeight = parseFloat(getComputedStyle(gutter).lineHeight) || 17;
  const mine = state.diagnostics.filter((d) => d.index === state.current && d.line > 0);
  const n = lineCount(text.value);
  for (let i = 1; i <= n; i++) {
    const here = mine.filter((d) => d.line === i);
    const kind = here.length ? (here.some((d) => !d.warning) ? "error" : "warning") : "";
    const row = el("div", { class: kind, id: `line-${i}` }, i);
    if (here.length) row.title = here.map((d) => d.message).join("\n");
    gutter.append(row);
    if (kind) {
      const m = el("div", { class: kind, title: row.title });
      m.style.top = `${4 + (i - 1) * lineHeight}px`;
      marks.append(m);
    }
  }
  syncScroll();
}

function syncScroll() {
  const t = $("text");
  $("gutter").scrollTop = t.scrollTop;
  $("marks").style.transform = `translateY(${-t.scrollTop}px)`;
}

function goToLine(index, line) {
  if (index < 0) return;
  if (index !== state.current) showFile(index);
  const t = $("text");
  const lines = t.value.split("\n");
  let at = 0;
  for (let i = 0; i < line - 1 && i < lines.length; i++) at += lines[i].length + 1;
  t.focus();
  t.setSelectionRange(at, at + (lines[line - 1] || "").length);
  const lineHeight = parseFloat(getComputedStyle($("gutter")).lineHeight) || 17;
  t.scrollTop = Math.max(0, (line - 5) * lineHeight);
  syncScroll();
}

function drawDiagnostics() {
  const list = $("diagnostics");
  list.replaceChildren();
  for (const d of state.diagnostics)
    list.append(el("li", { class: d.warning ? "warning" : "error", onclick: () => goToLine(d.index, d.line) }, d.text));
  drawTabs();
  drawGutter();
}

function onEdit() {
  state.files[state.current].text = $("text").value;
  drawGutter();
  clearTimeout(state.timer);
  const index = state.current;
  state.timer = setTimeout(reported(() => sendEdit(index)), 300);
}

// Tab indents (four spaces, as the lecture's sources) instead of leaving the editor.
function indentOnTab(event) {
  if (event.key !== "Tab" || event.shiftKey || event.ctrlKey || event.altKey) return;
  event.preventDefault();
  document.execCommand("insertText", false, "    ");  // keeps the browser's undo; fires "input"
}

async function sendEdit(index) {
  const edit = ++state.edits;
  setStatus("rendering", "busy");
  const result = await getJson(`/api/files/${index}`, { method: "POST", body: state.files[index].text,
                                                         headers: { "Content-Type": "text/plain" } });
  if (edit === state.edits) showRender(result);  // an answer to an older edit is stale
}

// ------------------------------------------------------------------ image ---
function showRender(r) {
  state.diagnostics = r.diagnostics || [];
  drawDiagnostics();
  const image = $("image");
  if (!r.ok) {
    image.classList.add("stale");
    $("no-image").hidden = false;
    $("heat").hidden = true;
    setStatus(`error: ${state.diagnostics.filter((d) => !d.warning).length} diagnostic(s)`, "error");
    document.body.dataset.renderOk = "false";
    return;
  }
  $("stats").textContent = r.stats;
  state.generation = r.generation;
  image.onload = () => {
    image.classList.remove("stale");
    $("no-image").hidden = true;
    setStatus(`rendered ${r.width}x${r.height}`);
    document.body.dataset.renderOk = "true";
    document.body.dataset.generation = String(r.generation);
    sizeOverlay();
    reported(refreshOverlays)();
  };
  image.src = `/api/image.png?g=${r.generation}`;
}

function sizeOverlay() {
  const image = $("image"), overlay = $("overlay");
  overlay.width = image.naturalWidth;
  overlay.height = image.naturalHeight;
  overlay.style.width = `${image.clientWidth}px`;
  overlay.style.height = `${image.clientHeight}px`;
  $("heat").style.width = `${image.clientWidth}px`;
}

function pixelOf(event) {
  const image = $("image");
  const rect = image.getBoundingClientRect();
  const x = Math.floor((event.clientX - rect.left) * image.naturalWidth / rect.width);
  const y = Math.floor((event.clientY - rect.top) * image.naturalHeight / rect.height);
  if (x < 0 || y < 0 || x >= image.naturalWidth || y >= image.naturalHeight) return null;
  return [x, y];
}

let findings = [];

function drawOverlay() {
  const overlay = $("overlay");
  const g = overlay.getContext("2d");
  g.clearRect(0, 0, overlay.width, overlay.height);
  const scale = Math.max(1, overlay.width / Math.max(1, overlay.clientWidth));
  g.lineWidth = 2 * scale;
  if ($("show-findings").checked)
    findings.forEach((f, i) => {
      if (f.vertex || f.in_target) return;  // not at an image pixel
      g.strokeStyle = FINDING_COLOURS[f.kind] || PALETTE[i % PALETTE.length];
      g.beginPath();
      g.arc(f.x + 0.5, f.y + 0.5, 8 * scale, 0, 2 * Math.PI);
      g.stroke();
    });
  if (state.pixel) {
    const [x, y] = state.pixel;
    g.strokeStyle = "#00ff00";
    g.strokeRect(x - 3 * scale, y - 3 * scale, 7 * scale, 7 * scale);
  }
}

async function refreshOverlays() {
  const panel = $("findings");
  panel.replaceChildren();
  findings = [];
  if ($("show-findings").checked) {
    panel.append("searching for NaN/inf and undefined operations ...");
    const r = await getJson("/api/findings");
    panel.replaceChildren();
    if (r.error) panel.append(el("div", { class: "kv" }, r.error));
    else {
      findings = r.findings;
      for (const [i, f] of findings.entries()) {
        const colour = FINDING_COLOURS[f.kind] || PALETTE[i % PALETTE.length];
        const sw = el("span", { class: "swatch" });
        sw.style.background = colour;
        panel.append(el("div", { class: "kv finding", "data-kind": f.kind }, sw, ` ${f.kind}: `,
                        f.vertex ? "a vertex" : `pixel ${f.x},${f.y}${f.in_target ? " (render target)" : ""}`,
                        ` ${f.where} ${f.op}`));
      }
      panel.append(el("div", { class: "kv" }, r.summary));
    }
  }
  if ($("show-heat").checked) {
    const note = el("div", { class: "kv" }, "measuring against reference ...");
    panel.append(note);
    const r = await getJson("/api/heat");
    if (r.error) note.textContent = r.error;
    else {
      note.textContent = `${r.output}: heat map of the ULP error against reference\n${r.legend}\n${r.table}`;
      $("heat").src = `/api/heat.png?g=${Date.now()}`;
      $("heat").hidden = false;
    }
  } else $("heat").hidden = true;
  drawOverlay();
}

// ------------------------------------------------------------------ trace ---
function formatValue(v) {
  if (v === null || v === undefined) return String(v);
  if (typeof v !== "object") return String(v);
  if (Array.isArray(v.value) && v.type) {
    if (v.rows) return `${v.type}\n  ` + v.rows.map((r) => `| ${r.join("  ")} |`).join("\n  ");
    return v.value.length === 1 ? String(v.value[0]) : `${v.type}(${v.value.join(", ")})`;
  }
  return JSON.stringify(v);
}

function namedValues(title, list) {
  const d = el("details", {}, el("summary", {}, `${title} (${list.length})`));
  for (const v of list) d.append(el("div", { class: "kv" }, `${v.name} = ${formatValue(v)}`));
  return d;
}

// "file:line[:column]" -> [file, line]
function splitWhere(where) {
  const m = /^(.*?):(\d+)(?::\d+)?$/.exec(where || "");  // the line, not a column
  return m ? [m[1], Number(m[2])] : [where, 0];
}

// What a step adds to its line: `name = value`, a decision, as the text
// trace words them; then any field this page does not know, as it is.
const STEP_KNOWN = ["kind", "depth", "where", "text", "name", "type", "value", "rows", "taken", "iteration"];
function stepNote(s) {
  let note;
  if (s.kind === "assign") note = `${s.name} = ${formatValue(s)}`;
  else if (s.kind === "branch") note = `=> if: ${s.taken ? "true, then-branch" : "false, else-branch"}`;
  else if (s.kind === "loop") note = `=> loop iteration ${s.iteration}`;
  else if (s.kind === "jump") note = `=> ${s.name}`;
  else if (s.kind === "call") note = `=> call ${s.name}`;
  else note = `=> ${s.kind}${s.name ? " " + s.name : ""}`;
  const rest = Object.entries(s).filter(([k]) => !STEP_KNOWN.includes(k));
  return note + rest.map(([k, v]) => `\n    ${k}: ${JSON.stringify(v)}`).join("");
}

// Each file the steps ran in, whole, with the values beside the lines that ran.
function listing(trace) {
  const byFile = new Map();
  let where = null;
  for (const s of trace.steps) {
    if (s.where) where = splitWhere(s.where);
    if (!where) continue;
    const [file, line] = where;
    if (!byFile.has(file)) byFile.set(file, new Map());
    const lines = byFile.get(file);
    if (!lines.has(line)) lines.set(line, { text: s.text || "", notes: [] });
    if (s.kind !== "statement") lines.get(line).notes.push(stepNote(s));
  }
  // A loop's lines: the first notes and a count of the rest, not thousands.
  for (const lines of byFile.values())
    for (const entry of lines.values())
      if (entry.notes.length > MAX_NOTES)
        entry.notes.splice(MAX_NOTES, entry.notes.length, `... ${entry.notes.length - MAX_NOTES} more`);
  const nanLine = trace.first_nan ? splitWhere(trace.first_nan.where) : null;
  const out = el("div", {});
  for (const [file, lines] of byFile) {
    const source = state.files.find((f) => f.name === file);
    // A generated fixed-function stage is not a file of the page: the trace carries its text.
    const generated = (state.generated || []).find((g) => g.name === file);
    const texts = source ? source.text.split("\n") : generated ? generated.text.split("\n") : null;
    const table = el("table", { class: "listing", "data-file": file },
                     el("colgroup", {}, el("col", { class: "n" }), el("col", { class: "src" }), el("col", {})));
    const numbers = texts ? texts.map((_, i) => i + 1) : [...lines.keys()].sort((a, b) => a - b);
    for (const n of numbers) {
      const ran = lines.get(n);
      const cls = (ran ? "ran" : "") + (nanLine && nanLine[0] === file && nanLine[1] === n ? " nan" : "");
      const index = state.files.indexOf(source);  // a click shows the line in the editor
      table.append(el("tr", { class: cls, "data-line": n, onclick: () => goToLine(index, n) },
                      el("td", { class: "n" }, n), el("td", { class: "src" }, texts ? texts[n - 1] : ran.text),
                      el("td", { class: "values" }, ran ? ran.notes.join("\n") : "")));
    }
    const about = generated ? ` (GL's fixed-function ${generated.stage} stage, generated from the scene's state; ` +
                              `glslrun trace --dump-fixed-function DIR writes it to DIR/${generated.file})` : "";
    out.append(el("div", { class: "kv" }, file + about), table);
  }
  return out;
}

function testsLine(tests) {
  return Object.entries(tests || {}).map(([name, t]) => {
    const operands = Object.entries(t).filter(([k]) => k !== "result").map(([k, v]) => `${k} ${v}`);
    return `${name}: ${t.result}${t.result === "off" ? "" : ` (${operands.join(", ")})`}`;
  }).join("; ");
}

const KNOWN_FRAGMENT = ["draw", "pass", "program", "primitive", "vertices", "front", "depth", "outcome", "tests",
                        "matches_render", "rendered", "trace"];
const KNOWN_TRACE = ["inputs", "uniforms", "steps", "outputs", "files"];

// Fields a newer trace has that this page does not know: shown as they are.
function otherFields(object, known) {
  const d = el("div", {});
  for (const [k, v] of Object.entries(object))
    if (!known.includes(k) && v !== null && v !== false && !(Array.isArray(v) && !v.length))
      d.append(el("div", { class: "kv extra", "data-key": k }, `${k}: ${JSON.stringify(v, null, 1)}`));
  return d;
}

function invocation(trace) {
  const d = el("div", {});
  d.append(namedValues("inputs", trace.inputs || []), namedValues("uniforms read", trace.uniforms || []));
  d.append(listing(trace), namedValues("outputs", trace.outputs || []), otherFields(trace, KNOWN_TRACE));
  return d;
}

function showTrace(t) {
  const panel = $("trace");
  panel.replaceChildren();
  state.generated = t.generated || [];
  if (t.error) {
    panel.append(el("div", { class: "kv" }, t.error));
    return;
  }
  if (!t.fragments.length) panel.append(el("div", { class: "kv" }, `no fragment at pixel ${t.pixel}`));
  t.fragments.forEach((f, i) => {
    const written = f.outcome === "written";
    const head = el("summary", {}, `fragment ${i}: draw ${f.draw}${f.pass ? ` (pass '${f.pass}')` : ""}, primitive ` +
                    `${f.primitive}, ${f.front ? "front" : "back"}, depth ${f.depth}: `,
                    el("span", { class: written ? "outcome-written" : "outcome-other" }, f.outcome));
    const d = el("details", { class: "fragment", "data-outcome": f.outcome }, head);
    if (written && !panel.querySelector("details[open]")) d.open = true;
    d.append(el("div", { class: "kv" }, `program ${f.program}\ntests: ${testsLine(f.tests)}`));
    if (!f.matches_render) d.append(el("div", { class: "kv outcome-other" }, "WARNING: the replay differs from the render"));
    d.append(otherFields(f, KNOWN_FRAGMENT), invocation(f.trace));
    panel.append(d);
  });
  if (t.scissored && t.scissored.length)
    panel.append(el("div", { class: "kv" }, `draws whose scissor box leaves the pixel out: ${t.scissored.join(", ")}`));
  for (const v of t.vertices || []) {
    const d = el("details", { class: "fragment vertex" }, el("summary", {}, `vertex ${v.vertex} of draw ${v.draw}`));
    d.append(otherFields(v, ["draw", "vertex", "pass", "program", "matches_render", "trace"]), invocation(v.trace));
    panel.append(d);
  }
  panel.append(otherFields(t, ["pixel", "scissored", "fragments", "vertices", "generated"]));
}

async function tracePixel(event) {
  const p = pixelOf(event);
  if (!p || document.body.dataset.renderOk !== "true") return;
  state.pixel = p;
  drawOverlay();
  const rgba = readPixel(p);
  $("pixel-info").textContent = `pixel ${p[0]},${p[1]}` + (rgba ? `: RGBA ${rgba.join(", ")}` : "") + " (tracing ...)";
  $("trace").dataset.state = "busy";
  const t = await getJson(`/api/trace?x=${p[0]}&y=${p[1]}`);
  $("pixel-info").textContent = `pixel ${p[0]},${p[1]}` + (rgba ? `: RGBA ${rgba.join(", ")}` : "");
  showTrace(t);
  $("trace").dataset.state = "done";
}

function readPixel([x, y]) {
  const image = $("image");
  const c = document.createElement("canvas");
  c.width = image.naturalWidth;
  c.height = image.naturalHeight;
  const g = c.getContext("2d");
  g.drawImage(image, 0, 0);
  return Array.from(g.getImageData(x, y, 1, 1).data);
}

// A failed request (the server stopped, say) on the status line, not lost.
function reported(handler) {
  return (...args) => handler(...args).catch((e) => setStatus(String(e), "error"));
}

// ------------------------------------------------------------------ start ---
async function start() {
  const r = await getJson("/api/files");
  state.files = r.files;
  document.title = `glslrun serve: ${state.files.map((f) => f.name.split("/").pop()).join(" ")}`;
  const frag = state.files.findIndex((f) => f.kind === "frag");
  showFile(frag >= 0 ? frag : 0);
  $("text").addEventListener("input", onEdit);
  $("text").addEventListener("keydown", indentOnTab);
  $("text").addEventListener("scroll", syncScroll);
  $("view").addEventListener("click", reported(tracePixel));
  $("show-findings").addEventListener("change", reported(refreshOverlays));
  $("show-heat").addEventListener("change", reported(refreshOverlays));
  window.addEventListener("resize", () => { sizeOverlay(); drawOverlay(); });
  showRender(await getJson("/api/render", { method: "POST" }));
}

start().catch((e) => setStatus(String(e), "error"));
