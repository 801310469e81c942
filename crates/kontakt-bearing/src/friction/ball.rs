//! The friction torque and power of a ball bearing (deep groove or angular contact),
//! contact by contact, from a solved ball load distribution (quasi-static,
//! [`crate::ball_equilibrium`], or at speed, [`crate::ball_speed`]; issue 29 §1-2).
//!
//! Every ball has an inner and an outer raceway contact, each with its own load Q and
//! contact angle α. For each loaded contact this module takes
//!
//! 1. the Hertz ellipse (`kontakt::hertz`, the contacts of [`BallBearing::contacts`] at α):
//!    semi-axes a ≥ b, the major axis across the rolling direction, central pressure p₀;
//! 2. the rigid-body kinematics of the ball (below): the sliding velocity of the ball
//!    relative to the ring over the ellipse, spin and Heathcote's differential slip;
//! 3. the film: the Hamrock & Dowson (1977) central film of the ellipse (entrainment along
//!    the rolling direction), times the Zhu-Cheng inlet-heating factor (when the viscosity's
//!    temperature slope is given) and the starvation factor; Λ = h_c/σ;
//! 4. the traction: the existing friction integral over the Hertz ellipse
//!    (`kontakt::friction::ellipse_friction_curved`: the mixed law with that film, its
//!    φ(Λ) load sharing, boundary Coulomb part and fluid part), which gives the sliding
//!    power `P_s = −∫ τ · v dA`;
//! 5. the rolling resistance of the EHL point contact by strips: the ellipse cut across its
//!    major axis into line contacts of load per length `w(y) = (π/2) p₀ b (1 − y²/a²)` and
//!    reduced radius R_x (rolling direction), each with the line-contact rolling resistance
//!    of the raceway model ([`RacewayLosses::slice`]: Biboulet & Houpert 2010 or Zhou &
//!    Hoeprich 1991, with its thermal and starvation factors), power `2 F_r u`. The strip
//!    sum neglects the side leakage of the point contact (an upper estimate of the
//!    hydrodynamic rolling force; `docs/bearing-friction.md`, "Ball bearings").
//!
//! # Kinematics (the ball's axial plane `(e_r, e_z)` and the tangent `e_t = e_z × e_r`)
//!
//! In the cage frame (cage speed ω_c) the inner ring turns at `Ω_i = ω_i − ω_c`, the outer
//! at `Ω_o = ω_o − ω_c` about +z, the ball at ω_R about its axis `a = (−sin β, cos β)`
//! through its centre C at the pitch radius. ω_c, ω_R follow from rolling without slip at
//! both contact centres ([`crate::speed::kinematics`], Jones 1960), β from the race
//! control ([`BallAttitude`]). Contact ρ (α_ρ, normal `n = (cos α, sin α)`, transverse
//! tangent `t = (−sin α, cos α)`, `(e_t, t, n)` right-handed) has the relative angular
//! velocity `W = ω_R a − Ω_ρ e_z`:
//!
//! ```text
//! W·n = ω_s = ω_R sin(α − β) − Ω_ρ sin α        (spin),
//! W·t = ω_y = ω_R cos(α − β) − Ω_ρ cos α        (roll about the transverse axis).
//! ```
//!
//! A point of the contact at `(x, y)` (x along e_t, y along t) lies on the deformed surface
//! of transverse radius `R_c = 2 f D/(2f + 1)` (Harris & Kotzalas 2006: the harmonic mean of
//! the ball's and the groove's radii), displaced `ζ = y²/(2 R_c)` towards the ball centre.
//! The sliding of ball over ring `v = v₀ + W × (x e_t + y t + ζ d)` (d = −n outer, +n
//! inner) has the tangential components
//!
//! ```text
//! v_x(x, y) = v₀ − ω_s y + s ω_y y²/(2 R_c),     v_y(x, y) = ω_s x,     s = ∓1 (outer, inner),
//! ```
//!
//! v₀ the sliding at the centre (0 for the Jones kinematics). The first term pair is the
//! spin, the quadratic one Heathcote's (1921) differential slip; with Coulomb friction and
//! no spin the force balance of the strips gives the two lines of pure rolling at
//! `y = ±c a`, `c³ − 3c + 1 = 0`, `c = 2 cos(4π/9) = 0.3473` (tested against the field).
//! Under outer-race control `ω_s = 0` at the outer contact: `tan β = sin α_o/(cos α_o + γ)`;
//! under inner-race control at the inner: `tan β = sin α_i/(cos α_i − γ)`, `γ = D/d_m`.
//!
//! # Torques
//!
//! As for rollers ([`super::torque`]): with the balls and cage in steady state and the cage
//! torque-free, the power the rings receive is `M (ω_i − ω_o)`, so each source's share of
//! the bearing torque is its power over `|ω_i − ω_o|`: `M_inner-race = Σ P_i/|Δω|`,
//! `M_outer-race = Σ P_o/|Δω|`, `M = M_inner-race + M_outer-race + M_drag`; the drive torque
//! on the inner ring is `M sign(ω_i − ω_o)`, on the outer ring its negative.
//!
//! **Starting torque** (`Δω = 0`): no film, no rolling resistance; each contact carries
//! exact Coulomb friction μ_b (no regularisation) over the sliding field of unit Δω (inner
//! ring at 1 rad/s): Coulomb power is homogeneous of degree one in the speed, so this power
//! over 1 rad/s is the limit of the torque as Δω → 0 (no division by zero).
//!
//! Units: mm, N, MPa, mm/s, rad/s; torques N·mm; power W.

use super::raceway::{RacewayLosses, RacewaySlice};
use super::torque::{DragModel, PowerBreakdown, RacewayTorque};
use crate::ball_equilibrium::BallLoad;
use crate::ball_speed::BallSpeedLoad;
use crate::geometry::BallBearing;
use crate::speed::{RingSpeeds, kinematics, outer_race_control_pitch};
use kontakt::friction::{
    EllipseRule, FilmState, FluidShear, FrictionLaw, LoadSharing, ellipse_friction_curved,
};
use kontakt::geometry::VelocityField;
use kontakt::lubrication::{
    FilmContact, FilmFormula, film_thickness, thermal_loading, zhu_cheng_thermal_factor,
};
use kontakt::{Error, Result};

/// Radial × angular nodes of the traction rule over each ellipse (`EllipseRule::new`).
pub const TRACTION_RULE: (usize, usize) = (16, 32);

/// Gauss-Legendre strips across the major axis for the rolling resistance.
pub const ROLLING_STRIPS: usize = 12;

/// Which contact the ball's axis is set by (the spin-free contact).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum BallAttitude {
    /// Outer-race control (Jones 1960), as the at-speed model assumes
    /// ([`crate::ball_speed::RaceControl`]): no spin at the outer contact,
    /// `tan β = sin α_o/(cos α_o + γ)`.
    #[default]
    OuterRaceControl,
    /// Inner-race control: no spin at the inner contact, `tan β = sin α_i/(cos α_i − γ)`.
    InnerRaceControl,
}

impl BallAttitude {
    /// The pitch β \[rad\] of the ball's axis for `γ = D/d_m` and the contact angles
    /// α_i, α_o \[rad\].
    pub fn pitch(self, gamma: f64, alpha_i: f64, alpha_o: f64) -> f64 {
        match self {
            BallAttitude::OuterRaceControl => outer_race_control_pitch(gamma, alpha_o),
            BallAttitude::InnerRaceControl => {
                let (s, c) = alpha_i.sin_cos();
                s.atan2(c - gamma)
            }
        }
    }
}

/// One ball's contacts as the friction takes them.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct BallContacts {
    /// Azimuth ψ \[rad\].
    pub azimuth_rad: f64,
    /// Inner raceway load Q_i \[N\], ≥ 0.
    pub inner_load_n: f64,
    /// Outer raceway load Q_o \[N\], ≥ 0.
    pub outer_load_n: f64,
    /// Inner contact angle α_i \[rad\].
    pub inner_contact_angle_rad: f64,
    /// Outer contact angle α_o \[rad\].
    pub outer_contact_angle_rad: f64,
}

impl From<&BallLoad> for BallContacts {
    /// A quasi-static ball: one load and one contact angle on both raceways.
    fn from(b: &BallLoad) -> Self {
        BallContacts {
            azimuth_rad: b.azimuth_rad,
            inner_load_n: b.load_n,
            outer_load_n: b.load_n,
            inner_contact_angle_rad: b.contact_angle_rad,
            outer_contact_angle_rad: b.contact_angle_rad,
        }
    }
}

impl From<&BallSpeedLoad> for BallContacts {
    /// A ball at speed: its own two loads and contact angles.
    fn from(b: &BallSpeedLoad) -> Self {
        BallContacts {
            azimuth_rad: b.azimuth_rad,
            inner_load_n: b.inner_load_n,
            outer_load_n: b.outer_load_n,
            inner_contact_angle_rad: b.inner_contact_angle_rad,
            outer_contact_angle_rad: b.outer_contact_angle_rad,
        }
    }
}

/// The kinematics of one contact in the cage frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactKinematics {
    /// Inner (true) or outer (false) raceway.
    pub inner: bool,
    /// Contact angle α \[rad\].
    pub contact_angle_rad: f64,
    /// The ring's speed relative to the cage Ω = ω_ring − ω_c \[rad/s\].
    pub ring_speed_rad_s: f64,
    /// The ball's speed ω_R about its axis relative to the cage \[rad/s\].
    pub ball_speed_rad_s: f64,
    /// The pitch β of the ball's axis \[rad\].
    pub pitch_rad: f64,
}

/// The sliding field of one contact (module docs): `v_x = v₀ − ω_s y + q y²`,
/// `v_y = ω_s x` in the contact frame (x rolling, y across).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlidingField {
    /// Sliding of the ball over the ring at the centre v₀ \[mm/s\].
    pub centre_mm_s: f64,
    /// Spin ω_s = W·n \[rad/s\].
    pub spin_rad_s: f64,
    /// Roll about the transverse axis ω_y = W·t \[rad/s\].
    pub roll_rad_s: f64,
    /// The differential-slip coefficient `q = s ω_y/(2 R_c)` \[1/(mm·s)\].
    pub curvature: f64,
    /// The ball's surface speed at the centre (along e_t) \[mm/s\].
    pub ball_surface_mm_s: f64,
    /// The ring's surface speed at the centre \[mm/s\].
    pub ring_surface_mm_s: f64,
}

impl SlidingField {
    /// Entrainment speed u = (|u_ball| + |u_ring|)/2 \[mm/s\].
    pub fn entrainment_mm_s(&self) -> f64 {
        0.5 * (self.ball_surface_mm_s.abs() + self.ring_surface_mm_s.abs())
    }

    /// The affine part as the friction integral's field (x rolling, y across).
    pub fn velocity_field(&self) -> VelocityField {
        let u = self.entrainment_mm_s();
        VelocityField {
            sliding: [
                [self.centre_mm_s, 0.0],
                [0.0, self.spin_rad_s],
                [-self.spin_rad_s, 0.0],
            ],
            entrainment: [[u, 0.0], [0.0, 0.0], [0.0, 0.0]],
        }
    }
}

/// The sliding field of a contact of a ball of diameter `ball_diameter` D \[mm\] on the
/// pitch diameter `pitch_diameter` d_m \[mm\], groove osculation `osculation` f, with the
/// kinematics `k` (module docs). No checks, no allocation.
pub fn sliding_field(
    ball_diameter: f64,
    pitch_diameter: f64,
    osculation: f64,
    k: &ContactKinematics,
) -> SlidingField {
    let (d, dm) = (ball_diameter, pitch_diameter);
    let (sa, ca) = k.contact_angle_rad.sin_cos();
    let diff = k.contact_angle_rad - k.pitch_rad;
    let (wr, om) = (k.ball_speed_rad_s, k.ring_speed_rad_s);
    let spin = wr * diff.sin() - om * sa;
    let roll = wr * diff.cos() - om * ca;
    let rc = 2.0 * osculation * d / (2.0 * osculation + 1.0);
    // Outer: the contact at C + (D/2) n, the surface bends to −n; inner: C − (D/2) n, +n.
    let (sign, ball, ring) = if k.inner {
        (1.0, -wr * 0.5 * d * diff.cos(), om * 0.5 * (dm - d * ca))
    } else {
        (-1.0, wr * 0.5 * d * diff.cos(), om * 0.5 * (dm + d * ca))
    };
    SlidingField {
        centre_mm_s: ball - ring,
        spin_rad_s: spin,
        roll_rad_s: roll,
        curvature: sign * roll / (2.0 * rc),
        ball_surface_mm_s: ball,
        ring_surface_mm_s: ring,
    }
}

/// The losses of one ball-raceway contact.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct BallContactLosses {
    /// Normal load Q \[N\].
    pub load_n: f64,
    /// Contact angle α \[rad\].
    pub contact_angle_rad: f64,
    /// Hertz semi-axes `[a, b]` \[mm\] (a across the rolling direction).
    pub semi_axes_mm: [f64; 2],
    /// Central Hertz pressure p₀ \[MPa\].
    pub max_pressure_mpa: f64,
    /// Spin ω_s \[rad/s\].
    pub spin_rad_s: f64,
    /// Roll about the transverse axis ω_y \[rad/s\].
    pub roll_rad_s: f64,
    /// Sliding at the centre v₀ \[mm/s\].
    pub centre_sliding_mm_s: f64,
    /// Bound of the sliding speed over the ellipse `|v₀| + |ω_s| a + |q| a²` \[mm/s\].
    pub max_sliding_mm_s: f64,
    /// Entrainment speed u \[mm/s\].
    pub entrainment_mm_s: f64,
    /// Central film φ_T φ_s h_c \[mm\] (Hamrock & Dowson 1977; 0 at standstill).
    pub central_film_mm: f64,
    /// Film parameter Λ = h_c/σ.
    pub lambda: f64,
    /// Asperity share φ(Λ).
    pub asperity_share: f64,
    /// Zhu-Cheng thermal factor φ_T (1 if isothermal).
    pub thermal_factor: f64,
    /// Traction on the ball `[along rolling, across]` \[N\].
    pub traction_n: [f64; 2],
    /// The traction's moment on the ball about the contact normal (spin moment) \[N·mm\].
    pub spin_moment_nmm: f64,
    /// Sliding power `−∫ τ·v dA` \[W\] (starting: per rad/s of Δω).
    pub sliding_w: f64,
    /// Rolling-resistance force Σ strips \[N\].
    pub rolling_force_n: f64,
    /// Rolling-resistance power `2 F_r u` \[W\].
    pub rolling_w: f64,
    /// The point-contact film formula left its fitted range.
    pub film_out_of_range: bool,
    /// Rolling-resistance strips whose line film left its fitted range.
    pub film_out_of_range_strips: usize,
}

impl BallContactLosses {
    /// Total power \[W\].
    pub fn power_w(&self) -> f64 {
        self.sliding_w + self.rolling_w
    }
}

/// One ball's losses and kinematics.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct BallFriction {
    /// Ball index j.
    pub ball: usize,
    /// Azimuth ψ \[rad\].
    pub azimuth_rad: f64,
    /// Cage speed ω_c \[rad/s\].
    pub cage_speed_rad_s: f64,
    /// The ball's speed about its axis relative to the cage ω_R \[rad/s\].
    pub ball_speed_rad_s: f64,
    /// Pitch β of its axis \[rad\].
    pub pitch_rad: f64,
    /// Inner contact.
    pub inner: BallContactLosses,
    /// Outer contact.
    pub outer: BallContactLosses,
    /// The ball's share of the bearing torque \[N·mm\].
    pub torque_nmm: f64,
}

impl BallFriction {
    /// Total power of both contacts \[W\].
    pub fn power_w(&self) -> f64 {
        self.inner.power_w() + self.outer.power_w()
    }
}

/// Validity flags of a ball-bearing friction evaluation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct BallFrictionWarnings {
    /// Loaded contacts whose Hamrock-Dowson film left its fitted range.
    pub film_out_of_range_contacts: usize,
    /// Rolling-resistance strips whose line film left its fitted range.
    pub film_out_of_range_strips: usize,
    /// A starvation degree below Biboulet & Houpert's computed range.
    pub starvation_extrapolated: bool,
    /// The rings do not turn relative to each other: the result is the starting torque.
    pub starting: bool,
}

impl BallFrictionWarnings {
    /// One sentence per raised flag (allocates; for reports).
    pub fn lines(&self) -> Vec<String> {
        let mut out = Vec::new();
        if self.film_out_of_range_contacts > 0 {
            out.push(format!(
                "{} loaded ball contacts outside the Hamrock-Dowson fit (ellipticity 1 <= k <= 8): films extrapolated",
                self.film_out_of_range_contacts
            ));
        }
        if self.film_out_of_range_strips > 0 {
            out.push(format!(
                "{} rolling-resistance strips outside the Dowson-Higginson fit: extrapolated",
                self.film_out_of_range_strips
            ));
        }
        if self.starvation_extrapolated {
            out.push("starvation degree below Biboulet & Houpert's computed range (S < 2)".into());
        }
        if self.starting {
            out.push("the rings do not turn relative to each other: starting torque (boundary friction of the ball contacts' spin and differential slip, no film)".into());
        }
        out
    }
}

/// A ball bearing's friction at one operating point.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct BallBearingFriction {
    /// Inner ring speed ω_i \[rad/s\].
    pub inner_speed_rad_s: f64,
    /// Outer ring speed ω_o \[rad/s\].
    pub outer_speed_rad_s: f64,
    /// Inner-race contacts' share of the bearing torque \[N·mm\].
    pub inner_race: RacewayTorque,
    /// Outer-race contacts' share \[N·mm\].
    pub outer_race: RacewayTorque,
    /// Drag share \[N·mm\].
    pub drag_nmm: f64,
    /// The bearing torque \[N·mm\] (the starting torque at Δω = 0).
    pub total_nmm: f64,
    /// Torque the drive applies to the inner ring, `M sign(ω_i − ω_o)` \[N·mm\].
    pub inner_ring_nmm: f64,
    /// Torque on the outer ring, `−inner_ring_nmm` \[N·mm\] (free cage).
    pub outer_ring_nmm: f64,
    /// Power per source \[W\] (`rib_w` = 0; zero at standstill).
    pub power: PowerBreakdown,
    /// The largest |ω_s| over the loaded contacts \[rad/s\] (per rad/s of Δω at
    /// standstill).
    pub largest_spin_rad_s: f64,
    /// Bearing friction coefficient μ = M/(P d/2) (`None` without a basis).
    pub coefficient: Option<f64>,
    /// Smallest Λ over the loaded contacts (∞ without load or at standstill).
    pub min_lambda: f64,
    /// Validity flags.
    pub warnings: BallFrictionWarnings,
}

/// The operating point of [`BallFrictionModel::evaluate`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BallFrictionOperating<'a> {
    /// Inner ring speed ω_i \[rad/s\].
    pub inner_speed: f64,
    /// Outer ring speed ω_o \[rad/s\].
    pub outer_speed: f64,
    /// Every ball's contacts (length Z).
    pub balls: &'a [BallContacts],
    /// Drag.
    pub drag: DragModel,
    /// The load P of the friction coefficient \[N\] and the bore d \[mm\].
    pub coefficient_basis: Option<(f64, f64)>,
}

/// The contact angles `(α_i, α_o)` \[rad\] of the ball's kinematics: its own where both
/// contacts are loaded; the loaded contact's on both where the other is open (the angle
/// the solver reports for an open contact is only the direction of its gap, up to π; the
/// at-speed solver's kinematics pass to the loaded contact's angle there too); `free`, the
/// bearing's free contact angle, for an idle ball.
///
/// # Errors
/// `inner_contact_angle_rad` / `outer_contact_angle_rad` for a loaded contact at |α| ≥ π/2
/// (no bearing geometry has one).
fn kinematic_angles(c: &BallContacts, free: f64) -> Result<(f64, f64)> {
    for (field, q, a) in [
        (
            "inner_contact_angle_rad",
            c.inner_load_n,
            c.inner_contact_angle_rad,
        ),
        (
            "outer_contact_angle_rad",
            c.outer_load_n,
            c.outer_contact_angle_rad,
        ),
    ] {
        if q > 0.0 && a.abs() >= std::f64::consts::FRAC_PI_2 {
            return Err(Error::invalid(
                field,
                a,
                "a contact angle of a loaded contact within ±π/2 rad",
            ));
        }
    }
    let (ai, ao) = (c.inner_contact_angle_rad, c.outer_contact_angle_rad);
    Ok(match (c.inner_load_n > 0.0, c.outer_load_n > 0.0) {
        (true, true) => (ai, ao),
        (false, true) => (ao, ao),
        (true, false) => (ai, ai),
        (false, false) => (free, free),
    })
}

/// The friction model of a ball bearing: lubrication checked, the rules and the per-ball
/// buffer built once; [`BallFrictionModel::evaluate`] allocates nothing.
#[derive(Debug, Clone)]
pub struct BallFrictionModel {
    bearing: BallBearing,
    losses: RacewayLosses,
    attitude: BallAttitude,
    rule: EllipseRule,
    /// Strips `(sin θ, weight · cos θ)` on θ ∈ (−π/2, π/2), y = a sin θ.
    strips: [(f64, f64); ROLLING_STRIPS],
    balls: Vec<BallFriction>,
}

impl BallFrictionModel {
    /// Check the bearing and the lubrication and build the model.
    ///
    /// # Errors
    /// Those of [`BallBearing::validate`] and [`RacewayLosses::new`].
    pub fn new(
        bearing: BallBearing,
        losses: RacewayLosses,
        attitude: BallAttitude,
    ) -> Result<Self> {
        bearing.validate()?;
        let (radial, angular) = TRACTION_RULE;
        let rule = EllipseRule::new(radial, angular)?;
        let mut strips = [(0.0, 0.0); ROLLING_STRIPS];
        let half_pi = std::f64::consts::FRAC_PI_2;
        for (slot, (x, w)) in strips
            .iter_mut()
            .zip(kontakt::quadrature::gauss_legendre(ROLLING_STRIPS))
        {
            let (s, c) = (half_pi * x).sin_cos();
            *slot = (s, w * half_pi * c);
        }
        Ok(BallFrictionModel {
            balls: vec![BallFriction::default(); bearing.balls],
            bearing,
            losses,
            attitude,
            rule,
            strips,
        })
    }

    /// The bearing.
    pub fn bearing(&self) -> &BallBearing {
        &self.bearing
    }

    /// The race control.
    pub fn attitude(&self) -> BallAttitude {
        self.attitude
    }

    /// Every ball's losses of the last evaluation.
    pub fn balls(&self) -> &[BallFriction] {
        &self.balls
    }

    /// The losses of one contact with the kinematics `k` under the load `load` Q \[N\];
    /// `starting`: exact Coulomb friction μ_b, no film, no rolling resistance. Allocates
    /// nothing.
    ///
    /// # Errors
    /// `load` (finite, ≥ 0); the Hertz contact's (`inner_osculation` /
    /// `outer_osculation`), the film's and the friction integral's fields.
    pub fn contact(
        &self,
        k: &ContactKinematics,
        load: f64,
        starting: bool,
    ) -> Result<BallContactLosses> {
        if !(load.is_finite() && load >= 0.0) {
            return Err(Error::invalid("load", load, "a finite ball load >= 0 N"));
        }
        let b = &self.bearing;
        let (d, dm) = (b.ball_diameter_mm, b.pitch_diameter_mm);
        let f = if k.inner {
            b.inner_osculation
        } else {
            b.outer_osculation
        };
        let field = sliding_field(d, dm, f, k);
        let mut out = BallContactLosses {
            load_n: load,
            contact_angle_rad: k.contact_angle_rad,
            spin_rad_s: field.spin_rad_s,
            roll_rad_s: field.roll_rad_s,
            centre_sliding_mm_s: field.centre_mm_s,
            entrainment_mm_s: field.entrainment_mm_s(),
            thermal_factor: 1.0,
            ..Default::default()
        };
        if load == 0.0 {
            return Ok(out);
        }
        let [inner, outer] = b.contacts(k.contact_angle_rad)?;
        let hertz = if k.inner { inner } else { outer };
        let sol = hertz.solve_force(load)?;
        let [a, bb] = sol.semi_axes;
        let p0 = sol.max_pressure;
        // The transverse semi-axis (across the rolling direction x).
        let (s_y, s_x) = if sol.orientation.sin().abs() > std::f64::consts::FRAC_1_SQRT_2 {
            (a, bb)
        } else {
            (bb, a)
        };
        out.semi_axes_mm = [s_y, s_x];
        out.max_pressure_mpa = p0;
        out.max_sliding_mm_s = field.centre_mm_s.abs()
            + field.spin_rad_s.abs() * a
            + field.curvature.abs() * s_y * s_y;
        let vf = field.velocity_field();
        let lub = self.losses.lubrication();
        let e_star = hertz.e_star();
        let cell = if starting {
            FrictionLaw {
                boundary_coefficient: lub.law.boundary_coefficient,
                sharing: LoadSharing::Boundary,
                fluid: FluidShear::None,
                regularisation_speed: 0.0,
            }
            .with_film(&FilmState::dry())?
        } else {
            let u = out.entrainment_mm_s;
            let c = 2.0 / d;
            let cos_a = k.contact_angle_rad.cos();
            // Ring curvature along the rolling direction: ±cos α/(d_m/2 ∓ (D/2) cos α).
            let ring = if k.inner {
                2.0 * cos_a / (dm - d * cos_a)
            } else {
                -2.0 * cos_a / (dm + d * cos_a)
            };
            let rx = 1.0 / (c + ring);
            let ry = 1.0 / (c - 1.0 / (f * d));
            let film = film_thickness(
                &FilmContact {
                    rx,
                    ry,
                    entrainment_angle: 0.0,
                    entrainment_speed: u,
                    load,
                    reduced_modulus: e_star,
                },
                lub.viscosity,
                lub.alpha,
                FilmFormula::HamrockDowson,
            )?;
            out.film_out_of_range =
                film.warnings.ellipticity_above_fit || film.warnings.ellipticity_below_fit;
            out.thermal_factor = match lub.viscosity_slope {
                Some(slope) if u > 0.0 => {
                    let lt = thermal_loading(slope, u, lub.conductivity)?;
                    zhu_cheng_thermal_factor(p0, e_star, lt, out.max_sliding_mm_s / u)?
                }
                _ => 1.0,
            };
            let h = out.thermal_factor * lub.film_starvation * film.central;
            out.central_film_mm = h;
            out.lambda = h / lub.roughness;
            let state = if h > 0.0 {
                FilmState::new(h, out.lambda, lub.viscosity, lub.alpha)?
            } else {
                FilmState::dry()
            };
            (
                out.rolling_force_n,
                out.rolling_w,
                out.film_out_of_range_strips,
            ) = self.rolling(s_y, s_x, p0, rx, u, e_star)?;
            lub.law.with_film(&state)?
        };
        out.asperity_share = cell.asperity_share();
        let fr = ellipse_friction_curved(
            sol.semi_axes,
            sol.orientation,
            p0,
            &vf,
            [field.curvature, 0.0],
            &cell,
            &self.rule,
        )?;
        out.traction_n = fr.force;
        out.spin_moment_nmm = fr.moment;
        out.sliding_w = fr.power;
        Ok(out)
    }

    /// The rolling resistance `(F_r [N], power [W], strips out of their film fit)` of the ellipse by strips across the
    /// transverse semi-axis `s_y` (rolling half-width `s_x`), reduced radius `rx` along the
    /// rolling direction, entrainment `u`, modulus `e_star`.
    fn rolling(
        &self,
        s_y: f64,
        s_x: f64,
        p0: f64,
        rx: f64,
        u: f64,
        e_star: f64,
    ) -> Result<(f64, f64, usize)> {
        let (mut force, mut power, mut flagged) = (0.0, 0.0, 0);
        let peak = std::f64::consts::FRAC_PI_2 * p0 * s_x;
        for &(s, wc) in &self.strips {
            // y = s_y sin θ: w = (π/2) p₀ s_x cos² θ, dy = s_y cos θ dθ.
            let slice = RacewaySlice {
                load_per_length: peak * (1.0 - s * s),
                width: s_y * wc,
                radius: rx,
                entrainment_speed: u,
                sliding_speed: 0.0,
                reduced_modulus: e_star,
            };
            let l = self.losses.slice(&slice)?;
            force += l.rolling_force;
            power += l.rolling_power;
            flagged += usize::from(!l.warnings.film.is_empty());
        }
        Ok((force, power, flagged))
    }

    /// The friction of the bearing at `op`. Writes every ball's losses (see
    /// [`BallFrictionModel::balls`]); allocates nothing.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the field: `inner_speed`, `outer_speed` (finite),
    /// `balls` (length Z), `inner_load_n` / `outer_load_n` (finite, ≥ 0), the contact
    /// angles (finite), `drag` (finite, ≥ 0), and those of [`BallFrictionModel::contact`].
    pub fn evaluate(&mut self, op: &BallFrictionOperating<'_>) -> Result<BallBearingFriction> {
        let z = self.bearing.balls;
        for (field, v) in [
            ("inner_speed", op.inner_speed),
            ("outer_speed", op.outer_speed),
        ] {
            if !v.is_finite() {
                return Err(Error::invalid(field, v, "a finite speed in rad/s"));
            }
        }
        if op.balls.len() != z {
            return Err(Error::invalid(
                "balls",
                op.balls.len(),
                format!("{z} balls (one entry per ball)"),
            ));
        }
        let drag_nmm = op.drag.torque_nmm()?;
        let dw = op.inner_speed - op.outer_speed;
        let starting = dw == 0.0;
        let speeds = if starting {
            RingSpeeds::new(1.0, 0.0)
        } else {
            RingSpeeds::new(op.inner_speed, op.outer_speed)
        };
        let (d, dm) = (
            self.bearing.ball_diameter_mm,
            self.bearing.pitch_diameter_mm,
        );
        let scale = if starting { 1e3 } else { 1e3 / dw.abs() };
        let mut warnings = BallFrictionWarnings {
            starting,
            ..Default::default()
        };
        let (mut inner_race, mut outer_race) = (RacewayTorque::default(), RacewayTorque::default());
        let mut power = PowerBreakdown::default();
        let mut min_lambda = f64::INFINITY;
        let mut largest_spin = 0.0_f64;
        for j in 0..z {
            let c = op.balls[j];
            for (field, v) in [
                ("inner_contact_angle_rad", c.inner_contact_angle_rad),
                ("outer_contact_angle_rad", c.outer_contact_angle_rad),
            ] {
                if !v.is_finite() {
                    return Err(Error::invalid(field, v, "a finite contact angle in rad"));
                }
            }
            for (field, v) in [
                ("inner_load_n", c.inner_load_n),
                ("outer_load_n", c.outer_load_n),
            ] {
                if !(v.is_finite() && v >= 0.0) {
                    return Err(Error::invalid(field, v, "a finite ball load >= 0 N"));
                }
            }
            let (ai, ao) = kinematic_angles(&c, self.bearing.free_contact_angle())?;
            let beta = self.attitude.pitch(d / dm, ai, ao);
            let kin = kinematics(speeds, d, dm, ai, ao, beta);
            let contact = |inner: bool| ContactKinematics {
                inner,
                contact_angle_rad: if inner { ai } else { ao },
                ring_speed_rad_s: if inner {
                    speeds.inner_rad_s - kin.cage_rad_s
                } else {
                    speeds.outer_rad_s - kin.cage_rad_s
                },
                ball_speed_rad_s: kin.element_rad_s,
                pitch_rad: beta,
            };
            let inner = self.contact(&contact(true), c.inner_load_n, starting)?;
            let outer = self.contact(&contact(false), c.outer_load_n, starting)?;
            for l in [&inner, &outer] {
                if l.load_n > 0.0 {
                    warnings.film_out_of_range_contacts += usize::from(l.film_out_of_range);
                    warnings.film_out_of_range_strips += l.film_out_of_range_strips;
                    if !starting {
                        min_lambda = min_lambda.min(l.lambda);
                    }
                    largest_spin = largest_spin.max(l.spin_rad_s.abs());
                }
            }
            inner_race.rolling_nmm += inner.rolling_w * scale;
            inner_race.sliding_nmm += inner.sliding_w * scale;
            outer_race.rolling_nmm += outer.rolling_w * scale;
            outer_race.sliding_nmm += outer.sliding_w * scale;
            power.rolling_w += inner.rolling_w + outer.rolling_w;
            power.sliding_w += inner.sliding_w + outer.sliding_w;
            let ball = BallFriction {
                ball: j,
                azimuth_rad: c.azimuth_rad,
                cage_speed_rad_s: kin.cage_rad_s,
                ball_speed_rad_s: kin.element_rad_s,
                pitch_rad: beta,
                inner,
                outer,
                torque_nmm: 0.0,
            };
            self.balls[j] = BallFriction {
                torque_nmm: ball.power_w() * scale,
                ..ball
            };
        }
        if let (false, Some(s)) = (starting, self.losses.lubrication().starvation_degree) {
            warnings.starvation_extrapolated =
                s < kontakt::lubrication::BIBOULET_HOUPERT_MIN_STARVATION;
        }
        if starting {
            power = PowerBreakdown::default();
        } else {
            power.drag_w = drag_nmm * dw.abs() * 1e-3;
        }
        power.total_w = power.rolling_w + power.sliding_w + power.rib_w + power.drag_w;
        let total = inner_race.total_nmm() + outer_race.total_nmm() + drag_nmm;
        let sign = if dw < 0.0 { -1.0 } else { 1.0 };
        let coefficient = op
            .coefficient_basis
            .filter(|&(p, d)| p > 0.0 && d > 0.0 && p.is_finite() && d.is_finite())
            .map(|(p, d)| total / (p * 0.5 * d));
        Ok(BallBearingFriction {
            inner_speed_rad_s: op.inner_speed,
            outer_speed_rad_s: op.outer_speed,
            inner_race,
            outer_race,
            drag_nmm,
            total_nmm: total,
            inner_ring_nmm: sign * total,
            outer_ring_nmm: -sign * total,
            power,
            largest_spin_rad_s: largest_spin,
            coefficient,
            min_lambda,
            warnings,
        })
    }
}

#[cfg(test)]
#[path = "ball_tests.rs"]
mod tests;
