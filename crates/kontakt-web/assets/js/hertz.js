// The Hertz page: the form is a `method = "hertz"` case; the report is `kontakt solve --json`'s.
import { page, toggle, showWarnings, runCase, resultTable, linePlot, toCsv } from "./common.js";

let last = null;
let lastStress = null;

const DEFAULT = {
  name: "ball on flat",
  method: "hertz",
  contact: { kind: "point" },
  body1: { radii_mm: [6.35, 6.35], e_mpa: 210000.0, nu: 0.3 },
  body2: { radii_mm: ["inf", "inf"], e_mpa: 210000.0, nu: 0.3 },
  load: { force_n: 100.0 },
  yield: { stress_mpa: 1500.0, criterion: "von_mises" },
};

const KEYS = [
  "kind", "force_n", "line_load_n_per_mm", "approach_mm", "max_pressure_mpa", "mean_pressure_mpa",
  "semi_axes_mm", "axis_ratio", "orientation_deg", "contact_area_mm2", "stiffness_n_per_mm",
  "e_star_mpa", "relative_curvature_per_mm", "max_shear_stress_mpa", "max_shear_depth_mm",
  "max_von_mises_stress_mpa", "max_von_mises_depth_mm", "first_yield_load_n",
  "first_yield_line_load_n_per_mm", "first_yield_max_pressure_mpa", "yield_pressure_margin",
];

// The Hertz pressure p0 sqrt(1 - (s/c)^2) along each semi-axis c of the report (the
// distribution the report's p0 and semi-axes define; no other model here).
function profile(report) {
  const [a, b] = report.semi_axes_mm;
  const p0 = report.max_pressure_mpa;
  const line = report.kind === "line";
  const c = line ? b : Math.max(a, b);
  const n = 201;
  const s = [];
  for (let i = 0; i < n; i++) s.push(-1.2 * c + (2.4 * c * i) / (n - 1));
  const p = (semi) => s.map((x) => (Math.abs(x) < semi ? p0 * Math.sqrt(1 - (x / semi) ** 2) : 0));
  const series = line
    ? [{ label: "p across the line (half-width b)", y: p(b) }]
    : [{ label: "p along x (semi-axis a)", y: p(a) }, { label: "p along y (semi-axis b)", y: p(b), dash: [6, 4] }];
  return { s, series };
}

function show(report, warnings, axisStress) {
  last = report;
  showWarnings(document.getElementById("warnings"), report.warnings || [], warnings);
  resultTable(document.getElementById("results"), report, KEYS);
  const { s, series } = profile(report);
  linePlot(document.getElementById("plot-pressure"), {
    title: "Contact pressure",
    x: s,
    xlabel: "position from the centre [mm]",
    ylabel: "pressure [MPa]",
    series,
  });
  // The stresses on the load axis (the server's, from kontakt::hertz::subsurface).
  const el = document.getElementById("plot-stress");
  lastStress = axisStress || null;
  if (axisStress) {
    const series = [];
    for (const b of axisStress.bodies) {
      const tag = axisStress.bodies.length > 1 ? ` (body ${b.body}, ν = ${b.nu})` : "";
      series.push({ label: `τ max (Tresca)${tag}`, y: b.max_shear_mpa });
      series.push({ label: `von Mises${tag}`, y: b.von_mises_mpa });
      if (b.body === 1) {
        series.push({ label: "σx", y: b.sigma_x_mpa, dash: [5, 4] });
        series.push({ label: "σy", y: b.sigma_y_mpa, dash: [5, 4] });
        series.push({ label: "σz", y: b.sigma_z_mpa, dash: [2, 3] });
      }
    }
    linePlot(el, {
      title: "Stresses along the load axis below the centre",
      x: axisStress.depth_mm,
      xlabel: "depth z [mm]",
      ylabel: "stress [MPa] (tension > 0)",
      series,
    });
  } else {
    el.replaceChildren();
  }
}

function csv() {
  const { s, series } = profile(last);
  let text = toCsv([["position_mm", s], ...series.map((x) => [x.label.startsWith("p along y") ? "pressure_y_mpa" : "pressure_x_mpa", x.y])]);
  if (lastStress) {
    const cols = [["depth_mm", lastStress.depth_mm]];
    for (const b of lastStress.bodies) {
      for (const k of ["sigma_x_mpa", "sigma_y_mpa", "sigma_z_mpa", "max_shear_mpa", "von_mises_mpa"]) {
        cols.push([`body${b.body}_${k}`, b[k]]);
      }
    }
    text += "\n" + toCsv(cols);
  }
  return text;
}

page({
  active: "hertz.html",
  methods: ["hertz"],
  stem: "hertz",
  // A line contact has one radius per body: the second inputs are off.
  onSet: () => toggle(document.getElementById("form"), ".point-only", document.getElementById("kind").value !== "line"),
  solve: async (c, status) => {
    const { report, warnings, axisStress } = await runCase(c, { status });
    show(report, warnings, axisStress);
    return `solved: p0 = ${report.max_pressure_mpa.toFixed(1)} MPa`;
  },
  report: () => last,
  csv,
  start: async () => ({ case: DEFAULT }),
});
