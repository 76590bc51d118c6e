"use strict";
// Everything the page shows comes from the server's JSON API: the criteria
// from the registry (GET /api/criteria), each criterion's result from its own
// POST /api/triangulate (the triangulation document of docs/json-schema.md),
// files parsed by the library's readers (POST /api/read). The page only
// draws. The criteria are requested side by side, so a fast one is drawn as
// soon as it answers and a slow one (stopped by the server's time limit)
// reports itself without holding up the others. The view (points, criteria,
// options) lives in the URL's fragment, so a link reproduces it.
const SVG_NS = "http://www.w3.org/2000/svg";
const state = {
  points: [],          // [[x, y], ...] or, with elevations, [[x, y, z], ...] (world, y up)
  polygon: false,      // send the points as a simple polygon's ring
  metric: "euclidean", // for the criteria and graphs that take one: euclidean, l1, linf or lp:P
  timeLimit: null,     // seconds each computation may take (null: the server's limit)
  graph: "",           // the proximity graph shown ("" for none)
  listing: { criteria: [], graphs: [] },  // the registry listing (GET /api/criteria)
  maxLp: 64,           // the largest Lp exponent the server takes (read from the listing)
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
  showLinkError("");
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

// A POST of the API, asked again while the server is busy: { status, value }
// (status 0: the server cannot be reached), or { aborted }.
async function post(path, body, signal) {
  for (let attempt = 0; ; attempt++) {
    let response, text;
    try {
      response = await fetch(path, {
        method: "POST", headers: { "Content-Type": "application/json" }, signal, body: JSON.stringify(body),
      });
      text = await response.text();
    } catch (e) {
      if (e.name === "AbortError") return { aborted: true };
      return { status: 0, value: { error: "cannot reach the optri server: " + e.message } };
    }
    let value;
    try { value = JSON.parse(text); } catch (_) { value = { error: text }; }
    const retry = Number(response.headers.get("Retry-After"));
    if (response.status === 503 && retry > 0 && attempt < BUSY_RETRIES) {
      await sleep(retry * 1000);
      if (signal.aborted) return { aborted: true };
      continue;
    }
    if (!response.ok && !value.error) value.error = response.statusText;
    return { status: response.status, value };
  }
}

// The options a request carries: the metric where the listing says the
// criterion or graph reads one (any other is refused by the server), and
// the time limit the page sets.
function requestOptions(entry) {
  const options = {};
  if (takesMetric(entry) && state.metric !== "euclidean") options.metric = state.metric;
  if (state.timeLimit !== null) options.time_limit = Math.min(state.timeLimit, state.limits.time_limit_s || Infinity);
  return Object.keys(options).length ? { options } : {};
}

// One criterion's answer: { result } (its triangulation document, or
// { criterion, error, status } for a refusal, a stop or a failure), or
// { inputError } when the input itself is refused (the same for every
// criterion: too few points, collinear, a bad request), or { aborted }.
async function triangulate(criterion, points, polygon, signal) {
  const answer = await post("/api/triangulate",
    { points, criterion, polygon, ...requestOptions(criterionEntry(criterion)) }, signal);
  if (answer.aborted) return answer;
  const { status, value } = answer;
  if (status === 200) return { result: value };
  // A criterion's own refusal names it (422), a stop (503) or a failure
  // (500) concerns this criterion's run; anything else the input.
  if (value.criterion || status === 503 || status === 500 || status === 0) {
    return { result: { criterion, error: value.error, status } };
  }
  return { inputError: status + ": " + value.error };
}

// A proximity graph's answer: its graph document, or { error, status }.
async function requestGraph(kind, points, signal) {
  const answer = await post("/api/graph", { points, kind, ...requestOptions(graphEntry(kind)) }, signal);
  if (answer.aborted) return answer;
  if (answer.status === 200) return answer.value;
  return { kind, error: (answer.status ? answer.status + ": " : "") + answer.value.error, status: answer.status };
}

async function compute() {
  const id = ++state.request;
  if (state.abort) state.abort.abort();
  const criteria = checkedCriteria();
  writeLocation();
  if (state.points.length === 0 || (criteria.length === 0 && !state.graph)) {
    state.abort = null;
    state.document = null;
    $("panels").replaceChildren();
    $("graph-view").replaceChildren();
    $("stats").hidden = true;
    showError("");
    document.body.dataset.state = "done";
    return;
  }
  const abort = new AbortController();
  state.abort = abort;
  document.body.dataset.state = "busy";
  const { points, polygon, graph } = state;
  // Every panel appears at once, busy, and is replaced by its result.
  const panels = criteria.map((name) => busyPanel(name, { criterion: name }));
  $("panels").replaceChildren(...panels);
  // The proximity graph is asked for beside the criteria.
  $("graph-view").replaceChildren(...(graph ? [busyPanel(graph + " graph", { graph })] : []));
  const graphJob = graph ? requestGraph(graph, points, abort.signal).then((answer) => {
    if (!answer.aborted && id === state.request) $("graph-view").replaceChildren(graphPanel(graph, answer));
  }) : null;
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
  await Promise.all([...Array.from({ length: parallel }, worker), graphJob]);
  if (id !== state.request) return;
  if (inputError !== null) {
    $("panels").replaceChildren();
    $("graph-view").replaceChildren();
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
  const c = result.coordinates, map = projection(c);
  const svg = el("svg", { viewBox: "0 0 1000 1000", class: "panel-svg", "data-criterion": result.criterion });
  const corners = (t) => t.map((i) => map(c[i]).map((v) => v.toFixed(2)).join(",")).join(" ");
  const tris = el("g", { class: "triangles" }, svg);
  for (const t of result.triangles) el("polygon", { class: "tri", points: corners(t), "data-triangle": t.join(" ") }, tris);
  const s = result.stats;
  el("polygon", { class: "largest", points: corners(s.largest_triangle), "data-triangle": s.largest_triangle.join(" ") }, svg);
  el("polygon", { class: "smallest", points: corners(s.smallest_triangle), "data-triangle": s.smallest_triangle.join(" ") }, svg);
  const [p, q] = s.longest_edge.map((i) => map(c[i]));
  el("line", { class: "longest", x1: p[0], y1: p[1], x2: q[0], y2: q[1], "data-edge": s.longest_edge.join(" ") }, svg);
  drawPoints(svg, c, map);
  return svg;
}

// World coordinates (y up) to a panel's 1000 x 1000 box (y down), framing `coords`.
function projection(coords) {
  const b = bounds(coords);
  return ([x, y]) => [(x - b.x0) / b.size * 1000, 1000 - (y - b.y0) / b.size * 1000];
}

function drawPoints(svg, coords, map) {
  const r = Math.max(3, Math.min(9, 60 / Math.sqrt(coords.length)));
  const pts = el("g", {}, svg);
  for (const pt of coords) { const [x, y] = map(pt); el("circle", { class: "pt", cx: x.toFixed(2), cy: y.toFixed(2), r }, pts); }
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

// A criterion's (or the graph's) panel while its request runs; `data` names
// it for the page's tests.
function busyPanel(title, data) {
  const panel = document.createElement("div");
  panel.className = "panel busy";
  Object.assign(panel.dataset, data);
  panel.dataset.state = "busy";
  panel.append(panelHead(title, "computing…", "badge"),
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
    if (criterionEntry(r.criterion)?.needs_elevations && !hasElevations()) {
      panel.append(Object.assign(document.createElement("p"), { className: "hint", textContent: ELEVATIONS_HINT }));
    }
  } else {
    panel.dataset.state = "done";
    panel.append(panelHead(r.criterion, r.exact ? "exact" : r.optimality, "badge" + (r.exact ? "" : " approx"),
      r.optimality_bound || r.algorithm), panelSvg(r), resultFacts(r));
  }
  return panel;
}

// ---- what a result guarantees ---------------------------------------------
// The document does not name the measure its criterion optimises, so the
// page knows it by name. Each is in `stats` (the exact value rounded once);
// the differences of the δ criteria the page computes in floating point
// from the document's coordinates, marked "≈".
const TRIANGLE_OBJECTIVES = {
  "delaunay": ["min angle°", (r) => r.stats.min_angle_deg],
  "minmax-length": ["max edge", (r) => (r.metric ? r.metric.max_edge_length : r.stats.max_edge_length)],
  "min-weight": ["total length", (r) => r.stats.total_edge_length],
  "maxmin-area": ["min area", (r) => r.stats.min_area],
  "minmax-area": ["max area", (r) => r.stats.max_area],
  "minmax-angle": ["max angle°", (r) => r.stats.max_angle_deg],
  "maxmin-height": ["min height", (r) => r.stats.min_height],
  "minmax-eccentricity": ["max eccentricity", (r) => r.stats.max_eccentricity],
  "minmax-slope": ["max slope", (r) => r.stats.max_slope],
  "minmax-delta-area": ["max − min area", (r) => r.stats.max_area - r.stats.min_area, true],
  "minmax-delta-angle": ["max − min angle°", (r) => r.stats.max_angle_deg - r.stats.min_angle_deg, true],
  "minmax-delta-length": ["longest − shortest edge", (r) => r.stats.max_edge_length - shortestEdge(r), true],
};

// The shortest edge (for δ-length), in floating point.
function shortestEdge(r) {
  const c = r.coordinates;
  return r.edges.reduce((m, [a, b]) => Math.min(m, Math.hypot(c[a][0] - c[b][0], c[a][1] - c[b][1])), Infinity);
}

// A certified bound in words (docs/json-schema.md, `bound`).
function boundText(bound) {
  const relation = bound.kind === "upper" ? "≤" : "≥";
  if (bound.measure === "area") {
    const which = bound.kind === "upper" ? "smallest" : "largest";
    return `the optimum's ${which} area ${relation} ${fmt(bound.area)} (triangle ${bound.triangle.join(" ")})`;
  }
  if (bound.measure === "total edge length") {
    return `the optimal total length ${relation} ${fmt(bound.weight)}; this result is within ${fmt(bound.gap)} of it`;
  }
  const { kind, measure, ...rest } = bound;
  return `${kind} bound on the ${measure}: ${JSON.stringify(rest)}`;
}

// Under a result's drawing: its guarantee, its certified bound when not
// exact, and the value of the measure its criterion optimises.
function resultFacts(r) {
  const list = document.createElement("dl");
  list.className = "facts";
  const add = (term, text, fact, title) => {
    const dd = Object.assign(document.createElement("dd"), { textContent: text, title: title || "" });
    dd.dataset.fact = fact;
    list.append(Object.assign(document.createElement("dt"), { textContent: term }), dd);
  };
  add("exact", r.exact ? "yes: provably optimal" : "no: " + r.optimality, "exact");
  if (state.metric !== "euclidean" && !takesMetric(criterionEntry(r.criterion))) {
    add("metric", "Euclidean (takes no metric)", "metric");
  }
  if (!r.exact && r.optimality_bound) add("guarantee", r.optimality_bound, "guarantee");
  if (r.bound) add("bound", boundText(r.bound), "bound");
  const objective = TRIANGLE_OBJECTIVES[r.criterion];
  if (objective) {
    const [label, value, computed] = objective;
    add(label + (r.metric ? ` (${r.metric.name})` : ""), (computed ? "≈ " : "") + fmt(value(r)), "measure",
      computed ? "computed by the page in floating point from the document" : "from the document");
  }
  return list;
}

// The proximity graph's panel: its edges and points, or why there are none.
function graphPanel(kind, doc) {
  const panel = document.createElement("div");
  panel.className = "panel graph-panel";
  panel.dataset.graph = kind;
  if (doc.error) {
    panel.dataset.state = "refused";
    panel.append(panelHead(kind + " graph", "refused", "badge approx"),
      Object.assign(document.createElement("p"), { className: "refused", textContent: doc.error }));
    return panel;
  }
  panel.dataset.state = "done";
  const c = doc.coordinates, map = projection(c);
  const svg = el("svg", { viewBox: "0 0 1000 1000", class: "graph-svg", "data-kind": kind });
  const edges = el("g", { class: "edges" }, svg);
  for (const [a, b] of doc.edges) {
    const [p, q] = [map(c[a]), map(c[b])];
    el("line", { class: "edge", x1: p[0].toFixed(2), y1: p[1].toFixed(2), x2: q[0].toFixed(2), y2: q[1].toFixed(2),
      "data-edge": a + " " + b }, edges);
  }
  drawPoints(svg, c, map);
  const description = graphEntry(kind)?.description || "";
  panel.append(panelHead(kind + " graph", doc.edges.length + " edges", "badge", description), svg);
  if (doc.metric) panel.append(Object.assign(document.createElement("p"), { className: "hint", textContent: "metric: " + doc.metric }));
  return panel;
}

// The table of the results so far, in the order of the criteria.
function drawTable(results) {
  const table = $("stats");
  table.replaceChildren();
  const solved = results.filter((r) => !r.error);
  // A measure no result has (the slope, without elevations) gets no column.
  const present = COLUMNS.filter(([, get]) => solved.some((r) => get(r.stats) !== undefined));
  const head = table.createTHead().insertRow();
  for (const name of ["criterion", "guarantee", ...present.map((c) => c[0]), "time ms"]) {
    head.append(Object.assign(document.createElement("th"), { textContent: name }));
  }
  const columns = [...present, ["time ms", libraryMs, "min"]];
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
  // The read supersedes a computation still pending or running, whose end
  // would otherwise clear the read's error message.
  clearTimeout(timer);
  state.request++;
  if (state.abort) state.abort.abort();
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

// ---- options: the metric, the time limit, the proximity graph --------------
// The listing says which criteria and graph kinds read a metric (each
// entry's `options`); the others always measure Euclidean lengths.
const takesMetric = (entry) => (entry?.options || []).includes("metric");
const criterionEntry = (name) => state.listing.criteria.find((c) => c.name === name);
const graphEntry = (name) => state.listing.graphs.find((g) => g.name === name);
const ELEVATIONS_HINT = "reads an elevation per point: generate “terrain” points, or paste or upload " +
  "an x y z file (a clicked point then takes its nearest point's elevation)";

// The metric the controls show, or null when the Lp exponent is not an
// integer the server takes.
function metricOfControls() {
  const kind = $("metric").value;
  $("lp-box").hidden = kind !== "lp";
  if (kind !== "lp") return kind;
  const p = Number($("lp").value);
  return Number.isInteger(p) && p >= 1 && p <= state.maxLp ? "lp:" + p : null;
}

function showMetric(metric) {
  const lp = /^lp:(\d+)$/.exec(metric);
  $("metric").value = lp ? "lp" : metric;
  if (lp) $("lp").value = lp[1];
  $("lp-box").hidden = !lp;
}

// The metric control is live only when a chosen criterion or the graph
// reads a metric; its tooltip and note say which do.
function describeMetricUse() {
  const users = checkedCriteria().filter((name) => takesMetric(criterionEntry(name)));
  if (state.graph && takesMetric(graphEntry(state.graph))) users.push(state.graph + " graph");
  const all = [...state.listing.criteria.filter(takesMetric).map((c) => c.name),
    ...state.listing.graphs.filter(takesMetric).map((g) => g.name + " graph")];
  const note = users.length
    ? "The metric applies to " + users.join(", ") + "; the other criteria measure Euclidean lengths."
    : "None of the chosen criteria or graph takes a metric; these do: " + all.join(", ") + ".";
  for (const control of [$("metric"), $("lp")]) {
    control.disabled = users.length === 0;
    control.title = note;
  }
  $("metric-note").textContent = note;
}

function setupOptions() {
  $("metric").onchange = $("lp").oninput = () => {
    const metric = metricOfControls();
    if (metric === null) {
      showError(`Lp: p must be an integer from 1 to ${state.maxLp}`);
      return;
    }
    state.metric = metric;
    changed();
  };
  $("time-limit").oninput = (e) => {
    const text = e.target.value.trim(), seconds = Number(text);
    if (text !== "" && !(seconds > 0)) return;
    state.timeLimit = text === "" ? null : seconds;
    changed();
  };
  $("graph").onchange = (e) => {
    state.graph = e.target.value;
    $("graph-description").textContent = state.graph ? graphEntry(state.graph).description : "";
    describeMetricUse();
    changed();
  };
}

// The criteria's checkboxes and the graph kinds, from the listing.
function showListing(listing) {
  const tag = (text, title) => Object.assign(document.createElement("span"), { className: "tag", textContent: text, title });
  const box = $("criteria");
  box.replaceChildren();
  for (const c of listing.criteria) {
    const label = document.createElement("label");
    const input = Object.assign(document.createElement("input"), { type: "checkbox", value: c.name, checked: true });
    input.onchange = () => { describeMetricUse(); changed(); };
    label.append(input, " " + c.name);
    if (takesMetric(c)) label.append(" ", tag("metric", "measures lengths in the chosen metric"));
    if (c.needs_elevations) label.append(" ", tag("needs elevations", ELEVATIONS_HINT));
    label.append(Object.assign(document.createElement("small"), { textContent: " — " + c.description }));
    label.title = c.reference + (takesMetric(c) ? "" : "\nTakes no metric: lengths are Euclidean.");
    box.append(label);
  }
  for (const g of listing.graphs) {
    const option = Object.assign(document.createElement("option"), {
      value: g.name, textContent: g.name + (takesMetric(g) ? " (metric)" : ""), title: g.description,
    });
    $("graph").append(option);
  }
  // "lp:P (integer 1 <= P <= 64)": the largest exponent the server takes.
  const metric = listing.options.find((o) => o.name === "metric");
  const most = /P <= (\d+)/.exec(metric?.values || "");
  if (most) state.maxLp = Number(most[1]);
  $("lp").max = state.maxLp;
}

// ---- the view in the URL ------------------------------------------------------
// The fragment (never sent to the server, no length limit of a request line)
// holds the view, e.g. #v=1&c=delaunay,greedy&m=l1&g=mst&t=5&poly=1&p=0,0;4,0;2,3&end
//   v     the format's version (a later format gets another)
//   c     the checked criteria (absent: every one)
//   m     the metric: l1, linf or lp:P (absent: euclidean)
//   g     the proximity graph shown; t: the time limit in seconds
//   poly  1: the points are a simple polygon's ring
//   p     the points, x,y or x,y,z, separated by ";", each number in shortest
//         round-trip decimals (String(x)), so the link gives the same doubles
//   end   always last, so that a link cut short is told from a whole one
const LINK_VERSION = "1";
const LINK_KEYS = ["v", "c", "m", "g", "t", "poly", "p"];
const LINK_NUMBER = /^[+-]?(\d+\.?\d*|\.\d+)(e[+-]?\d+)?$/i;

function linkFragment() {
  const keys = ["v=" + LINK_VERSION, "c=" + checkedCriteria().join(",")];
  if (state.metric !== "euclidean") keys.push("m=" + state.metric);
  if (state.graph) keys.push("g=" + state.graph);
  if (state.timeLimit !== null) keys.push("t=" + String(state.timeLimit));
  if (state.polygon) keys.push("poly=1");
  if (state.points.length) keys.push("p=" + state.points.map((p) => p.map(String).join(",")).join(";"));
  return "#" + [...keys, "end"].join("&");
}

const linkUrl = () => location.href.split("#")[0] + linkFragment();

// Keeps the URL on the view, replacing the history entry (an entry per
// click would make Back walk through every edit).
function writeLocation() {
  const fragment = linkFragment();
  if (location.hash !== fragment) history.replaceState(null, "", fragment);
  if (!$("share-url").hidden) $("share-url").value = linkUrl();
}

function parseMetric(text) {
  if (["euclidean", "l1", "linf"].includes(text)) return text;
  const lp = /^lp:(\d+)$/.exec(text);
  if (lp && Number(lp[1]) >= 1 && Number(lp[1]) <= state.maxLp) return "lp:" + Number(lp[1]);
  throw new Error(`the metric “${text}” is not euclidean, l1, linf or lp:P with 1 ≤ P ≤ ${state.maxLp}`);
}

function parsePoints(text) {
  const points = text.split(";").map((item, k) => {
    const numbers = item.split(",");
    if ((numbers.length !== 2 && numbers.length !== 3) || !numbers.every((v) => LINK_NUMBER.test(v))) {
      throw new Error(`point ${k + 1}, “${item}”, is not x,y or x,y,z`);
    }
    return numbers.map(Number);
  });
  const mixed = points.findIndex((p) => p.length !== points[0].length);
  if (mixed >= 0) throw new Error(`point ${mixed + 1} has ${points[mixed].length} numbers, point 1 has ${points[0].length}`);
  if (!points.flat().every(Number.isFinite)) throw new Error("a coordinate is too large");
  return points;
}

const defaultView = () => ({
  criteria: state.listing.criteria.map((c) => c.name), metric: "euclidean", graph: "",
  timeLimit: null, polygon: false, points: [],
});

// The view a fragment describes; throws an Error saying what is wrong.
function parseFragment(fragment) {
  let text;
  try { text = decodeURIComponent(fragment.replace(/^#/, "")); } catch (_) { throw new Error("its percent-encoding is broken"); }
  const items = text.split("&");
  if (items[items.length - 1] !== "end") throw new Error("it is cut short (it does not end with “&end”)");
  const keys = new Map();
  for (const item of items.slice(0, -1)) {
    const eq = item.indexOf("=");
    const key = item.slice(0, eq);
    if (eq < 1 || !LINK_KEYS.includes(key)) throw new Error(`“${item}” is not one of its keys (${LINK_KEYS.join(", ")})`);
    if (keys.has(key)) throw new Error(`the key ${key} appears twice`);
    keys.set(key, item.slice(eq + 1));
  }
  if (keys.get("v") !== LINK_VERSION) {
    throw new Error(keys.has("v") ? `its version v=${keys.get("v")} is not one this page reads (v=${LINK_VERSION})`
      : "it has no version (v=1)");
  }
  const view = defaultView();
  if (keys.has("c")) {
    view.criteria = keys.get("c") === "" ? [] : keys.get("c").split(",");
    const unknown = view.criteria.find((name) => !criterionEntry(name));
    if (unknown !== undefined) throw new Error(`“${unknown}” is not a criterion of this server`);
  }
  if (keys.has("m")) view.metric = parseMetric(keys.get("m"));
  if (keys.has("g")) {
    view.graph = keys.get("g");
    if (!graphEntry(view.graph)) throw new Error(`“${view.graph}” is not a graph kind of this server`);
  }
  if (keys.has("t")) {
    view.timeLimit = Number(keys.get("t"));
    if (!LINK_NUMBER.test(keys.get("t")) || !(view.timeLimit > 0)) throw new Error(`the time limit “${keys.get("t")}” is not a positive number`);
  }
  if (keys.has("poly")) {
    if (!["0", "1"].includes(keys.get("poly"))) throw new Error(`poly=${keys.get("poly")} is not 0 or 1`);
    view.polygon = keys.get("poly") === "1";
  }
  if (keys.has("p") && keys.get("p") !== "") view.points = parsePoints(keys.get("p"));
  return view;
}

function applyView(view) {
  state.points = view.points;
  state.polygon = view.polygon;
  $("polygon").checked = view.polygon;
  state.metric = view.metric;
  showMetric(view.metric);
  state.timeLimit = view.timeLimit;
  $("time-limit").value = view.timeLimit === null ? "" : String(view.timeLimit);
  state.graph = view.graph;
  $("graph").value = view.graph;
  $("graph-description").textContent = view.graph ? graphEntry(view.graph).description : "";
  for (const box of document.querySelectorAll("#criteria input")) box.checked = view.criteria.includes(box.value);
  describeMetricUse();
}

// Shows the view of the URL's fragment; one that cannot be read is said so
// and the default view is shown instead (never a blank page).
function restoreLocation() {
  let view = defaultView(), problem = null;
  if (location.hash.length > 1) {
    try { view = parseFragment(location.hash); } catch (e) { problem = e.message; }
  }
  applyView(view);
  changed(true);
  if (problem) showLinkError(`This link could not be read: ${problem}. Showing the default view instead.`);
}

function showLinkError(message) {
  $("link-error").textContent = message;
  $("link-error").hidden = !message;
}

// Copies the link; where the clipboard is unavailable (an insecure origin,
// a refused permission) the link is shown in a field to copy by hand.
async function copyLink() {
  const url = linkUrl(), field = $("share-url");
  try {
    if (!navigator.clipboard) throw new Error("no clipboard");
    await navigator.clipboard.writeText(url);
    field.hidden = true;
    $("share-status").textContent = "link copied";
  } catch (_) {
    field.value = url;
    field.hidden = false;
    field.select();
    $("share-status").textContent = "copy the link from the field below";
  }
}

// ---- start ------------------------------------------------------------------
async function start() {
  setupEditor();
  setupOptions();
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
  $("copy-link").onclick = copyLink;
  try {
    state.limits = (await api("/api/limits")).value;
    if (state.limits.time_limit_s) $("time-limit").max = state.limits.time_limit_s;
    const { value } = await api("/api/criteria");
    state.listing = value;
    COLUMNS = [["triangles", (s) => s.triangles, null],
      ...value.measures.map((m) => [m.label, (s) => s[m.name], m.better === "smaller" ? "min" : "max"])];
    showListing(value);
    restoreLocation();
    // A link pasted into this tab's address bar changes only the fragment.
    addEventListener("hashchange", restoreLocation);
    document.body.dataset.ready = "yes";
  } catch (e) {
    showError("cannot reach the optri server: " + e.message);
  }
  drawEditor();
}
start();
