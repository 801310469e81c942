// The roller end / rib page: a `method = "friction"` case (the rib friction against speed
// for each pressure model), then the same pairing as a PimP and a half-space case at the
// most loaded roller's rib load, their pressure zones beside Hertz's ellipse.
import { page, modelBoxes, toggle, showWarnings, linePlot, plotly, rowsCsv, fmt, runCase, exampleCase } from "./common.js";

let last = null;

// The pressure models' boxes; one's own face and rib only without a built-in pairing.
const syncModels = modelBoxes(["pimp"]);
function syncForm(c) {
  syncModels(c);
  toggle(document.getElementById("form"), "label.own", document.getElementById("pairing").value === "");
}

const STYLE = { hertz: undefined, pimp: [6, 4], halfspace: [2, 3] };

function curves(r, key) {
  const models = [...new Set(r.rows.map((x) => x.model))];
  const speeds = [...new Set(r.rows.map((x) => x.speed_rpm))];
  return {
    x: speeds,
    series: models.map((m) => ({
      label: m,
      y: speeds.map((n) => (r.rows.find((x) => x.model === m && x.speed_rpm === n) || {})[key]),
      dash: STYLE[m],
      points: true,
    })),
  };
}

// The outline of a zone from its field: the cells above 0 (a contour at a tiny pressure).
function mapTraces(name, field, report, showScale) {
  const t = [];
  if (field && field.values) {
    const [nx, ny] = field.cells || report.grid.cells;
    const [x0, x1] = field.x_range_mm || report.grid.x_range_mm;
    const [y0, y1] = field.y_range_mm || report.grid.y_range_mm;
    const dx = (x1 - x0) / nx, dy = (y1 - y0) / ny;
    const xs = Array.from({ length: nx }, (_, i) => x0 + (i + 0.5) * dx);
    const ys = Array.from({ length: ny }, (_, j) => y0 + (j + 0.5) * dy);
    const z = ys.map((_, j) => field.values.slice(j * nx, (j + 1) * nx));
    t.push({ type: "heatmap", x: xs, y: ys, z, colorscale: "Viridis", showscale: showScale, colorbar: { title: { text: "MPa" } }, name: `${name} pressure` });
    t.push({ type: "contour", x: xs, y: ys, z, contours: { start: 1e-9, end: 1e-9, size: 1, coloring: "none" }, line: { color: "black", width: 2 }, showscale: false, name: `${name} outline` });
  } else if (report.extents_mm) {
    const [[xa, xb], [ya, yb]] = report.extents_mm;
    t.push({ type: "scatter", mode: "lines", x: [xa, xb, xb, xa, xa], y: [ya, ya, yb, yb, ya], line: { color: "black" }, name: `${name} zone extents` });
  }
  if (report.hertz && report.hertz.semi_axes_mm) {
    const [a, b] = report.hertz.semi_axes_mm;
    const th = Array.from({ length: 121 }, (_, i) => (2 * Math.PI * i) / 120);
    const c = report.centroid_mm || [0, 0];
    t.push({ type: "scatter", mode: "lines", x: th.map((s) => a * Math.cos(s)), y: th.map((s) => c[1] + b * Math.sin(s)), line: { color: "magenta", dash: "dot" }, name: "Hertz ellipse" });
  }
  return t;
}

async function show(r, warnings, maps) {
  last = r;
  showWarnings(document.getElementById("warnings"), r.warnings || [], warnings, ...maps.map((m) => m.report.warnings || []));
  const tq = curves(r, "bearing_drag_torque_nmm");
  linePlot(document.getElementById("plot-torque"), {
    title: `Rib friction torque of the bearing (${r.rollers} rollers)`,
    x: tq.x, xlabel: "inner ring speed [r/min]", ylabel: "rib torque [N·mm]", series: tq.series, logx: true,
  });
  const mu = curves(r, "coefficient");
  linePlot(document.getElementById("plot-coefficient"), {
    title: "Rib friction coefficient",
    x: mu.x, xlabel: "inner ring speed [r/min]", ylabel: "coefficient μ [–]", series: mu.series, logx: true,
  });
  // Hertz, PimP and the half-space solver at one load: a table and the maps.
  const rows = [];
  const h = maps[0] && maps[0].report.hertz;
  if (h) rows.push({ model: "Hertz", max: h.max_pressure_mpa, area: h.contact_area_mm2, approach: h.approach_mm });
  for (const m of maps) rows.push({ model: m.label, max: m.report.max_pressure_mpa, area: m.report.contact_area_mm2, approach: m.report.approach_mm });
  const table = document.createElement("table");
  table.className = "results";
  table.innerHTML = "<thead><tr><th>model</th><th>max. pressure [MPa]</th><th>contact area [mm²]</th><th>approach [mm]</th></tr></thead>";
  const tb = table.createTBody();
  for (const x of rows) {
    const tr = tb.insertRow();
    tr.insertCell().textContent = x.model;
    for (const [k, v] of [["max_pressure_mpa", x.max], ["contact_area_mm2", x.area], ["approach_mm", x.approach]]) {
      const c = tr.insertCell();
      c.className = "num";
      c.dataset.key = `${x.model}.${k}`;
      c.textContent = fmt(v);
    }
  }
  const cmp = document.getElementById("compare");
  const p = document.createElement("p");
  p.textContent = `Rib load ${fmt(maps.length ? maps[0].report.force_n : null)} N (the most loaded roller's at the lowest speed, ${r.rows[0].model} model).`;
  cmp.replaceChildren(p, table);
  const holder = document.getElementById("maps");
  holder.replaceChildren();
  // Every cell first, then the plots: each sizes itself to its cell of the grid.
  const cells = maps.map(() => holder.appendChild(document.createElement("div")));
  for (const [i, m] of maps.entries()) {
    const div = cells[i];
    const field = (m.fields || []).find((f) => f.name === "pressure");
    await plotly(div, mapTraces(m.label, field, m.report, true), {
      xaxis: { title: { text: "along the rib (circumferential) [mm]" } },
      yaxis: { title: { text: "across the rib [mm]" }, scaleanchor: "x" },
      legend: { orientation: "h", y: -0.25 },
    }, `${m.label}: pressure map, max. ${fmt(m.report.max_pressure_mpa)} MPa`);
  }
}

function csv() {
  return rowsCsv(last.rows);
}

page({
  active: "rib.html",
  methods: ["friction"],
  stem: "rib",
  onSet: syncForm,
  solve: async (c, status) => {
    const long = (c.models || []).includes("halfspace");
    const { report, warnings } = await runCase(c, { long, status });
    // The same pairing at the most loaded roller's rib load, PimP and half-space.
    const load = report.rows[0].rib_load_n;
    const steel = { e_mpa: 210000.0, nu: 0.3 };
    const pair = { geometry: c.geometry, body1: steel, body2: steel, load: { force_n: load } };
    const pimp = await runCase({ method: "pimp", ...pair, pimp: { mode: "corrected" } }, { status });
    const bem = await runCase({ method: "bem", ...pair }, { long: true, status });
    await show(report, warnings, [{ label: "PimP", ...pimp }, { label: "half-space", ...bem }]);
    return `solved: ${report.rows.length} rows`;
  },
  report: () => last,
  csv,
  start: async () => ({ case: await exampleCase("rib_friction"), example: "rib_friction" }),
});
