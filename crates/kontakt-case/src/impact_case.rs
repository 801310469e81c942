//! Impact cases (`method = "impact"`, `schema_version = 1`): a sphere striking a flat, at
//! any angle of incidence and with spin, and its report: the Hertz normal impact (duration,
//! peak force, approach and pressure; Johnson 1982 eqs 36-38) and, with a friction
//! coefficient, the oblique rebound of the rigid-body theory (Johnson 1982 eqs 39-40) and
//! of the elastic analysis of Maw, Barber and Fawcett (1976). The physics is
//! [`kontakt::hertz::impact`] and [`kontakt::impact`].
//!
//! ```toml
//! name = "steel ball on a steel plate at 30 deg"
//! method = "impact"
//!
//! [sphere]
//! radius_mm = 5.0
//! density_t_per_mm3 = 7.85e-9    # or mass_t
//! # radius_of_gyration_mm = ...  # optional: default that of a solid sphere, sqrt(2/5) R
//! e_mpa = 210000.0
//! nu = 0.3
//!
//! [flat]                         # a half-space at rest (infinite mass)
//! e_mpa = 210000.0
//! nu = 0.3
//!
//! [impact]
//! speed_mm_per_s = 1000.0        # speed of the centre at first contact
//! angle_deg = 30.0               # from the normal of the flat, -90 < angle < 90 (default 0)
//! spin_rad_per_s = 0.0           # positive when it moves the contact point along the tangential velocity (default 0)
//!
//! [friction]                     # optional for a normal impact without spin
//! mu = 0.3
//! restitution = 1.0              # rigid-body theory only, 0..=1 (default 1)
//! ```

use crate::common::{MaterialSpec, SCHEMA_VERSION, material, parse_toml};
use crate::validity::{ContactSize, Size, checked, checked_report};
use kontakt::hertz::impact::{HertzImpact, sphere_mass};
use kontakt::hertz::validity::SizeCheck;
use kontakt::impact::{
    ElasticImpactOptions, ElasticObliqueImpact, IncidentMotion, RigidObliqueImpact, RigidRegime,
    SphereBody,
};
use kontakt::material::effective_modulus;
use kontakt::{Error, Result};
use serde::{Deserialize, Serialize};

/// An impact case, as read from TOML.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ImpactCase {
    /// Optional label echoed in the report.
    #[serde(default)]
    pub name: Option<String>,
    /// Must be `"impact"`.
    pub method: String,
    /// The striking sphere.
    pub sphere: SphereSpec,
    /// The flat (a half-space at rest).
    pub flat: MaterialSpec,
    /// The motion at first contact.
    pub impact: IncidenceSpec,
    /// Friction, for oblique impacts and spin.
    #[serde(default)]
    pub friction: Option<ImpactFrictionSpec>,
}

/// `[sphere]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SphereSpec {
    /// Radius \[mm\], > 0.
    pub radius_mm: f64,
    /// Density \[t/mm³\] (steel 7.85e-9); exactly one of density and mass.
    #[serde(default)]
    pub density_t_per_mm3: Option<f64>,
    /// Mass \[t\].
    #[serde(default)]
    pub mass_t: Option<f64>,
    /// Radius of gyration about a diameter \[mm\]; default `sqrt(2/5) R` (solid sphere).
    #[serde(default)]
    pub radius_of_gyration_mm: Option<f64>,
    /// Young's modulus \[MPa\].
    pub e_mpa: f64,
    /// Poisson's ratio.
    pub nu: f64,
}

/// `[impact]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct IncidenceSpec {
    /// Speed of the centre at first contact \[mm/s\], > 0.
    pub speed_mm_per_s: f64,
    /// Angle of incidence from the normal of the flat \[deg\], in (-90, 90), default 0.
    #[serde(default)]
    pub angle_deg: f64,
    /// Angular velocity \[rad/s\] about the axis normal to the plane of incidence, positive
    /// when it moves the contact point along `+x` (the tangential velocity's direction for
    /// a positive angle), default 0.
    #[serde(default)]
    pub spin_rad_per_s: f64,
}

/// `[friction]` of an impact case.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ImpactFrictionSpec {
    /// Coefficient of friction \[-\], > 0.
    pub mu: f64,
    /// Normal coefficient of restitution of the rigid-body theory \[-\], 0..=1, default 1
    /// (the elastic analysis is elastic: its restitution is 1).
    #[serde(default = "one")]
    pub restitution: f64,
}

fn one() -> f64 {
    1.0
}

/// The Hertz normal impact in an [`ImpactReport`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct NormalImpactReport {
    /// Normal approach speed `V = v cos(angle)` \[mm/s\].
    pub normal_speed_mm_per_s: f64,
    /// Duration of contact \[s\].
    pub contact_duration_s: f64,
    /// Largest force \[N\].
    pub max_force_n: f64,
    /// Largest approach \[mm\].
    pub max_approach_mm: f64,
    /// Largest contact radius \[mm\].
    pub max_contact_radius_mm: Option<f64>,
    /// Largest Hertz pressure \[MPa\].
    pub max_pressure_mpa: Option<f64>,
}

/// The rigid-body oblique rebound in an [`ImpactReport`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RigidReport {
    /// `gross_sliding` or `sliding_then_rolling`.
    pub regime: &'static str,
    /// Normal rebound speed `e V` \[mm/s\].
    pub normal_velocity_mm_per_s: f64,
    /// Tangential velocity of the centre after the impact \[mm/s\].
    pub tangential_velocity_mm_per_s: f64,
    /// Angular velocity after the impact \[rad/s\].
    pub angular_velocity_rad_per_s: f64,
    /// Peripheral (contact-point) velocity after the impact \[mm/s\].
    pub peripheral_velocity_mm_per_s: f64,
    /// Kinetic energy lost \[N·mm\].
    pub energy_loss_nmm: f64,
}

/// The elastic oblique rebound (Maw, Barber and Fawcett) in an [`ImpactReport`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ElasticReport {
    /// Incident peripheral velocity, non-dimensional: `psi1 = kappa w1/(mu V)` \[-\].
    pub psi1: f64,
    /// Rebound peripheral velocity, non-dimensional: `psi2 = kappa w2/(mu V)` \[-\].
    pub psi2: f64,
    /// Tangential velocity of the centre after the impact \[mm/s\].
    pub tangential_velocity_mm_per_s: f64,
    /// Angular velocity after the impact \[rad/s\].
    pub angular_velocity_rad_per_s: f64,
    /// Peripheral velocity after the impact \[mm/s\].
    pub peripheral_velocity_mm_per_s: f64,
    /// Largest tangential force \[N\].
    pub max_tangential_force_n: f64,
    /// Kinetic energy lost to friction \[N·mm\].
    pub energy_loss_nmm: f64,
    /// Whether the whole contact slid throughout the impact.
    pub slid_throughout: bool,
}

/// The result of an impact case. Keys carry their units.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ImpactReport {
    /// Version of kontakt that produced the record.
    pub kontakt_version: &'static str,
    /// Version of this schema.
    pub schema_version: u32,
    /// The case's name, if any.
    pub name: Option<String>,
    /// `"impact"`.
    pub method: &'static str,
    /// Mass of the sphere \[t\].
    pub mass_t: f64,
    /// Contact modulus E* \[MPa\].
    pub e_star_mpa: f64,
    /// Incident tangential velocity of the centre \[mm/s\].
    pub tangential_velocity_mm_per_s: f64,
    /// Incident peripheral velocity `w1 = u1 + omega1 R` \[mm/s\].
    pub peripheral_velocity_mm_per_s: f64,
    /// The normal impact.
    pub normal: NormalImpactReport,
    /// Stiffness ratio `kappa = 4 G*/E*` \[-\] (with friction).
    pub kappa: Option<f64>,
    /// Maw, Barber and Fawcett's `chi = (kappa/2)(1 + R²/k²)` \[-\] (with friction).
    pub chi: Option<f64>,
    /// The rigid-body rebound (with friction).
    pub rigid: Option<RigidReport>,
    /// The elastic rebound (with friction).
    pub elastic: Option<ElasticReport>,
    /// Results to treat with care: a contact large against the sphere's radius. Absent
    /// when none applies.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub warnings: Vec<String>,
    /// The largest contact's size against the sphere, for the validity check
    /// ([`crate::validity`]); not in the JSON.
    #[serde(skip)]
    pub contacts: Vec<ContactSize>,
}

checked_report!(ImpactReport);

impl ImpactCase {
    /// Parse an impact case from TOML text.
    ///
    /// # Errors
    /// [`Error::CaseFile`] (line, key path, what the schema takes) for malformed TOML,
    /// unknown keys or wrong types.
    pub fn from_toml_str(text: &str) -> Result<Self> {
        parse_toml(text)
    }
}

/// Run an impact case.
///
/// # Errors
/// [`Error::InvalidInput`] naming the case key (`impact.speed_mm_per_s` zero, negative or
/// not finite, `impact.angle_deg` outside (-90, 90), `sphere.radius_mm`, `sphere.mass_t`,
/// `friction.mu`, `friction.restitution`, ...), and an oblique or spinning impact without
/// `[friction]`.
pub fn run_impact_case(case: &ImpactCase) -> Result<ImpactReport> {
    checked(run_impact_case_unchecked(case)?)
}

/// [`run_impact_case`] before the validity check of [`crate::validity::checked`].
pub(crate) fn run_impact_case_unchecked(case: &ImpactCase) -> Result<ImpactReport> {
    if case.method != "impact" {
        return Err(Error::invalid(
            "method",
            &case.method,
            "\"impact\" for this schema",
        ));
    }
    let s = case.sphere;
    let sphere_material = material(
        &MaterialSpec {
            e_mpa: s.e_mpa,
            nu: s.nu,
        },
        "sphere",
    )?;
    let flat_material = material(&case.flat, "flat")?;
    // The library's argument names as the case file spells them.
    let rename = |e: Error| {
        e.map_field(|f| match f {
            "radius" => "sphere.radius_mm".into(),
            "density" => "sphere.density_t_per_mm3".into(),
            "mass" => "sphere.mass_t".into(),
            "radius_of_gyration" => "sphere.radius_of_gyration_mm".into(),
            "speed" | "normal_speed" => "impact.speed_mm_per_s".into(),
            "incidence_angle" => "impact.angle_deg".into(),
            "angular_velocity" => "impact.spin_rad_per_s".into(),
            "friction_coefficient" => "friction.mu".into(),
            "restitution" => "friction.restitution".into(),
            "materials" => "sphere, flat".into(),
            other => other.into(),
        })
    };
    let mass = match (s.density_t_per_mm3, s.mass_t) {
        (Some(rho), None) => sphere_mass(s.radius_mm, rho).map_err(rename)?,
        (None, Some(m)) => kontakt::error::positive_as("sphere.mass_t", m, "a finite mass > 0 t")?,
        (d, _) => {
            return Err(Error::invalid(
                "sphere",
                if d.is_some() {
                    "both density_t_per_mm3 and mass_t"
                } else {
                    "neither density_t_per_mm3 nor mass_t"
                },
                "exactly one of density_t_per_mm3 [t/mm^3] or mass_t [t]",
            ));
        }
    };
    let body = match s.radius_of_gyration_mm {
        None => SphereBody::solid_sphere(s.radius_mm, mass),
        Some(k) => SphereBody::new(s.radius_mm, mass, k),
    }
    .map_err(rename)?;
    let i = case.impact;
    if !(i.angle_deg.is_finite() && i.angle_deg.abs() < 90.0) {
        return Err(Error::invalid(
            "impact.angle_deg",
            i.angle_deg,
            "-90 < angle < 90 deg (from the normal of the flat)",
        ));
    }
    let incident =
        IncidentMotion::from_angle(i.speed_mm_per_s, i.angle_deg.to_radians(), i.spin_rad_per_s)
            .map_err(rename)?;
    let e_star = effective_modulus(&sphere_material, &flat_material);
    // A sphere on a flat at rest: the effective radius is the sphere's, the effective mass
    // the sphere's (the flat's is infinite).
    let hertz = HertzImpact::sphere(s.radius_mm, e_star, mass, incident.normal_speed())
        .map_err(rename)?
        .result();
    let normal = NormalImpactReport {
        normal_speed_mm_per_s: incident.normal_speed(),
        contact_duration_s: hertz.contact_duration,
        max_force_n: hertz.max_force,
        max_approach_mm: hertz.max_approach,
        max_contact_radius_mm: hertz.max_contact_radius,
        max_pressure_mpa: hertz.max_pressure,
    };
    // The largest contact (at the largest approach) against the sphere's radius; the
    // flat does not limit it. Refused before the oblique analyses.
    let contacts: Vec<ContactSize> = hertz
        .max_contact_radius
        .map(|a| {
            ContactSize::new(
                Size::Hertz(SizeCheck {
                    ratio: a / s.radius_mm,
                    body: 1,
                    extent: a,
                    radius: s.radius_mm,
                    direction: 0.0,
                }),
                ["sphere.radius_mm", "flat"],
            )
            .at("impact, at the largest approach")
        })
        .into_iter()
        .collect();
    for c in &contacts {
        c.verdict()?;
    }
    let w1 = incident.peripheral_velocity(s.radius_mm);
    let (kappa, chi, rigid, elastic) = match case.friction {
        None if w1 != 0.0 => {
            return Err(Error::invalid(
                "friction",
                "missing",
                "a [friction] table (mu) for an oblique or spinning impact",
            ));
        }
        None => (None, None, None, None),
        Some(f) => {
            let rigid = RigidObliqueImpact::new(body, f.mu, f.restitution)
                .and_then(|r| r.rebound(&incident))
                .map_err(rename)?;
            let model = ElasticObliqueImpact::new(
                body,
                sphere_material,
                flat_material,
                f.mu,
                ElasticImpactOptions::default(),
            )
            .map_err(rename)?;
            let el = model.rebound(&incident).map_err(rename)?;
            (
                Some(model.kappa()),
                Some(model.chi()),
                Some(RigidReport {
                    regime: match rigid.regime {
                        RigidRegime::GrossSliding => "gross_sliding",
                        RigidRegime::SlidingThenRolling => "sliding_then_rolling",
                    },
                    normal_velocity_mm_per_s: rigid.normal_velocity,
                    tangential_velocity_mm_per_s: rigid.tangential_velocity,
                    angular_velocity_rad_per_s: rigid.angular_velocity,
                    peripheral_velocity_mm_per_s: rigid.peripheral_velocity,
                    energy_loss_nmm: rigid.energy_loss,
                }),
                Some(ElasticReport {
                    psi1: el.psi1,
                    psi2: el.psi2,
                    tangential_velocity_mm_per_s: el.tangential_velocity,
                    angular_velocity_rad_per_s: el.angular_velocity,
                    peripheral_velocity_mm_per_s: el.peripheral_velocity,
                    max_tangential_force_n: el.max_tangential_force,
                    energy_loss_nmm: el.energy_loss,
                    slid_throughout: el.slid_throughout,
                }),
            )
        }
    };
    Ok(ImpactReport {
        kontakt_version: kontakt::VERSION,
        schema_version: SCHEMA_VERSION,
        name: case.name.clone(),
        method: "impact",
        mass_t: mass,
        e_star_mpa: e_star,
        tangential_velocity_mm_per_s: incident.tangential_velocity(),
        peripheral_velocity_mm_per_s: w1,
        normal,
        kappa,
        chi,
        rigid,
        elastic,
        warnings: Vec::new(),
        contacts,
    })
}
