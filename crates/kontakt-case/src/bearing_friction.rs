//! The friction torque of a roller bearing case (issue 29 §1-2): the optional tables
//! `[operating]` (supply, drag, film options, speed sweep; the ring speeds are the case's
//! one `[speed]` table, `speed.inner_rpm` and `speed.outer_rpm`), `[lubricant]` and `[friction]` (the friction
//! case's own vocabulary, [`crate::friction_case::LubricantSpec`] and
//! [`crate::friction_case::FrictionSpec`]) and `[catalogue]` (envelope, SKF series and Y,
//! Schaeffler factors) of a bearing case, and the report's `friction` section: the torque
//! contact by contact of `kontakt_bearing::friction::torque` beside the catalogue torques.
//! Ball bearings: [`ball`] (the same tables and report, `kontakt_bearing::friction::ball`).
//!
//! Units: r/min in the case (rad/s in the library), mm, N, N·mm, W, °C.
//! Derivations: `docs/bearing-friction.md`.

use crate::friction_case::{FrictionSpec, LubricantSpec};
use kontakt::bearing::{
    PressureModel, RibFrictionModel, RibLubrication, RollerLoads, RollerRibLoad, RollerSet,
};
use kontakt::lubrication::{RollingResistanceModel, viscosity_temperature_slope};
use kontakt::{Error, Result};
use kontakt_bearing::friction::aihara::{
    AiharaBearing, AiharaLubricant, aihara, rib_film_parameter,
};
use kontakt_bearing::friction::crb_rib::CylindricalRibFriction;
use kontakt_bearing::friction::raceway::RacewayLosses;
use kontakt_bearing::friction::schaeffler::m0;
use kontakt_bearing::friction::skf2004::{
    CylindricalSeries, SkfBearing, SkfOptions, TaperedSeries, skf2004,
};
use kontakt_bearing::friction::torque::{
    BearingFriction, BearingFrictionModel, DragModel, FrictionOperating, iso_slice_loads,
    raceway_lubrication,
};
use kontakt_bearing::friction::{Envelope, Lubrication, OperatingPoint, RPM_PER_RAD_S};
use kontakt_bearing::geometry::{RollerBearing, RollerBearingKind};
use kontakt_bearing::roller_equilibrium::RibContactSolver;
use serde::{Deserialize, Serialize};

pub mod ball;
mod checks;
pub(crate) use checks::{oil_level, oil_level_below};
mod sweeps;
pub use sweeps::MAX_SWEEP_POINTS;
pub(crate) use sweeps::load_sweep;

/// The largest ring speed, r/min: `[speed]`'s (`bearing_case::speed::MAX_RING_RPM`, not
/// imported: `bearing_case` imports this module), for the sweep's speeds.
const MAX_RING_RPM: f64 = 100_000.0;

/// `[operating]`: the operating point of the friction torque but for the ring speeds, which
/// are the case's `[speed]` (`speed.inner_rpm`, `speed.outer_rpm`, r/min; at rest: the
/// starting torque).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OperatingSpec {
    /// `"circulating"` (default) or `"oil_bath"`.
    #[serde(default)]
    pub supply: Supply,
    /// Oil bath: static oil level above the lowest point of the outer raceway \[mm\].
    #[serde(default)]
    pub oil_level_mm: Option<f64>,
    /// Drag: `"none"` (default), `"skf"` (SKF 2004 M_drag; needs `catalogue.skf_series`) or
    /// `"schaeffler_m0"` (needs `catalogue.schaeffler_f0`).
    #[serde(default)]
    pub drag: DragSpec,
    /// Rolling-resistance fit: `"biboulet_houpert"` (default) or `"zhou_hoeprich"`.
    #[serde(default)]
    pub rolling_resistance: RollingSpec,
    /// Zhu-Cheng inlet-heating factor on (default true).
    #[serde(default = "yes")]
    pub thermal: bool,
    /// Oil thermal conductivity \[W/(m·K)\] (default 0.134).
    #[serde(default = "conductivity")]
    pub conductivity_w_mk: f64,
    /// Film starvation factor φ_s in (0, 1] (default 1).
    #[serde(default = "one")]
    pub film_starvation: f64,
    /// Biboulet-Houpert degree of starvation S_a (default: fully flooded).
    #[serde(default)]
    pub starvation_degree: Option<f64>,
    /// Inner ring speeds of a speed sweep \[r/min\] on the same load distribution (the one
    /// solved at `[speed]`), the outer ring at `speed.outer_rpm`, each beside the catalogue
    /// models (`friction.speed_sweep`; 1 to 10 000 speeds).
    #[serde(default)]
    pub sweep_inner_rpm: Option<Vec<f64>>,
    /// Axial forces `load.force_n[2]` of a load sweep \[N\], the load distribution
    /// re-solved at each (`friction.axial_load_sweep`; 1 to 10 000 forces; one sweep at a
    /// time).
    #[serde(default)]
    pub sweep_axial_n: Option<Vec<f64>>,
    /// Radial force magnitudes of a load sweep \[N\] (≥ 0) along the case's radial force
    /// (+x when `load.force_n[0..2]` is zero), the load distribution re-solved at each
    /// (`friction.radial_load_sweep`).
    #[serde(default)]
    pub sweep_radial_n: Option<Vec<f64>>,
    /// Oil temperatures of a temperature sweep \[°C\] on the load distribution of `[load]`,
    /// the viscosity from the lubricant's data at each (`friction.temperature_sweep`).
    #[serde(default)]
    pub sweep_temperature_c: Option<Vec<f64>>,
    /// The pressure field of the roller end/rib contacts' friction (a tapered bearing with
    /// `roller_model = "rib_contact"`): `"hertz"` (default), `"pimp"` or `"halfspace"`, the
    /// models of the rib friction case (`kontakt friction`); a cylindrical bearing's ribs
    /// take `"hertz"` only.
    #[serde(default = "hertz")]
    pub rib_pressure: PressureModel,
}

fn hertz() -> PressureModel {
    PressureModel::Hertz
}

/// The `[operating]` of a case without the table: every key at its default.
impl Default for OperatingSpec {
    fn default() -> Self {
        OperatingSpec {
            supply: Supply::default(),
            oil_level_mm: None,
            drag: DragSpec::default(),
            rolling_resistance: RollingSpec::default(),
            thermal: yes(),
            conductivity_w_mk: conductivity(),
            film_starvation: one(),
            starvation_degree: None,
            sweep_inner_rpm: None,
            sweep_axial_n: None,
            sweep_radial_n: None,
            sweep_temperature_c: None,
            rib_pressure: hertz(),
        }
    }
}

fn yes() -> bool {
    true
}
fn one() -> f64 {
    1.0
}
fn conductivity() -> f64 {
    0.134
}

/// Oil supply.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum Supply {
    /// Circulating oil or oil jet.
    #[default]
    Circulating,
    /// Oil bath with `oil_level_mm`.
    OilBath,
}

/// Drag model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum DragSpec {
    /// No drag.
    #[default]
    None,
    /// SKF 2004 drag term.
    Skf,
    /// Schaeffler M0.
    SchaefflerM0,
}

/// Rolling-resistance fit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum RollingSpec {
    /// Biboulet & Houpert (2010).
    #[default]
    BibouletHoupert,
    /// Zhou & Hoeprich (1991).
    ZhouHoeprich,
}

/// `[catalogue]`: what the catalogue models need.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CatalogueSpec {
    /// Bore d \[mm\].
    pub bore_mm: f64,
    /// Outside diameter D \[mm\].
    pub outer_mm: f64,
    /// Width B (tapered: T) \[mm\].
    pub width_mm: f64,
    /// SKF series name (`"320 X"`, `"322"`, ...; cylindrical: `"2"`, `"10"`, ...).
    #[serde(default)]
    pub skf_series: Option<String>,
    /// Axial load factor Y of the product table (tapered).
    #[serde(default)]
    pub y: Option<f64>,
    /// Schaeffler f0.
    #[serde(default)]
    pub schaeffler_f0: Option<f64>,
    /// Schaeffler f1.
    #[serde(default)]
    pub schaeffler_f1: Option<f64>,
    /// Schaeffler P1 \[N\].
    #[serde(default)]
    pub schaeffler_p1_n: Option<f64>,
    /// Basic static load rating C_0 \[N\] (the SKF 2004 deep groove ball bearing's axial
    /// term needs it).
    #[serde(default)]
    pub c0_n: Option<f64>,
    /// SKF drag loss factor V_M, read from SKF's diagram at the oil level's H/d_m (oil bath;
    /// finite, ≥ 0): the SKF 2004 drag term needs it (`operating.drag = "skf"`).
    #[serde(default)]
    pub skf_drag_factor_vm: Option<f64>,
}

/// One roller of the friction table.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrictionRollerRow {
    /// Roller index.
    pub roller: usize,
    /// Azimuth \[deg\].
    pub azimuth_deg: f64,
    /// Cone load \[N\].
    pub cone_load_n: f64,
    /// Cup load \[N\].
    pub cup_load_n: f64,
    /// Rib load \[N\].
    pub rib_load_n: f64,
    /// Roller tilt \[rad\].
    pub tilt_rad: f64,
    /// Rolling-resistance power at the cone \[W\].
    pub cone_rolling_w: f64,
    /// Sliding power at the cone \[W\].
    pub cone_sliding_w: f64,
    /// Rolling-resistance power at the cup \[W\].
    pub cup_rolling_w: f64,
    /// Sliding power at the cup \[W\].
    pub cup_sliding_w: f64,
    /// Rib power \[W\].
    pub rib_w: f64,
    /// The roller's share of the bearing torque \[N·mm\].
    pub torque_nmm: f64,
    /// Largest sliding speed \[mm/s\].
    pub max_sliding_mm_s: f64,
    /// Smallest film parameter Λ (absent without loaded slice or at standstill).
    pub min_lambda: Option<f64>,
}

/// The catalogue torques of the same bearing and operating point \[N·mm\].
#[derive(Debug, Clone, PartialEq, Serialize, Default)]
pub struct CatalogueTorques {
    /// SKF 2004 total (absent without `catalogue.skf_series`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub skf_total_nmm: Option<f64>,
    /// SKF rolling φ_ish φ_rs M_rr.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub skf_rolling_nmm: Option<f64>,
    /// SKF sliding M_sl.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub skf_sliding_nmm: Option<f64>,
    /// SKF drag M_drag.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub skf_drag_nmm: Option<f64>,
    /// Schaeffler M0 + M1 (absent without f0, f1, P1).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub schaeffler_total_nmm: Option<f64>,
    /// Schaeffler M0 (absent without f0).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub schaeffler_m0_nmm: Option<f64>,
    /// Aihara (1987) rolling part M_R (running TRB under pure axial load).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub aihara_rolling_nmm: Option<f64>,
    /// Aihara (1987) total M_R + M_S (with the rib of `roller_model = "rib_contact"`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub aihara_total_nmm: Option<f64>,
}

/// The report's `friction` section.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrictionReport {
    /// Inner ring speed \[r/min\].
    pub inner_rpm: f64,
    /// Outer ring speed \[r/min\].
    pub outer_rpm: f64,
    /// Cage speed \[r/min\] (0 at standstill).
    pub cage_rpm: f64,
    /// Oil temperature \[°C\].
    pub temperature_c: f64,
    /// Kinematic viscosity there \[mm²/s\].
    pub viscosity_mm2_s: f64,
    /// The rings do not turn relative to each other: the torques are starting torques.
    pub starting: bool,
    /// Bearing torque M \[N·mm\].
    pub total_nmm: f64,
    /// Torque on the inner ring \[N·mm\].
    pub inner_ring_nmm: f64,
    /// Torque on the outer ring \[N·mm\].
    pub outer_ring_nmm: f64,
    /// Cone rolling-resistance share \[N·mm\].
    pub cone_rolling_nmm: f64,
    /// Cone sliding share \[N·mm\].
    pub cone_sliding_nmm: f64,
    /// Cup rolling-resistance share \[N·mm\].
    pub cup_rolling_nmm: f64,
    /// Cup sliding share \[N·mm\].
    pub cup_sliding_nmm: f64,
    /// Rib share \[N·mm\].
    pub rib_nmm: f64,
    /// Drag share \[N·mm\].
    pub drag_nmm: f64,
    /// Rolling-resistance power \[W\].
    pub rolling_power_w: f64,
    /// Sliding power \[W\].
    pub sliding_power_w: f64,
    /// Rib power \[W\].
    pub rib_power_w: f64,
    /// Drag power \[W\].
    pub drag_power_w: f64,
    /// Total power \[W\].
    pub power_w: f64,
    /// μ = M/(P d/2), P = |applied force|, d the bore (`catalogue.bore_mm`) or else the
    /// pitch diameter (absent without force).
    pub coefficient: Option<f64>,
    /// The d of `coefficient` \[mm\].
    pub coefficient_diameter_mm: f64,
    /// Smallest film parameter Λ of the raceways.
    pub min_lambda: Option<f64>,
    /// The catalogue torques.
    pub catalogue: CatalogueTorques,
    /// Every roller.
    pub rollers: Vec<FrictionRollerRow>,
    /// Results to treat with care.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub warnings: Vec<String>,
    /// With `operating.sweep_inner_rpm`: the torque at each of its speeds.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub speed_sweep: Vec<FrictionSweepRow>,
    /// With `operating.sweep_axial_n`: the torque at each axial force, re-solved.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub axial_load_sweep: Vec<FrictionSweepRow>,
    /// With `operating.sweep_radial_n`: the torque at each radial force, re-solved.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub radial_load_sweep: Vec<FrictionSweepRow>,
    /// With `operating.sweep_temperature_c`: the torque at each oil temperature.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub temperature_sweep: Vec<FrictionSweepRow>,
    /// Every ball of a ball bearing (then `cone_*` is the inner race, `cup_*` the outer
    /// race, `rollers` empty; `bearing_friction::ball`).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub balls: Vec<ball::FrictionBallRow>,
}

/// One point of a friction sweep: a speed of `operating.sweep_inner_rpm`, a load of
/// `sweep_axial_n` / `sweep_radial_n` or a temperature of `sweep_temperature_c` (torques
/// N·mm, power W).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrictionSweepRow {
    /// Inner ring speed \[r/min\].
    pub inner_rpm: f64,
    /// Bearing torque \[N·mm\].
    pub total_nmm: f64,
    /// Cone share (rolling + sliding) \[N·mm\].
    pub cone_nmm: f64,
    /// Cup share (rolling + sliding) \[N·mm\].
    pub cup_nmm: f64,
    /// Rib share \[N·mm\].
    pub rib_nmm: f64,
    /// Drag share \[N·mm\].
    pub drag_nmm: f64,
    /// Total power \[W\].
    pub power_w: f64,
    /// Friction coefficient μ.
    pub coefficient: Option<f64>,
    /// Smallest raceway Λ.
    pub min_lambda: Option<f64>,
    /// SKF 2004 total \[N·mm\].
    pub skf_total_nmm: Option<f64>,
    /// Aihara (1987) total, or its rolling part without the rib \[N·mm\].
    pub aihara_nmm: Option<f64>,
    /// Schaeffler M0 (+ M1) \[N·mm\].
    pub schaeffler_nmm: Option<f64>,
    /// Axial force `Fz` \[N\] (load sweeps: the swept value as given; otherwise the
    /// carried one).
    pub axial_load_n: f64,
    /// Radial force `|(Fx, Fy)|` \[N\] (as `axial_load_n`).
    pub radial_load_n: f64,
    /// Oil temperature \[°C\].
    pub temperature_c: f64,
    /// Kinematic viscosity there \[mm²/s\].
    pub viscosity_mm2_s: f64,
    /// Rollers that carry load on a raceway.
    pub loaded_rollers: usize,
}

/// The solved state a friction evaluation reads.
#[derive(Clone, Copy)]
pub(crate) enum Solved<'a> {
    /// The ISO (or coupled) slice model: its slice loads and rollers.
    Iso {
        slice_loads: &'a [f64],
        rollers: &'a [kontakt_bearing::equilibrium::RollerLoad],
    },
    /// The rib-contact roller model.
    Rib(&'a RibContactSolver),
}

fn key(prefix: &str) -> impl Fn(&str) -> String + '_ {
    move |f: &str| format!("{prefix}.{f}")
}

/// The friction section of `bearing` under the force `force` \[N\] (its magnitude is the
/// P of the coefficient) at the ring speeds `rpm` = `[speed.inner_rpm, speed.outer_rpm]`
/// (r/min).
///
/// # Errors
/// [`Error::InvalidInput`] naming the case key (`speed.inner_rpm`, `lubricant.*`,
/// `friction.*`, `catalogue.*`, `operating.drag`, `operating.sweep_inner_rpm`).
#[allow(clippy::too_many_arguments)]
pub(crate) fn friction_report(
    op: &OperatingSpec,
    rpm: [f64; 2],
    lubricant: Option<&LubricantSpec>,
    friction: Option<&FrictionSpec>,
    catalogue: Option<&CatalogueSpec>,
    bearing: &RollerBearing,
    solved: Solved<'_>,
    force: [f64; 3],
) -> Result<FrictionReport> {
    with_sweeps(op, rpm, lubricant, force, |rpm, lub| {
        point(op, rpm, lub, friction, catalogue, bearing, solved, force)
    })
}

/// The report of `at(rpm, lubricant)` at the ring speeds `rpm` (r/min) and the case's
/// `[lubricant]`, with the rows of `operating.sweep_temperature_c` (the lubricant at each
/// temperature) and `operating.sweep_inner_rpm` (each inner ring speed) on the same load
/// distribution (roller and ball bearings).
///
/// # Errors
/// Those of `at`, a sweep's renamed to its key.
pub(crate) fn with_sweeps(
    op: &OperatingSpec,
    rpm: [f64; 2],
    lubricant: Option<&LubricantSpec>,
    force: [f64; 3],
    at: impl Fn([f64; 2], Option<&LubricantSpec>) -> Result<FrictionReport>,
) -> Result<FrictionReport> {
    let mut report = at(rpm, lubricant)?;
    if let Some((sweeps::SweepKind::Temperature, temperatures)) = sweeps::sweep_of(op)? {
        let lub = lubricant.cloned();
        sweeps::temperature_sweep(&mut report, temperatures, force, |t| {
            let lub = lub.map(|mut l| {
                l.temperature_c = t;
                l
            });
            at(rpm, lub.as_ref())
        })?;
    }
    if let Some(speeds) = &op.sweep_inner_rpm {
        if speeds.is_empty() || speeds.len() > 10_000 {
            return Err(Error::invalid(
                "operating.sweep_inner_rpm",
                format!("{} speeds", speeds.len()),
                "1 to 10000 speeds in r/min",
            ));
        }
        for &n in speeds {
            let p = at([n, rpm[1]], lubricant).map_err(|e| {
                e.map_field(|f| match f {
                    "speed.inner_rpm" => "operating.sweep_inner_rpm".to_string(),
                    other => other.to_string(),
                })
            })?;
            report.speed_sweep.push(p.state_row(force));
        }
    }
    Ok(report)
}

/// [`friction_report`] at the ring speeds `rpm` (r/min).
#[allow(clippy::too_many_arguments)]
fn point(
    op: &OperatingSpec,
    rpm: [f64; 2],
    lubricant: Option<&LubricantSpec>,
    friction: Option<&FrictionSpec>,
    catalogue: Option<&CatalogueSpec>,
    bearing: &RollerBearing,
    solved: Solved<'_>,
    force: [f64; 3],
) -> Result<FrictionReport> {
    if bearing.kind == RollerBearingKind::Thrust {
        return Err(Error::invalid(
            "operating",
            "given for a thrust bearing",
            "[operating] with a tapered or cylindrical roller bearing (thrust: not yet)",
        ));
    }
    check_rpm(rpm)?;
    let lub = lubricant_of(lubricant)?;
    let RacewayPlan {
        mut model,
        rib_lub,
        law,
        nu,
    } = plan_raceways(op, lub, friction, bearing)?;
    let oil = rib_lub.lubricant;
    let t = lub.temperature_c;
    let (wi, wo) = (rpm[0] / RPM_PER_RAD_S, rpm[1] / RPM_PER_RAD_S);
    let starting = wi == wo;
    let mut warnings = Vec::new();

    // Slices, tilts, rib loads.
    let n = bearing.rollers * bearing.slices;
    let (mut cup, mut cone) = (vec![0.0; n], vec![0.0; n]);
    let mut tilts = vec![0.0; bearing.rollers];
    let mut rib_loads = vec![0.0; bearing.rollers];
    let mut azimuths = vec![0.0; bearing.rollers];
    let mut rib_values: Option<Vec<f64>> = None;
    // Aihara's rib height e and rib film parameter (1.25 h_min/σ) from the most loaded
    // rib contact (running only).
    let mut aihara_rib: Option<(f64, f64)> = None;
    match solved {
        Solved::Iso {
            slice_loads,
            rollers,
        } => {
            iso_slice_loads(slice_loads, rollers, &mut cup, &mut cone)?;
            for (j, r) in rollers.iter().enumerate() {
                rib_loads[j] = r.rib_n;
                azimuths[j] = r.azimuth_rad;
            }
            if bearing.kind == RollerBearingKind::Tapered {
                warnings.push("rib friction not computed: it needs the roller end/rib pair (roller_model = \"rib_contact\" with [bearing.rib_contact])".to_string());
            }
        }
        Solved::Rib(solver) => {
            cup.copy_from_slice(solver.cup_slice_loads());
            cone.copy_from_slice(solver.cone_slice_loads());
            for (j, r) in solver.roller_loads().iter().enumerate() {
                tilts[j] = r.tilt_rad;
                rib_loads[j] = r.rib_n;
                azimuths[j] = r.azimuth_rad;
            }
            match solver.rib_pair() {
                Some(pair) => {
                    let rib = rib_model(pair, bearing, law, rib_lub)?;
                    let mut values = vec![0.0; bearing.rollers];
                    let f = rib_powers(
                        &rib,
                        op.rib_pressure,
                        solver,
                        [wi, wo],
                        &mut Vec::new(),
                        &mut values,
                    )?;
                    if let Some(c) = f.most_loaded().and_then(|r| r.friction.as_ref())
                        && let Some(film) = &c.film_thickness
                    {
                        let sigma_rib = rib_lub.roughness[0].hypot(rib_lub.roughness[1]);
                        aihara_rib = Some((
                            c.contact_height,
                            rib_film_parameter(film.minimum, sigma_rib)?,
                        ));
                    }
                    rib_values = Some(values);
                }
                None => {
                    // a cylindrical roller bearing's roller ends on its ribs
                    crb_rib_pressure(op)?;
                    let crb = crb_rib_model(bearing, law, rib_lub)?;
                    let mut values = vec![0.0; bearing.rollers];
                    crb_rib_values(&crb, solver, [wi, wo], &mut values)?;
                    rib_values = Some(values);
                }
            }
        }
    }

    // Catalogue torques and drag.
    let envelope = envelope(catalogue)?;
    let lubrication = oil_supply(op)?;
    if let Lubrication::OilBath { level_mm } = lubrication {
        checks::oil_level(level_mm, bearing)?;
    }
    warnings.extend(checks::temperature_warning(lub));
    let (fr, fa) = (force[0].hypot(force[1]), force[2].abs());
    let point = OperatingPoint {
        speed_rad_s: (wi - wo).abs(),
        viscosity_mm2_s: nu,
        radial_load_n: fr,
        axial_load_n: fa,
        lubrication,
    };
    let mut cat = CatalogueTorques::default();
    if let (Some(c), Some(env)) = (catalogue, envelope.as_ref()) {
        if let Some(series) = &c.skf_series {
            let skf = skf_bearing(c, series, bearing)?;
            let t = skf2004(&skf, env, &point, &skf_options(op, Some(c))?)
                .map_err(|e| e.map_field(key("catalogue")))?;
            cat.add_skf(&t, &mut warnings);
        } else {
            warnings.push("SKF catalogue torque not computed: give catalogue.skf_series (and y for tapered bearings)".to_string());
        }
        cat.add_schaeffler(c, nu * point.speed_rpm(), env);
    } else {
        warnings.push("catalogue torques not computed: give [catalogue] (bore_mm, outer_mm, width_mm, skf_series, y)".to_string());
    }
    if bearing.kind == RollerBearingKind::Tapered {
        if fa > 0.0 && fr <= 1e-9 * fa && !starting {
            let (ri0, ro0, _) = model.pitch_radii();
            let slope = viscosity_temperature_slope(&oil, t)?;
            let eta = oil.dynamic_viscosity(t)?;
            let (e, lambda_r) = aihara_rib.unwrap_or((0.0, 0.0));
            let a = aihara(
                &AiharaBearing {
                    rollers: u32::try_from(bearing.rollers).unwrap_or(u32::MAX),
                    roller_diameter_mm: bearing.roller_diameter_mm,
                    inner_radius_mm: ri0,
                    outer_radius_mm: ro0,
                    effective_length_mm: bearing.effective_length_mm,
                    cup_angle_rad: bearing.contact_angle_rad,
                    roller_half_angle_rad: 0.5
                        * (bearing.contact_angle_rad - bearing.cone_angle_rad),
                    rib_height_mm: e,
                    reduced_modulus_mpa: 2.0
                        * kontakt::material::effective_modulus(
                            &kontakt::material::ElasticMaterial::STEEL,
                            &kontakt::material::ElasticMaterial::STEEL,
                        ),
                },
                &AiharaLubricant {
                    viscosity_mpa_s: eta,
                    pressure_viscosity_per_mpa: oil.alpha(),
                    temperature_viscosity_per_k: if op.thermal { -slope / eta } else { 0.0 },
                    thermal_conductivity_w_mk: op.conductivity_w_mk,
                },
                (wi - wo).abs(),
                fa,
                lambda_r,
            )?;
            cat.aihara_rolling_nmm = Some(a.rolling_nmm);
            if aihara_rib.is_some() {
                cat.aihara_total_nmm = Some(a.total_nmm);
            } else {
                warnings.push("Aihara (1987): rolling part only (the rib needs roller_model = \"rib_contact\")".into());
            }
        } else {
            warnings.push(
                "Aihara (1987) not computed: it is for a running TRB under pure axial load".into(),
            );
        }
    }
    let drag = drag_model(op, &cat, nu * point.speed_rpm(), &mut warnings)?;

    let p = force.iter().map(|f| f * f).sum::<f64>().sqrt();
    let d = envelope.map_or(bearing.pitch_diameter_mm, |e| e.bore_mm);
    let f: BearingFriction = model.evaluate(&FrictionOperating {
        inner_speed: wi,
        outer_speed: wo,
        cup_slices: &cup,
        cone_slices: &cone,
        tilts: Some(&tilts),
        rib: rib_values.as_deref(),
        drag,
        coefficient_basis: Some((p, d)),
    })?;
    warnings.extend(checks::film_warning(
        &model,
        [wi, wo],
        &azimuths,
        [&cone, &cup],
        f.warnings.film_out_of_range_slices,
    )?);
    if f.warnings.starvation_extrapolated {
        warnings.push("starvation degree below Biboulet & Houpert's computed range (S < 2)".into());
    }
    if starting {
        warnings.push("the rings do not turn relative to each other: starting torque (boundary friction of the sliding contacts, no film)".into());
    }
    let finite = |v: f64| v.is_finite().then_some(v);
    let rollers = model
        .rollers()
        .iter()
        .enumerate()
        .map(|(j, r)| FrictionRollerRow {
            roller: j,
            azimuth_deg: azimuths[j].to_degrees(),
            cone_load_n: r.cone_load_n,
            cup_load_n: r.cup_load_n,
            rib_load_n: rib_loads[j],
            tilt_rad: r.tilt_rad,
            cone_rolling_w: r.cone_rolling_w,
            cone_sliding_w: r.cone_sliding_w,
            cup_rolling_w: r.cup_rolling_w,
            cup_sliding_w: r.cup_sliding_w,
            rib_w: r.rib_w,
            torque_nmm: r.torque_nmm,
            max_sliding_mm_s: r.max_sliding_mm_s,
            min_lambda: finite(r.min_lambda),
        })
        .collect();
    Ok(FrictionReport {
        inner_rpm: rpm[0],
        outer_rpm: rpm[1],
        cage_rpm: f.cage_speed_rad_s * RPM_PER_RAD_S,
        temperature_c: t,
        viscosity_mm2_s: nu,
        starting,
        total_nmm: f.total_nmm,
        inner_ring_nmm: f.inner_ring_nmm,
        outer_ring_nmm: f.outer_ring_nmm,
        cone_rolling_nmm: f.cone.rolling_nmm,
        cone_sliding_nmm: f.cone.sliding_nmm,
        cup_rolling_nmm: f.cup.rolling_nmm,
        cup_sliding_nmm: f.cup.sliding_nmm,
        rib_nmm: f.rib_nmm,
        drag_nmm: f.drag_nmm,
        rolling_power_w: f.power.rolling_w,
        sliding_power_w: f.power.sliding_w,
        rib_power_w: f.power.rib_w,
        drag_power_w: f.power.drag_w,
        power_w: f.power.total_w,
        coefficient: f.coefficient,
        coefficient_diameter_mm: d,
        min_lambda: finite(f.min_lambda),
        catalogue: cat,
        rollers,
        warnings,
        speed_sweep: Vec::new(),
        axial_load_sweep: Vec::new(),
        radial_load_sweep: Vec::new(),
        temperature_sweep: Vec::new(),
        balls: Vec::new(),
    })
}

/// The oil supply of `[operating]` as the catalogue models take it.
///
/// # Errors
/// Field `operating.oil_level_mm`: missing with `supply = "oil_bath"`, not finite or < 0.
/// The SKF 2004 options of a case: the drag factor `catalogue.skf_drag_factor_vm`. With
/// `operating.drag = "skf"` the supply must be an oil bath (SKF's drag term is the oil
/// bath's) and V_M given: no silent zero drag.
///
/// # Errors
/// [`Error::InvalidInput`] naming `operating.drag` or `catalogue.skf_drag_factor_vm`.
pub(crate) fn skf_options(op: &OperatingSpec, cat: Option<&CatalogueSpec>) -> Result<SkfOptions> {
    let vm = cat.and_then(|c| c.skf_drag_factor_vm);
    if let Some(v) = vm
        && !(v.is_finite() && v >= 0.0)
    {
        return Err(Error::invalid(
            "catalogue.skf_drag_factor_vm",
            v,
            "a finite drag loss factor V_M >= 0 (SKF's diagram at H/d_m)",
        ));
    }
    if op.drag == DragSpec::Skf {
        if op.supply != Supply::OilBath {
            return Err(Error::invalid(
                "operating.drag",
                "skf",
                "\"none\" or \"schaeffler_m0\" unless supply = \"oil_bath\" (SKF's drag term is the oil bath's)",
            ));
        }
        if vm.is_none() {
            return Err(Error::invalid(
                "catalogue.skf_drag_factor_vm",
                "missing",
                "V_M read from SKF's diagram at H/d_m (finite, >= 0): operating.drag = \"skf\" needs it",
            ));
        }
    }
    Ok(SkfOptions {
        drag_factor_vm: vm,
        ..SkfOptions::default()
    })
}

pub(crate) fn oil_supply(op: &OperatingSpec) -> Result<Lubrication> {
    let lubrication = match op.supply {
        Supply::Circulating => Lubrication::OilJet,
        Supply::OilBath => Lubrication::OilBath {
            level_mm: op.oil_level_mm.ok_or_else(|| {
                Error::invalid(
                    "operating.oil_level_mm",
                    "missing",
                    "the oil level above the lowest point of the outer raceway, mm, with supply = \"oil_bath\"",
                )
            })?,
        },
    };
    if let Lubrication::OilBath { level_mm } = lubrication
        && !(level_mm.is_finite() && level_mm >= 0.0)
    {
        return Err(Error::invalid(
            "operating.oil_level_mm",
            level_mm,
            "a finite oil level >= 0 mm above the lowest point of the outer raceway",
        ));
    }
    Ok(lubrication)
}

/// The SKF 2004 bearing of `[catalogue]` with the series `series` for `bearing`'s kind.
///
/// # Errors
/// Fields `catalogue.skf_series` (unknown series) and `catalogue.y` (missing, tapered).
pub(crate) fn skf_bearing(
    c: &CatalogueSpec,
    series: &str,
    bearing: &RollerBearing,
) -> Result<SkfBearing> {
    Ok(match bearing.kind {
        RollerBearingKind::Tapered => SkfBearing::TaperedRoller {
            series: TaperedSeries::from_name(series)
                .map_err(|e| e.map_field(|_| "catalogue.skf_series".to_string()))?,
            y: c.y.ok_or_else(|| {
                Error::invalid(
                    "catalogue.y",
                    "missing",
                    "the axial load factor Y of the product table with skf_series",
                )
            })?,
        },
        _ => SkfBearing::CylindricalRoller {
            series: CylindricalSeries::from_name(series)
                .map_err(|e| e.map_field(|_| "catalogue.skf_series".to_string()))?,
        },
    })
}

/// The tables of a bearing case that the friction reads besides `[operating]`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Tables<'a> {
    /// `[speed]`: `[inner_rpm, outer_rpm]` \[r/min\].
    pub(crate) rpm: [f64; 2],
    /// `[lubricant]`.
    pub(crate) lubricant: Option<&'a LubricantSpec>,
    /// `[friction]`.
    pub(crate) friction: Option<&'a FrictionSpec>,
    /// `[catalogue]`.
    pub(crate) catalogue: Option<&'a CatalogueSpec>,
}

/// `speed.inner_rpm` and `speed.outer_rpm` finite and within `|n| <= MAX_RING_RPM`.
pub(crate) fn check_rpm(rpm: [f64; 2]) -> Result<()> {
    for (k, v) in [("speed.inner_rpm", rpm[0]), ("speed.outer_rpm", rpm[1])] {
        if !(v.is_finite() && v.abs() <= MAX_RING_RPM) {
            return Err(Error::invalid(
                k,
                v,
                format!("a finite speed with |speed| <= {MAX_RING_RPM} r/min"),
            ));
        }
    }
    Ok(())
}

/// The case's `[lubricant]`, required with `[operating]`.
pub(crate) fn lubricant_of(lubricant: Option<&LubricantSpec>) -> Result<&LubricantSpec> {
    lubricant.ok_or_else(|| Error::CaseFile {
        line: None,
        key: "lubricant".into(),
        message: "missing table `[lubricant]`: [operating] needs the oil (iso_vg or nu40_mm2_s and nu100_mm2_s, density_kg_m3, alpha_per_mpa, temperature_c, roughness_mm)".into(),
    })
}

/// The envelope of `[catalogue]` (errors named `catalogue.*`).
pub(crate) fn envelope(catalogue: Option<&CatalogueSpec>) -> Result<Option<Envelope>> {
    catalogue
        .map(|c| {
            Envelope::new(c.bore_mm, c.outer_mm, c.width_mm)
                .map_err(|e| e.map_field(key("catalogue")))
        })
        .transpose()
}

impl CatalogueTorques {
    /// Record the SKF 2004 torque `t` and its warnings.
    pub(crate) fn add_skf(
        &mut self,
        t: &kontakt_bearing::friction::skf2004::SkfTorque,
        warnings: &mut Vec<String>,
    ) {
        self.skf_total_nmm = Some(t.total_nmm);
        self.skf_rolling_nmm = Some(t.rolling_nmm);
        self.skf_sliding_nmm = Some(t.sliding_nmm);
        self.skf_drag_nmm = Some(t.drag_nmm);
        warnings.extend(t.warnings.lines().into_iter().map(|w| format!("SKF: {w}")));
    }

    /// Record the Schaeffler M0 (and M0 + M1) of `c` at ν n = `nu_n` \[mm²/s · r/min\].
    pub(crate) fn add_schaeffler(&mut self, c: &CatalogueSpec, nu_n: f64, env: &Envelope) {
        if let Some(f0) = c.schaeffler_f0 {
            let m = m0(f0, nu_n, env.mean_diameter_mm());
            self.schaeffler_m0_nmm = Some(m);
            if let (Some(f1), Some(p1)) = (c.schaeffler_f1, c.schaeffler_p1_n) {
                self.schaeffler_total_nmm = Some(m + f1 * p1 * env.mean_diameter_mm());
            }
        }
    }
}

/// The drag of `operating.drag` from the catalogue torques `cat`; `nu_n` = ν n
/// \[mm²/s · r/min\] for the Schaeffler low-speed warning.
///
/// # Errors
/// Field `operating.drag` when its catalogue term is not computed.
pub(crate) fn drag_model(
    op: &OperatingSpec,
    cat: &CatalogueTorques,
    nu_n: f64,
    warnings: &mut Vec<String>,
) -> Result<DragModel> {
    let drag = match op.drag {
        DragSpec::None => DragModel::None,
        DragSpec::Skf => DragModel::Torque {
            nmm: cat.skf_drag_nmm.ok_or_else(|| {
                Error::invalid(
                    "operating.drag",
                    "skf",
                    "\"none\" or \"schaeffler_m0\" unless [catalogue] has skf_series (the SKF drag term needs its series)",
                )
            })?,
        },
        DragSpec::SchaefflerM0 => DragModel::Torque {
            nmm: cat.schaeffler_m0_nmm.ok_or_else(|| {
                Error::invalid(
                    "operating.drag",
                    "schaeffler_m0",
                    "\"none\" or \"skf\" unless [catalogue] has schaeffler_f0",
                )
            })?,
        },
    };
    if op.drag == DragSpec::SchaefflerM0 && nu_n < 2000.0 {
        warnings.push("Schaeffler M0: ν n < 2000, the catalogue's low-speed constant".into());
    }

    Ok(drag)
}

/// The raceway oil of a case: the loss model of `[lubricant]`, `[friction]` and
/// `[operating]`, the rib lubrication, the friction law and ν \[mm²/s\] at the oil
/// temperature (roller and ball bearings).
pub(crate) struct RacewayOil {
    /// The raceway loss model.
    pub losses: RacewayLosses,
    /// The rib contacts' lubrication (`[lubricant]`).
    pub rib_lub: RibLubrication,
    /// The friction law (`[friction]`, film-dependent).
    pub law: kontakt::friction::FrictionLaw,
    /// Kinematic viscosity at `lubricant.temperature_c` \[mm²/s\].
    pub nu: f64,
}

/// [`RacewayOil`] of the case's tables.
///
/// # Errors
/// [`Error::InvalidInput`] naming the case key (`lubricant.*`, `friction.*`,
/// `operating.*`).
pub(crate) fn raceway_oil(
    op: &OperatingSpec,
    lub: &LubricantSpec,
    friction: Option<&FrictionSpec>,
) -> Result<RacewayOil> {
    // each surface's roughness, not only the composite σ the raceways use (the rib
    // contacts check theirs later, without the case's key)
    for (i, r) in lub.roughness_mm.iter().enumerate() {
        if !(r.is_finite() && *r >= 0.0) {
            return Err(Error::invalid(
                format!("lubricant.roughness_mm[{i}]"),
                r,
                "a finite rms roughness >= 0 mm",
            ));
        }
    }
    let rib_lub: RibLubrication = lub.lubrication()?;
    let oil = rib_lub.lubricant;
    let t = lub.temperature_c;
    let nu = oil
        .kinematic_viscosity(t)
        .map_err(|e| e.map_field(|_| "lubricant.temperature_c".to_string()))?;
    let law = friction.copied().unwrap_or_default().law(true)?;
    let sigma = lub.roughness_mm[0].hypot(lub.roughness_mm[1]);
    let mut raceway = raceway_lubrication(
        &oil,
        t,
        op.thermal,
        sigma,
        law,
        match op.rolling_resistance {
            RollingSpec::BibouletHoupert => RollingResistanceModel::BibouletHoupert,
            RollingSpec::ZhouHoeprich => RollingResistanceModel::ZhouHoeprich,
        },
    )?;
    raceway.conductivity = op.conductivity_w_mk;
    raceway.film_starvation = op.film_starvation;
    raceway.starvation_degree = op.starvation_degree;
    let losses = RacewayLosses::new(raceway).map_err(|e| {
        e.map_field(|f| match f {
            "conductivity" => "operating.conductivity_w_mk".into(),
            "starvation_factor" => "operating.film_starvation".into(),
            "starvation_degree" => "operating.starvation_degree".into(),
            "roughness" => "lubricant.roughness_mm".into(),
            other => format!("friction.{other}"),
        })
    })?;
    Ok(RacewayOil {
        losses,
        rib_lub,
        law,
        nu,
    })
}

/// The planned raceway friction of a case: the model of `bearing` with the raceway
/// lubrication of `[lubricant]`, `[friction]` and `[operating]`, the rib lubrication and
/// friction law, and the kinematic viscosity ν \[mm²/s\] at the oil temperature.
pub(crate) struct RacewayPlan {
    /// The raceway friction model.
    pub model: BearingFrictionModel,
    /// The rib contacts' lubrication (`[lubricant]`).
    pub rib_lub: RibLubrication,
    /// The friction law (`[friction]`, film-dependent).
    pub law: kontakt::friction::FrictionLaw,
    /// Kinematic viscosity at `lubricant.temperature_c` \[mm²/s\].
    pub nu: f64,
}

/// Plan the raceway friction of `bearing` (tapered or cylindrical) from the case's
/// tables.
///
/// # Errors
/// [`Error::InvalidInput`] naming the case key (`lubricant.*`, `friction.*`,
/// `operating.*`).
pub(crate) fn plan_raceways(
    op: &OperatingSpec,
    lub: &LubricantSpec,
    friction: Option<&FrictionSpec>,
    bearing: &RollerBearing,
) -> Result<RacewayPlan> {
    let RacewayOil {
        losses,
        rib_lub,
        law,
        nu,
    } = raceway_oil(op, lub, friction)?;
    Ok(RacewayPlan {
        model: BearingFrictionModel::new(bearing.clone(), losses)?,
        rib_lub,
        law,
        nu,
    })
}

/// The rib friction model of a rib-contact solver's roller end/rib pair `pair` (steel
/// rollers of `bearing`, no centrifugal term: the solver's load distribution has it).
///
/// # Errors
/// Those of [`RibFrictionModel::new`].
pub(crate) fn rib_model(
    pair: &kontakt::bearing::RollerRib,
    bearing: &RollerBearing,
    law: kontakt::friction::FrictionLaw,
    rib_lub: RibLubrication,
) -> Result<RibFrictionModel> {
    RibFrictionModel::new(
        pair.spec,
        RollerSet {
            count: bearing.rollers,
            length: bearing.effective_length_mm,
            density: 7850.0,
        },
        law,
        Some(rib_lub),
        false,
    )
}

/// Every roller's rib friction of a rib-contact `solver` after its solve, at the ring
/// speeds `[ω_i, ω_o]` \[rad/s\], written to `values` (one per roller): the rib power \[W\]
/// while the rings turn relative to each other, and at standstill (`ω_i = ω_o`) each rib's
/// starting torque `μ_b Q_f v_s(Δω = 1)` \[N·mm\] (boundary friction at the contact point's
/// sliding speed per unit Δω, no film) — what
/// [`kontakt_bearing::friction::torque::FrictionOperating::rib`] takes. `loads` is a
/// buffer (reused: no allocation once it holds the rollers; the contact fields of the
/// rib friction itself are allocated).
///
/// # Errors
/// Those of [`RibFrictionModel::kinematics`] and
/// [`RibFrictionModel::evaluate_rollers`]; field `rib` for a `values` of the wrong length.
pub(crate) fn rib_powers(
    rib: &RibFrictionModel,
    pressure: PressureModel,
    solver: &RibContactSolver,
    speeds: [f64; 2],
    loads: &mut Vec<RollerRibLoad>,
    values: &mut [f64],
) -> Result<kontakt::bearing::BearingRibFriction> {
    let starting = speeds[0] == speeds[1];
    // At standstill: the kinematics of Δω = 1 rad/s.
    let (ri, ro) = if starting {
        (1.0, 0.0)
    } else {
        (speeds[0], speeds[1])
    };
    let k = rib.kinematics(ri, ro)?;
    loads.clear();
    loads.extend(solver.roller_loads().iter().map(|r| RollerRibLoad {
        azimuth: r.azimuth_rad,
        loads: RollerLoads {
            outer_raceway: r.outer_n,
            inner_raceway: r.inner_n,
            rib: r.rib_n,
            centrifugal: solver.centrifugal_n(),
        },
    }));
    if values.len() != loads.len() {
        return Err(Error::invalid(
            "rib",
            values.len(),
            format!("{} values, one per roller", loads.len()),
        ));
    }
    let f = rib.evaluate_rollers(pressure, &k, loads)?;
    let mu_b = rib.law().boundary_coefficient;
    for (v, r) in values.iter_mut().zip(&f.rollers) {
        *v = match (&r.friction, starting) {
            (Some(c), true) => mu_b * r.loads.rib * c.sliding_speed.abs(),
            (_, true) | (None, false) => 0.0,
            (Some(_), false) => r.power(),
        };
    }
    Ok(f)
}

/// A cylindrical roller bearing's ribs take the Hertz pressure only (their friction
/// integrates each rib contact's Hertz ellipse).
///
/// # Errors
/// [`Error::InvalidInput`] naming `operating.rib_pressure`.
pub(crate) fn crb_rib_pressure(op: &OperatingSpec) -> Result<()> {
    if op.rib_pressure == PressureModel::Hertz {
        Ok(())
    } else {
        Err(Error::invalid(
            "operating.rib_pressure",
            op.rib_pressure.as_str(),
            "\"hertz\" for a cylindrical roller bearing (its roller-end/rib friction integrates the Hertz ellipse; \"pimp\" and \"halfspace\" are for a tapered bearing's rib)",
        ))
    }
}

/// The roller-end/rib friction model of a cylindrical roller bearing with ribs
/// (`roller_model = "rib_contact"`), steel, with the case's friction law and rib
/// lubrication.
///
/// # Errors
/// Those of [`CylindricalRibFriction::new`].
pub(crate) fn crb_rib_model(
    bearing: &RollerBearing,
    law: kontakt::friction::FrictionLaw,
    rib_lub: RibLubrication,
) -> Result<CylindricalRibFriction> {
    CylindricalRibFriction::new(
        bearing.pitch_diameter_mm,
        bearing.roller_diameter_mm,
        law,
        Some(rib_lub),
    )
}

/// Every roller's rib value of a cylindrical rib-contact `solver` after its solve, at the
/// ring speeds `[ω_i, ω_o]` \[rad/s\], into `values` (one per roller): the rib power \[W\],
/// at standstill the rib starting torque \[N·mm\] (as [`rib_powers`]). Allocates nothing.
///
/// # Errors
/// Those of [`CylindricalRibFriction::roller_value`]; field `rib` for a `values` of the
/// wrong length.
pub(crate) fn crb_rib_values(
    model: &CylindricalRibFriction,
    solver: &RibContactSolver,
    speeds: [f64; 2],
    values: &mut [f64],
) -> Result<()> {
    let z = solver.roller_loads().len();
    if values.len() != z {
        return Err(Error::invalid(
            "rib",
            values.len(),
            format!("{z} values, one per roller"),
        ));
    }
    for (j, v) in values.iter_mut().enumerate() {
        *v = model.roller_value(solver, j, speeds[0], speeds[1])?;
    }
    Ok(())
}

impl FrictionReport {
    /// Human-readable lines for `kontakt bearing`.
    pub fn lines(&self) -> Vec<String> {
        let mut out = vec![
            format!(
                "friction at {:.0}/{:.0} r/min (inner/outer), cage {:.1} r/min, {:.1} °C, ν = {:.2} mm²/s{}",
                self.inner_rpm,
                self.outer_rpm,
                self.cage_rpm,
                self.temperature_c,
                self.viscosity_mm2_s,
                if self.starting {
                    " (starting torque)"
                } else {
                    ""
                }
            ),
            format!(
                "  torque {:.2} N·mm = {} {:.2} (rolling {:.2}, sliding {:.2}) + {} {:.2} (rolling {:.2}, sliding {:.2}) + rib {:.2} + drag {:.2}",
                self.total_nmm,
                if self.balls.is_empty() {
                    "cone"
                } else {
                    "inner race"
                },
                self.cone_rolling_nmm + self.cone_sliding_nmm,
                self.cone_rolling_nmm,
                self.cone_sliding_nmm,
                if self.balls.is_empty() {
                    "cup"
                } else {
                    "outer race"
                },
                self.cup_rolling_nmm + self.cup_sliding_nmm,
                self.cup_rolling_nmm,
                self.cup_sliding_nmm,
                self.rib_nmm,
                self.drag_nmm
            ),
            format!(
                "  power {:.3} W (rolling {:.3}, sliding {:.3}, rib {:.3}, drag {:.3}); inner ring {:.2} N·mm, outer ring {:.2} N·mm",
                self.power_w,
                self.rolling_power_w,
                self.sliding_power_w,
                self.rib_power_w,
                self.drag_power_w,
                self.inner_ring_nmm,
                self.outer_ring_nmm
            ),
        ];
        if let Some(mu) = self.coefficient {
            out.push(format!(
                "  friction coefficient μ = M/(P d/2) = {mu:.5} (P = |force|, d = {:.1} mm)",
                self.coefficient_diameter_mm
            ));
        }
        if let Some(l) = self.min_lambda {
            out.push(format!("  smallest raceway film parameter Λ = {l:.3}"));
        }
        let c = &self.catalogue;
        if let Some(t) = c.skf_total_nmm {
            out.push(format!(
                "  SKF 2004: {t:.2} N·mm (rolling {:.2}, sliding {:.2}, drag {:.2})",
                c.skf_rolling_nmm.unwrap_or(0.0),
                c.skf_sliding_nmm.unwrap_or(0.0),
                c.skf_drag_nmm.unwrap_or(0.0)
            ));
        }
        if let Some(m) = c.schaeffler_m0_nmm {
            out.push(match c.schaeffler_total_nmm {
                Some(t) => format!("  Schaeffler: M0 + M1 = {t:.2} N·mm (M0 {m:.2})"),
                None => format!("  Schaeffler: M0 = {m:.2} N·mm"),
            });
        }
        if let Some(m) = c.aihara_rolling_nmm {
            out.push(match c.aihara_total_nmm {
                Some(t) => format!("  Aihara 1987: {t:.2} N·mm (rolling {m:.2})"),
                None => format!("  Aihara 1987: rolling {m:.2} N·mm (rib not computed)"),
            });
        }
        out.extend(self.warnings.iter().map(|w| format!("  warning: {w}")));
        if !self.speed_sweep.is_empty() {
            out.push("  speed sweep (N·mm): n r/min | total | cone | cup | rib | drag | SKF | Aihara | min Λ".into());
            let opt = |v: Option<f64>, d: usize| v.map_or("-".to_string(), |x| format!("{x:.d$}"));
            for r in &self.speed_sweep {
                out.push(format!(
                    "    {:8.1} | {:9.2} | {:8.2} | {:8.2} | {:8.2} | {:7.2} | {:>9} | {:>9} | {:>6}",
                    r.inner_rpm,
                    r.total_nmm,
                    r.cone_nmm,
                    r.cup_nmm,
                    r.rib_nmm,
                    r.drag_nmm,
                    opt(r.skf_total_nmm, 2),
                    opt(r.aihara_nmm, 2),
                    opt(r.min_lambda, 3)
                ));
            }
        }
        out.extend(sweeps::state_sweep_lines(self));
        out
    }
}
