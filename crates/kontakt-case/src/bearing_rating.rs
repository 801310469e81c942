//! The rating part of a whole-bearing report (`[bearing.rating]` in, `rating` out): the
//! ISO 76 static safety from the contact pressure and from a given C0, the ISO 281 basic
//! rating life from a given C and the ISO/TS 16281 reference life (the lamina method of
//! roller bearings, the ball loads of ball bearings), on [`kontakt_bearing::life`]. The
//! raceway pressures it starts from ([`kontakt_bearing::stress`]) and the call of
//! `rating` after every solve, the report's and a sweep row's alike, are in
//! `crate::bearing_post`. Loads in N, pressures in MPa, lives in millions of revolutions;
//! `docs/bearing-model.md`, "Life and static safety".
//!
//! ```toml
//! [bearing.rating]
//! dynamic_n = 14000.0         # basic dynamic load rating C (catalogue), N
//! static_n = 7850.0           # basic static load rating C0, N
//! rotating_ring = "inner"     # "inner" (default) | "outer": the lamina life's exponents
//! edge_stress_factor = false  # ISO/TS 16281's edge factor on the lamina loads (rollers)
//! ```

use kontakt::{Error, Result};
use kontakt_bearing::geometry::{BallBearing, RollerBearing};
use kontakt_bearing::life::{
    BALL_PRESSURE_LIMIT_MPA, Contact, LaminaOptions, ROLLER_PRESSURE_LIMIT_MPA, RatingType,
    RotatingRing, ball_reference_life, basic_rating_life, dynamic_equivalent_load, lamina_life,
    static_equivalent_load, static_safety_from_pressure,
};
use serde::{Deserialize, Serialize};

/// `[bearing.rating]`: the catalogue's load ratings and the lamina life's options.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RatingSpec {
    /// Basic dynamic load rating C, N (radial C_r; axial C_a of a thrust bearing), from the
    /// manufacturer's catalogue: enables the ISO 281 life L10 and (roller bearings) the
    /// ISO/TS 16281 lamina life L10r.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dynamic_n: Option<f64>,
    /// Basic static load rating C0, N: enables the ISO 76 static safety C0/P0 (and a deep
    /// groove ball bearing's e and Y under axial load).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub static_n: Option<f64>,
    /// The ring that rotates relative to the load, `"inner"` (default) or `"outer"`.
    #[serde(default)]
    pub rotating_ring: RotatingRingSpec,
    /// Roller bearings: apply ISO/TS 16281's edge-stress factor to the lamina loads
    /// (default false; it depends on the slice count, `docs/bearing-model.md`, "Life and static safety").
    #[serde(default)]
    pub edge_stress_factor: bool,
}

/// The rotating ring of `[bearing.rating]`.
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize, schemars::JsonSchema,
)]
#[serde(rename_all = "snake_case")]
pub enum RotatingRingSpec {
    /// The inner ring rotates.
    #[default]
    Inner,
    /// The outer ring rotates.
    Outer,
}

impl RotatingRingSpec {
    fn ring(self) -> RotatingRing {
        match self {
            RotatingRingSpec::Inner => RotatingRing::Inner,
            RotatingRingSpec::Outer => RotatingRing::Outer,
        }
    }
    fn as_str(self) -> &'static str {
        match self {
            RotatingRingSpec::Inner => "inner",
            RotatingRingSpec::Outer => "outer",
        }
    }
}

/// The `rating` keys of a bearing report.
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct RatingReport {
    /// ISO 76's contact pressure at the static capacity for this type, MPa (4000 roller,
    /// 4200 ball bearings).
    pub pressure_limit_mpa: f64,
    /// The largest raceway pressure of any rolling element, MPa.
    pub max_pressure_mpa: f64,
    /// ISO 76's static safety from the pressure, `(p_lim/p_max)^2` (line contact) or `^3`
    /// (point contact); absent without load.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub static_safety_from_pressure: Option<f64>,
    /// The radial load `√(Fx² + Fy²)` the bearing carries, N.
    pub radial_load_n: f64,
    /// The axial load |Fz| the bearing carries, N.
    pub axial_load_n: f64,
    /// The given C, N.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dynamic_capacity_n: Option<f64>,
    /// The given C0, N.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub static_capacity_n: Option<f64>,
    /// ISO 281's dynamic equivalent load P = X F_r + Y F_a, N (with C).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub equivalent_dynamic_load_n: Option<f64>,
    /// The factors `[X, Y]` of P.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub load_factors_xy: Option<[f64; 2]>,
    /// ISO 281's basic rating life L10 = (C/P)^p, millions of revolutions (absent at P = 0).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub l10_mrev: Option<f64>,
    /// ISO 76's static equivalent load P0, N (with C0).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub equivalent_static_load_n: Option<f64>,
    /// ISO 76's static safety C0/P0 (absent at P0 = 0).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub static_safety: Option<f64>,
    /// With C: the ISO/TS 16281 modified reference rating life L10r, millions of revolutions
    /// (roller bearings by the lamina method, ball bearings from the ball loads; absent
    /// without load).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub l10r_mrev: Option<f64>,
    /// The dynamic equivalent reference load, N: `P_ref = C L10r^(−3/10)` (rollers),
    /// `C L10r^(−1/3)` (balls).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reference_load_n: Option<f64>,
    /// The raceway capacities `[Q_ci, Q_ce]` of one rolling element, N.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub raceway_capacities_n: Option<[f64; 2]>,
    /// The ring that rotates (the lamina life's exponents).
    pub rotating_ring: &'static str,
    /// Whether the lamina loads carry ISO/TS 16281's edge-stress factor.
    pub edge_stress_factor: bool,
}

/// The rating spec of a case, checked: each capacity finite and > 0 (named
/// `bearing.rating.dynamic_n`), and no edge factor for a ball bearing.
pub(crate) fn checked_spec(spec: Option<&RatingSpec>, balls: bool) -> Result<RatingSpec> {
    let s = spec.copied().unwrap_or_default();
    for (key, v) in [("dynamic_n", s.dynamic_n), ("static_n", s.static_n)] {
        if let Some(v) = v
            && !(v.is_finite() && v > 0.0)
        {
            return Err(Error::invalid(
                format!("bearing.rating.{key}"),
                v,
                "a finite load rating > 0 N (the catalogue value)",
            ));
        }
    }
    if balls && s.edge_stress_factor {
        return Err(Error::invalid(
            "bearing.rating.edge_stress_factor",
            true,
            "false for a ball bearing (the edge factor is the roller laminae's)",
        ));
    }
    Ok(s)
}

/// The rolling elements' loads for the reference life L10r.
pub(crate) enum LifeInput<'a> {
    /// A roller bearing: its slice loads (outer raceway, roller-major) and `Q_i/Q_o`.
    Rollers(&'a RollerBearing, &'a [f64], f64),
    /// A ball bearing: its nominal contact angle (rad) and the ball loads.
    Balls(&'a BallBearing, f64, &'a [f64]),
}

/// The rating of a solved bearing of type `t` carrying `load` (N, N·mm) with the largest
/// raceway pressure `p_max` (MPa); `life`: the element loads for L10r; `moment` the applied
/// moment (N·mm, the force-controlled components). Adds its warnings to `warnings`.
pub(crate) fn rating(
    t: RatingType,
    spec: &RatingSpec,
    load: [f64; 5],
    moment: f64,
    p_max: f64,
    life: LifeInput<'_>,
    warnings: &mut Vec<String>,
) -> Result<RatingReport> {
    let contact = match life {
        LifeInput::Rollers(..) => Contact::Line,
        LifeInput::Balls(..) => Contact::Point,
    };
    let limit = match contact {
        Contact::Line => ROLLER_PRESSURE_LIMIT_MPA,
        Contact::Point => BALL_PRESSURE_LIMIT_MPA,
    };
    let s0p = static_safety_from_pressure(limit, p_max, contact);
    if let Some(s) = s0p
        && s < 1.0
    {
        warnings.push(format!(
            "the largest raceway pressure {p_max:.0} MPa exceeds ISO 76's {limit:.0} MPa: static safety from the pressure {s:.3} < 1 (permanent deformation expected)"
        ));
    }
    let fr = load[0].hypot(load[1]);
    let fa = load[2].abs();
    let mut r = RatingReport {
        pressure_limit_mpa: limit,
        max_pressure_mpa: p_max,
        static_safety_from_pressure: s0p,
        radial_load_n: fr,
        axial_load_n: fa,
        dynamic_capacity_n: spec.dynamic_n,
        static_capacity_n: spec.static_n,
        equivalent_dynamic_load_n: None,
        load_factors_xy: None,
        l10_mrev: None,
        equivalent_static_load_n: None,
        static_safety: None,
        l10r_mrev: None,
        reference_load_n: None,
        raceway_capacities_n: None,
        rotating_ring: spec.rotating_ring.as_str(),
        edge_stress_factor: spec.edge_stress_factor,
    };
    if (spec.dynamic_n.is_some() || spec.static_n.is_some()) && moment > 0.0 {
        warnings.push(format!(
            "ISO 281 and ISO 76 take the radial and axial load only: the moment {moment:.1} N mm is not in P and P0 (the reference life L10r includes it)"
        ));
    }
    if let Some(c) = spec.dynamic_n {
        match dynamic_equivalent_load(t, fr, fa, spec.static_n) {
            Ok(p) => {
                r.equivalent_dynamic_load_n = Some(p.load_n);
                r.load_factors_xy = Some([p.x, p.y]);
                r.l10_mrev = (p.load_n > 0.0).then(|| basic_rating_life(c, p.load_n, contact));
            }
            Err(e) => warnings.push(format!("no ISO 281 life L10: {}", case_key(e))),
        }
        let rotating = spec.rotating_ring.ring();
        let l = match life {
            LifeInput::Rollers(b, loads, ratio) => {
                let opts = LaminaOptions {
                    rotating,
                    edge_factor: spec.edge_stress_factor,
                };
                lamina_life(b, c, loads, ratio, opts)?
            }
            LifeInput::Balls(b, alpha, loads) => {
                ball_reference_life(b, alpha, c, loads, rotating).map_err(case_key)?
            }
        };
        if l.l10r_mrev.is_finite() {
            r.l10r_mrev = Some(l.l10r_mrev);
            r.reference_load_n = Some(l.reference_load_n);
        }
        r.raceway_capacities_n = Some([l.inner_capacity_n, l.outer_capacity_n]);
    }
    if let Some(c0) = spec.static_n {
        match static_equivalent_load(t, fr, fa) {
            Ok(p0) => {
                r.equivalent_static_load_n = Some(p0);
                r.static_safety = (p0 > 0.0).then(|| c0 / p0);
                if let Some(s) = r.static_safety
                    && s < 1.0
                {
                    warnings.push(format!(
                        "static safety s0 = C0/P0 = {s:.3} < 1 (ISO 76): the load exceeds the static capacity"
                    ));
                }
            }
            Err(e) => warnings.push(format!("no ISO 76 static safety C0/P0: {}", case_key(e))),
        }
    }
    Ok(r)
}

/// The library's field names of a rating error as the case file's keys.
fn case_key(e: Error) -> Error {
    e.map_field(|f| match f {
        "static_n" | "dynamic_n" => format!("bearing.rating.{f}"),
        other => format!("bearing.{other}"),
    })
}
