// Shared by every page of `kontakt serve`: the JSON API, the form <-> case binding, the
// error shown beside its field, long solves through /api/jobs, downloads and plots.
// Plain ES module, no build step. The physics is the server's (kontakt_case::Case::run);
// this file only moves numbers between the form, the API and the plots.

import uPlot from "../vendor/uplot/uPlot.esm.js";

// ---------------------------------------------------------------- page frame

const PAGES = [
  ["hertz.html", "Hertz contact"],
  ["rib.html", "Roller end / rib"],
  ["bearing.html", "Bearing"],
  ["traction.html", "Traction"],
];

/** Draws the header with the navigation; `active` is the page's file name. */
export function frame(active) {
  const nav = document.createElement("nav");
  nav.className = "topnav";
  const home = document.createElement("a");
  home.href = "index.html";
  home.className = "brand";
  home.textContent = "kontakt";
  nav.append(home);
  for (const [href, label] of PAGES) {
    const a = document.createElement("a");
    a.href = href;
    a.textContent = label;
    if (href === active) a.className = "active";
    nav.append(a);
  }
  document.body.prepend(nav);
  // A field's name (text and <sub>) in one grid cell, the input and its unit beside it.
  for (const label of document.querySelectorAll("form.case label:not(.check)")) {
    const ctrl = label.querySelector("input, select");
    if (!ctrl) continue;
    const name = document.createElement("span");
    name.className = "name";
    while (label.firstChild && label.firstChild !== ctrl) name.append(label.firstChild);
    label.prepend(name);
  }
}

// ---------------------------------------------------------------- API

/** An answer of the API that is not 2xx: `.error` is the server's error object. */
export class ApiError extends Error {
  constructor(status, error) {
    super(error && error.message ? error.message : `HTTP ${status}`);
    this.status = status;
    this.error = error || {};
  }
}

/** Calls the API: GET without `body`, POST (or `method`) with it; returns the JSON or text. */
export async function api(path, body, method) {
  const init = { method: method || (body === undefined ? "GET" : "POST"), headers: {} };
  if (body !== undefined) {
    init.headers["content-type"] = "application/json";
    init.body = JSON.stringify(body);
  }
  const res = await fetch(path, init);
  const type = res.headers.get("content-type") || "";
  const data = type.includes("json") ? await res.json() : await res.text();
  if (!res.ok) {
    throw new ApiError(res.status, typeof data === "object" ? data.error : { message: String(data) });
  }
  return data;
}

// ---------------------------------------------------------------- case <-> form

// A key path: "body1.radii_mm[0]" -> ["body1", "radii_mm", 0].
function parsePath(path) {
  const out = [];
  for (const part of path.split(".")) {
    const m = part.match(/^([^[\]]+)((?:\[\d+\])*)$/);
    if (!m) throw new Error(`bad key path ${path}`);
    out.push(m[1]);
    for (const i of m[2].matchAll(/\[(\d+)\]/g)) out.push(Number(i[1]));
  }
  return out;
}

export function getPath(obj, path) {
  let cur = obj;
  for (const k of parsePath(path)) {
    if (cur === null || cur === undefined || typeof cur !== "object") return undefined;
    cur = cur[k];
  }
  return cur;
}

export function setPath(obj, path, value) {
  const keys = parsePath(path);
  let cur = obj;
  for (let i = 0; i < keys.length - 1; i++) {
    const k = keys[i];
    if (cur[k] === null || typeof cur[k] !== "object") cur[k] = typeof keys[i + 1] === "number" ? [] : {};
    cur = cur[k];
  }
  cur[keys[keys.length - 1]] = value;
}

export function deletePath(obj, path) {
  const keys = parsePath(path);
  const parents = [];
  let cur = obj;
  for (let i = 0; i < keys.length - 1; i++) {
    if (cur === null || typeof cur !== "object") return;
    parents.push([cur, keys[i]]);
    cur = cur[keys[i]];
  }
  if (cur === null || typeof cur !== "object") return;
  const last = keys[keys.length - 1];
  if (Array.isArray(cur)) {
    // An array element left empty: drop the whole array (its other entries are re-set).
    const [parent, key] = parents[parents.length - 1];
    delete parent[key];
  } else {
    delete cur[last];
  }
  // Remove tables left empty.
  for (let i = parents.length - 1; i >= 0; i--) {
    const [p, k] = parents[i];
    const v = p[k];
    if (v && typeof v === "object" && !Array.isArray(v) && Object.keys(v).length === 0) delete p[k];
    else break;
  }
}

// The value of an input: numbers accept `inf` (a flat body; the API's JSON spells TOML's
// special floats "inf", "-inf"), lists are comma-separated.
function inputValue(el) {
  const type = el.dataset.type || "num";
  if (type === "bool") return el.checked;
  const raw = el.value.trim();
  if (raw === "") return undefined;
  if (type === "str") return raw;
  const num = (s) => {
    const t = s.trim().toLowerCase();
    if (t === "inf" || t === "+inf" || t === "infinity") return "inf";
    if (t === "-inf") return "-inf";
    const x = Number(t);
    return Number.isNaN(x) ? s.trim() : x; // the server names a non-number
  };
  if (type === "int") return num(raw);
  if (type === "list") return raw.split(",").filter((s) => s.trim() !== "").map(num);
  if (type === "strlist") return raw.split(",").map((s) => s.trim()).filter((s) => s !== "");
  return num(raw);
}

function showValue(el, v) {
  const type = el.dataset.type || "num";
  if (type === "bool") {
    el.checked = v === true;
    return;
  }
  if (v === undefined || v === null) {
    el.value = "";
  } else if (Array.isArray(v)) {
    el.value = v.map(String).join(", ");
  } else if (typeof v === "number" && !Number.isFinite(v)) {
    el.value = v > 0 ? "inf" : "-inf";
  } else {
    el.value = String(v);
  }
}

/** The form's inputs (every element with `data-key`, enabled and visible to the case). */
export function keyedInputs(root) {
  return [...root.querySelectorAll("[data-key]")].filter((el) => !el.closest("[data-off]"));
}

/**
 * The case of the form: `base` (the case last loaded, kept for the keys the form has no
 * input for) with every keyed input written over it; an empty input removes its key.
 */
export function readCase(root, base) {
  const obj = structuredClone(base || {});
  const all = [...root.querySelectorAll("[data-key]")];
  for (const el of all) deletePath(obj, el.dataset.key);
  for (const el of keyedInputs(root)) {
    const v = inputValue(el);
    if (v !== undefined) setPath(obj, el.dataset.key, v);
  }
  // A list given element by element with one left empty (`load.force_n[0]` blank): 0.
  for (const el of keyedInputs(root)) {
    const m = el.dataset.key.match(/^(.*)\[\d+\]$/);
    const arr = m ? getPath(obj, m[1]) : undefined;
    if (Array.isArray(arr)) for (let i = 0; i < arr.length; i++) if (arr[i] === undefined) arr[i] = 0;
  }
  return obj;
}

/** Fills the form's inputs from a case object. */
export function fillForm(root, obj) {
  for (const el of root.querySelectorAll("[data-key]")) showValue(el, getPath(obj, el.dataset.key));
  root.dispatchEvent(new Event("change"));
}

// ---------------------------------------------------------------- errors and status

/** Removes the error marks of the last run. */
export function clearErrors(root) {
  for (const el of root.querySelectorAll(".field-error")) el.remove();
  for (const el of root.querySelectorAll(".invalid")) el.classList.remove("invalid");
}

// The input an error's `field` names: the key itself, the first element of a list key
// (`body1.radii_mm` -> `body1.radii_mm[0]`), or the list an element belongs to
// (`operating.sweep_inner_rpm[3]` -> `operating.sweep_inner_rpm`).
function inputFor(root, field) {
  const inputs = keyedInputs(root);
  const exact = inputs.find((el) => el.dataset.key === field);
  if (exact) return exact;
  const child = inputs.find((el) => el.dataset.key.startsWith(field + "[") || el.dataset.key.startsWith(field + "."));
  if (child) return child;
  const base = field.replace(/\[\d+\]$/, "");
  return inputs.find((el) => el.dataset.key === base) || null;
}

/**
 * Shows an API error: beside the input its `field` names (the CLI's one-line message), and
 * in the page's status line. Returns whether a field was found.
 */
export function showError(root, status, err) {
  const e = err instanceof ApiError ? err.error : { message: String(err && err.message ? err.message : err) };
  setStatus(status, e.message || "error", "error");
  if (!e.field) return false;
  const el = inputFor(root, e.field);
  if (!el) return false;
  el.classList.add("invalid");
  const span = document.createElement("span");
  span.className = "field-error";
  span.setAttribute("role", "alert");
  span.textContent = e.message;
  const holder = el.closest("label") || el;
  holder.after(span);
  el.scrollIntoView({ block: "center" });
  return true;
}

export function setStatus(el, text, kind) {
  el.textContent = text;
  el.className = "status" + (kind ? " " + kind : "");
}

/** Lists the report's warnings (and the API's) in `el`. */
export function showWarnings(el, ...lists) {
  el.replaceChildren();
  const all = [...new Set(lists.flat().filter(Boolean))];
  if (all.length === 0) {
    el.hidden = true;
    return;
  }
  el.hidden = false;
  const h = document.createElement("h3");
  h.textContent = "Warnings";
  const ul = document.createElement("ul");
  for (const w of all) {
    const li = document.createElement("li");
    li.textContent = w;
    ul.append(li);
  }
  el.append(h, ul);
}

// ---------------------------------------------------------------- running a case

/**
 * Runs a case. `long`: through /api/jobs, with the elapsed time, progress and a Cancel
 * button in `status`; otherwise POST /api/run. Resolves to `{report, warnings}`; rejects
 * with an ApiError (input errors) or an Error("cancelled").
 */
export async function runCase(caseValue, { long = false, status } = {}) {
  if (!long) {
    if (status) setStatus(status, "solving …", "busy");
    const out = await api("/api/run", { case: caseValue });
    return { report: out.report, warnings: out.warnings || [], fields: out.fields, axisStress: out.axis_stress };
  }
  const job = await api("/api/jobs", { case: caseValue });
  const id = job.id;
  let cancelled = false;
  const cancel = document.createElement("button");
  cancel.type = "button";
  cancel.textContent = "Cancel";
  cancel.className = "cancel";
  cancel.addEventListener("click", async () => {
    cancelled = true;
    cancel.disabled = true;
    try {
      await api(`/api/jobs/${encodeURIComponent(id)}`, undefined, "DELETE");
    } catch (_) {
      /* the job may have ended meanwhile */
    }
  });
  const text = document.createElement("span");
  const bar = document.createElement("progress");
  bar.max = 1;
  if (status) {
    status.className = "status busy";
    status.replaceChildren(text, bar, cancel);
  }
  try {
    for (;;) {
      const s = await api(`/api/jobs/${encodeURIComponent(id)}`);
      const elapsed = typeof s.elapsed_s === "number" ? s.elapsed_s.toFixed(1) : "?";
      text.textContent = `solving (${s.state}) ${elapsed} s `;
      if (typeof s.progress === "number") bar.value = s.progress;
      else bar.removeAttribute("value");
      if (s.state === "done" || s.report) {
        return { report: s.report, warnings: s.warnings || [], fields: s.fields, axisStress: s.axis_stress };
      }
      if (s.state === "cancelled" || cancelled) throw new Error("cancelled");
      if (s.state === "failed" || s.state === "error" || s.error) {
        throw new ApiError(422, s.error || { message: "the solve failed" });
      }
      await new Promise((r) => setTimeout(r, 250));
    }
  } finally {
    cancel.remove();
  }
}

// ---------------------------------------------------------------- TOML files

/** Asks the server for the case's TOML (checked by its case parser) and downloads it. */
export async function saveToml(caseObj, name) {
  const out = await api("/api/case/toml", { case: caseObj });
  download(out.toml, `${name}.toml`, "application/toml");
}

/** Reads an uploaded TOML file into a case object (the server parses and checks it). */
export async function loadTomlFile(file) {
  const text = await file.text();
  const out = await api("/api/case/parse", { toml: text });
  return out.case;
}

/** The built-in examples of `method` (or of several methods). */
export async function examples(...methods) {
  const list = await api("/api/examples");
  return list.filter((e) => methods.includes(e.method));
}

export async function exampleCase(name) {
  const text = await api(`/api/examples/${encodeURIComponent(name)}`);
  const out = await api("/api/case/parse", { toml: text });
  return out.case;
}

/**
 * Wires the page's file bar: a select of examples, Load TOML (upload), Save TOML, JSON and
 * CSV downloads. `get()` gives the current case, `set(case)` fills the form, `report()` the
 * last report, `csv()` the CSV text of the last result.
 */
export async function fileBar(bar, { methods, get, set, report, csv, name, status }) {
  const sel = bar.querySelector("select.examples");
  if (sel) {
    try {
      for (const e of await examples(...methods)) {
        const o = document.createElement("option");
        o.value = e.name;
        o.textContent = `${e.name}: ${e.title || ""}`;
        sel.append(o);
      }
    } catch (err) {
      setStatus(status, `examples not available: ${err.message}`, "error");
    }
    sel.addEventListener("change", async () => {
      if (!sel.value) return;
      try {
        set(await exampleCase(sel.value));
        setStatus(status, `example ${sel.value} loaded`);
      } catch (err) {
        setStatus(status, err.message, "error");
      }
    });
  }
  const file = bar.querySelector("input[type=file]");
  file.addEventListener("change", async () => {
    const f = file.files[0];
    if (!f) return;
    try {
      set(await loadTomlFile(f));
      setStatus(status, `${f.name} loaded`);
    } catch (err) {
      setStatus(status, `${f.name}: ${err.message}`, "error");
    }
    file.value = "";
  });
  bar.querySelector(".save-toml").addEventListener("click", async () => {
    try {
      await saveToml(get(), name());
    } catch (err) {
      showError(document.body, status, err);
    }
  });
  bar.querySelector(".save-json").addEventListener("click", () => {
    const r = report();
    if (r) download(JSON.stringify(r, null, 2), `${name()}.json`, "application/json");
    else setStatus(status, "run the case first", "error");
  });
  bar.querySelector(".save-csv").addEventListener("click", () => {
    const text = report() ? csv() : null;
    if (text) download(text, `${name()}.csv`, "text/csv");
    else setStatus(status, "run the case first", "error");
  });
}

// ---------------------------------------------------------------- downloads

export function download(data, filename, type) {
  const blob = data instanceof Blob ? data : new Blob([data], { type });
  const a = document.createElement("a");
  a.href = URL.createObjectURL(blob);
  a.download = filename;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}

/** CSV text of columns: `cols` is [[header, values[]], ...]. */
export function toCsv(cols) {
  const n = Math.max(0, ...cols.map(([, v]) => v.length));
  const cell = (v) => (v === null || v === undefined ? "" : typeof v === "string" && /[",\n]/.test(v) ? `"${v.replaceAll('"', '""')}"` : String(v));
  const lines = [cols.map(([h]) => cell(h)).join(",")];
  for (let i = 0; i < n; i++) lines.push(cols.map(([, v]) => cell(v[i])).join(","));
  return lines.join("\n") + "\n";
}

/** CSV of an array of flat objects (rows of a report table). */
export function rowsCsv(rows) {
  if (!rows || rows.length === 0) return "";
  const keys = Object.keys(rows[0]).filter((k) => typeof rows[0][k] !== "object" || rows[0][k] === null);
  return toCsv(keys.map((k) => [k, rows.map((r) => r[k])]));
}

// ---------------------------------------------------------------- units and tables

// The unit of a report key, from its suffix (the project's naming rule: units in the key).
const SUFFIX_UNITS = [
  ["_n_per_mm10_9", "N/mm^(10/9)"],
  ["_n_per_mm1_5", "N/mm^1.5"],
  ["_n_per_mm", "N/mm"],
  ["_per_mm", "1/mm"],
  ["_per_mpa", "1/MPa"],
  ["_mm2_s", "mm²/s"],
  ["_mm_s", "mm/s"],
  ["_rad_s", "rad/s"],
  ["_mpa_s", "MPa·s"],
  ["_kg_m3", "kg/m³"],
  ["_mm2", "mm²"],
  ["_mm", "mm"],
  ["_mpa", "MPa"],
  ["_nmm", "N·mm"],
  ["_n", "N"],
  ["_deg", "°"],
  ["_rad", "rad"],
  ["_rpm", "r/min"],
  ["_w", "W"],
  ["_kg", "kg"],
  ["_c", "°C"],
  ["_s", "s"],
  ["_mrev", "10⁶ rev"],
];

export function unitOf(key) {
  for (const [suffix, unit] of SUFFIX_UNITS) if (key.endsWith(suffix)) return unit;
  return "";
}

// A report key as a quantity's name: its unit suffix off (the unit has its own column).
function nameOf(path) {
  const parts = path.split(".");
  const last = parts.pop();
  const suffix = SUFFIX_UNITS.find(([s]) => last.endsWith(s) && last.length > s.length);
  const stem = suffix ? last.slice(0, -suffix[0].length) : last;
  return [...parts, stem].map((p) => p.replaceAll("_", " ")).join(": ");
}

export function fmt(v) {
  if (v === null || v === undefined) return "–";
  if (typeof v === "number") {
    if (v === 0) return "0";
    const a = Math.abs(v);
    if (a >= 1e-3 && a < 1e6) return Number(v.toPrecision(6)).toString();
    return v.toExponential(4);
  }
  if (Array.isArray(v)) return v.map(fmt).join(", ");
  return String(v);
}

/**
 * A table of the report's scalar entries (and short numeric lists), `keys` in this order
 * or every scalar key; the unit from the key's suffix. Each value cell carries
 * `data-key` so that tests and people can find it.
 */
export function resultTable(el, report, keys) {
  const table = document.createElement("table");
  table.className = "results";
  const head = table.createTHead().insertRow();
  for (const h of ["quantity", "value", "unit"]) {
    const th = document.createElement("th");
    th.textContent = h;
    head.append(th);
  }
  const body = table.createTBody();
  const ks = keys || Object.keys(report);
  for (const k of ks) {
    const v = getPath(report, k);
    if (v === undefined) continue;
    if (typeof v === "object" && v !== null && !(Array.isArray(v) && v.length <= 5 && v.every((x) => typeof x !== "object"))) continue;
    const row = body.insertRow();
    row.insertCell().textContent = nameOf(k);
    const c = row.insertCell();
    c.textContent = fmt(v);
    c.dataset.key = k;
    c.className = "num";
    row.insertCell().textContent = unitOf(k.split(".").pop());
  }
  el.replaceChildren(table);
}

// ---------------------------------------------------------------- plots

const COLOURS = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#17becf"];

/**
 * A line plot (uPlot) in `el`: `x` the shared abscissa, `series` [{label, y, dash}], axis
 * labels with their units. Returns the uPlot instance; the element gets PNG and SVG buttons.
 */
export function linePlot(el, { title, x, xlabel, ylabel, series, logx = false }) {
  el.replaceChildren();
  el.classList.add("plot");
  const width = Math.max(320, Math.min(el.clientWidth || 600, 900));
  const opts = {
    title,
    width,
    height: 300,
    scales: { x: { time: false, distr: logx ? 3 : 1 } },
    legend: { live: false },
    axes: [
      { label: xlabel, stroke: "#222" },
      { label: ylabel, stroke: "#222", size: 70 },
    ],
    series: [
      { label: xlabel },
      ...series.map((s, i) => ({
        label: s.label,
        stroke: s.colour || COLOURS[i % COLOURS.length],
        width: 2,
        dash: s.dash,
        points: { show: s.points === true },
        value: (u, v) => (v === null || v === undefined ? "–" : fmt(v)),
      })),
    ],
  };
  const data = [x, ...series.map((s) => s.y.map((v) => (typeof v === "number" && Number.isFinite(v) ? v : null)))];
  const u = new uPlot(opts, data, el);
  const plotData = { title, x, xlabel, ylabel, series, logx };
  exportButtons(el, title, {
    png: () => canvasPng(u, title),
    svg: () => lineSvg(plotData, width, 300),
  });
  return u;
}

function canvasPng(u, title) {
  const src = u.ctx.canvas;
  const pad = 30;
  const c = document.createElement("canvas");
  c.width = src.width;
  c.height = src.height + pad * devicePixelRatio;
  const ctx = c.getContext("2d");
  ctx.fillStyle = "#fff";
  ctx.fillRect(0, 0, c.width, c.height);
  ctx.fillStyle = "#000";
  ctx.font = `${14 * devicePixelRatio}px sans-serif`;
  ctx.fillText(title || "", 10 * devicePixelRatio, 20 * devicePixelRatio);
  ctx.drawImage(src, 0, pad * devicePixelRatio);
  // The legend (series names) under the title's line, right-aligned.
  return new Promise((res) => c.toBlob(res, "image/png"));
}

// An SVG of the same curves, for documents (uPlot draws on a canvas only).
function lineSvg({ title, x, xlabel, ylabel, series, logx }, width, height) {
  const m = { l: 70, r: 20, t: 40, b: 50 };
  const fx = logx ? (v) => Math.log10(v) : (v) => v;
  const xs = x.map(fx);
  const ys = series.flatMap((s) => s.y).filter((v) => typeof v === "number" && Number.isFinite(v));
  const x0 = Math.min(...xs), x1 = Math.max(...xs);
  let y0 = Math.min(0, ...ys), y1 = Math.max(...ys);
  if (y1 === y0) y1 = y0 + 1;
  const px = (v) => m.l + ((fx(v) - x0) / (x1 - x0 || 1)) * (width - m.l - m.r);
  const py = (v) => height - m.b - ((v - y0) / (y1 - y0)) * (height - m.t - m.b);
  const esc = (s) => String(s).replace(/[<&>]/g, (c) => ({ "<": "&lt;", "&": "&amp;", ">": "&gt;" })[c]);
  let s = `<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${height}" font-family="sans-serif" font-size="12">`;
  s += `<rect width="100%" height="100%" fill="white"/><text x="${m.l}" y="20" font-size="14">${esc(title || "")}</text>`;
  s += `<rect x="${m.l}" y="${m.t}" width="${width - m.l - m.r}" height="${height - m.t - m.b}" fill="none" stroke="#444"/>`;
  for (let i = 0; i <= 4; i++) {
    const yv = y0 + ((y1 - y0) * i) / 4;
    s += `<text x="${m.l - 5}" y="${py(yv) + 4}" text-anchor="end">${esc(fmt(yv))}</text>`;
    const xv = logx ? 10 ** (x0 + ((x1 - x0) * i) / 4) : x0 + ((x1 - x0) * i) / 4;
    s += `<text x="${px(xv)}" y="${height - m.b + 16}" text-anchor="middle">${esc(fmt(xv))}</text>`;
  }
  s += `<text x="${(width + m.l) / 2}" y="${height - 10}" text-anchor="middle">${esc(xlabel)}</text>`;
  s += `<text transform="translate(15 ${(height - m.b + m.t) / 2}) rotate(-90)" text-anchor="middle">${esc(ylabel)}</text>`;
  series.forEach((ser, i) => {
    const col = ser.colour || COLOURS[i % COLOURS.length];
    let d = "";
    let pen = false;
    ser.y.forEach((v, k) => {
      if (typeof v !== "number" || !Number.isFinite(v)) {
        pen = false;
        return;
      }
      d += `${pen ? "L" : "M"}${px(x[k]).toFixed(1)},${py(v).toFixed(1)}`;
      pen = true;
    });
    const dash = ser.dash ? ` stroke-dasharray="${ser.dash.join(" ")}"` : "";
    s += `<path d="${d}" fill="none" stroke="${col}" stroke-width="2"${dash}/>`;
    s += `<text x="${width - m.r - 5}" y="${m.t + 15 + 15 * i}" text-anchor="end" fill="${col}">${esc(ser.label)}</text>`;
  });
  return new Blob([s + "</svg>"], { type: "image/svg+xml" });
}

/** PNG and SVG buttons under a plot; `png()` and `svg()` give Blobs (or promises of them). */
export function exportButtons(el, title, { png, svg }) {
  const bar = document.createElement("div");
  bar.className = "plot-export noprint";
  const stem = (title || "plot").toLowerCase().replace(/[^a-z0-9]+/g, "_").replace(/^_|_$/g, "");
  for (const [label, make, ext] of [["PNG", png, "png"], ["SVG", svg, "svg"]]) {
    const b = document.createElement("button");
    b.type = "button";
    b.textContent = label;
    b.addEventListener("click", async () => download(await make(), `${stem}.${ext}`));
    bar.append(b);
  }
  el.append(bar);
}

/** A Plotly figure in `el` with the PNG/SVG export buttons; Plotly is the global script. */
export async function plotly(el, data, layout, title) {
  el.replaceChildren();
  el.classList.add("plot");
  const div = document.createElement("div");
  el.append(div);
  const width = Math.max(320, Math.min(el.clientWidth || 600, 900));
  await window.Plotly.newPlot(
    div,
    data,
    { width, height: 360, margin: { l: 70, r: 20, t: 40, b: 55 }, title: { text: title, font: { size: 14 } }, ...layout },
    { displaylogo: false, displayModeBar: false, responsive: false },
  );
  const stem = (title || "plot").toLowerCase().replace(/[^a-z0-9]+/g, "_").replace(/^_|_$/g, "");
  const img = async (format) => {
    const url = await window.Plotly.toImage(div, { format, width, height: 360 });
    const res = await fetch(url);
    return res.blob();
  };
  exportButtons(el, stem, { png: () => img("png"), svg: () => img("svg") });
  return div;
}

/** Disables a button while `task` runs. */
export async function busy(button, task) {
  button.disabled = true;
  try {
    return await task();
  } finally {
    button.disabled = false;
  }
}

// ---------------------------------------------------------------- a page

/** Turns the form's labels matching `selector` on or off: off ones are hidden and left out of the case. */
export function toggle(form, selector, on) {
  for (const el of form.querySelectorAll(selector)) {
    el.classList.toggle("hidden", !on);
    if (on) delete el.dataset.off;
    else el.dataset.off = "1";
  }
}

/**
 * The `input.model` check boxes and the hidden `#models` input they write: returns the
 * page's `onSet`, which sets the boxes from a newly loaded case (or `defaults`) and writes
 * the list.
 */
export function modelBoxes(defaults) {
  const input = document.getElementById("models");
  const boxes = [...document.querySelectorAll("input.model")];
  let loaded = null;
  return (c) => {
    if (c !== loaded) {
      loaded = c;
      const models = c.models || defaults;
      for (const b of boxes) b.checked = models.includes(b.value);
    }
    input.value = boxes.filter((b) => b.checked).map((b) => b.value).join(",");
  };
}

const FILE_BAR = `<select class="examples" id="examples"><option value="">example …</option></select>
<label class="upload"><input type="file" accept=".toml,text/plain"><span>Load TOML</span></label>
<button type="button" class="save-toml">Save TOML</button>
<button type="button" class="save-json">JSON</button>
<button type="button" class="save-csv">CSV</button>`;

/**
 * Wires a page whose form is `#form`, status line `#status`, file bar `#filebar` and Solve
 * button `#run`: `solve(case)` runs the case and draws it, resolving to the status text;
 * `onSet(case)` after the form is filled (and on every change of the form), `report()` and
 * `csv()` for the downloads, `start()` the first case. Input errors go beside their
 * field, a cancelled job into the status line.
 */
export async function page({ active, methods, stem, solve, onSet, report, csv, start }) {
  frame(active);
  const form = document.getElementById("form");
  const status = document.getElementById("status");
  let base = {};
  const sync = () => onSet && onSet(base);
  const setCase = (c) => {
    base = c;
    fillForm(form, c);
    sync();
  };
  form.addEventListener("change", sync);
  form.addEventListener("submit", async (ev) => {
    ev.preventDefault();
    clearErrors(form);
    sync();
    await busy(document.getElementById("run"), async () => {
      try {
        setStatus(status, await solve(readCase(form, base), status), "done");
      } catch (err) {
        if (err.message === "cancelled") setStatus(status, "cancelled", "error");
        else showError(form, status, err);
      }
    });
  });
  const bar = document.getElementById("filebar");
  bar.innerHTML = FILE_BAR;
  await fileBar(bar, {
    methods,
    get: () => readCase(form, base),
    set: setCase,
    report,
    csv,
    name: () => (document.getElementById("name").value || stem).replace(/[^A-Za-z0-9_-]+/g, "_"),
    status,
  });
  try {
    const first = await start();
    if (first) setCase(first.case);
    if (first && first.example) bar.querySelector("select.examples").value = first.example;
  } catch (err) {
    setStatus(status, err.message, "error");
  }
  return { form, status };
}
