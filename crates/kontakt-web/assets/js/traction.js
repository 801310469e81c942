// The traction page: a `method = "traction"` case, every model's curve on one plot.
import {
  frame, readCase, fillForm, clearErrors, showError, setStatus, showWarnings, runCase,
  fileBar, resultTable, linePlot, toCsv, busy, exampleCase,
} from "./common.js";

frame("traction.html");
const form = document.getElementById("form");
const status = document.getElementById("status");
const modelsInput = document.getElementById("models");
const boxes = [...form.querySelectorAll("input.model")];
let base = {};
let last = null;

// The check boxes write the `models` list.
function syncModels() {
  modelsInput.value = boxes.filter((b) => b.checked).map((b) => b.value).join(",");
}
for (const b of boxes) b.addEventListener("change", syncModels);

function setCase(c) {
  base = c;
  fillForm(form, c);
  const models = c.models || ["carter", "kalker_linear", "fastsim"];
  for (const b of boxes) b.checked = models.includes(b.value);
  syncModels();
}

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

form.addEventListener("submit", async (ev) => {
  ev.preventDefault();
  clearErrors(form);
  syncModels();
  await busy(document.getElementById("run"), async () => {
    try {
      const c = readCase(form, base);
      const long = (c.models || []).includes("kalker_exact");
      const { report, warnings } = await runCase(c, { long, status });
      show(report, warnings);
      setStatus(status, `solved: ${report.curves.length} curves`, "done");
    } catch (err) {
      if (err.message === "cancelled") setStatus(status, "cancelled", "error");
      else showError(form, status, err);
    }
  });
});

(async () => {
  await fileBar(document.getElementById("filebar"), {
    methods: ["traction"],
    get: () => readCase(form, base),
    set: setCase,
    report: () => last,
    csv,
    name: () => (document.getElementById("name").value || "traction").replace(/[^A-Za-z0-9_-]+/g, "_"),
    status,
  });
  try {
    setCase(await exampleCase("traction_ball_all_models"));
  } catch (err) {
    setStatus(status, err.message, "error");
  }
})();
