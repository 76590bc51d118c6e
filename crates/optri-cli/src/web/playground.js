"use strict";
// Everything the page shows comes from the server's JSON API: the criteria
// from the registry (GET /api/criteria), each criterion's result from its own
// POST /api/triangulate (the triangulation document of docs/json-schema.md),
// files parsed by the library's readers (POST /api/read). The page only
// draws. The criteria are requested side by side, so a fast one is drawn as
// soon as it answers and a slow one (stopped by the server's time limit)
// reports itself without holding up the others.
const SVG_NS = "http://www.w3.org/2000/svg";
const state = {
  points: [],          // [[x, y], ...] or, with elevations, [[x, y, z], ...] (world, y up)
  polygon: false,      // send the points as a simple polygon's ring
  view: { x0: 0, y0: 0, size: 1000 },  // world square shown in the editor
  document: null,      // the last results, as a comparison document
  documentText: "",
  request: 0,          // sequence number: only the latest answers are drawn
  abort: null,         // stops the requests of an older computation
  // The server's limits (GET /api/limits): how many points are small, how
  // many large computations may run at once.
  limits: { small_points: 2000, max_running: 2 },
};
const $ = (id) => document.getElementById(id);

function el(name, attrs, parent) {
  const node = document.createElementNS(SVG_NS, name);
  for (const [k, v] of Object.entries(attrs || {})) node.setAttribute(k, v);
  if (parent) parent.appendChild(node);
  return node;
}

// ---- numbers -------------------------------------------------------------
function fmt(v) {
  if (typeof v !== "number" || !isFinite(v)) return String(v);
  if (v === 0) return "0";
  const a = Math.abs(v);
  if (a >= 1e-3 && a < 1e7) return String(Number(v.toPrecision(6)));
  return v.toExponential(4);
}

// ---- generators (seeded, so a picture can be reproduced) ------------------
function rng(seed) {
  let t = (seed >>> 0) || 1;
  return () => {
    t += 0x6D2B79F5;
    let r = Math.imul(t ^ (t >>> 15), 1 | t);
    r ^= r + Math.imul(r ^ (r >>> 7), 61 | r);
    return ((r ^ (r >>> 14)) >>> 0) / 4294967296;
  };
}
const round2 = (v) => Math.round(v * 100) / 100;
// A smooth surface over the editor's square, in whole units: the elevation
// of the "terrain" generator.
const terrainHeight = (x, y) => Math.round(100 * Math.sin(x / 160) * Math.cos(y / 210));
const generators = {
  terrain(n, rand) {
    return generators.uniform(n, rand).map(([x, y]) => [x, y, terrainHeight(x, y)]);
  },
  uniform(n, rand) {
    return Array.from({ length: n }, () => [round2(50 + 900 * rand()), round2(50 + 900 * rand())]);
  },
  grid(n) {
    const k = Math.ceil(Math.sqrt(n)), step = 900 / Math.max(k - 1, 1), out = [];
    for (let i = 0; i < n; i++) out.push([round2(50 + step * (i % k)), round2(50 + step * Math.floor(i / k))]);
    return out;
  },
  circle(n) {
    return Array.from({ length: n }, (_, i) => {
      const a = 2 * Math.PI * i / n;
      return [500 + 450 * Math.cos(a), 500 + 450 * Math.sin(a)];
    });
  },
  clustered(n, rand) {
    const centres = Array.from({ length: 4 }, () => [200 + 600 * rand(), 200 + 600 * rand()]);
    const gauss = () => Math.sqrt(-2 * Math.log(1 - rand())) * Math.cos(2 * Math.PI * rand());
    return Array.from({ length: n }, (_, i) => {
      const c = centres[i % centres.length];
      return [round2(c[0] + 60 * gauss()), round2(c[1] + 60 * gauss())];
    });
  },
};

// ---- the editor ----------------------------------------------------------
function fitView() {
  if (state.points.length === 0) { state.view = { x0: 0, y0: 0, size: 1000 }; return; }
  let [lx, ly, hx, hy] = [Infinity, Infinity, -Infinity, -Infinity];
  for (const [x, y] of state.points) { lx = Math.min(lx, x); ly = Math.min(ly, y); hx = Math.max(hx, x); hy = Math.max(hy, y); }
  const size = Math.max(hx - lx, hy - ly) || 1, pad = size * 0.06;
  state.view = { x0: (lx + hx) / 2 - size / 2 - pad, y0: (ly + hy) / 2 - size / 2 - pad, size: size + 2 * pad };
}
// World (y up) to editor coordinates (0..1000, y down), and back.
const toScreen = ([x, y]) => [(x - state.view.x0) / state.view.size * 1000, 1000 - (y - state.view.y0) / state.view.size * 1000];
const toWorld = (sx, sy) => [state.view.x0 + sx / 1000 * state.view.size, state.view.y0 + (1000 - sy) / 1000 * state.view.size];

function eventPoint(evt) {
  const svg = $("editor"), m = svg.getScreenCTM().inverse();
  const p = new DOMPoint(evt.clientX, evt.clientY).matrixTransform(m);
  return [p.x, p.y];
}

function drawEditor() {
  const svg = $("editor");
  svg.replaceChildren();
  if (state.polygon && state.points.length >= 3) {
    el("polygon", { class: "ring", points: state.points.map((p) => toScreen(p).join(",")).join(" ") }, svg);
  }
  state.points.forEach((p, i) => {
    const [x, y] = toScreen(p);
    el("circle", { cx: x, cy: y, r: 9, "data-index": i }, svg);
  });
  $("status").textContent = state.points.length + " point" + (state.points.length === 1 ? "" : "s") +
    (hasElevations() ? " with elevations" : "") + (state.polygon ? " (polygon ring)" : "");
}

// Whether the points carry an elevation (every one does, or none).
const hasElevations = () => state.points.length > 0 && state.points[0].length === 3;

// A point placed at world (x, y): with elevations, it takes the elevation of
// the nearest point (a click has no height of its own).
function placed([x, y]) {
  if (!hasElevations()) return [x, y];
  let nearest = state.points[0], best = Infinity;
  for (const p of state.points) {
    const d = (p[0] - x) ** 2 + (p[1] - y) ** 2;
    if (d < best) { best = d; nearest = p; }
  }
  return [x, y, nearest[2]];
}

let drag = null;
function setupEditor() {
  const svg = $("editor");
  svg.addEventListener("contextmenu", (e) => e.preventDefault());
  svg.addEventListener("pointerdown", (e) => {
    const target = e.target.closest("circle");
    if (target) {
      const i = Number(target.dataset.index);
      if (e.button === 2 || e.shiftKey) { state.points.splice(i, 1); changed(); return; }
      if (e.button === 0) { drag = i; svg.setPointerCapture(e.pointerId); }
      return;
    }
    if (e.button !== 0 || e.shiftKey) return;
    const [sx, sy] = eventPoint(e);
    state.points.push(placed(toWorld(sx, sy).map(round2)));
    changed();
  });
  svg.addEventListener("pointermove", (e) => {
    if (drag === null) return;
    const [sx, sy] = eventPoint(e);
    // A dragged point keeps its elevation.
    const [x, y] = toWorld(Math.min(Math.max(sx, 0), 1000), Math.min(Math.max(sy, 0), 1000)).map(round2);
    state.points[drag] = [x, y, ...state.points[drag].slice(2)];
    changed();
  });
  const end = () => { drag = null; };
  svg.addEventListener("pointerup", end);
  svg.addEventListener("pointercancel", end);
}

// ---- talking to the server -----------------------------------------------
async function api(path, body) {
  const response = await fetch(path, body === undefined ? {} : {
    method: "POST", headers: { "Content-Type": "application/json" }, body: JSON.stringify(body),
  });
  const text = await response.text();
  let value;
  try { value = JSON.parse(text); } catch (_) { value = { error: text }; }
  if (!response.ok) throw new Error(response.status + ": " + (value.error || response.statusText));
  return { value, text };
}

function showError(message) {
  const box = $("error");
  box.textContent = message;
  box.hidden = !message;
}

function checkedCriteria() {
  return [...document.querySelectorAll("#criteria input:checked")].map((c) => c.value);
}

let timer = null;
function changed(refit) {
  if (refit) fitView();
  // Tests (and the curious) can wait for data-state="done".
  document.body.dataset.state = "pending";
  drawEditor();
  clearTimeout(timer);
  timer = setTimeout(compute, 120);
}

// How often a criterion is asked again when the server is busy with other
// large computations (it says so with 503 and Retry-After).
const BUSY_RETRIES = 10;
const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

// One criterion's answer: { result } (its triangulation document, or
// { criterion, error, status } for a refusal, a stop or a failure), or
// { inputError } when the input itself is refused (the same for every
// criterion: too few points, collinear, a bad request), or { aborted }.
async function triangulate(criterion, points, polygon, signal) {
  for (let attempt = 0; ; attempt++) {
    let response, text;
    try {
      response = await fetch("/api/triangulate", {
        method: "POST", headers: { "Content-Type": "application/json" }, signal,
        body: JSON.stringify({ points, criterion, polygon }),
      });
      text = await response.text();
    } catch (e) {
      if (e.name === "AbortError") return { aborted: true };
      return { result: { criterion, error: "cannot reach the optri server: " + e.message, status: 0 } };
    }
    let value;
    try { value = JSON.parse(text); } catch (_) { value = { error: text }; }
    if (response.ok) return { result: value };
    const retry = Number(response.headers.get("Retry-After"));
    if (response.status === 503 && retry > 0 && attempt < BUSY_RETRIES) {
      await sleep(retry * 1000);
      if (signal.aborted) return { aborted: true };
      continue;
    }
    const message = value.error || response.statusText;
    // A criterion's own refusal names it (422), a stop (503) or a failure
    // (500) concerns this criterion's run; anything else the input.
    if (value.criterion || response.status === 503 || response.status === 500) {
      return { result: { criterion, error: message, status: response.status } };
    }
    return { inputError: response.status + ": " + message };
  }
}

async function compute() {
  const id = ++state.request;
  if (state.abort) state.abort.abort();
  const criteria = checkedCriteria();
  if (state.points.length === 0 || criteria.length === 0) {
    state.abort = null;
    state.document = null;
    $("panels").replaceChildren();
    $("stats").hidden = true;
    showError("");
    document.body.dataset.state = "done";
    return;
  }
  const abort = new AbortController();
  state.abort = abort;
  document.body.dataset.state = "busy";
  const { points, polygon } = state;
  // Every panel appears at once, busy, and is replaced by its result.
  const panels = criteria.map(busyPanel);
  $("panels").replaceChildren(...panels);
  $("stats").hidden = true;
  state.document = null;
  const results = criteria.map(() => null);
  let inputError = null, next = 0;
  // Small inputs: every criterion at once. Large ones: as many as the
  // server runs at once (more would be refused as busy).
  const parallel = points.length <= state.limits.small_points
    ? criteria.length : Math.max(1, Math.min(criteria.length, state.limits.max_running));
  const worker = async () => {
    while (next < criteria.length && inputError === null && !abort.signal.aborted) {
      const k = next++;
      const answer = await triangulate(criteria[k], points, polygon, abort.signal);
      if (answer.aborted || id !== state.request) return;
      if (answer.inputError) {
        inputError = answer.inputError;
        abort.abort();
        return;
      }
      results[k] = answer.result;
      const panel = resultPanel(answer.result);
      panels[k].replaceWith(panel);
      panels[k] = panel;
      drawTable(results.filter((r) => r !== null));
    }
  };
  await Promise.all(Array.from({ length: parallel }, worker));
  if (id !== state.request) return;
  if (inputError !== null) {
    $("panels").replaceChildren();
    $("stats").hidden = true;
    showError(inputError);
  } else {
    showError("");
    // The results as the comparison document of `optri compare --json`.
    state.document = {
      schema_version: results.find((r) => r.schema_version)?.schema_version ?? 1,
      document: "comparison",
      results: results.map((r) => (r.error ? { criterion: r.criterion, error: r.error } : r)),
    };
    state.documentText = JSON.stringify(state.document);
  }
  document.body.dataset.state = "done";
}

// ---- results ---------------------------------------------------------------
function bounds(coords) {
  let [lx, ly, hx, hy] = [Infinity, Infinity, -Infinity, -Infinity];
  for (const [x, y] of coords) { lx = Math.min(lx, x); ly = Math.min(ly, y); hx = Math.max(hx, x); hy = Math.max(hy, y); }
  const size = Math.max(hx - lx, hy - ly) || 1, pad = size * 0.05;
  return { x0: (lx + hx) / 2 - size / 2 - pad, y0: (ly + hy) / 2 - size / 2 - pad, size: size + 2 * pad };
}

// One panel's picture: every triangle, the smallest and largest triangles
// and the longest edge (the indices the stats name), and the points.
function panelSvg(result) {
  const c = result.coordinates, b = bounds(c);
  const map = ([x, y]) => [(x - b.x0) / b.size * 1000, 1000 - (y - b.y0) / b.size * 1000];
  const svg = el("svg", { viewBox: "0 0 1000 1000", class: "panel-svg", "data-criterion": result.criterion });
  const corners = (t) => t.map((i) => map(c[i]).map((v) => v.toFixed(2)).join(",")).join(" ");
  const tris = el("g", { class: "triangles" }, svg);
  for (const t of result.triangles) el("polygon", { class: "tri", points: corners(t) }, tris);
  const s = result.stats;
  el("polygon", { class: "largest", points: corners(s.largest_triangle), "data-triangle": s.largest_triangle.join(" ") }, svg);
  el("polygon", { class: "smallest", points: corners(s.smallest_triangle), "data-triangle": s.smallest_triangle.join(" ") }, svg);
  const [p, q] = s.longest_edge.map((i) => map(c[i]));
  el("line", { class: "longest", x1: p[0], y1: p[1], x2: q[0], y2: q[1], "data-edge": s.longest_edge.join(" ") }, svg);
  const r = Math.max(3, Math.min(9, 60 / Math.sqrt(c.length)));
  const pts = el("g", {}, svg);
  for (const pt of c) { const [x, y] = map(pt); el("circle", { class: "pt", cx: x.toFixed(2), cy: y.toFixed(2), r }, pts); }
  return svg;
}

// The quality measures come from the registry listing (its "measures":
// name, label, which direction is better), as the CLI's table does.
let COLUMNS = [["triangles", (s) => s.triangles, null]];
// The criterion's own phases: not the request's validation nor its total.
const libraryMs = (r) => Object.entries(r.timing_ms || {})
  .filter(([name]) => name !== "total" && name !== "validate")
  .reduce((sum, [, ms]) => sum + ms, 0);

function panelHead(criterion, badge, className, title) {
  const h = document.createElement("h3");
  h.textContent = criterion;
  h.append(Object.assign(document.createElement("span"), { className, textContent: badge, title: title || "" }));
  return h;
}

// A criterion's panel while its request runs.
function busyPanel(criterion) {
  const panel = document.createElement("div");
  panel.className = "panel busy";
  panel.dataset.criterion = criterion;
  panel.dataset.state = "busy";
  panel.append(panelHead(criterion, "computing…", "badge"),
    Object.assign(document.createElement("div"), { className: "spinner", textContent: "computing" }));
  return panel;
}

// A criterion's panel with its answer: the drawing, or why there is none
// (refused by the criterion, stopped by the time limit, failed).
function resultPanel(r) {
  const panel = document.createElement("div");
  panel.className = "panel";
  panel.dataset.criterion = r.criterion;
  if (r.error) {
    const stopped = r.status === 503;
    panel.classList.add(stopped ? "stopped-panel" : "refused-panel");
    panel.dataset.state = stopped ? "stopped" : "refused";
    panel.append(panelHead(r.criterion, stopped ? "stopped" : r.status === 422 ? "refused" : "failed", "badge approx"),
      Object.assign(document.createElement("p"), { className: "refused", textContent: r.error }));
  } else {
    panel.dataset.state = "done";
    panel.append(panelHead(r.criterion, r.exact ? "exact" : r.optimality, "badge" + (r.exact ? "" : " approx"),
      r.optimality_bound || r.algorithm), panelSvg(r));
  }
  return panel;
}

// The table of the results so far, in the order of the criteria.
function drawTable(results) {
  const table = $("stats");
  table.replaceChildren();
  const solved = results.filter((r) => !r.error);
  const head = table.createTHead().insertRow();
  for (const name of ["criterion", "guarantee", ...COLUMNS.map((c) => c[0]), "time ms"]) {
    head.append(Object.assign(document.createElement("th"), { textContent: name }));
  }
  const columns = [...COLUMNS, ["time ms", libraryMs, "min"]];
  const measure = (r, get) => (get === libraryMs ? libraryMs(r) : get(r.stats));
  // Best by the value shown (ties are all marked).
  const best = columns.map(([, get, better]) => {
    if (!better || solved.length < 2) return null;
    const values = solved.map((r) => Number(fmt(measure(r, get))));
    return better === "min" ? Math.min(...values) : Math.max(...values);
  });
  const body = table.createTBody();
  for (const r of results) {
    const row = body.insertRow();
    row.dataset.criterion = r.criterion;
    row.insertCell().textContent = r.criterion;
    if (r.error) {
      const cell = row.insertCell();
      cell.colSpan = columns.length + 1;
      cell.className = "refused note";
      cell.textContent = (r.status === 422 ? "refused: " : "") + r.error;
      continue;
    }
    const g = row.insertCell();
    g.textContent = r.exact ? "exact" : r.optimality + " (!)";
    if (!r.exact) g.title = r.optimality_bound || "";
    columns.forEach(([, get], k) => {
      const v = measure(r, get);
      const cell = row.insertCell();
      cell.textContent = fmt(v);
      if (best[k] !== null && Number(fmt(v)) === best[k]) cell.classList.add("best");
    });
  }
  const foot = table.createTFoot().insertRow().insertCell();
  foot.colSpan = columns.length + 2;
  foot.textContent = "★ best in its column · (!) not proven optimal · time: the library's phases";
  table.hidden = false;
}

// ---- files and downloads ----------------------------------------------------
async function loadText(text, filename) {
  document.body.dataset.state = "pending";
  try {
    const { value } = await api("/api/read", filename ? { text, filename } : { text });
    state.points = value.points;
    state.polygon = value.polygon;
    $("polygon").checked = value.polygon;
    showError("");
    changed(true);
  } catch (e) {
    showError(e.message);
    document.body.dataset.state = "done";
  }
}

function download(name, type, text) {
  const a = document.createElement("a");
  a.href = URL.createObjectURL(new Blob([text], { type }));
  a.download = name;
  document.body.append(a);
  a.click();
  setTimeout(() => { URL.revokeObjectURL(a.href); a.remove(); }, 0);
}

function downloadSvg() {
  const panels = [...document.querySelectorAll("#panels .panel")].filter((p) => p.querySelector("svg"));
  if (panels.length === 0) { showError("nothing to download yet: add points"); return; }
  const cell = 340, out = el("svg", { xmlns: SVG_NS, width: cell * panels.length, height: cell + 30,
    viewBox: `0 0 ${cell * panels.length} ${cell + 30}`, "font-family": "sans-serif" });
  const style = el("style", {}, out);
  style.textContent = ".tri{fill:#f2f5fb;stroke:#3b5b92;stroke-width:1;vector-effect:non-scaling-stroke}" +
    ".smallest{fill:#f4a742;fill-opacity:.75;stroke:#f4a742;stroke-width:3;vector-effect:non-scaling-stroke}.largest{fill:#5fb36a;fill-opacity:.55}" +
    ".longest{stroke:#d62728;stroke-width:3;vector-effect:non-scaling-stroke}.pt{fill:#111}";
  panels.forEach((p, k) => {
    const title = el("text", { x: k * cell + 10, y: 20, "font-size": 14, "font-weight": "bold" }, out);
    title.textContent = p.querySelector("h3").textContent;
    const svg = p.querySelector("svg").cloneNode(true);
    for (const [name, v] of Object.entries({ x: k * cell + 10, y: 30, width: cell - 20, height: cell - 20 })) svg.setAttribute(name, v);
    out.append(svg);
  });
  download("optri-compare.svg", "image/svg+xml", new XMLSerializer().serializeToString(out));
}

// ---- start ------------------------------------------------------------------
async function start() {
  setupEditor();
  $("generate").onclick = () => {
    const n = Math.max(1, Math.min(5000, Number($("n").value) || 30));
    state.points = generators[$("generator").value](n, rng(Number($("seed").value)));
    changed(true);
  };
  $("clear").onclick = () => { state.points = []; changed(true); };
  $("polygon").onchange = (e) => { state.polygon = e.target.checked; changed(); };
  $("load-text").onclick = () => loadText($("paste").value);
  $("file").onchange = async (e) => {
    const file = e.target.files[0];
    if (!file) return;
    document.body.dataset.state = "pending";
    loadText(await file.text(), file.name);
  };
  $("download-json").onclick = () => state.document
    ? download("optri-compare.json", "application/json", state.documentText)
    : showError("nothing to download yet: add points");
  $("download-svg").onclick = downloadSvg;
  $("download-points").onclick = () => download("points.txt", "text/plain",
    state.points.map((p) => p.join(" ")).join("\n") + "\n");
  try {
    state.limits = (await api("/api/limits")).value;
    const { value } = await api("/api/criteria");
    COLUMNS = [["triangles", (s) => s.triangles, null],
      ...value.measures.map((m) => [m.label, (s) => s[m.name], m.better === "smaller" ? "min" : "max"])];
    const box = $("criteria");
    box.replaceChildren();
    for (const c of value.criteria) {
      const label = document.createElement("label");
      const input = Object.assign(document.createElement("input"), { type: "checkbox", value: c.name, checked: true });
      input.onchange = () => changed();
      const small = Object.assign(document.createElement("small"), { textContent: " — " + c.description });
      label.append(input, " " + c.name, small);
      label.title = c.reference;
      box.append(label);
    }
    document.body.dataset.ready = "yes";
  } catch (e) {
    showError("cannot reach the optri server: " + e.message);
  }
  drawEditor();
}
start();
