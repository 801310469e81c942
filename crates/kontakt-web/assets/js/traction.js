// The traction page: a `method = "traction"` case, every model's curve on one plot.
import { page, modelBoxes, showWarnings, runCase, resultTable, linePlot, toCsv, exampleCase } from "./common.js";

let last = null;

const KEYS = [
  "force_n", "mu", "semi_axes_mm", "max_pressure_mpa", "e_star_mpa", "shear_modulus_mpa",
  "poisson_ratio", "creep_coefficients.c11", "creep_coefficients.c22", "creep_coefficients.c23",
  "kalker_saturation_creepage", "carter_saturation_creepage", "difference_parameter", "asperities",
];

function show(r, warnings) {
  last = r;
  showWarnings(document.getElementById("warnings"), r.warnings || [], warnings);
  linePlot(document.getElementById("plot-traction"), {
    title: `Traction curves, ${r.name || ""}`,
    x: r.creepage,
    xlabel: "creepage (slide-to-roll ratio) [–]",
    ylabel: "F_T / (μ F_N) [–]",
    series: r.curves.map((c) => ({
      label: c.model,
      // The linear theory is unclipped in the report; drawn up to 1 like the CLI's plot.
      y: c.model === "kalker_linear" ? c.normalized_force.map((v) => (v <= 1 ? v : null)) : c.normalized_force,
      dash: c.model === "kalker_linear" ? [6, 4] : undefined,
    })),
  });
  resultTable(document.getElementById("results"), r, KEYS);
}

function csv() {
  return toCsv([["creepage", last.creepage], ...last.curves.map((c) => [`${c.model}_ft_over_mu_fn`, c.normalized_force])]);
}

page({
  active: "traction.html",
  methods: ["traction"],
  stem: "traction",
  onSet: modelBoxes(["carter", "kalker_linear", "fastsim"]),
  solve: async (c, status) => {
    const long = (c.models || []).includes("kalker_exact");
    const { report, warnings } = await runCase(c, { long, status });
    show(report, warnings);
    return `solved: ${report.curves.length} curves`;
  },
  report: () => last,
  csv,
  start: async () => ({ case: await exampleCase("traction_ball_all_models"), example: "traction_ball_all_models" }),
});
