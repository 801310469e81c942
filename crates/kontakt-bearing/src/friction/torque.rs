//! The friction torque and power of a whole roller bearing (tapered or cylindrical),
//! contact by contact, from a solved load distribution (issue 29 §1-2).
//!
//! For every roller and every slice of its cup and cone lines this module builds the
//! [`RacewaySlice`] (load per length, reduced radius, entrainment and sliding speed from the
//! roller's rigid-body kinematics, with its tilt) and takes its losses from
//! [`RacewayLosses::slice`]; the rib contacts' powers come from the rib friction model
//! (`kontakt::bearing::RibFrictionModel`, per roller) and the drag torque from a catalogue
//! term ([`DragModel`]). Every source's share of the bearing torque is its power over the
//! rings' relative speed, so the torques and powers balance exactly.
//!
//! # Kinematics (2-D axial plane of a roller, `(r, z)`, origin the roller centre `O`)
//!
//! The frames and points are those of [`crate::roller_equilibrium`]: cup normal
//! `n_o = (cos α, sin α)`, cone normal `n_i = (cos α_i, sin α_i)`, roller axis direction
//! `t_m = (−sin α_m, cos α_m)`, `α_m = (α + α_i)/2`, `β = (α − α_i)/2`; the slice `k` at `x_k`
//! along each raceway line from its midpoint touches the cup at `p_o = (D/2) n_m + x_k t_o`
//! and the cone at `p_i = −(D/2) n_m + x_k t_i` (`n_m = (cos α_m, sin α_m)`). Its radius from
//! the bearing axis is `R = d_m/2 + p_r`; its distance from the roller axis (tilted by φ,
//! counter-clockwise) is `r = |p × t_m(φ)|`.
//!
//! In the cage frame (cage speed ω_c) the cone turns at `Ω_i = ω_i − ω_c`, the cup at
//! `Ω_o = ω_o − ω_c`, the roller spins at ω_R about its axis. The cage speed and the roller
//! speed follow from pure rolling at the midpoints of both lines (`r_i⁰ = r_o⁰`,
//! untilted): `|Ω_i| R_i⁰ = |ω_R| r⁰ = |Ω_o| R_o⁰`, so
//! `ω_c = (ω_i R_i⁰ + ω_o R_o⁰)/(R_i⁰ + R_o⁰)`; a tilted roller takes the mean of the two
//! midpoint conditions for its own ω_R. At slice k of raceway ρ the ring surface moves at
//! `V_g = |Ω_ρ| R_ρ(x_k)`, the roller surface at `V_r = |ω_R| r_ρ(x_k)`, both along the
//! rolling direction, so
//!
//! ```text
//! u = (V_r + V_g)/2,   v_s = V_r − V_g.
//! ```
//!
//! With a common apex (tapered) or parallel lines (cylindrical) and no tilt, `R_ρ(x)` and
//! `r(x)` are both linear in x and vanish together at the apex, so `v_s ≡ 0` on every slice
//! (pure rolling on the whole line, not only on the pitch point). A tilt φ turns the roller
//! axis and gives `v_s(x) = ± |ω_R| φ cos β (x − x₀) + O(φ²)`: sliding that grows linearly
//! from the midpoint (a spin about the contact normal). The slip that the traction balance
//! of the roller would add (to drive the rolling resistance, Zhou & Hoeprich 1991: "only a
//! very small amount of slip is required") is not solved: this is the kinematic model.
//!
//! # Torques
//!
//! The rolling resistance of a slice dissipates `2 F_r u`, the sliding `|F_s v_s|`, each rib
//! contact its `P_rib,j`, the drag `M_drag |Δω|`. With the cage and rollers in steady
//! state and the cage torque-free, the power the rings receive is
//! `M_inner ω_inner + M_outer ω_outer = M (ω_i − ω_o)` (`M_outer = −M_inner`), so each
//! source's share of the bearing torque is its power over `|ω_i − ω_o|`:
//!
//! ```text
//! M_cone = Σ (2 F_r u + |F_s v_s|)_cone / |Δω|,   M_cup likewise,
//! M_rib = Σ P_rib,j / |Δω|,   M = M_cone + M_cup + M_rib + M_drag.
//! ```
//!
//! For a cylindrical roller this is Zhou & Hoeprich's (1991) force form
//! `F_i (R_i + R_e,i) + F_o (R_o − R_e,o)` exactly; for a tapered roller their lever
//! `R + R_e cos α_m` is ours times cos β (`docs/bearing-friction.md` §3).
//!
//! **Starting torque** (`Δω = 0`): no film, no rolling resistance; each sliding contact
//! carries its boundary friction μ_b per unit normal load against the sliding speed per unit
//! `Δω` of the running kinematics (a limit, not a division by zero).
//!
//! Units: mm, N, N/mm, MPa, mm/s, rad/s; torques N·mm; power W.

use super::raceway::{RacewayLosses, RacewaySlice, SliceLosses, SlicePlan};
use crate::geometry::{RollerBearing, RollerBearingKind};
use kontakt::material::{ElasticMaterial, effective_modulus};
use kontakt::{Error, Result};
use nalgebra::Vector2;

/// One slice's fixed geometry (untilted) on both raceways.
#[derive(Debug, Clone, Copy)]
struct SliceGeom {
    /// Contact points from the roller centre, cup and cone, mm.
    p_o: Vector2<f64>,
    p_i: Vector2<f64>,
}

/// The drag (churning) model of the bearing.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum DragModel {
    /// No drag.
    None,
    /// A drag torque \[N·mm\] from a catalogue term (SKF 2004 `M_drag`, Schaeffler `M0`),
    /// computed by the caller at the same operating point.
    Torque {
        /// The drag torque \[N·mm\], finite and ≥ 0.
        nmm: f64,
    },
}

impl DragModel {
    /// The drag torque \[N·mm\] (0 for [`DragModel::None`]).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `drag` unless the torque is finite and ≥ 0.
    pub fn torque_nmm(&self) -> Result<f64> {
        match *self {
            DragModel::None => Ok(0.0),
            DragModel::Torque { nmm } if nmm.is_finite() && nmm >= 0.0 => Ok(nmm),
            DragModel::Torque { nmm } => {
                Err(Error::invalid("drag", nmm, "a finite torque >= 0 N·mm"))
            }
        }
    }
}

/// The losses of one roller \[W\] and its kinematics.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RollerFriction {
    /// Roller index j.
    pub roller: usize,
    /// Cone (inner raceway) load Σ slices \[N\].
    pub cone_load_n: f64,
    /// Cup (outer raceway) load \[N\].
    pub cup_load_n: f64,
    /// The roller's tilt φ \[rad\].
    pub tilt_rad: f64,
    /// Roller spin speed |ω_R| relative to the cage \[rad/s\].
    pub spin_rad_s: f64,
    /// Rolling-resistance power at the cone \[W\].
    pub cone_rolling_w: f64,
    /// Sliding power at the cone \[W\].
    pub cone_sliding_w: f64,
    /// Rolling-resistance power at the cup \[W\].
    pub cup_rolling_w: f64,
    /// Sliding power at the cup \[W\].
    pub cup_sliding_w: f64,
    /// Rib power \[W\] (as given).
    pub rib_w: f64,
    /// Largest |v_s| over the roller's loaded slices \[mm/s\].
    pub max_sliding_mm_s: f64,
    /// Smallest film parameter Λ of the roller's loaded slices (∞ without load).
    pub min_lambda: f64,
    /// The roller's share of the bearing torque \[N·mm\] (starting: its boundary share).
    pub torque_nmm: f64,
}

impl RollerFriction {
    /// Total power of the roller's contacts \[W\].
    pub fn power_w(&self) -> f64 {
        self.cone_rolling_w
            + self.cone_sliding_w
            + self.cup_rolling_w
            + self.cup_sliding_w
            + self.rib_w
    }
}

/// Torque shares \[N·mm\] of one source pair.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RacewayTorque {
    /// Rolling resistance \[N·mm\].
    pub rolling_nmm: f64,
    /// Sliding traction \[N·mm\].
    pub sliding_nmm: f64,
}

impl RacewayTorque {
    /// Their sum \[N·mm\].
    pub fn total_nmm(&self) -> f64 {
        self.rolling_nmm + self.sliding_nmm
    }
}

/// Power per source \[W\].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PowerBreakdown {
    /// Rolling resistance of both raceways \[W\].
    pub rolling_w: f64,
    /// Sliding of both raceways \[W\].
    pub sliding_w: f64,
    /// Rib contacts \[W\].
    pub rib_w: f64,
    /// Drag \[W\].
    pub drag_w: f64,
    /// Sum \[W\].
    pub total_w: f64,
}

/// Validity flags of a friction evaluation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct FrictionWarnings {
    /// Loaded slices whose line-film formula left its fitted range.
    pub film_out_of_range_slices: usize,
    /// A starvation degree below Biboulet & Houpert's computed range.
    pub starvation_extrapolated: bool,
    /// The rings do not turn relative to each other: the result is the starting torque.
    pub starting: bool,
}

/// The bearing's friction at one operating point.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct BearingFriction {
    /// Inner ring speed ω_i \[rad/s\].
    pub inner_speed_rad_s: f64,
    /// Outer ring speed ω_o \[rad/s\].
    pub outer_speed_rad_s: f64,
    /// Cage speed ω_c \[rad/s\] (pure rolling at the midpoints).
    pub cage_speed_rad_s: f64,
    /// Roller spin |ω_R| relative to the cage, untilted \[rad/s\].
    pub roller_spin_rad_s: f64,
    /// Cone (inner raceway) share of the bearing torque \[N·mm\].
    pub cone: RacewayTorque,
    /// Cup (outer raceway) share \[N·mm\].
    pub cup: RacewayTorque,
    /// Rib share \[N·mm\].
    pub rib_nmm: f64,
    /// Drag share \[N·mm\].
    pub drag_nmm: f64,
    /// The bearing torque M = cone + cup + rib + drag \[N·mm\] (starting torque at Δω = 0).
    pub total_nmm: f64,
    /// Torque the drive applies to the inner ring, `M sign(ω_i − ω_o)` \[N·mm\].
    pub inner_ring_nmm: f64,
    /// Torque on the outer ring, `−inner_ring_nmm` \[N·mm\] (free cage).
    pub outer_ring_nmm: f64,
    /// Power per source \[W\].
    pub power: PowerBreakdown,
    /// Bearing friction coefficient μ = M / (P d/2) with P the given load \[N\] and d the
    /// bore \[mm\] (`None` when P or d is not given or P = 0).
    pub coefficient: Option<f64>,
    /// Smallest Λ over all loaded slices (∞ without loaded slice or at standstill).
    pub min_lambda: f64,
    /// Validity flags.
    pub warnings: FrictionWarnings,
}

/// The operating point of [`BearingFrictionModel::evaluate`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrictionOperating<'a> {
    /// Inner ring speed ω_i \[rad/s\].
    pub inner_speed: f64,
    /// Outer ring speed ω_o \[rad/s\].
    pub outer_speed: f64,
    /// Cup slice loads \[N\], roller-major (`Z × slices`).
    pub cup_slices: &'a [f64],
    /// Cone slice loads \[N\], roller-major.
    pub cone_slices: &'a [f64],
    /// Each roller's tilt φ \[rad\] (`None`: untilted).
    pub tilts: Option<&'a [f64]>,
    /// Each roller's rib power \[W\] (`None`: no rib friction). At standstill: each roller's
    /// rib starting torque \[N·mm\] instead.
    pub rib: Option<&'a [f64]>,
    /// Drag.
    pub drag: DragModel,
    /// The load P of the friction coefficient \[N\] and the bore d \[mm\].
    pub coefficient_basis: Option<(f64, f64)>,
}

/// The friction model of a roller bearing: geometry and lubrication checked and the
/// per-roller buffer allocated once; [`BearingFrictionModel::evaluate`] allocates nothing.
/// A speed sweep over one load distribution plans it once
/// ([`BearingFrictionModel::plan_loads`]): the same results, bit for bit, for less work.
#[derive(Debug, Clone)]
pub struct BearingFrictionModel {
    losses: RacewayLosses,
    bearing: RollerBearing,
    slices: Vec<SliceGeom>,
    width: f64,
    half_pitch: f64,
    alpha_m: f64,
    cos_beta: f64,
    cos_o: f64,
    cos_i: f64,
    modulus: f64,
    rollers: Vec<RollerFriction>,
    /// [`BearingFrictionModel::plan_loads`]: the speed-independent part of every slice,
    /// `(roller · slices + slice) · 2 + (0 cone, 1 cup)`; empty without a plan.
    plans: Vec<Option<SlicePlan>>,
    /// Each roller's raceway warnings of the last evaluation: loaded slices whose film left
    /// its fit, and whether the starvation degree was extrapolated.
    roller_warnings: Vec<(usize, bool)>,
}

/// An earlier roller than `j` with the same tilt and the same cup and cone slice loads (bit
/// for bit) at `op`, whose raceway losses are therefore roller j's: under axial load every
/// roller of a bearing has its twins (the rib's and the drag's shares are per roller all
/// the same). `n` slices per roller.
fn twin(op: &FrictionOperating<'_>, n: usize, j: usize) -> Option<usize> {
    let tilt = |r: usize| op.tilts.map_or(0.0, |t| t[r]).to_bits();
    let same = |a: &[f64], i: usize| {
        a[i * n..(i + 1) * n]
            .iter()
            .zip(&a[j * n..(j + 1) * n])
            .all(|(x, y)| x.to_bits() == y.to_bits())
    };
    (0..j).find(|&i| tilt(i) == tilt(j) && same(op.cup_slices, i) && same(op.cone_slices, i))
}

/// The load \[N\] of slice `i` (roller-major) of the cup or the cone, checked finite and ≥ 0.
fn slice_load(cup_side: bool, cup: &[f64], cone: &[f64], i: usize) -> Result<f64> {
    let (field, q) = if cup_side {
        ("cup_slices", cup[i])
    } else {
        ("cone_slices", cone[i])
    };
    if q.is_finite() && q >= 0.0 {
        Ok(q)
    } else {
        Err(Error::invalid(field, q, "finite slice loads >= 0 N"))
    }
}

/// Check a per-roller list `s` of field `field`: `z` finite values.
fn per_roller(field: &'static str, s: &[f64], z: usize) -> Result<()> {
    if s.len() != z || s.iter().any(|v| !v.is_finite()) {
        return Err(Error::invalid(
            field,
            s.len(),
            format!("{z} finite values, one per roller"),
        ));
    }
    Ok(())
}

/// The roller axis direction tilted by φ (counter-clockwise in `(r, z)`).
fn axis(alpha_m: f64, tilt: f64) -> Vector2<f64> {
    let a = alpha_m + tilt;
    Vector2::new(-a.sin(), a.cos())
}

fn cross(a: &Vector2<f64>, b: &Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

impl BearingFrictionModel {
    /// Plan the model of `bearing` (tapered or cylindrical) with the raceway lubrication of
    /// `losses`; steel rollers and rings.
    ///
    /// # Errors
    /// Those of [`RollerBearing::validate`]; field `kind` for a thrust bearing.
    pub fn new(bearing: RollerBearing, losses: RacewayLosses) -> Result<Self> {
        bearing.validate()?;
        if bearing.kind == RollerBearingKind::Thrust {
            return Err(Error::invalid(
                "kind",
                "thrust",
                "a tapered or cylindrical roller bearing (thrust bearings: not yet)",
            ));
        }
        let (a, ai) = (bearing.contact_angle_rad, bearing.cone_angle_rad);
        let alpha_m = 0.5 * (a + ai);
        let n = bearing.slices;
        let l = bearing.effective_length_mm;
        let width = l / n as f64;
        let n_m = Vector2::new(alpha_m.cos(), alpha_m.sin());
        let t_o = Vector2::new(-a.sin(), a.cos());
        let t_i = Vector2::new(-ai.sin(), ai.cos());
        let half_d = 0.5 * bearing.roller_diameter_mm;
        let slices = (0..n)
            .map(|k| {
                let x = -0.5 * l + (k as f64 + 0.5) * width;
                SliceGeom {
                    p_o: n_m * half_d + t_o * x,
                    p_i: -n_m * half_d + t_i * x,
                }
            })
            .collect();
        let steel = ElasticMaterial::STEEL;
        Ok(BearingFrictionModel {
            losses,
            half_pitch: 0.5 * bearing.pitch_diameter_mm,
            alpha_m,
            cos_beta: (0.5 * (a - ai)).cos(),
            cos_o: a.cos(),
            cos_i: ai.cos(),
            modulus: effective_modulus(&steel, &steel),
            width,
            slices,
            rollers: vec![RollerFriction::default(); bearing.rollers],
            plans: Vec::new(),
            roller_warnings: vec![(0, false); bearing.rollers],
            bearing,
        })
    }

    /// Plan the load distribution `cup_slices`, `cone_slices` (roller-major, N) with the
    /// tilts `tilts` (rad, `None`: untilted), as [`FrictionOperating`] takes them: the
    /// speed-independent part of every loaded slice's losses
    /// ([`RacewayLosses::plan_slice`]: the film's load groups and Hertz values, the powers
    /// of G and W, the Barus factors of the traction nodes) is computed once, and every
    /// [`BearingFrictionModel::evaluate`] that follows takes it for each slice whose load,
    /// radius and modulus are the planned ones (bit for bit; any other slice is computed
    /// in full). A speed sweep over one load distribution plans once: its results are
    /// those of the unplanned evaluations bit for bit, with 4 `powf`, 2 `sqrt` and 16
    /// `exp` fewer per loaded slice and speed. Allocates the plan on the first call only
    /// (Z × slices × 2 entries of about 260 bytes); a new plan replaces the old one (an
    /// error leaves none).
    ///
    /// # Errors
    /// As [`BearingFrictionModel::evaluate`] for `cup_slices`, `cone_slices` and `tilts`,
    /// and those of [`RacewayLosses::plan_slice`].
    pub fn plan_loads(
        &mut self,
        cup_slices: &[f64],
        cone_slices: &[f64],
        tilts: Option<&[f64]>,
    ) -> Result<()> {
        let z = self.bearing.rollers;
        let n = self.slices.len();
        self.plans.clear();
        self.check_loads(cup_slices, cone_slices, tilts)?;
        self.plans.reserve_exact(z * n * 2);
        // The kinematics of Δω = 1 rad/s: any valid speeds (the plan does not depend on
        // them).
        let (cage, spin0) = self.speeds(1.0, 0.0);
        let (om_i, om_o) = ((1.0 - cage).abs(), cage.abs());
        for j in 0..z {
            let tilt = tilts.map_or(0.0, |t| t[j]);
            let (t_m, spin) = self.roller_spin(tilt, spin0, om_i, om_o);
            for k in 0..n {
                for cup_side in [false, true] {
                    let q = slice_load(cup_side, cup_slices, cone_slices, j * n + k);
                    let plan = q.and_then(|q| {
                        let ring = if cup_side { om_o } else { om_i };
                        let w = q / self.width;
                        let s = self.slice(&self.slices[k], cup_side, &t_m, ring, spin, w);
                        self.losses.plan_slice(&s)
                    });
                    match plan {
                        Ok(plan) => self.plans.push(plan),
                        Err(e) => {
                            self.plans.clear();
                            return Err(e);
                        }
                    }
                }
            }
        }
        Ok(())
    }

    /// Drop the plan of [`BearingFrictionModel::plan_loads`] (keeping its memory): every
    /// evaluation computes every slice in full again.
    pub fn clear_plan(&mut self) {
        self.plans.clear();
    }

    /// The checks of the load distribution of [`BearingFrictionModel::evaluate`]: lengths
    /// and finite tilts (the slice loads' values are checked slice by slice,
    /// [`slice_load`]).
    fn check_loads(&self, cup: &[f64], cone: &[f64], tilts: Option<&[f64]>) -> Result<()> {
        let count = self.bearing.rollers * self.slices.len();
        for (field, s) in [("cup_slices", cup), ("cone_slices", cone)] {
            if s.len() != count {
                return Err(Error::invalid(
                    field,
                    s.len(),
                    format!("{count} slice loads (rollers × slices)"),
                ));
            }
        }
        tilts.map_or(Ok(()), |s| per_roller("tilts", s, self.bearing.rollers))
    }

    /// The axis of a roller tilted by `tilt` and its spin |ω_R| (`spin0` untilted; the mean
    /// of the two midpoint rolling conditions at the cage-frame ring speeds `om_i`, `om_o`
    /// when tilted).
    fn roller_spin(&self, tilt: f64, spin0: f64, om_i: f64, om_o: f64) -> (Vector2<f64>, f64) {
        let (ri0, ro0, r0) = self.pitch_radii();
        let t_m = axis(self.alpha_m, tilt);
        let (pi0, po0) = (
            -Vector2::new(self.alpha_m.cos(), self.alpha_m.sin()) * r0,
            Vector2::new(self.alpha_m.cos(), self.alpha_m.sin()) * r0,
        );
        let spin = if tilt == 0.0 {
            spin0
        } else {
            0.5 * (om_i * ri0 / cross(&pi0, &t_m).abs() + om_o * ro0 / cross(&po0, &t_m).abs())
        };
        (t_m, spin)
    }

    /// The bearing.
    pub fn bearing(&self) -> &RollerBearing {
        &self.bearing
    }

    /// The raceway loss model.
    pub fn losses(&self) -> &RacewayLosses {
        &self.losses
    }

    /// Every roller's losses of the last evaluation.
    pub fn rollers(&self) -> &[RollerFriction] {
        &self.rollers
    }

    /// Slice centres along the raceway lines from their midpoints \[mm\].
    pub fn slice_position(&self, k: usize) -> f64 {
        let l = self.bearing.effective_length_mm;
        -0.5 * l + (k as f64 + 0.5) * self.width
    }

    /// Radii of the midpoints of the cone and cup lines from the bearing axis \[mm\] and
    /// the roller radius there \[mm\] (untilted).
    pub fn pitch_radii(&self) -> (f64, f64, f64) {
        let n_m = Vector2::new(self.alpha_m.cos(), self.alpha_m.sin());
        let h = 0.5 * self.bearing.roller_diameter_mm;
        (self.half_pitch - h * n_m.x, self.half_pitch + h * n_m.x, h)
    }

    /// Cage speed ω_c and roller spin |ω_R| (relative to the cage) \[rad/s\] at the ring
    /// speeds, pure rolling at the midpoints of both lines (untilted).
    pub fn speeds(&self, inner_speed: f64, outer_speed: f64) -> (f64, f64) {
        let (ri, ro, r) = self.pitch_radii();
        let cage = (inner_speed * ri + outer_speed * ro) / (ri + ro);
        (cage, (inner_speed - cage).abs() * ri / r)
    }

    /// The slice of roller geometry `g` on raceway `cup` at tilt `tilt`, speeds of the
    /// ring `ring` (|Ω| rad/s) and roller `spin` (|ω_R|), load per length `w`.
    fn slice(
        &self,
        g: &SliceGeom,
        cup: bool,
        t_m: &Vector2<f64>,
        ring: f64,
        spin: f64,
        w: f64,
    ) -> RacewaySlice {
        let p = if cup { g.p_o } else { g.p_i };
        let big_r = self.half_pitch + p.x;
        let r = cross(&p, t_m).abs();
        let (v_g, v_r) = (ring * big_r, spin * r);
        let ring_curv = if cup {
            -self.cos_o / big_r
        } else {
            self.cos_i / big_r
        };
        RacewaySlice {
            load_per_length: w,
            width: self.width,
            radius: 1.0 / (self.cos_beta / r + ring_curv),
            entrainment_speed: 0.5 * (v_r + v_g),
            sliding_speed: v_r - v_g,
            reduced_modulus: self.modulus,
        }
    }

    /// The friction of the bearing at `op`. Writes every roller's losses (see
    /// [`BearingFrictionModel::rollers`]); allocates nothing.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the field: `inner_speed`, `outer_speed` (finite),
    /// `cup_slices` / `cone_slices` (length Z × slices), `tilts` / `rib` (length Z, finite),
    /// `drag` (finite, ≥ 0), and those of [`RacewayLosses::slice`].
    pub fn evaluate(&mut self, op: &FrictionOperating<'_>) -> Result<BearingFriction> {
        let z = self.bearing.rollers;
        let n = self.slices.len();
        for (field, v) in [
            ("inner_speed", op.inner_speed),
            ("outer_speed", op.outer_speed),
        ] {
            if !v.is_finite() {
                return Err(Error::invalid(field, v, "a finite speed in rad/s"));
            }
        }
        self.check_loads(op.cup_slices, op.cone_slices, op.tilts)?;
        if let Some(s) = op.rib {
            per_roller("rib", s, z)?;
        }
        let drag_nmm = match op.drag {
            DragModel::None => 0.0,
            DragModel::Torque { nmm } => {
                if !(nmm.is_finite() && nmm >= 0.0) {
                    return Err(Error::invalid("drag", nmm, "a finite torque >= 0 N·mm"));
                }
                nmm
            }
        };
        let dw = op.inner_speed - op.outer_speed;
        let starting = dw == 0.0;
        // At standstill the kinematics of unit Δω (inner ring) give the sliding per unit
        // speed; the film is off.
        let (wi, wo) = if starting {
            (1.0, 0.0)
        } else {
            (op.inner_speed, op.outer_speed)
        };
        let (cage, spin0) = self.speeds(wi, wo);
        let (om_i, om_o) = ((wi - cage).abs(), (wo - cage).abs());
        let mu_b = self.losses.lubrication().law.boundary_coefficient;
        let mut warnings = FrictionWarnings {
            starting,
            ..Default::default()
        };
        let mut min_lambda = f64::INFINITY;
        let (mut cone, mut cup) = (RacewayTorque::default(), RacewayTorque::default());
        let mut power = PowerBreakdown::default();
        let mut rib_nmm = 0.0;
        let scale = if starting { 1e3 } else { 1e3 / dw.abs() };
        for j in 0..z {
            let tilt = op.tilts.map_or(0.0, |t| t[j]);
            let (t_m, spin) = self.roller_spin(tilt, spin0, om_i, om_o);
            let mut out = if let Some(i) = twin(op, n, j) {
                // The same slice loads and tilt as roller i: its raceway losses, bit for bit.
                let (films, starved) = self.roller_warnings[i];
                warnings.film_out_of_range_slices += films;
                warnings.starvation_extrapolated |= starved;
                self.roller_warnings[j] = (films, starved);
                RollerFriction {
                    roller: j,
                    ..self.rollers[i]
                }
            } else {
                let mut out = RollerFriction {
                    roller: j,
                    tilt_rad: tilt,
                    spin_rad_s: spin,
                    min_lambda: f64::INFINITY,
                    ..Default::default()
                };
                let (mut films, mut starved) = (0, false);
                for k in 0..n {
                    let g = self.slices[k];
                    for cup_side in [false, true] {
                        let q = slice_load(cup_side, op.cup_slices, op.cone_slices, j * n + k)?;
                        if q == 0.0 {
                            continue;
                        }
                        let ring = if cup_side { om_o } else { om_i };
                        let s = self.slice(&g, cup_side, &t_m, ring, spin, q / self.width);
                        let (rolling, sliding) = if starting {
                            // Boundary friction per unit Δω: μ_b q |v_s(Δω = 1)|, N·mm/s.
                            (0.0, mu_b * q * s.sliding_speed.abs() * 1e-3)
                        } else {
                            let plan = self.plans.get((j * n + k) * 2 + usize::from(cup_side));
                            let l: SliceLosses = match plan {
                                Some(Some(plan)) => self.losses.slice_planned(&s, plan)?,
                                _ => self.losses.slice(&s)?,
                            };
                            if !l.warnings.film.is_empty() {
                                films += 1;
                            }
                            starved |= l.warnings.starvation_extrapolated;
                            out.min_lambda = out.min_lambda.min(l.lambda);
                            (l.rolling_power, l.sliding_power)
                        };
                        out.max_sliding_mm_s = out.max_sliding_mm_s.max(s.sliding_speed.abs());
                        if cup_side {
                            out.cup_load_n += q;
                            out.cup_rolling_w += rolling;
                            out.cup_sliding_w += sliding;
                        } else {
                            out.cone_load_n += q;
                            out.cone_rolling_w += rolling;
                            out.cone_sliding_w += sliding;
                        }
                    }
                }
                warnings.film_out_of_range_slices += films;
                warnings.starvation_extrapolated |= starved;
                self.roller_warnings[j] = (films, starved);
                out
            };
            let rib = op.rib.map_or(0.0, |r| r[j]);
            if starting {
                // Given as torque shares (N·mm): as power at unit Δω (W).
                out.rib_w = rib * 1e-3;
            } else {
                out.rib_w = rib;
            }
            out.torque_nmm = out.power_w() * scale;
            min_lambda = min_lambda.min(out.min_lambda);
            cone.rolling_nmm += out.cone_rolling_w * scale;
            cone.sliding_nmm += out.cone_sliding_w * scale;
            cup.rolling_nmm += out.cup_rolling_w * scale;
            cup.sliding_nmm += out.cup_sliding_w * scale;
            rib_nmm += out.rib_w * scale;
            power.rolling_w += out.cone_rolling_w + out.cup_rolling_w;
            power.sliding_w += out.cone_sliding_w + out.cup_sliding_w;
            power.rib_w += out.rib_w;
            self.rollers[j] = out;
        }
        if starting {
            power = PowerBreakdown::default();
            min_lambda = f64::INFINITY;
        } else {
            power.drag_w = drag_nmm * dw.abs() * 1e-3;
        }
        power.total_w = power.rolling_w + power.sliding_w + power.rib_w + power.drag_w;
        let total = cone.total_nmm() + cup.total_nmm() + rib_nmm + drag_nmm;
        let sign = if dw < 0.0 { -1.0 } else { 1.0 };
        let coefficient = op
            .coefficient_basis
            .filter(|&(p, d)| p > 0.0 && d > 0.0 && p.is_finite() && d.is_finite())
            .map(|(p, d)| total / (p * 0.5 * d));
        Ok(BearingFriction {
            inner_speed_rad_s: op.inner_speed,
            outer_speed_rad_s: op.outer_speed,
            cage_speed_rad_s: if starting { 0.0 } else { cage },
            roller_spin_rad_s: if starting { 0.0 } else { spin0 },
            cone,
            cup,
            rib_nmm,
            drag_nmm,
            total_nmm: total,
            inner_ring_nmm: sign * total,
            outer_ring_nmm: -sign * total,
            power,
            coefficient,
            min_lambda,
            warnings,
        })
    }
}

/// The cup and cone slice loads \[N\] (roller-major) of an ISO/TS 16281 slice model's
/// solve (`slice_loads`, `rollers` of `RollerBearingSolver` or the coupled-slice solver),
/// written into `cup` and `cone` (each as long as `slice_loads`): the model has one load per
/// slice along the cup normal; the cone's slices carry it scaled by the roller's
/// `inner_n / outer_n` (a tapered roller's cone load differs by the rib's share).
/// Allocates nothing.
///
/// # Errors
/// Field `cup_slices` / `cone_slices` when a buffer has the wrong length, `slice_loads`
/// when it is not a whole number of slices per roller.
pub fn iso_slice_loads(
    slice_loads: &[f64],
    rollers: &[crate::equilibrium::RollerLoad],
    cup: &mut [f64],
    cone: &mut [f64],
) -> Result<()> {
    let z = rollers.len();
    if z == 0 || !slice_loads.len().is_multiple_of(z) {
        return Err(Error::invalid(
            "slice_loads",
            slice_loads.len(),
            format!("a whole number of slices for each of {z} rollers"),
        ));
    }
    let n = slice_loads.len() / z;
    for (field, b) in [("cup_slices", cup.len()), ("cone_slices", cone.len())] {
        if b != slice_loads.len() {
            return Err(Error::invalid(
                field,
                b,
                format!("{} slice loads (rollers × slices)", slice_loads.len()),
            ));
        }
    }
    for (j, r) in rollers.iter().enumerate() {
        let ratio = if r.outer_n > 0.0 {
            r.inner_n / r.outer_n
        } else {
            1.0
        };
        for k in 0..n {
            let q = slice_loads[j * n + k];
            cup[j * n + k] = q;
            cone[j * n + k] = q * ratio;
        }
    }
    Ok(())
}

/// Every roller's cup load at its azimuth, as the rib friction takes them
/// (`kontakt::bearing::RibFrictionModel::roller_loads_on_cups`), from an ISO slice model's
/// rollers. Allocates the list.
pub fn roller_cups(rollers: &[crate::equilibrium::RollerLoad]) -> Vec<kontakt::bearing::RollerCup> {
    rollers
        .iter()
        .map(|r| kontakt::bearing::RollerCup {
            azimuth: r.azimuth_rad,
            outer_raceway: r.outer_n,
        })
        .collect()
}

/// The raceway lubrication of `oil` at `temperature_c` \[°C\]: its dynamic viscosity and
/// pressure-viscosity coefficient, the temperature slope of the viscosity when `thermal`
/// (Zhu-Cheng factor), conductivity 0.134 W/(m·K) (mineral oil), fully flooded, composite
/// roughness `roughness` \[mm\], the law `law` and the fit `rolling`.
///
/// # Errors
/// Those of the lubricant at `temperature_c` (field `temperature_c`).
pub fn raceway_lubrication(
    oil: &kontakt::lubrication::Lubricant,
    temperature_c: f64,
    thermal: bool,
    roughness: f64,
    law: kontakt::friction::FrictionLaw,
    rolling: kontakt::lubrication::RollingResistanceModel,
) -> Result<super::raceway::RacewayLubrication> {
    Ok(super::raceway::RacewayLubrication {
        viscosity: oil.dynamic_viscosity(temperature_c)?,
        alpha: oil.alpha(),
        viscosity_slope: if thermal {
            Some(kontakt::lubrication::viscosity_temperature_slope(
                oil,
                temperature_c,
            )?)
        } else {
            None
        },
        conductivity: 0.134,
        film_starvation: 1.0,
        starvation_degree: None,
        roughness,
        law,
        rolling,
    })
}

#[cfg(test)]
#[path = "torque_tests.rs"]
mod tests;
