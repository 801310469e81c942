// The bearing page: a `method = "bearing"` case (a roller or ball bearing), its load
// distribution, stiffness and, with [operating] and [lubricant], the friction torque.
import { page, toggle, showWarnings, runCase, resultTable, linePlot, plotly, rowsCsv, fmt, exampleCase, examples } from "./common.js";

let last = null;

const BALL = ["deep_groove_ball", "angular_contact_ball"];

// Inputs that do not apply to the bearing type are off (not written into the case).
function syncType() {
  const form = document.getElementById("form");
  const t = document.getElementById("type").value;
  const ball = BALL.includes(t);
  toggle(form, "label.roller", !ball);
  toggle(form, "label.ball", ball);
  toggle(form, "label.tapered", t === "tapered");
  toggle(form, "label.acbb", t === "angular_contact_ball");
}

// The slow models (docs/bearing-model.md §12, §15.8) go through a job with a Cancel button.
function isLong(c) {
  const b = c.bearing || {};
  return b.slice_model === "coupled" || (b.rib_contact && b.rib_contact.model === "pimp");
}

const KEYS = [
  "bearing_type", "max_roller_load_n", "max_ball_load_n", "max_load_per_length_n_per_mm",
  "max_inner_pressure_mpa", "max_outer_pressure_mpa", "max_rib_pressure_mpa", "load_zone_epsilon",
  "displacement_mm", "tilt_rad", "force_n", "moment_nmm", "rating.static_safety_from_pressure",
  "rating.l10_mrev", "solver.iterations", "friction.total_nmm", "friction.power_w",
  "friction.coefficient", "friction.viscosity_mm2_s", "friction.min_lambda", "friction.catalogue.skf_total_nmm",
];

function elements(r) {
  if (r.roller_loads) {
    return r.roller_loads.map((e) => ({ az: e.azimuth_deg, inner: e.inner_load_n, outer: e.outer_load_n, rib: e.rib_load_n }));
  }
  return (r.ball_loads || []).map((e) => ({ az: e.azimuth_deg, inner: e.inner_load_n ?? e.load_n, outer: e.outer_load_n ?? e.load_n }));
}

async function show(r, warnings) {
  last = r;
  showWarnings(document.getElementById("warnings"), r.warnings || [], (r.friction && r.friction.warnings) || [], warnings);
  resultTable(document.getElementById("results"), r, KEYS);
  // Stiffness matrix with its units per entry.
  const st = document.getElementById("stiffness");
  st.replaceChildren();
  if (r.stiffness_matrix) {
    const t = document.createElement("table");
    t.className = "results";
    const h = t.createTHead().insertRow();
    h.insertCell().textContent = "";
    for (const d of r.stiffness_dofs) h.insertCell().textContent = d;
    const b = t.createTBody();
    r.stiffness_matrix.forEach((row, i) => {
      const tr = b.insertRow();
      tr.insertCell().textContent = r.stiffness_dofs[i];
      row.forEach((v, j) => {
        const c = tr.insertCell();
        c.className = "num";
        const small = Math.abs(v) < 1e-9 * Math.max(Math.abs(r.stiffness_matrix[i][i]), Math.abs(r.stiffness_matrix[j][j]), 1);
        c.textContent = small ? "0" : Number(v.toPrecision(4)).toExponential();
        const unit = document.createElement("span");
        unit.className = "unit";
        unit.textContent = ` ${r.stiffness_units ? r.stiffness_units[i][j].replace("*", "·") : ""}`;
        c.append(unit);
      });
    });
    st.append(t);
  }
  // The load distribution: a polar diagram of the element loads (Plotly barpolar).
  const el = elements(r);
  const kind = r.roller_loads ? "roller" : "ball";
  await plotly(
    document.getElementById("plot-loads"),
    [
      { type: "barpolar", theta: el.map((e) => e.az), r: el.map((e) => e.outer), name: `${kind} load, outer raceway [N]`, marker: { color: "#1f77b4" }, width: el.map(() => 360 / Math.max(el.length, 1) * 0.6) },
      ...(el.some((e) => e.rib) ? [{ type: "barpolar", theta: el.map((e) => e.az), r: el.map((e) => e.rib), name: "rib load [N]", marker: { color: "#d62728" }, width: el.map(() => 360 / Math.max(el.length, 1) * 0.3) }] : []),
    ],
    { polar: { angularaxis: { direction: "counterclockwise", rotation: 0, ticksuffix: "°" }, radialaxis: { angle: 90, tickangle: 90, ticksuffix: " N", tickfont: { size: 10 } } }, legend: { orientation: "h", y: -0.1 } },
    `Load distribution (${kind} loads [N] against azimuth [°])`,
  );
  // The pressure along the most loaded roller.
  const m = r.most_loaded_roller;
  const sl = document.getElementById("plot-slices");
  if (m && m.position_mm) {
    linePlot(sl, {
      title: `Pressure along roller ${m.roller} (most loaded)`,
      x: m.position_mm,
      xlabel: "position along the roller [mm]",
      ylabel: "pressure [MPa]",
      series: [
        { label: "inner raceway (cone) [MPa]", y: m.inner_pressure_mpa || [] },
        { label: "outer raceway (cup) [MPa]", y: m.outer_pressure_mpa || [], dash: [6, 4] },
      ],
    });
  } else if (r.ball_loads) {
    await plotly(
      sl,
      [
        { type: "bar", x: r.ball_loads.map((b) => b.azimuth_deg), y: r.ball_loads.map((b) => b.inner_max_pressure_mpa), name: "inner race [MPa]" },
        { type: "bar", x: r.ball_loads.map((b) => b.azimuth_deg), y: r.ball_loads.map((b) => b.outer_max_pressure_mpa), name: "outer race [MPa]" },
      ],
      { xaxis: { title: { text: "ball azimuth [°]" } }, yaxis: { title: { text: "max. Hertz pressure [MPa]" } }, legend: { orientation: "h", y: -0.25 } },
      "Contact pressure of every ball",
    );
  } else {
    sl.replaceChildren();
  }
  // Friction torque and its breakdown beside SKF (2004).
  const f = r.friction;
  const tq = document.getElementById("plot-torque");
  const sw = document.getElementById("plot-sweep");
  if (f) {
    const ball = !!r.ball_loads;
    const parts = [
      [ball ? "inner race rolling" : "cone rolling", f.cone_rolling_nmm, 0],
      [ball ? "inner race sliding" : "cone sliding", f.cone_sliding_nmm, 0],
      [ball ? "outer race rolling" : "cup rolling", f.cup_rolling_nmm, 0],
      [ball ? "outer race sliding" : "cup sliding", f.cup_sliding_nmm, 0],
      ["rib", f.rib_nmm, 0],
      ["drag", f.drag_nmm, 0],
    ];
    const c = f.catalogue || {};
    const skf = [["SKF rolling", c.skf_rolling_nmm], ["SKF sliding", c.skf_sliding_nmm], ["SKF drag", c.skf_drag_nmm]];
    const cols = ["#1f77b4", "#aec7e8", "#2ca02c", "#98df8a", "#d62728", "#7f7f7f"];
    const traces = parts.map(([name, v], i) => ({ type: "bar", name: `${name}`, x: ["kontakt (contacts)"], y: [v || 0], marker: { color: cols[i] } }));
    if (c.skf_total_nmm !== undefined) {
      skf.forEach(([name, v], i) => traces.push({ type: "bar", name, x: ["SKF (2004)"], y: [v || 0], marker: { color: ["#ff7f0e", "#ffbb78", "#c5b0d5"][i] } }));
    }
    if (c.aihara_rolling_nmm !== undefined && c.aihara_rolling_nmm !== null) {
      traces.push({ type: "bar", name: "Aihara rolling", x: ["Aihara (1987)"], y: [c.aihara_rolling_nmm], marker: { color: "#8c564b" } });
    }
    await plotly(tq, traces, { barmode: "stack", yaxis: { title: { text: "friction torque [N·mm]" } }, legend: { orientation: "v" } },
      `Friction torque at ${fmt(f.inner_rpm)} r/min: ${fmt(f.total_nmm)} N·mm`);
    if (f.speed_sweep && f.speed_sweep.length > 1) {
      const s = f.speed_sweep;
      linePlot(sw, {
        title: "Friction torque against speed",
        x: s.map((p) => p.inner_rpm),
        xlabel: "inner ring speed [r/min]",
        ylabel: "torque [N·mm]",
        series: [
          { label: "total [N·mm]", y: s.map((p) => p.total_nmm) },
          { label: `${ball ? "inner race" : "cone"} [N·mm]`, y: s.map((p) => p.cone_nmm), dash: [4, 3] },
          { label: `${ball ? "outer race" : "cup"} [N·mm]`, y: s.map((p) => p.cup_nmm), dash: [4, 3] },
          { label: "rib [N·mm]", y: s.map((p) => p.rib_nmm), dash: [2, 2] },
          { label: "SKF (2004) [N·mm]", y: s.map((p) => p.skf_total_nmm), colour: "#ff7f0e" },
        ],
      });
    } else {
      sw.replaceChildren();
    }
  } else {
    tq.replaceChildren();
    sw.replaceChildren();
  }
}

function csv() {
  const rows = last.roller_loads || last.ball_loads || [];
  let text = rowsCsv(rows);
  if (last.friction && last.friction.speed_sweep && last.friction.speed_sweep.length) {
    text += "\n" + rowsCsv(last.friction.speed_sweep);
  }
  return text;
}

page({
  active: "bearing.html",
  methods: ["bearing"],
  stem: "bearing",
  onSet: syncType,
  solve: async (c, status) => {
    const t0 = performance.now();
    const { report, warnings } = await runCase(c, { long: isLong(c), status });
    await show(report, warnings);
    return `solved in ${((performance.now() - t0) / 1000).toFixed(2)} s`;
  },
  report: () => last,
  csv,
  // Start from the 32008 X with its rib contact and friction torque.
  start: async () => {
    const list = await examples("bearing");
    const first = list.find((e) => e.name.includes("32008x_rib_friction")) || list[0];
    return first ? { case: await exampleCase(first.name), example: first.name } : null;
  },
});
