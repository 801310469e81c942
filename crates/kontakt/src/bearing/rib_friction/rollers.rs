//! The rib friction of every roller of a bearing under any load: each roller's loads in,
//! each roller's rib friction and the bearing's totals out.
//!
//! # Where the loads come from
//!
//! A bearing model (kontakt-bearing's ring equilibrium under radial load, axial load and
//! moment, or a full per-roller equilibrium with the rib contact) gives every roller `j`
//! at the azimuth `ψ_j` its cup (outer raceway) load `Q_e,j`. The rib study's roller
//! balance of the module docs of [`super`] then holds per roller, in the roller's own
//! meridian plane, with its own cup load and its centrifugal force `F_c = m ω_c² r_c`:
//!
//! ```text
//! Q_i,j n_i + Q_f,j d = −Q_e,j n_o − F_c e_x        (2 × 2, for Q_i,j and Q_f,j)
//! ```
//!
//! With `d = −e_r`: `Q_i,j = Q_e,j − F_c cos α_m / cos β`, `Q_f,j = 2 Q_e,j sin β + F_c sin
//! α_i / cos β`. Under pure axial load every roller has `Q_e = F_a / (Z sin α_o)` (the
//! cup's axial balance, whatever F_c), so this is the rib study's load, roller by roller.
//!
//! **Why the cup load and not the cone load.** The rings' balance does not see the
//! centrifugal forces: the inner ring receives `−(Q_i n_i + Q_f d) = Q_e n_o + F_c e_x,j`
//! from roller `j`, and over equally spaced rollers `Σ_j F_c e_x,j = 0` and
//! `Σ_j (R e_x,j + z e_z) × F_c e_x,j = 0`; so `Σ_j Q_e,j n_o,j` equals the applied load
//! with or without F_c, and the cup loads of a static ring equilibrium are the ones to
//! keep. What F_c does change is the split between cone and rib; a static model (no F_c
//! in its deflection law, `Q_i = Q_e` in its slice approach) misplaces the load zone by
//! the difference `Q_e − Q_i`, which the per-roller balance here does not correct: exact
//! under pure axial load, an approximation under combined load at speed (stated in
//! `docs/bearing-model.md`, "The rib friction of every roller").
//!
//! **A roller off the cone.** A roller whose cup load is below `F_c cos α_m / cos β`
//! (with `d = −e_r`; in general where the balance gives `Q_i < 0`), such as one outside
//! the load zone at speed, leaves the cone: its centrifugal force presses it into the
//! cup and, the cup being conical, against the rib. With `Q_i = 0` the balance
//! `Q_e n_o + Q_f d = −F_c e_x` gives `Q_f = F_c sin α_o / cos β`,
//! `Q_e = F_c cos α_m / cos β` (`d = −e_r`); at the threshold both branches agree
//! (continuous). Without F_c an unloaded roller carries nothing, its rib included.
//! When no roller stays on the cone (pure axial load at a speed where F_c exceeds
//! `Q_e cos β / cos α_m`), the rings cannot be in balance: an error, as for one roller.
//!
//! # Totals
//!
//! Each roller's rib contact dissipates its own `P_j`; the bearing's rib power is
//! `Σ_j P_j` and, by the power balance, the rib's share of the bearing's friction torque
//! is `M = Σ_j P_j / |ω_i − ω_o|`; the moment of the rib friction on the inner ring about
//! the ring axis is the sum of the rollers' (rotation about the ring axis leaves each
//! roller's contact the same, so the roller at cage angle 0 stands for each).
//!
//! Units: mm, N, MPa, rad (azimuths), rad/s; torque N·mm, power W.

use super::{
    PressureModel, RibFriction, RibFrictionModel, RollerLoads, raceway_and_rib, rib_direction,
};
use crate::bearing::kinematics::TaperedKinematics;
use crate::error::{Error, Result};
use crate::field::NormalSolution;
use nalgebra::Vector3;

/// Fields solved at rib loads within this relative difference are reused: the friction
/// outputs move by less than it (the pressure grows as Q^(1/3)).
const REUSE: f64 = 1e-10;

/// One roller's cup (outer raceway) load at its azimuth, as a bearing model gives it.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RollerCup {
    /// Azimuth ψ of the roller \[rad\] (of the bearing model's frame).
    pub azimuth: f64,
    /// Cup load Q_e \[N\] (≥ 0; 0 outside the load zone).
    pub outer_raceway: f64,
}

/// One roller's loads at its azimuth: the input of
/// [`RibFrictionModel::evaluate_rollers`], from cup loads by
/// [`RibFrictionModel::roller_loads_on_cups`] or from a per-roller equilibrium that
/// resolves the rib contact itself.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RollerRibLoad {
    /// Azimuth ψ of the roller \[rad\].
    pub azimuth: f64,
    /// The roller's loads \[N\].
    pub loads: RollerLoads,
}

/// The rib friction of one roller of the bearing.
#[derive(Debug, Clone, PartialEq)]
pub struct RollerRibFriction {
    /// Azimuth ψ of the roller \[rad\].
    pub azimuth: f64,
    /// The roller's loads \[N\].
    pub loads: RollerLoads,
    /// The friction of its rib contact, `None` without rib load. Its `bearing_power`,
    /// `bearing_torque` and `ring_axis_moment` are this roller's share (Z = 1).
    pub friction: Option<RibFriction>,
}

impl RollerRibFriction {
    /// Power dissipated at the roller's rib contact \[W\] (0 without rib load).
    pub fn power(&self) -> f64 {
        self.friction.as_ref().map_or(0.0, |f| f.power)
    }

    /// Magnitude of the rib friction force on the roller \[N\] (0 without rib load).
    pub fn friction_force(&self) -> f64 {
        self.friction
            .as_ref()
            .map_or(0.0, |f| f.contact.force.norm())
    }
}

/// The rib friction of the whole bearing at one operating point: every roller's, and the
/// sums.
#[derive(Debug, Clone, PartialEq)]
pub struct BearingRibFriction {
    /// Pressure model of the fields.
    pub model: PressureModel,
    /// Inner ring speed ω_i \[rad/s\].
    pub inner_speed: f64,
    /// Outer ring speed ω_o \[rad/s\].
    pub outer_speed: f64,
    /// Cage speed ω_c \[rad/s\].
    pub cage_speed: f64,
    /// |ω_rel|, the rollers' angular speed relative to the rib \[rad/s\].
    pub relative_speed: f64,
    /// Every roller, in the order given.
    pub rollers: Vec<RollerRibFriction>,
    /// Sum of the rib loads Σ Q_f \[N\].
    pub rib_load: f64,
    /// Power dissipated at all rib contacts, Σ P_j \[W\].
    pub power: f64,
    /// The rib's share of the bearing's friction torque, `Σ P_j / |ω_i − ω_o|` \[N·mm\]
    /// (0 when the rings turn together).
    pub torque: f64,
    /// Moment of the rib friction on the inner ring about the ring axis, all rollers
    /// \[N·mm\].
    pub ring_axis_moment: f64,
}

impl BearingRibFriction {
    /// The roller with the largest rib load (the first of equals), `None` for no rollers.
    pub fn most_loaded(&self) -> Option<&RollerRibFriction> {
        self.rollers
            .iter()
            .reduce(|a, b| if b.loads.rib > a.loads.rib { b } else { a })
    }
}

/// The loads on one roller with the cup load `cup_load` \[N\] (from a bearing model) and
/// the centrifugal force `centrifugal` \[N\], the rib's force on the roller along
/// `rib_normal` (world, roller at cage angle 0; its component out of the section plane is
/// ignored). A roller the balance would pull off the cone (Q_i < 0) is held by the cup
/// and the rib against its centrifugal force alone (module docs); the returned
/// `outer_raceway` is then that cup load, `inner_raceway` 0.
///
/// # Errors
/// [`Error::InvalidInput`]: `cup_load` finite and ≥ 0; `centrifugal` finite and ≥ 0;
/// `rib_normal` finite, in the section plane and pointing towards the apex side; the
/// same field when the rib would pull the roller (Q_f < 0).
pub fn roller_loads_on_cup(
    kinematics: &TaperedKinematics,
    rib_normal: &Vector3<f64>,
    cup_load: f64,
    centrifugal: f64,
) -> Result<RollerLoads> {
    if !(cup_load.is_finite() && cup_load >= 0.0) {
        return Err(Error::invalid(
            "cup_load",
            cup_load,
            "a finite force >= 0 N",
        ));
    }
    if !(centrifugal.is_finite() && centrifugal >= 0.0) {
        return Err(Error::invalid(
            "centrifugal",
            centrifugal,
            "a finite force >= 0 N",
        ));
    }
    let d = rib_direction(kinematics, rib_normal)?;
    let (q_i, q_f) = raceway_and_rib(kinematics, &d, cup_load, centrifugal);
    let loads = if q_i >= 0.0 {
        RollerLoads {
            outer_raceway: cup_load,
            inner_raceway: q_i,
            rib: q_f,
            centrifugal,
        }
    } else {
        // Off the cone: Q_e n_o + Q_f d = −F_c e_x, n_o = (−cos α_o, sin α_o).
        let ao = kinematics.outer_raceway_angle();
        let (no_x, no_z) = (-ao.cos(), ao.sin());
        let det = no_x * d.z - no_z * d.x;
        RollerLoads {
            outer_raceway: -centrifugal * d.z / det,
            inner_raceway: 0.0,
            rib: centrifugal * no_z / det,
            centrifugal,
        }
    };
    if !(loads.rib >= 0.0 && loads.rib.is_finite() && loads.outer_raceway.is_finite()) {
        return Err(Error::invalid(
            "rib_normal",
            format!("{:?}", rib_normal),
            "a rib contact normal that takes load (Q_f >= 0)",
        ));
    }
    Ok(loads)
}

/// The friction of an earlier roller whose rib load is `rib_load` bit for bit. Every output
/// of [`RibFrictionModel::friction_share`] depends on the roller's loads only through its
/// rib load (the field, the film, the coefficient) apart from the copy of the loads, so such
/// a roller's friction with its own loads is the result of solving it again, bit for bit
/// (under axial load every roller has the same rib load: one friction integral instead of
/// Z; `kontakt-bearing/tests/friction_speed.rs` checks it against a solve per roller).
fn same_rib_load(done: &[RollerRibFriction], rib_load: f64) -> Option<&RibFriction> {
    done.iter()
        .filter(|o| o.loads.rib.to_bits() == rib_load.to_bits())
        .find_map(|o| o.friction.as_ref())
}

/// Fields already solved, by rib load.
struct Fields {
    solved: Vec<(f64, NormalSolution<()>)>,
}

impl Fields {
    fn at(
        &mut self,
        model: &RibFrictionModel,
        pressure: PressureModel,
        load: f64,
    ) -> Result<&NormalSolution<()>> {
        let i = match self
            .solved
            .iter()
            .position(|(q, _)| (q - load).abs() <= REUSE * load)
        {
            Some(i) => i,
            None => {
                self.solved.push((load, model.solve(pressure, load)?));
                self.solved.len() - 1
            }
        };
        Ok(&self.solved[i].1)
    }
}

impl RibFrictionModel {
    /// The bearing's kinematics at the ring speeds `inner_speed`, `outer_speed` \[rad/s\].
    ///
    /// # Errors
    /// Those of [`TaperedKinematics::of_roller_rib`].
    pub fn kinematics(&self, inner_speed: f64, outer_speed: f64) -> Result<TaperedKinematics> {
        TaperedKinematics::of_roller_rib(&self.pair, inner_speed, outer_speed)
    }

    /// Every roller's loads from its cup load, with the centrifugal force at the cage
    /// speed of `k` ([`roller_loads_on_cup`] on the pairing's rib normal).
    ///
    /// # Errors
    /// Those of [`roller_loads_on_cup`]; field `inner_speed` when some roller carries
    /// a cup load but none stays on the cone (the centrifugal force exceeds what the
    /// load holds, as [`super::roller_loads`] refuses it under axial load).
    pub fn roller_loads_on_cups(
        &self,
        k: &TaperedKinematics,
        cups: &[RollerCup],
    ) -> Result<Vec<RollerRibLoad>> {
        let centrifugal = self.centrifugal_force(k);
        let normal = self.pair.contact.normal.into_inner();
        let out = cups
            .iter()
            .map(|c| {
                Ok(RollerRibLoad {
                    azimuth: c.azimuth,
                    loads: roller_loads_on_cup(k, &normal, c.outer_raceway, centrifugal)?,
                })
            })
            .collect::<Result<Vec<_>>>()?;
        let loaded = cups.iter().any(|c| c.outer_raceway > 0.0);
        if loaded && out.iter().all(|r| r.loads.inner_raceway <= 0.0) {
            return Err(Error::invalid(
                "inner_speed",
                format!("a speed at which the centrifugal force {centrifugal:.4e} N exceeds"),
                "a speed at which the loaded rollers stay on the inner raceway (Q_i >= 0)",
            ));
        }
        Ok(out)
    }

    /// The rib friction of every roller of `rollers` (each with its own loads, the
    /// centrifugal force included in them) at the ring speeds of `k`, the fields by
    /// `model`, and the bearing's sums.
    ///
    /// # Errors
    /// Field `rollers` for an empty list, or a rib load not finite or negative; those of
    /// [`RibFrictionModel::solve`] and [`RibFrictionModel::friction_on`].
    pub fn evaluate_rollers(
        &self,
        model: PressureModel,
        k: &TaperedKinematics,
        rollers: &[RollerRibLoad],
    ) -> Result<BearingRibFriction> {
        let mut fields = Fields { solved: Vec::new() };
        self.evaluate_with(model, k, rollers, &mut fields)
    }

    fn evaluate_with(
        &self,
        model: PressureModel,
        k: &TaperedKinematics,
        rollers: &[RollerRibLoad],
        fields: &mut Fields,
    ) -> Result<BearingRibFriction> {
        if rollers.is_empty() {
            return Err(Error::invalid(
                "rollers",
                "an empty list",
                "at least one roller",
            ));
        }
        let ao = k.outer_raceway_angle();
        let op = super::Operating {
            // the axial force the cups carry (the applied one under pure axial load)
            axial_load: rollers
                .iter()
                .map(|r| r.loads.outer_raceway * ao.sin())
                .sum(),
            inner_speed: k.inner_speed,
            outer_speed: k.outer_speed,
        };
        let mut out = Vec::with_capacity(rollers.len());
        for r in rollers {
            let q = r.loads.rib;
            if !(q.is_finite() && q >= 0.0) {
                return Err(Error::invalid(
                    "rollers",
                    format!("rib load {q} N"),
                    "finite rib loads >= 0 N",
                ));
            }
            let friction = if q > 0.0 {
                match same_rib_load(&out, q) {
                    Some(f) => Some(RibFriction {
                        loads: r.loads,
                        ..f.clone()
                    }),
                    None => {
                        let field = fields.at(self, model, q)?;
                        Some(self.friction_share(model, field, &op, k, &r.loads, 1.0)?)
                    }
                }
            } else {
                None
            };
            out.push(RollerRibFriction {
                azimuth: r.azimuth,
                loads: r.loads,
                friction,
            });
        }
        let power: f64 = out.iter().map(RollerRibFriction::power).sum();
        let dw = (k.inner_speed - k.outer_speed).abs();
        Ok(BearingRibFriction {
            model,
            inner_speed: k.inner_speed,
            outer_speed: k.outer_speed,
            cage_speed: k.cage_speed,
            relative_speed: k.relative_speed.abs(),
            rib_load: out.iter().map(|r| r.loads.rib).sum(),
            power,
            torque: if dw > 0.0 { power * 1e3 / dw } else { 0.0 },
            ring_axis_moment: out
                .iter()
                .filter_map(|r| r.friction.as_ref())
                .map(|f| f.ring_axis_moment)
                .sum(),
            rollers: out,
        })
    }

    /// The rib friction of every roller at each inner-ring speed of `inner_speeds`
    /// \[rad/s\] (outer ring fixed) with the cup loads `cups` of a bearing model (static:
    /// the same at every speed; the centrifugal force added per speed). Fields are solved
    /// once per distinct rib load over the whole sweep.
    ///
    /// # Errors
    /// Field `speeds` for an empty list; those of
    /// [`RibFrictionModel::roller_loads_on_cups`] and
    /// [`RibFrictionModel::evaluate_rollers`].
    pub fn sweep_rollers(
        &self,
        model: PressureModel,
        cups: &[RollerCup],
        inner_speeds: &[f64],
    ) -> Result<Vec<BearingRibFriction>> {
        if inner_speeds.is_empty() {
            return Err(Error::invalid(
                "speeds",
                "an empty list",
                "at least one speed",
            ));
        }
        let mut fields = Fields { solved: Vec::new() };
        inner_speeds
            .iter()
            .map(|&w| {
                let k = self.kinematics(w, 0.0)?;
                let loads = self.roller_loads_on_cups(&k, cups)?;
                self.evaluate_with(model, &k, &loads, &mut fields)
            })
            .collect()
    }
}
