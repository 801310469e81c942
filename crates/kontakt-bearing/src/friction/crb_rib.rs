//! The roller-end/rib friction of a cylindrical roller bearing (NJ, NUP; and NU, N where a
//! rib is loaded): the sliding power of each loaded roller end/rib contact of the
//! rib-contact model ([`crate::roller_equilibrium::RibContactSolver::cylindrical`]), the
//! rib share of the bearing's friction torque (issue 29 §1: "rib contacts: the existing rib
//! friction with loads from the bearing model"). Derivation: `docs/bearing-friction.md`,
//! section "Rib friction of cylindrical roller bearings".
//!
//! # Kinematics (cage frame, roller at azimuth 0)
//!
//! `e_r`, `e_θ`, z: the roller centre `C = R e_r` (R the pitch radius), the roller axis
//! parallel to z (the roller's tilt from the rib couple is neglected here: it changes the
//! sliding speed by O(φ)). The cage turns at `ω_c`, the rings at `Ω_ρ = ω_ρ − ω_c`
//! relative to it, the roller at `ω_R` about its axis. Pure rolling at the raceways
//! (`R_i = R − r`, `R_o = R + r`, `r = D/2`) gives
//!
//! ```text
//! ω_c = (ω_i R_i + ω_o R_o) / (2R),   ω_R = −Ω_i R_i / r = Ω_o R_o / r.
//! ```
//!
//! The roller end touches a rib at `P = C + s` (s in the axial plane, `s_r = −h` on the
//! inner ring, `+h` on the outer, h the contact height above the roller axis). There the
//! roller's surface moves at `ω_R s_r e_θ`, the rib's at `Ω_ρ (R + s_r) e_θ`, so the
//! sliding of the roller on the rib is circumferential,
//!
//! ```text
//! v_s = ω_R s_r − Ω_ρ (R + s_r) = −Ω_ρ R (1 − h/r)      (both rings),
//! ```
//!
//! zero for a contact at the raceway's height (h = r) and largest at the axis; the
//! entrainment speed is `u = (ω_R s_r + Ω_ρ (R + s_r))/2`. The relative rotation of roller
//! and ring is `(ω_R − Ω_ρ) z`: about the contact normal n a spin `ω_n = (ω_R − Ω_ρ) n_z`,
//! so the sliding over the contact area is `v_s(P) + ω_n n × (X − P)` (exact for rigid
//! bodies).
//!
//! # Friction
//!
//! The Hertz ellipse of the roller end and the rib at the contact's load (the solver's
//! Hertz contact), the film at its centre (the point-contact film formula of the
//! lubricant, Λ from the roughness: `kontakt::lubrication`), the mixed friction law of the
//! rib (`kontakt::friction::FrictionLaw` with that film) integrated over the ellipse with
//! the sliding field above ([`kontakt::friction::HertzFrictionRules`]): the contact's
//! friction force, spin moment and power P ≥ 0. The rib share of the torque is
//! `Σ P / |ω_i − ω_o|` (`crate::friction::torque`); at standstill each contact gives its
//! starting torque `μ_b Q |v_s(Δω = 1)|` (boundary friction, no film), as the tapered
//! bearing's rib.
//!
//! Units: mm, N, MPa, mm/s, rad/s; power W, torque N·mm.

use crate::roller_equilibrium::RibContactSolver;
use kontakt::bearing::RibLubrication;
use kontakt::friction::{FilmState, FrictionLaw, HertzFrictionRules};
use kontakt::geometry::VelocityField;
use kontakt::hertz::HertzPointContact;
use kontakt::lubrication::{FilmContact, film_parameter, film_thickness};
use kontakt::material::{ElasticMaterial, effective_modulus};
use kontakt::{Error, Result};
use nalgebra::{Vector2, Vector3};

/// The kinematics of one roller end/rib contact (cage frame, roller at azimuth 0).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RibContactKinematics {
    /// Cage speed ω_c \[rad/s\].
    pub cage_speed: f64,
    /// Roller speed ω_R about its axis (+z), relative to the cage \[rad/s\].
    pub roller_speed: f64,
    /// The rib's ring speed relative to the cage, Ω_ρ \[rad/s\].
    pub ring_speed: f64,
    /// Contact point from the bearing centre `(r, 0, z)` \[mm\].
    pub point: Vector3<f64>,
    /// Contact normal, rib into roller (unit, in the axial plane).
    pub normal: Vector3<f64>,
    /// Sliding velocity of the roller on the rib at the contact point, along `e_θ` \[mm/s\].
    pub sliding: f64,
    /// Entrainment (mean surface) velocity at the contact point, along `e_θ` \[mm/s\].
    pub entrainment: f64,
    /// Spin of the roller relative to the rib about the normal \[rad/s\].
    pub spin: f64,
}

/// The friction of one roller end/rib contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RibContactFriction {
    /// The contact's kinematics.
    pub kinematics: RibContactKinematics,
    /// Normal load Q \[N\].
    pub load: f64,
    /// Friction force on the roller (cage frame, roller at azimuth 0) \[N\].
    pub force: Vector3<f64>,
    /// Moment of the friction stresses on the roller about the contact point, along the
    /// normal \[N·mm\].
    pub spin_moment: f64,
    /// Dissipated power \[W\], ≥ 0.
    pub power: f64,
    /// Film parameter Λ at the contact centre (∞ dry).
    pub lambda: f64,
}

/// The rib friction model of a cylindrical roller bearing: the friction law, the rib
/// lubrication and the ellipse quadrature rules (allocated once).
#[derive(Debug, Clone)]
pub struct CylindricalRibFriction {
    law: FrictionLaw,
    lubrication: Option<RibLubrication>,
    rules: HertzFrictionRules,
    pitch_radius: f64,
    roller_radius: f64,
}

impl CylindricalRibFriction {
    /// The model of a bearing of pitch diameter `pitch_diameter_mm` and roller diameter
    /// `roller_diameter_mm` with the rib friction law `law` and lubrication (`None`: dry).
    ///
    /// # Errors
    /// Field `pitch_diameter_mm` / `roller_diameter_mm` (finite, 0 < D < d_m); those of
    /// [`FrictionLaw::check`].
    pub fn new(
        pitch_diameter_mm: f64,
        roller_diameter_mm: f64,
        law: FrictionLaw,
        lubrication: Option<RibLubrication>,
    ) -> Result<Self> {
        if !(roller_diameter_mm.is_finite() && roller_diameter_mm > 0.0) {
            return Err(Error::invalid(
                "roller_diameter_mm",
                roller_diameter_mm,
                "a finite diameter > 0 mm",
            ));
        }
        if !(pitch_diameter_mm.is_finite() && pitch_diameter_mm > roller_diameter_mm) {
            return Err(Error::invalid(
                "pitch_diameter_mm",
                pitch_diameter_mm,
                format!("a finite diameter > the roller diameter {roller_diameter_mm} mm"),
            ));
        }
        law.check()?;
        Ok(CylindricalRibFriction {
            law,
            lubrication,
            rules: HertzFrictionRules::new()?,
            pitch_radius: 0.5 * pitch_diameter_mm,
            roller_radius: 0.5 * roller_diameter_mm,
        })
    }

    /// The friction law.
    pub fn law(&self) -> &FrictionLaw {
        &self.law
    }

    /// The kinematics of the contact at `point` (from the roller centre, `(r, z)`, mm) with
    /// the normal `normal` (rib into roller) on the inner ring (`inner`) or the outer, at
    /// the ring speeds ω_i, ω_o \[rad/s\] (module docs).
    pub fn kinematics(
        &self,
        inner: bool,
        point: Vector2<f64>,
        normal: Vector2<f64>,
        inner_speed: f64,
        outer_speed: f64,
    ) -> RibContactKinematics {
        let (big_r, r) = (self.pitch_radius, self.roller_radius);
        let (ri, ro) = (big_r - r, big_r + r);
        let cage = (inner_speed * ri + outer_speed * ro) / (2.0 * big_r);
        let (om_i, om_o) = (inner_speed - cage, outer_speed - cage);
        // pure rolling at the inner raceway: the roller's surface at −r e_r moves at
        // −ω_R r e_θ, the ring's at Ω_i R_i e_θ
        let roller = -om_i * ri / r;
        let ring = if inner { om_i } else { om_o };
        let z = Vector3::z();
        let centre = Vector3::new(big_r, 0.0, 0.0);
        let p = centre + Vector3::new(point.x, 0.0, point.y);
        let n = Vector3::new(normal.x, 0.0, normal.y);
        let v_roller = (z * roller).cross(&(p - centre));
        let v_ring = (z * ring).cross(&p);
        let e_theta = Vector3::y();
        RibContactKinematics {
            cage_speed: cage,
            roller_speed: roller,
            ring_speed: ring,
            point: p,
            normal: n,
            sliding: (v_roller - v_ring).dot(&e_theta),
            entrainment: 0.5 * (v_roller + v_ring).dot(&e_theta),
            spin: (roller - ring) * n.z,
        }
    }

    /// The friction of one contact with the kinematics `k`, the load `load` \[N\] and the
    /// Hertz contact `hertz` (roller end body 1, rib body 2, its first principal direction
    /// in the axial plane). Allocates nothing.
    ///
    /// # Errors
    /// Field `load` (finite, ≥ 0); those of the Hertz solution, the film and the friction
    /// integral.
    pub fn contact(
        &self,
        hertz: &HertzPointContact,
        k: &RibContactKinematics,
        load: f64,
    ) -> Result<RibContactFriction> {
        if !(load.is_finite() && load >= 0.0) {
            return Err(Error::invalid("load", load, "a finite rib load >= 0 N"));
        }
        let none = RibContactFriction {
            kinematics: *k,
            load,
            force: Vector3::zeros(),
            spin_moment: 0.0,
            power: 0.0,
            lambda: f64::INFINITY,
        };
        if load == 0.0 {
            return Ok(none);
        }
        // the contact frame: x the first principal direction (in the axial plane, along
        // the rib's straight generator), y = n × x (±e_θ), n the normal
        let n = k.normal;
        let x = Vector3::new(-n.z, 0.0, n.x);
        let y = n.cross(&x);
        let sol = hertz.solve_force(load)?;
        let (film, lambda) = self.film(hertz, k, load)?;
        let law = self.law.with_film(&film)?;
        let e_theta = Vector3::y();
        let (vs, ve) = (e_theta * k.sliding, e_theta * k.entrainment);
        let mean_spin = (k.roller_speed + k.ring_speed) * n.z * 0.5;
        // v(X) = v(P) + ω_n n × (X − P): ∂v/∂x = ω_n y, ∂v/∂y = −ω_n x
        let field = VelocityField {
            sliding: [[vs.dot(&x), vs.dot(&y)], [0.0, k.spin], [-k.spin, 0.0]],
            entrainment: [
                [ve.dot(&x), ve.dot(&y)],
                [0.0, mean_spin],
                [-mean_spin, 0.0],
            ],
        };
        let f = self.rules.friction(
            sol.semi_axes,
            sol.orientation,
            sol.max_pressure,
            &field,
            &law,
        )?;
        Ok(RibContactFriction {
            force: x * f.force[0] + y * f.force[1],
            spin_moment: f.moment,
            power: f.power,
            lambda,
            ..none
        })
    }

    /// The film at the contact centre: the Hertz contact's reduced radii, the entrainment
    /// along `e_θ` (= ±y of the contact frame); dry without a lubricant.
    fn film(
        &self,
        hertz: &HertzPointContact,
        k: &RibContactKinematics,
        load: f64,
    ) -> Result<(FilmState, f64)> {
        let Some(lub) = &self.lubrication else {
            return Ok((FilmState::dry(), f64::INFINITY));
        };
        let c = hertz.geometry().curvature();
        // the entrainment is along ±y; its angle from the direction of A (c.orientation
        // from x); θ and θ + π give the same film
        let angle = std::f64::consts::FRAC_PI_2 - c.orientation;
        let steel = ElasticMaterial::STEEL;
        let contact = FilmContact {
            rx: 0.5 / c.a_coef,
            ry: 0.5 / c.b_coef,
            entrainment_angle: angle,
            entrainment_speed: k.entrainment.abs(),
            load,
            reduced_modulus: effective_modulus(&steel, &steel),
        };
        let eta = lub.lubricant.dynamic_viscosity(lub.temperature)?;
        let alpha = lub.lubricant.alpha();
        let h = film_thickness(&contact, eta, alpha, lub.formula)?;
        let lambda = film_parameter(h.central, lub.roughness[0], lub.roughness[1])?;
        Ok((FilmState::new(h.central, lambda, eta, alpha)?, lambda))
    }

    /// The friction of roller `j`'s rib contact `r` (in the order of
    /// [`RibContactSolver::rib_contacts`]) at the solver's last evaluation, at the ring
    /// speeds ω_i, ω_o \[rad/s\].
    ///
    /// # Errors
    /// Those of [`CylindricalRibFriction::contact`].
    ///
    /// # Panics
    /// If `j` or `r` is out of range.
    pub fn rib_contact(
        &self,
        solver: &RibContactSolver,
        j: usize,
        r: usize,
        inner_speed: f64,
        outer_speed: f64,
    ) -> Result<RibContactFriction> {
        let (inner, point, normal) = contact_geometry(solver, r);
        let k = self.kinematics(inner, point, normal, inner_speed, outer_speed);
        self.contact(solver.rib_hertz_of(r), &k, solver.roller_rib_loads(j)[r])
    }

    /// Roller `j`'s rib value for `crate::friction::torque::FrictionOperating::rib`, from
    /// the solver's last evaluation at the ring speeds ω_i, ω_o \[rad/s\]: the power of its
    /// rib contacts \[W\] while the rings turn relative to each other; at ω_i = ω_o the
    /// starting torque `μ_b Σ Q |v_s(Δω = 1)|` \[N·mm\] (the kinematics of ω_i = 1,
    /// ω_o = 0; boundary friction, no film). Allocates nothing.
    ///
    /// # Errors
    /// Those of [`CylindricalRibFriction::contact`].
    ///
    /// # Panics
    /// If `j` is not a roller index.
    pub fn roller_value(
        &self,
        solver: &RibContactSolver,
        j: usize,
        inner_speed: f64,
        outer_speed: f64,
    ) -> Result<f64> {
        let mut value = 0.0;
        for (r, &load) in solver.roller_rib_loads(j).iter().enumerate() {
            if inner_speed == outer_speed {
                if !(load.is_finite() && load >= 0.0) {
                    return Err(Error::invalid("load", load, "a finite rib load >= 0 N"));
                }
                let (inner, point, normal) = contact_geometry(solver, r);
                let k = self.kinematics(inner, point, normal, 1.0, 0.0);
                value += self.law.boundary_coefficient * load * k.sliding.abs();
            } else {
                value += self
                    .rib_contact(solver, j, r, inner_speed, outer_speed)?
                    .power;
            }
        }
        Ok(value)
    }
}

/// Rib contact `r` of `solver`: on the inner ring or not, its point from the roller centre
/// and its normal.
fn contact_geometry(solver: &RibContactSolver, r: usize) -> (bool, Vector2<f64>, Vector2<f64>) {
    let (inner, p, n) =
        solver
            .rib_contacts()
            .nth(r)
            .unwrap_or((false, [f64::NAN; 2], [f64::NAN; 2]));
    (inner, Vector2::from(p), Vector2::from(n))
}

#[cfg(test)]
#[path = "crb_rib_tests.rs"]
mod tests;
