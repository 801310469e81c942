//! Cattaneo-Mindlin cases (`method = "mindlin"`, `schema_version = 1`): a Hertz point
//! contact under a constant normal force and an oscillating tangential force `Q = ±Q*`
//! below `mu P`, and its report: the stick zone and the shift at `Q*`, the
//! Mindlin-Deresiewicz loading history (the hysteresis loop of `Q` against the tangential
//! displacement) and the energy dissipated per cycle. The physics is
//! [`kontakt::tangential::mindlin`] (Johnson 1982 eqs 30-33; Mindlin and Deresiewicz 1953).
//!
//! ```toml
//! name = "steel ball on a flat, fretting"
//! method = "mindlin"
//!
//! [geometry]                 # as in traction cases: kind = "hertz" (principal radii)
//! kind = "hertz"             # or kind = "ellipse" with semi_axes_mm = [a, b]
//! radii1_mm = [6.35, 6.35]
//! radii2_mm = [inf, inf]
//!
//! [body1]
//! e_mpa = 210000.0
//! nu = 0.3
//! [body2]
//! e_mpa = 210000.0
//! nu = 0.3
//!
//! [load]
//! force_n = 100.0            # normal force P [N]
//!
//! [friction]
//! mu = 0.3
//!
//! [tangential]
//! amplitude_n = 20.0         # Q* [N], 0 < Q* <= mu P
//! angle_deg = 0.0            # direction of Q from the ellipse's first axis (optional)
//! cycles = 2                 # full cycles after the first loading (optional, default 1)
//! points = 41                # points per branch (optional, default 41)
//! ```
//!
//! With `kind = "hertz"` the first axis `x` is the major semi-axis of the contact ellipse;
//! with `kind = "ellipse"` it is the semi-axis `a` as given.

use crate::common::{MaterialSpec, SCHEMA_VERSION, in_degrees, material, parse_toml};
use crate::traction_case::{FrictionSpec, TractionGeometry, TractionLoad};
use crate::validity::{ContactSize, checked, checked_report};
use kontakt::tangential::{ContactEllipse, EllipseAxis, Mindlin};
use kontakt::{Error, Result};
use serde::{Deserialize, Serialize};

/// A Cattaneo-Mindlin case, as read from TOML.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MindlinCase {
    /// Optional label echoed in the report.
    #[serde(default)]
    pub name: Option<String>,
    /// Must be `"mindlin"`.
    pub method: String,
    /// The contact: `kind = "hertz"` (radii) or `"ellipse"` (semi-axes).
    pub geometry: TractionGeometry,
    /// Body 1 material.
    pub body1: MaterialSpec,
    /// Body 2 material.
    pub body2: MaterialSpec,
    /// The normal force (`force_n`).
    pub load: TractionLoad,
    /// The friction coefficient.
    pub friction: FrictionSpec,
    /// The tangential loading.
    pub tangential: TangentialSpec,
}

/// `[tangential]`: the oscillating tangential force.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct TangentialSpec {
    /// Amplitude `Q*` \[N\] of the tangential force, `0 < Q* <= mu P`.
    pub amplitude_n: f64,
    /// Direction of the force from the first axis `x` \[deg\], default 0.
    #[serde(default)]
    pub angle_deg: f64,
    /// Full cycles `Q* -> -Q* -> Q*` after the first loading `0 -> Q*`, 1..=100,
    /// default 1.
    #[serde(default = "default_cycles")]
    pub cycles: usize,
    /// Points per branch of the loop, 2..=10000, default 41.
    #[serde(default = "default_points")]
    pub points: usize,
}

/// Smallest `Q*/(mu P)` of a case: below it the loop area, a difference of displacements
/// that agree to that fraction, loses more than 1e-4 of its value to rounding with 10000
/// points per branch (measured: 4e-4 at 6.7e-12 with 41 points, 1.4 % at 6.7e-14).
pub const MIN_LOAD_FRACTION: f64 = 1e-8;

/// `x` as Rust prints it within 1e-3..1e7, in exponent form outside (a limit of 1e302 N
/// in one line, not 303 digits).
fn short(x: f64) -> String {
    if (1e-3..1e7).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

fn default_cycles() -> usize {
    1
}

fn default_points() -> usize {
    41
}

/// The result of a Cattaneo-Mindlin case. Keys carry their units.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MindlinReport {
    /// Version of kontakt that produced the record.
    pub kontakt_version: &'static str,
    /// Version of this schema.
    pub schema_version: u32,
    /// The case's name, if any.
    pub name: Option<String>,
    /// `"mindlin"`.
    pub method: &'static str,
    /// `"hertz"` or `"ellipse"`.
    pub geometry: &'static str,
    /// Normal force P \[N\].
    pub force_n: f64,
    /// Friction coefficient \[-\].
    pub mu: f64,
    /// Semi-axes `[a, b]` \[mm\] of the contact ellipse, `a` along `x`.
    pub semi_axes_mm: [f64; 2],
    /// Maximum Hertz pressure p0 \[MPa\].
    pub max_pressure_mpa: f64,
    /// Direction of Q from `x` \[deg\].
    pub load_angle_deg: f64,
    /// The sliding limit `mu P` \[N\].
    pub limit_force_n: f64,
    /// Compliance of the contact without slip along Q \[mm/N\] (Mindlin 1949).
    pub no_slip_compliance_mm_per_n: f64,
    /// Its inverse, the initial tangential stiffness \[N/mm\].
    pub tangential_stiffness_n_per_mm: f64,
    /// The amplitude `Q*` \[N\].
    pub amplitude_n: f64,
    /// `Q*/(mu P)` \[-\].
    pub load_fraction: f64,
    /// Stick-zone semi-axes over the contact's at `Q*`: `(1 - Q*/(mu P))^(1/3)` \[-\].
    pub stick_ratio: f64,
    /// Stick-zone semi-axes `[a', b']` \[mm\] at `Q*`.
    pub stick_semi_axes_mm: [f64; 2],
    /// Tangential displacement (shift) of the stick zone at `Q*` on first loading \[mm\].
    pub displacement_at_amplitude_mm: f64,
    /// The shift at which the contact slides, at `Q = mu P` \[mm\].
    pub slip_displacement_mm: f64,
    /// Energy dissipated per cycle `Q = ±Q*`, closed form \[N·mm\].
    pub dissipated_energy_per_cycle_nmm: f64,
    /// The same from the computed loop: the area enclosed by its last cycle, by the
    /// trapezoidal rule \[N·mm\] (a check of the loop against the closed form).
    pub loop_energy_nmm: f64,
    /// The loading history: `Q` \[N\] at each point (first loading, then the cycles).
    pub loop_force_n: Vec<f64>,
    /// The tangential displacement \[mm\] at each point of `loop_force_n`.
    pub loop_displacement_mm: Vec<f64>,
    /// Results to treat with care: a contact large against the bodies' radii of
    /// curvature. Absent when none applies.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub warnings: Vec<String>,
    /// The contact's size against the bodies (`kind = "hertz"`), for the validity check
    /// ([`crate::validity`]); not in the JSON.
    #[serde(skip)]
    pub contacts: Vec<ContactSize>,
}

checked_report!(MindlinReport);

impl MindlinCase {
    /// Parse a Cattaneo-Mindlin case from TOML text.
    ///
    /// # Errors
    /// [`Error::CaseFile`] (line, key path, what the schema takes) for malformed TOML,
    /// unknown keys or wrong types.
    pub fn from_toml_str(text: &str) -> Result<Self> {
        parse_toml(text)
    }
}

/// Run a Cattaneo-Mindlin case.
///
/// # Errors
/// [`Error::InvalidInput`] or [`Error::Geometry`] naming the case key at fault
/// (`tangential.amplitude_n` outside `0 < Q* <= mu P`, `tangential.cycles`,
/// `tangential.points`, `friction.mu`, `load.force_n`, `geometry.radii1_mm`, ...).
pub fn run_mindlin_case(case: &MindlinCase) -> Result<MindlinReport> {
    checked(run_mindlin_case_unchecked(case)?)
}

/// [`run_mindlin_case`] before the validity check of [`crate::validity::checked`].
pub(crate) fn run_mindlin_case_unchecked(case: &MindlinCase) -> Result<MindlinReport> {
    if case.method != "mindlin" {
        return Err(Error::invalid(
            "method",
            &case.method,
            "\"mindlin\" for this schema",
        ));
    }
    let t = case.tangential;
    if !(1..=100).contains(&t.cycles) {
        return Err(Error::invalid(
            "tangential.cycles",
            t.cycles,
            "1..=100 cycles",
        ));
    }
    if !(2..=10_000).contains(&t.points) {
        return Err(Error::invalid(
            "tangential.points",
            t.points,
            "2..=10000 points per branch",
        ));
    }
    if !t.angle_deg.is_finite() {
        return Err(Error::invalid(
            "tangential.angle_deg",
            t.angle_deg,
            "a finite angle [deg]",
        ));
    }
    let m1 = material(&case.body1, "body1")?;
    let m2 = material(&case.body2, "body2")?;
    let (force, _) = case.load.force(None)?;
    let mu = case.friction.mu;
    let map = |e: Error| {
        e.map_field(|f| match f {
            "friction_coefficient" => "friction.mu".into(),
            "normal_force" | "force" => "load.force_n".into(),
            "semi_axes[0]" => "geometry.semi_axes_mm[0]".into(),
            "semi_axes[1]" => "geometry.semi_axes_mm[1]".into(),
            "tangential_force" => "tangential.amplitude_n".into(),
            "materials" => "body1, body2".into(),
            other => other.into(),
        })
    };
    let mut contacts = Vec::new();
    let (label, ellipse) = match &case.geometry {
        TractionGeometry::Hertz {
            radii1_mm,
            radii2_mm,
            angle_deg,
        } => {
            let (sol, size) = crate::traction_case::hertz_of_geometry(
                *radii1_mm, *radii2_mm, *angle_deg, m1, m2, force,
            )
            .map_err(map)?;
            contacts.push(size);
            (
                "hertz",
                ContactEllipse::from_hertz(&sol, EllipseAxis::Major)?,
            )
        }
        TractionGeometry::Ellipse { semi_axes_mm } => (
            "ellipse",
            ContactEllipse::new(semi_axes_mm[0], semi_axes_mm[1], force).map_err(map)?,
        ),
        TractionGeometry::Line { .. } => {
            return Err(Error::invalid(
                "geometry.kind",
                "line",
                "\"hertz\" or \"ellipse\" (kontakt's Cattaneo-Mindlin model is for point contacts)",
            ));
        }
    };
    let contact = Mindlin::new(ellipse, m1, m2, mu)
        .and_then(|c| {
            c.with_load_direction(t.angle_deg.to_radians())
                .map_err(|e| in_degrees(e, "load_direction", "tangential.angle_deg", t.angle_deg))
        })
        .map_err(map)?;
    let limit = contact.limit_force();
    let q = t.amplitude_n;
    // Below MIN_LOAD_FRACTION the loop's width (of relative order Q*/(mu P) against its
    // length) is below what double precision resolves over the loop's points: the loop
    // area came out as rounding noise (1e-18 N mm against 6e-154 at Q*/(mu P) = 2e-153).
    let least = MIN_LOAD_FRACTION * limit;
    if !(q.is_finite() && q >= least && q <= limit) {
        return Err(Error::invalid(
            "tangential.amplitude_n",
            q,
            format!(
                "{} N <= Q* <= mu P = {} N (beyond mu P the contact slides; below \
                 {MIN_LOAD_FRACTION:e} mu P it practically sticks, and its hysteresis loop is \
                 narrower than double precision resolves)",
                short(least),
                short(limit)
            ),
        ));
    }

    // The history: 0 -> Q*, then `cycles` times Q* -> -Q* -> Q*.
    let mut history = contact.history();
    let n = t.points;
    let mut forces = Vec::with_capacity(n * (1 + 2 * t.cycles));
    let mut shifts = Vec::with_capacity(forces.capacity());
    let mut branch = |from: f64, to: f64, first: bool| -> Result<()> {
        for i in usize::from(!first)..n {
            let qi = from + (to - from) * i as f64 / (n - 1) as f64;
            let d = history.apply_force(qi).map_err(map)?;
            forces.push(qi);
            shifts.push(d);
        }
        Ok(())
    };
    branch(0.0, q, true)?;
    for _ in 0..t.cycles {
        branch(q, -q, false)?;
        branch(-q, q, false)?;
    }
    // Area of the last cycle (its 2(n-1) + 1 points), counter-clockwise in (delta, Q).
    let start = forces.len() - 2 * (n - 1) - 1;
    let loop_energy = (start..forces.len() - 1)
        .map(|k| 0.5 * (forces[k] + forces[k + 1]) * (shifts[k + 1] - shifts[k]))
        .sum::<f64>()
        .abs();
    let stick = contact.stick_semi_axes(q).map_err(map)?;
    let compliance = contact.no_slip_compliance();
    Ok(MindlinReport {
        kontakt_version: kontakt::VERSION,
        schema_version: SCHEMA_VERSION,
        name: case.name.clone(),
        method: "mindlin",
        geometry: label,
        force_n: force,
        mu,
        semi_axes_mm: [ellipse.a(), ellipse.b()],
        max_pressure_mpa: ellipse.max_pressure(),
        load_angle_deg: t.angle_deg,
        limit_force_n: limit,
        no_slip_compliance_mm_per_n: compliance,
        tangential_stiffness_n_per_mm: 1.0 / compliance,
        amplitude_n: q,
        load_fraction: q / limit,
        stick_ratio: contact.stick_ratio(q).map_err(map)?,
        stick_semi_axes_mm: stick,
        displacement_at_amplitude_mm: contact.displacement(q).map_err(map)?,
        slip_displacement_mm: contact.slip_displacement(),
        dissipated_energy_per_cycle_nmm: contact.dissipated_energy_per_cycle(q).map_err(map)?,
        loop_energy_nmm: loop_energy,
        loop_force_n: forces,
        loop_displacement_mm: shifts,
        warnings: Vec::new(),
        contacts,
    })
}
