//! Roller bearings (tapered; cylindrical with ribs) with every roller in its own
//! equilibrium and the roller-end/rib contacts in the loop (issue 28 §2, "the roller's force
//! and moment balance with the rib contact included"): the option next to the fast
//! ISO/TS 16281 model of
//! [`crate::equilibrium`], which stays the default. Derivation, frames and signs:
//! `docs/bearing-model.md` §15.
//!
//! **The roller.** Roller j has three degrees of freedom in its axial plane (2-D
//! coordinates `(r, z)`: radial along `e_r(ψ_j)`, axial along z; origin the roller centre
//! `O = R e_r` on its axis): a translation `a` along the cup normal
//! `n_o = (cos α, sin α)`, a translation `b` along the cup line `t_o = (−sin α, cos α)`
//! (toward the small end), and a tilt φ (rad, counter-clockwise in `(r, z)`: a positive
//! tilt turns the small end toward the bearing axis). It touches
//!
//! - the cup in `n` slices at `x_k` along the cup line: approach
//!   `δ_ok = a − φ x̃_k − e_ok` (mm), `x̃_k = x_k − (D/2) sin β_r` the moment arm about O,
//!   `β_r = (α − α_i)/2` the roller half-angle, `e_ok = s/4 + P_roller(x_k) + P_outer(x_k)`;
//! - the cone in `n` slices along the cone line: approach
//!   `δ_ik = g_ik · u − a cos γ + b sin γ + φ x̃_k − e_ik`, `γ = α − α_i`,
//!   `e_ik = s/4 + P_roller(x_k) + P_inner(x_k)`, `g_ik` the cone normal's 5-vector of the
//!   ring motion `u` (as in [`crate::equilibrium`], with the cone normal
//!   `n_i = (cos α_i, sin α_i)`);
//! - the rib at one point `s_f` (from O) with the rib normal `n_f` (rib into roller):
//!   approach `δ_f = g_f · u − (a n_o + b t_o) · n_f − φ (s_f × n_f)`.
//!
//! Each raceway slice carries `q = c δ₊^(10/9)` with `c = 2^(10/9) c_s`: two such
//! contacts in series at equal load have the approach `2 (q/c)^(9/10)`, which is the
//! ISO/TS 16281 slice law `q = c_s δ^(10/9)` of both contacts (`c_s = 35948 L^(8/9)/n`).
//! The rib carries Hertz's `Q_f = K_f δ_f₊^(3/2)` of the face/rib pair of
//! `kontakt::bearing::roller_rib` at its contact point (`kontakt::hertz`, steel on steel),
//! or, with [`RibContactSolver::set_rib_model`], PimP's or the half-space solver's
//! load-approach curve of the same pair, tabulated once (`rib_law`, docs/bearing-model.md
//! §15.8).
//! A given centrifugal force `F_c` (N per roller, along `+e_r`, at O) loads the roller.
//!
//! **Solver.** The total potential
//! `Π(u, ρ) = Σ_contacts W(δ) − F_c (a cos α − b sin α) − F · u` with
//! `W = c (9/19) δ₊^(19/9)` (slices) and `(2/5) K_f δ₊^(5/2)` (rib) is convex in the ring
//! motion u and all roller motions ρ (every approach is affine in them). For a given u,
//! each roller's three equations `∂Π/∂ρ_j = 0` (its force and moment balance) are solved
//! by Newton with an Armijo line search on Π, warm-started from the roller's last
//! position; the ring sees the reduced potential `Φ(u) = min_ρ Π`, its gradient the
//! carried load `F(u) = Σ q_ik g_ik + Q_f g_f` and its Hessian the statically condensed
//! stiffness `K = K_uu − K_uρ K_ρρ⁻¹ K_ρu`, consistent with the solution. The ring
//! iteration is the one of [`crate::equilibrium`] (`newton.rs`). A roller without contact
//! (and without centrifugal force) carries nothing and floats at the position where its
//! cup, cone and rib gaps are equal and it is not tilted. Buffers are allocated once in
//! [`RibContactSolver::new`]; a solve allocates nothing.
//!
//! **Cylindrical roller bearings** ([`RibContactSolver::cylindrical`]): the same balance
//! with α = α_i = 0 and the ribs of the arrangement ([`RibArrangement`]: NU, NJ, NUP, N) on
//! either ring, spherical roller ends against straight ribs ([`CylindricalRibs`]), so that
//! NJ and NUP carry an axial load through the roller ends and NU and N refuse one
//! (`docs/bearing-model.md` §15.5).
//!
//! **Not modelled.** Friction (so the skew moment about the cup normal is zero: reported
//! as 0), the cage, the roller's gyroscopic moment, the centrifugal force's offset from O,
//! the change of the rib's contact point with the roller's tilt (the point and normal are
//! those of the unloaded construction; the approach is linear in the motions), coupled
//! slices, ring deformation. The rib's curvature about the bearing axis is that of the
//! common-apex construction of `roller_rib` for this roller (docs/bearing-model.md §15).

use crate::equilibrium::{
    Dof, RingLoad, RollerBearingSolver, RollerSolution, free_and_target, load_scale, load_zone,
    slice_touch, warm_start,
};
use crate::geometry::{RollerBearing, RollerBearingKind};
use crate::newton::{ConvexRing, Outcome, newton, to_rows};
use kontakt::bearing::{FaceShape, RibShape, RollerRib, RollerRibSpec, TaperedRollerBearing};
use kontakt::gap::GapSource;
use kontakt::hertz::{HertzPointContact, PointGeometry};
use kontakt::material::ElasticMaterial;
use kontakt::solve::{SolveStatus, Termination};
use kontakt::{Error, Result};
use nalgebra::{Matrix3, Matrix5, Matrix5x3, Vector2, Vector3, Vector5};
use std::f64::consts::PI;

mod rib_law;
use rib_law::RibLaw;
pub use rib_law::{RibModel, RibTable, RibTableRange, tabulate};

/// The roller-end/rib pair of a tapered roller bearing, in the vocabulary of the rib study
/// (`kontakt::bearing::roller_rib`, Wirsching et al. 2020): the roller's large-end face, the
/// cone's rib and the height of their contact point above the roller axis.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RibContact {
    /// The roller's end face (sphere or torus), mm.
    pub face: FaceShape,
    /// The rib (cone or torus), mm.
    pub rib: RibShape,
    /// Distance h of the contact point from the roller axis, mm (toward the cone).
    pub contact_height_mm: f64,
}

/// Which rings of a cylindrical roller bearing have ribs (ISO 15 / catalogue type codes):
/// they decide whether an axial load passes through the roller end/rib contacts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "lowercase"))]
pub enum RibArrangement {
    /// Outer ring ribs at both ends, none on the inner ring: no axial load.
    Nu,
    /// Outer ring ribs at both ends, one inner ring rib at the −z end: axial load in +z
    /// (the inner ring pushed toward +z).
    Nj,
    /// Ribs at both ends of both rings (NJ with a loose rib washer): axial load both ways.
    Nup,
    /// Inner ring ribs at both ends, none on the outer ring: no axial load.
    N,
}

impl RibArrangement {
    /// The catalogue's name: `NU`, `NJ`, `NUP`, `N`.
    pub fn name(&self) -> &'static str {
        match self {
            RibArrangement::Nu => "NU",
            RibArrangement::Nj => "NJ",
            RibArrangement::Nup => "NUP",
            RibArrangement::N => "N",
        }
    }

    /// The ribs: (on the inner ring, at the +z (1) or the −z (−1) end).
    fn ribs(&self) -> Vec<(bool, f64)> {
        let outer = [(false, 1.0), (false, -1.0)];
        let inner = [(true, 1.0), (true, -1.0)];
        match self {
            RibArrangement::Nu => outer.to_vec(),
            RibArrangement::Nj => vec![outer[0], outer[1], inner[1]],
            RibArrangement::Nup => [outer, inner].concat(),
            RibArrangement::N => inner.to_vec(),
        }
    }

    /// Whether the ribs carry an axial load on the inner ring toward +z and toward −z: +z
    /// needs an inner ring rib at the −z end and an outer ring rib at the +z end.
    pub fn axial_directions(&self) -> (bool, bool) {
        match self {
            RibArrangement::Nu | RibArrangement::N => (false, false),
            RibArrangement::Nj => (true, false),
            RibArrangement::Nup => (true, true),
        }
    }
}

/// The roller end faces and the rib faces of a cylindrical roller bearing, the same at
/// every rib: a spherical end face of radius r_R centred on the roller axis, touching a rib
/// whose face is straight in the axial plane at the height h from the roller axis (toward
/// the rib's ring); the rib's normal there leans by `asin(h/r_R)` from the roller axis.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct CylindricalRibs {
    /// The end face's sphere radius r_R, mm (>= L_we/2).
    pub face_radius_mm: f64,
    /// The contact height h above (toward the ring) the roller axis, mm (0 < h < D_we/2).
    pub contact_height_mm: f64,
    /// The roller's axial end play between the two ribs of one ring, mm (>= 0; half of it
    /// on each side with the roller centred): with none, a radially loaded roller would
    /// wedge between the leaning ribs.
    pub end_play_mm: f64,
}

/// One roller of the rib-contact model at the solution.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RibRollerLoad {
    /// Azimuth ψ_j, rad.
    pub azimuth_rad: f64,
    /// Cup (outer raceway) load, the sum of the cup slices, N.
    pub outer_n: f64,
    /// Cone (inner raceway) load, the sum of the cone slices, N.
    pub inner_n: f64,
    /// Rib load Q_f on the inner ring's rib(s) (the cone's rib of a tapered roller), N.
    pub rib_n: f64,
    /// Load on the outer ring's rib(s), N (cylindrical NU/NJ/NUP bearings; 0 otherwise).
    pub outer_rib_n: f64,
    /// The roller's tilt φ in its axial plane, rad (positive: the small end toward the
    /// bearing axis).
    pub tilt_rad: f64,
    /// The roller's translation `(a, b)` along the cup normal and the cup line, mm.
    pub translation_mm: [f64; 2],
    /// The largest Hertz pressure of the roller's rib contacts, MPa (0 without rib load).
    pub rib_max_pressure_mpa: f64,
    /// The skew moment about the cup normal, N·mm: 0 in this frictionless model.
    pub skew_moment_nmm: f64,
    /// The largest approach of the roller's rib contacts, mm (negative: open).
    pub rib_approach_mm: f64,
    /// The largest cup slice approach plus the largest cone slice approach, mm (negative:
    /// lifted off by that much in total).
    pub max_approach_mm: f64,
    /// Newton iterations of the roller's own balance at the last evaluation.
    pub iterations: usize,
}

/// Most rib contacts of a roller: an NUP roller touches the inner and the outer ring's
/// ribs at both ends.
const MAX_RIBS: usize = 4;

/// Per roller: the cone slices' `g = g0 + x g1` and each rib's `g_f` (zero for a rib of
/// the fixed outer ring).
#[derive(Debug, Clone, Copy)]
struct Frame {
    psi: f64,
    g0: Vector5<f64>,
    g1: Vector5<f64>,
    gf: [Vector5<f64>; MAX_RIBS],
}

/// One roller end/rib contact, the same on every roller, in the roller's axial plane.
#[derive(Debug, Clone)]
struct Rib {
    /// On the inner ring (it moves with u) or the outer ring (fixed).
    inner: bool,
    /// Normal, rib into roller.
    n: Vector2<f64>,
    /// Contact point from the roller centre O, mm.
    s: Vector2<f64>,
    /// `∂δ/∂ρ`.
    d: Vector3<f64>,
    /// The gap at zero motion, mm (a cylindrical roller's end play, half per rib).
    gap: f64,
    /// Hertz contact, its load coefficient (N/mm^1.5) and p0 at 1 N (MPa).
    hertz: HertzPointContact,
    k: f64,
    p0: f64,
    /// The force law in the balance (Hertz's `k`, `p0` or a tabulated model).
    law: RibLaw,
}

/// The ring approaches of one roller: the cone slices' `G0 + x G1` and each rib's.
#[derive(Debug, Clone, Copy)]
struct RingApproach {
    g0: f64,
    g1: f64,
    gf: [f64; MAX_RIBS],
}

/// One evaluation of a roller at its position ρ.
#[derive(Debug, Clone, Copy, Default)]
struct RollerEval {
    grad: Vector3<f64>,
    hess: Matrix3<f64>,
    pi: f64,
    /// Σ q_o, Σ q_i, Σ q_i x, the cone's Σ k, Σ k x, Σ k x².
    qo: f64,
    qi0: f64,
    qi1: f64,
    s0: f64,
    s1: f64,
    s2: f64,
    qf: [f64; MAX_RIBS],
    kf: [f64; MAX_RIBS],
    df: [f64; MAX_RIBS],
    max_o: f64,
    max_i: f64,
}

impl RollerEval {
    /// Every contact's load together (0: the roller touches nothing).
    fn total(&self) -> f64 {
        self.qo + self.qi0 + self.qf.iter().sum::<f64>()
    }
}

const EXP: f64 = 10.0 / 9.0;

/// The tapered roller bearing solver with every roller in its own equilibrium and the
/// rib contact in the loop.
#[derive(Debug, Clone)]
pub struct RibContactSolver {
    iso: RollerBearingSolver,
    pair: Option<RollerRib>,
    ribs: Vec<Rib>,
    /// Directions the bearing has stiffness in (a CRB's z through its ribs).
    stiff: [bool; 5],
    /// Cylindrical only: the rib arrangement.
    arrangement: Option<RibArrangement>,
    frames: Vec<Frame>,
    x: Vec<f64>,
    /// Moment arm offset `(D/2) sin β_r`, mm: `x̃ = x − arm0`.
    arm0: f64,
    e_o: Vec<f64>,
    e_i: Vec<f64>,
    /// Per-contact slice constant `2^(10/9) c_s`, N/mm^(10/9).
    c: f64,
    /// cos γ, sin γ.
    cg: f64,
    sg: f64,
    /// 2-D unit vectors in the roller's axial plane.
    n_o: Vector2<f64>,
    n_i: Vector2<f64>,
    t_o: Vector2<f64>,
    t_i: Vector2<f64>,
    rho: Vec<Vector3<f64>>,
    /// Each roller's rib loads of the last evaluation, N, `[j * MAX_RIBS + r]`.
    rib_load: Vec<f64>,
    cup_load: Vec<f64>,
    cone_load: Vec<f64>,
    series_approach: Vec<f64>,
    rollers: Vec<RibRollerLoad>,
    probe: Matrix5<f64>,
    centrifugal_n: f64,
    /// The force scale of one roller for the roller's own tolerance, N (set per solve).
    roller_scale: f64,
    /// The rib contact's force law (Hertz by default; [`RibContactSolver::set_rib_model`]).
    rib_model: RibModel,
    /// Multiplies the rib's load (Hertz's load coefficient or the tabulated law; 1 by
    /// default; a large factor makes the rib rigid, a study and test device).
    pub rib_stiffness_factor: f64,
    /// Hold every roller's tilt at 0 (false by default; a study and test device).
    pub hold_roller_tilt: bool,
    /// Largest relative residual of the ring accepted as converged (default 1e-11).
    pub tolerance: f64,
    /// Iteration limit of the ring (default 100).
    pub max_iterations: usize,
}

/// A rib of the contact normal `n` (rib into roller) at `s` (from the roller centre) on
/// the inner or the outer ring of a bearing with the cup angle `cup_angle` (rad).
fn make_rib(
    cup_angle: f64,
    inner: bool,
    n: Vector2<f64>,
    s: Vector2<f64>,
    hertz: HertzPointContact,
) -> Rib {
    let n_o = unit(cup_angle);
    let t_o = Vector2::new(-cup_angle.sin(), cup_angle.cos());
    Rib {
        inner,
        n,
        s,
        d: -Vector3::new(n_o.dot(&n), t_o.dot(&n), cross(&s, &n)),
        gap: 0.0,
        k: hertz.load_coefficient(),
        p0: hertz.max_pressure_at_unit_force(),
        law: RibLaw::Hertz {
            k: hertz.load_coefficient(),
            p0: hertz.max_pressure_at_unit_force(),
        },
        hertz,
    }
}

/// At least 3 slices: a roller's tilt is balanced by its slices.
fn check_slices(bearing: &RollerBearing) -> Result<()> {
    if bearing.slices < 3 {
        return Err(Error::invalid(
            "slices",
            bearing.slices,
            "at least 3 slices for the rib-contact roller model (the roller's tilt is balanced by its slices)",
        ));
    }
    Ok(())
}

/// The 2-D vector `(cos a, sin a)`.
fn unit(a: f64) -> Vector2<f64> {
    Vector2::new(a.cos(), a.sin())
}

/// 2-D cross product `a × b = a_r b_z − a_z b_r`.
fn cross(a: &Vector2<f64>, b: &Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

/// The ring's 5-vector of a load along the 2-D normal `n` at the 2-D point `p` (from the
/// bearing axis, in the axial plane at azimuth ψ): `(n, (p × n)_x, (p × n)_y)`.
fn ring_vector(psi: f64, p: &Vector2<f64>, n: &Vector2<f64>) -> Vector5<f64> {
    let (s, c) = psi.sin_cos();
    let w = cross(p, n);
    Vector5::new(n.x * c, n.x * s, n.y, w * s, -w * c)
}

impl RibContactSolver {
    /// Set up the solver of the tapered roller bearing `bearing` with the rib pair `rib`.
    ///
    /// # Errors
    /// As [`RollerBearing::validate`]; `kind` unless tapered; `slices` below 3 (a roller's
    /// tilt needs slices to balance it); the rib pair's errors of
    /// `kontakt::bearing::RollerRib::new` named `rib_contact.<field>`
    /// (`rib_contact.contact_height_mm`, `rib_contact.face.radius_mm`, ...);
    /// `rib_angle_rad` when it is given and differs from the rib normal of the pair by more
    /// than 1e-8 rad.
    pub fn new(bearing: RollerBearing, rib: RibContact) -> Result<Self> {
        bearing.validate()?;
        if bearing.kind != RollerBearingKind::Tapered {
            return Err(Error::invalid(
                "kind",
                format!("{:?}", bearing.kind).to_lowercase(),
                "a tapered roller bearing (cylindrical ones: RibContactSolver::cylindrical with their rib arrangement)",
            ));
        }
        check_slices(&bearing)?;
        let (a, ai) = (bearing.contact_angle_rad, bearing.cone_angle_rad);
        let beta_r = 0.5 * (a - ai);
        let l = bearing.effective_length_mm;
        let pair = rib_pair(&bearing, &rib)?;
        // roller_rib's section plane (X radial, Z toward the large end) is (r, −z) here
        let nf3 = pair.contact.normal.into_inner();
        let n_f = Vector2::new(nf3.x, -nf3.z).normalize();
        let u = pair.roller_axis.into_inner();
        let rho_l = pair.spec.bearing.roller_large_end_radius;
        let mid = pair.apex + u * (rho_l / beta_r.tan() - 0.5 * l);
        let rel = pair.contact.point - mid;
        let s_f = Vector2::new(rel.x, -rel.z);
        let built = n_f.y.atan2(n_f.x);
        if let Some(given) = bearing.rib_angle_rad
            && !((given - built).abs() <= 1e-8)
        {
            return Err(Error::invalid(
                "rib_angle_rad",
                given,
                format!(
                    "the rib normal of the roller end/rib pair, {built:.12} rad = {:.9} deg, or none: with the rib contact the face and the contact height set it",
                    built.to_degrees()
                ),
            ));
        }
        let steel = ElasticMaterial::STEEL;
        let gap = pair.gap()?;
        let hertz =
            HertzPointContact::new(PointGeometry::from_curvature(gap.curvature()), steel, steel)?;
        let ribs = vec![make_rib(a, true, n_f, s_f, hertz)];
        let stiff = *RollerBearingSolver::new(bearing.clone())?.stiff();
        Self::build(bearing, ribs, Some(pair), None, stiff)
    }

    /// Set up the solver of the cylindrical roller bearing `bearing` with the ribs of
    /// `arrangement` (NU: outer ring ribs at both ends, NJ: and an inner ring rib at the
    /// −z end, NUP: inner ring ribs at both ends too, N: inner ring ribs at both ends only)
    /// and the roller end faces and rib faces `ribs` (the same at every rib).
    ///
    /// # Errors
    /// As [`RollerBearing::validate`]; `kind` unless cylindrical; `slices` below 3;
    /// `ribs.face_radius_mm`, `ribs.contact_height_mm` out of range (0 < h < D/2,
    /// h < r_R, r_R >= L/2 ... see [`CylindricalRibs`]).
    pub fn cylindrical(
        bearing: RollerBearing,
        arrangement: RibArrangement,
        ribs: CylindricalRibs,
    ) -> Result<Self> {
        bearing.validate()?;
        if bearing.kind != RollerBearingKind::Cylindrical {
            return Err(Error::invalid(
                "kind",
                format!("{:?}", bearing.kind).to_lowercase(),
                "a cylindrical roller bearing (tapered ones: RibContactSolver::new)",
            ));
        }
        check_slices(&bearing)?;
        let (d, l) = (bearing.roller_diameter_mm, bearing.effective_length_mm);
        let rr = ribs.face_radius_mm;
        let h = ribs.contact_height_mm;
        if !(rr.is_finite() && rr >= 0.5 * l) {
            return Err(Error::invalid(
                "ribs.face_radius_mm",
                rr,
                format!(
                    "a finite radius >= half the roller length, {} mm (the face's sphere centred on the roller axis)",
                    0.5 * l
                ),
            ));
        }
        if !(h.is_finite() && h > 0.0 && h < 0.5 * d && h < rr) {
            return Err(Error::invalid(
                "ribs.contact_height_mm",
                h,
                format!(
                    "0 < h < half the roller diameter, {} mm (and < face_radius_mm)",
                    0.5 * d
                ),
            ));
        }
        let play = ribs.end_play_mm;
        if !(play.is_finite() && play >= 0.0 && play < l) {
            return Err(Error::invalid(
                "ribs.end_play_mm",
                play,
                format!("a finite play, 0 <= play < the roller length {l} mm"),
            ));
        }
        let lean = (h / rr).asin();
        let (sl, cl) = lean.sin_cos();
        let r = 0.5 * bearing.pitch_diameter_mm;
        let steel = ElasticMaterial::STEEL;
        let mut list = Vec::new();
        // (inner ring?, end: +1 the +z end, −1 the −z end)
        for (inner, end) in arrangement.ribs() {
            let side = if inner { -1.0 } else { 1.0 };
            // the face's normal out of the roller leans by asin(h/r_R) toward the ring
            let m = Vector2::new(side * sl, end * cl);
            let centre = Vector2::new(0.0, end * (0.5 * l - rr));
            let s_f = centre + m * rr;
            let n_f = -m;
            // the rib: straight in the axial plane, its parallel circle of radius R ± h
            // curved by sin(lean)/(R ± h) about the normal (Meusnier): convex on the inner
            // ring, concave on the outer
            let rc = r + side * h;
            let rib_radius = if sl > 0.0 {
                -side * rc / sl
            } else {
                f64::INFINITY
            };
            let geometry = PointGeometry::new([rr, rr], [f64::INFINITY, rib_radius], 0.0)
                .map_err(|e| e.map_field(|_| "ribs.contact_height_mm".to_string()))?;
            let hertz = HertzPointContact::new(geometry, steel, steel)?;
            let mut rib = make_rib(0.0, inner, n_f, s_f, hertz);
            rib.gap = 0.5 * ribs.end_play_mm;
            list.push(rib);
        }
        let mut stiff = *RollerBearingSolver::new(bearing.clone())?.stiff();
        stiff[2] = arrangement.axial_directions() != (false, false);
        Self::build(bearing, list, None, Some(arrangement), stiff)
    }

    fn build(
        bearing: RollerBearing,
        ribs: Vec<Rib>,
        pair: Option<RollerRib>,
        arrangement: Option<RibArrangement>,
        stiff: [bool; 5],
    ) -> Result<Self> {
        let (a, ai) = (bearing.contact_angle_rad, bearing.cone_angle_rad);
        let gamma = a - ai;
        let beta_r = 0.5 * gamma;
        let am = 0.5 * (a + ai);
        let d = bearing.roller_diameter_mm;
        let r = 0.5 * bearing.pitch_diameter_mm;
        let n_o = unit(a);
        let n_i = unit(ai);
        let t_o = Vector2::new(-a.sin(), a.cos());
        let t_i = Vector2::new(-ai.sin(), ai.cos());
        let z = bearing.rollers;
        let arm0 = 0.5 * d * beta_r.sin();
        // the cone line's midpoint O − (D/2) n_m, n_m the roller's normal
        let o = Vector2::new(r, 0.0);
        let p_i = o - unit(am) * (0.5 * d);
        let frames: Vec<Frame> = (0..z)
            .map(|j| {
                let psi = bearing.first_roller_azimuth_rad + 2.0 * PI * j as f64 / z as f64;
                let (s, c) = psi.sin_cos();
                let mut gf = [Vector5::zeros(); MAX_RIBS];
                for (g, rib) in gf.iter_mut().zip(&ribs) {
                    if rib.inner {
                        *g = ring_vector(psi, &(o + rib.s), &rib.n);
                    }
                }
                Frame {
                    psi,
                    g0: ring_vector(psi, &p_i, &n_i),
                    g1: Vector5::new(0.0, 0.0, 0.0, -s, c),
                    gf,
                }
            })
            .collect();
        let x: Vec<f64> = bearing.slice_positions().collect();
        let quarter = 0.25 * bearing.clearance_mm;
        let e_o = x
            .iter()
            .map(|&xk| quarter + bearing.roller_profile.drop(xk) + bearing.outer_profile.drop(xk))
            .collect();
        let e_i = x
            .iter()
            .map(|&xk| quarter + bearing.roller_profile.drop(xk) + bearing.inner_profile.drop(xk))
            .collect();
        let c_s = bearing.roller_stiffness() / bearing.slices as f64;
        let mut probe = Matrix5::zeros();
        for f in &frames {
            for &xk in &x {
                let g = f.g0 + f.g1 * xk;
                probe += g * g.transpose();
            }
            // the ribs carry a cylindrical bearing's axial load
            for g in &f.gf {
                probe += g * g.transpose() * (x.len() as f64);
            }
        }
        let n = z * bearing.slices;
        let iso = RollerBearingSolver::new(bearing)?;
        Ok(RibContactSolver {
            iso,
            pair,
            ribs,
            stiff,
            arrangement,
            frames,
            arm0,
            e_o,
            e_i,
            c: c_s * 2f64.powf(EXP),
            cg: gamma.cos(),
            sg: gamma.sin(),
            n_o,
            n_i,
            t_o,
            t_i,
            rho: vec![Vector3::zeros(); z],
            rib_load: vec![0.0; z * MAX_RIBS],
            cup_load: vec![0.0; n],
            cone_load: vec![0.0; n],
            series_approach: vec![0.0; n],
            rollers: vec![RibRollerLoad::default(); z],
            probe,
            centrifugal_n: 0.0,
            roller_scale: 0.0,
            x,
            rib_model: RibModel::Hertz,
            rib_stiffness_factor: 1.0,
            hold_roller_tilt: false,
            tolerance: 1e-11,
            max_iterations: 100,
        })
    }

    /// The bearing.
    pub fn bearing(&self) -> &RollerBearing {
        self.iso.bearing()
    }

    /// The roller end/rib pair of a tapered bearing as built by `kontakt::bearing::RollerRib`
    /// (the contact point, its normal, the surfaces); `None` for a cylindrical bearing.
    pub fn rib_pair(&self) -> Option<&RollerRib> {
        self.pair.as_ref()
    }

    /// The rib arrangement of a cylindrical bearing (`None`: tapered).
    pub fn arrangement(&self) -> Option<RibArrangement> {
        self.arrangement
    }

    /// The Hertz contact of rib contact `r` (in the order of
    /// [`RibContactSolver::rib_contacts`]; roller end body 1, rib body 2, the first
    /// principal direction in the axial plane): a cylindrical bearing's inner ring ribs
    /// are convex about the bearing axis, its outer ring ribs concave.
    ///
    /// # Panics
    /// If `r` is not a rib contact index.
    pub fn rib_hertz_of(&self, r: usize) -> &HertzPointContact {
        &self.ribs[r].hertz
    }

    /// Roller `j`'s load on each of its rib contacts (in the order of
    /// [`RibContactSolver::rib_contacts`]) at the last evaluation, N.
    ///
    /// # Panics
    /// If `j` is not a roller index.
    pub fn roller_rib_loads(&self, j: usize) -> &[f64] {
        &self.rib_load[j * MAX_RIBS..j * MAX_RIBS + self.ribs.len()]
    }

    /// The first rib's normal direction (rib into roller) in the roller's axial plane,
    /// measured like the contact angles, rad (a tapered bearing's only rib, on the cone).
    pub fn rib_normal_angle(&self) -> f64 {
        self.ribs.first().map_or(f64::NAN, |r| r.n.y.atan2(r.n.x))
    }

    /// Every rib contact: on the inner ring or not, its point from the roller centre and
    /// its normal (rib into roller) in the axial plane `(r, z)`, mm.
    pub fn rib_contacts(&self) -> impl Iterator<Item = (bool, [f64; 2], [f64; 2])> + '_ {
        self.ribs
            .iter()
            .map(|r| (r.inner, [r.s.x, r.s.y], [r.n.x, r.n.y]))
    }

    /// The first rib's Hertz contact (face and rib curvatures at the contact point, steel
    /// on steel), before `rib_stiffness_factor`; every rib of a bearing is alike.
    pub fn rib_hertz(&self) -> &HertzPointContact {
        &self.ribs[0].hertz
    }

    /// The Hertz load coefficient of the rib contact (before `rib_stiffness_factor`),
    /// `Q = K_f δ^(3/2)`, N/mm^1.5.
    pub fn rib_load_coefficient(&self) -> f64 {
        self.ribs[0].k
    }

    /// The rib contact's force law in the balance (default [`RibModel::Hertz`]).
    pub fn rib_model(&self) -> RibModel {
        self.rib_model
    }

    /// Give the rib contact of a tapered bearing the force law of `model`: Hertz (the
    /// closed form) or PimP or the half-space solver, each solved once here over `range`
    /// and tabulated as a load-approach curve (docs/bearing-model.md §15.8); the solves
    /// after it allocate nothing. The pressure reported on the rib is that model's.
    ///
    /// # Errors
    /// `rib_contact.model` for a cylindrical bearing (its rib pair is Hertz's only) or when
    /// the model cannot solve the contact at 4 knots; `rib_table.*` out of range.
    pub fn set_rib_model(&mut self, model: RibModel, range: &RibTableRange) -> Result<()> {
        if model == RibModel::Hertz {
            for rib in &mut self.ribs {
                rib.law = RibLaw::Hertz {
                    k: rib.k,
                    p0: rib.p0,
                };
            }
            self.rib_model = model;
            return Ok(());
        }
        let Some(pair) = &self.pair else {
            return Err(Error::invalid(
                "rib_contact.model",
                model.as_str(),
                "hertz for a cylindrical roller bearing (PimP and the half-space law need the roller end/rib pair of a tapered bearing)",
            ));
        };
        let gap = pair.gap()?;
        // the roller's line contact at pressure p: Q = π L (D/2) p² / E* (Hertz 1881)
        let b = self.iso.bearing();
        let (l, r) = (b.effective_length_mm, 0.5 * b.roller_diameter_mm);
        let steel = ElasticMaterial::STEEL;
        let e_star = kontakt::material::effective_modulus(&steel, &steel);
        let limit = move |p: f64| PI * l * r * p * p / e_star;
        let table = tabulate(model, &gap, self.ribs[0].p0, &limit, range)?;
        for rib in &mut self.ribs {
            rib.law = RibLaw::Table(Box::new(table.clone()));
        }
        self.rib_model = model;
        Ok(())
    }

    /// The tabulated rib law (`None` for Hertz).
    pub fn rib_table(&self) -> Option<&RibTable> {
        match &self.ribs[0].law {
            RibLaw::Table(t) => Some(t),
            RibLaw::Hertz { .. } => None,
        }
    }

    /// The rib contact's load `Q` (N), its derivative `dQ/dδ` (N/mm) and potential
    /// `∫ Q dδ` (N·mm) at the approach `delta` (mm) by the law in the balance (0 when
    /// open), before `rib_stiffness_factor`.
    pub fn rib_law(&self, delta: f64) -> (f64, f64, f64) {
        if delta > 0.0 {
            self.ribs[0].law.eval(delta, 1.0)
        } else {
            (0.0, 0.0, 0.0)
        }
    }

    /// The maximum pressure on the rib at the load `q` (N) by the law in the balance, MPa.
    pub fn rib_pressure(&self, q: f64) -> f64 {
        if q > 0.0 {
            self.ribs[0].law.pressure(q)
        } else {
            0.0
        }
    }

    /// The centrifugal force on every roller, N (default 0).
    pub fn centrifugal_n(&self) -> f64 {
        self.centrifugal_n
    }

    /// Set the centrifugal force on every roller, N (along the roller's radial direction,
    /// at its centre).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `centrifugal_n` unless finite and >= 0.
    pub fn set_centrifugal_n(&mut self, f: f64) -> Result<()> {
        if !(f.is_finite() && f >= 0.0) {
            return Err(Error::invalid(
                "centrifugal_n",
                f,
                "a finite force >= 0 N per roller",
            ));
        }
        self.centrifugal_n = f;
        Ok(())
    }

    /// Slice centres along the raceway lines from their midpoints, mm.
    pub fn slice_positions(&self) -> &[f64] {
        &self.x
    }

    /// Cup slice loads of the last evaluation, N, roller-major.
    pub fn cup_slice_loads(&self) -> &[f64] {
        &self.cup_load
    }

    /// Cone slice loads of the last evaluation, N, roller-major.
    pub fn cone_slice_loads(&self) -> &[f64] {
        &self.cone_load
    }

    /// Per-slice sum of the cup and cone approaches of the last evaluation, mm.
    pub fn slice_approaches(&self) -> &[f64] {
        &self.series_approach
    }

    /// Per-roller results of the last solve.
    pub fn roller_loads(&self) -> &[RibRollerLoad] {
        &self.rollers
    }

    /// The net force `(r, z)` (N) and moment about the roller centre (N·mm) on roller `j`
    /// from its cup and cone slices, its rib contact and the centrifugal force at the last
    /// evaluation, summed from the contact points and normals (zero in equilibrium).
    pub fn roller_balance(&self, j: usize) -> [f64; 3] {
        let ns = self.x.len();
        let b = self.bearing();
        let half_d = 0.5 * b.roller_diameter_mm;
        let am = 0.5 * (b.contact_angle_rad + b.cone_angle_rad);
        let n_m = unit(am);
        let mut f = Vector2::zeros();
        let mut m = 0.0;
        for k in 0..ns {
            let (qo, qi) = (self.cup_load[j * ns + k], self.cone_load[j * ns + k]);
            let po = n_m * half_d + self.t_o * self.x[k];
            let pi = -n_m * half_d + self.t_i * self.x[k];
            let fo = -self.n_o * qo;
            let fi = self.n_i * qi;
            f += fo + fi;
            m += cross(&po, &fo) + cross(&pi, &fi);
        }
        for (r, rib) in self.ribs.iter().enumerate() {
            let ff = rib.n * self.rib_load[j * MAX_RIBS + r];
            f += ff;
            m += cross(&rib.s, &ff);
        }
        f += Vector2::new(self.centrifugal_n, 0.0);
        [f.x, f.y, m]
    }

    /// Evaluate roller j at ρ with the ring approaches `gi`; fills its slice and rib
    /// buffers.
    fn eval_roller(&mut self, j: usize, rho: &Vector3<f64>, gi: &RingApproach) -> RollerEval {
        let ns = self.x.len();
        let (a, b, phi) = (rho[0], rho[1], rho[2]);
        let mut e = RollerEval::default();
        let (mut h00, mut h02, mut h22) = (0.0, 0.0, 0.0);
        let (mut max_o, mut max_i) = (f64::NEG_INFINITY, f64::NEG_INFINITY);
        let base_i = gi.g0 - a * self.cg + b * self.sg;
        let c = self.c;
        for k in 0..ns {
            let xk = self.x[k];
            let xt = xk - self.arm0;
            let d_o = a - phi * xt - self.e_o[k];
            let d_i = base_i + gi.g1 * xk + phi * xt - self.e_i[k];
            max_o = max_o.max(d_o);
            max_i = max_i.max(d_i);
            self.series_approach[j * ns + k] = d_o + d_i;
            let mut qo = 0.0;
            if d_o > 0.0 {
                let r9 = d_o.powf(1.0 / 9.0);
                qo = c * d_o * r9;
                let ko = EXP * c * r9;
                e.pi += qo * d_o * (9.0 / 19.0);
                e.qo += qo;
                e.grad[2] -= qo * xt;
                h00 += ko;
                h02 -= ko * xt;
                h22 += ko * xt * xt;
            }
            self.cup_load[j * ns + k] = qo;
            let mut qi = 0.0;
            if d_i > 0.0 {
                let r9 = d_i.powf(1.0 / 9.0);
                qi = c * d_i * r9;
                let ki = EXP * c * r9;
                e.pi += qi * d_i * (9.0 / 19.0);
                e.qi0 += qi;
                e.qi1 += qi * xk;
                e.s0 += ki;
                e.s1 += ki * xk;
                e.s2 += ki * xk * xk;
            }
            self.cone_load[j * ns + k] = qi;
        }
        // cone: ∂δ_i/∂ρ = (−cos γ, sin γ, x − arm0)
        let (cg, sg, a0) = (self.cg, self.sg, self.arm0);
        let m_i = e.qi1 - a0 * e.qi0; // Σ q x̃
        e.grad[0] += e.qo - cg * e.qi0;
        e.grad[1] += sg * e.qi0;
        e.grad[2] += m_i;
        let (k0, k1) = (e.s0, e.s1 - a0 * e.s0); // Σk, Σk x̃
        let k2 = e.s2 - 2.0 * a0 * e.s1 + a0 * a0 * e.s0; // Σk x̃²
        let mut h = Matrix3::new(
            h00 + cg * cg * k0,
            -cg * sg * k0,
            h02 - cg * k1,
            -cg * sg * k0,
            sg * sg * k0,
            sg * k1,
            h02 - cg * k1,
            sg * k1,
            h22 + k2,
        );
        // ribs: Hertz, δ = g_f·u + d·ρ
        for (r, rib) in self.ribs.iter().enumerate() {
            let df = gi.gf[r] + rib.d.dot(rho) - rib.gap;
            e.df[r] = df;
            let mut qf = 0.0;
            if df > 0.0 {
                let (q, k, w) = rib.law.eval(df, self.rib_stiffness_factor);
                qf = q;
                e.qf[r] = qf;
                e.kf[r] = k;
                e.pi += w;
                e.grad += rib.d * qf;
                h += rib.d * rib.d.transpose() * e.kf[r];
            }
            self.rib_load[j * MAX_RIBS + r] = qf;
        }
        // centrifugal force along +e_r: its work F_c (a cos α − b sin α)
        let fc = self.centrifugal_n;
        if fc != 0.0 {
            e.pi -= fc * (a * self.n_o.x + b * self.t_o.x);
            e.grad[0] -= fc * self.n_o.x;
            e.grad[1] -= fc * self.t_o.x;
        }
        if self.hold_roller_tilt {
            e.grad[2] = 0.0;
            for i in 0..3 {
                h[(i, 2)] = 0.0;
                h[(2, i)] = 0.0;
            }
            h[(2, 2)] = 1.0;
        }
        e.hess = h;
        e.max_o = max_o;
        e.max_i = max_i;
        e
    }

    /// The position where a roller without contact floats: no tilt, its cup and cone gaps
    /// at the slice midpoints equal and, along the cup line, in the middle of the range
    /// where no rib's gap is smaller than those (at the one bound there is, 0 without
    /// ribs).
    fn floating(&self, gi: &RingApproach) -> Vector3<f64> {
        let mid = self.x.len() / 2;
        let (eo, ei) = (self.e_o[mid], self.e_i[mid]);
        // cup = cone: a − eo = G_i − a cγ + b sγ − ei;  rib r: a − eo = G_f + d0 a + d1 b − gap
        let (m00, m01, r0) = (
            1.0 + self.cg,
            -self.sg,
            gi.g0 + gi.g1 * self.x[mid] - ei + eo,
        );
        let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
        let (mut a_sum, mut n) = (0.0, 0.0);
        for (r, rib) in self.ribs.iter().enumerate() {
            if rib.d[1].abs() <= 1e-12 {
                continue;
            }
            let (m10, m11, r1) = (1.0 - rib.d[0], -rib.d[1], gi.gf[r] - rib.gap + eo);
            let det = m00 * m11 - m01 * m10;
            let (a, b) = ((r0 * m11 - m01 * r1) / det, (m00 * r1 - m10 * r0) / det);
            a_sum += a;
            n += 1.0;
            // the rib's approach grows with b when d1 > 0: b may not exceed this one
            if rib.d[1] > 0.0 {
                hi = hi.min(b);
            } else {
                lo = lo.max(b);
            }
        }
        let b = match (lo.is_finite(), hi.is_finite()) {
            (true, true) => 0.5 * (lo + hi),
            (true, false) => lo,
            (false, true) => hi,
            (false, false) => 0.0,
        };
        let a = if n > 0.0 && self.sg != 0.0 {
            a_sum / n
        } else {
            (r0 - m01 * b) / m00
        };
        Vector3::new(a, b, 0.0)
    }

    /// A roller's `K_ρρ` with 1e-12 of its largest contact stiffness added on the diagonal
    /// (the tilt's scaled by (L/2)²): directions without contact stiffness stay solvable
    /// and the step a descent direction. Also the reference stiffness, N/mm.
    fn regularised(&self, hess: &Matrix3<f64>) -> (Matrix3<f64>, f64) {
        let l = self.iso.bearing().effective_length_mm;
        let k_ref = hess[(0, 0)]
            .max(hess[(1, 1)])
            .max(hess[(2, 2)] * 4.0 / (l * l))
            .max(self.c * 1e-3);
        let mut h = *hess;
        h[(0, 0)] += 1e-12 * k_ref;
        h[(1, 1)] += 1e-12 * k_ref;
        h[(2, 2)] += 1e-12 * k_ref * 0.25 * l * l;
        (h, k_ref)
    }

    /// Solve roller j's balance for the ring approaches `gi`, from its stored position.
    fn solve_roller(&mut self, j: usize, gi: &RingApproach) -> (RollerEval, usize) {
        let l = self.bearing().effective_length_mm;
        let mut rho = self.rho[j];
        if self.hold_roller_tilt {
            rho[2] = 0.0;
        }
        let mut e = self.eval_roller(j, &rho, gi);
        // without the cone and the rib (and without centrifugal force) nothing can hold
        // the roller on the cup: it floats where it touches nothing, if it can
        // (nor can the ribs alone: without raceway contact their forces do not balance)
        let ribs: f64 = e.qf.iter().sum();
        let cup_only = e.qi0 == 0.0 && ribs == 0.0 && e.qo > 0.0;
        let ribs_only = e.qo + e.qi0 == 0.0 && ribs > 0.0;
        if self.centrifugal_n == 0.0 && (cup_only || ribs_only) {
            let float = self.floating(gi);
            let ef = self.eval_roller(j, &float, gi);
            if ef.total() == 0.0 {
                self.rho[j] = float;
                return (ef, 0);
            }
            e = self.eval_roller(j, &rho, gi);
        }
        if e.total() == 0.0 {
            // no contact at the stored position: start from (or stay at) the float
            let float = self.floating(gi);
            let ef = self.eval_roller(j, &float, gi);
            rho = float;
            e = ef;
            if self.centrifugal_n == 0.0 && e.total() == 0.0 {
                self.rho[j] = rho;
                return (e, 0);
            }
        }
        let scale = self.roller_scale.max(e.total() + self.centrifugal_n);
        let tol = 1e-13 * scale;
        let mut iterations = 0;
        for _ in 0..100 {
            if e.grad[0].abs() <= tol && e.grad[1].abs() <= tol && e.grad[2].abs() <= tol * l {
                break;
            }
            iterations += 1;
            // regularise directions without contact stiffness (a descent direction still)
            let (h, k_ref) = self.regularised(&e.hess);
            let step = match h.cholesky() {
                Some(ch) => -ch.solve(&e.grad),
                None => -e.grad / k_ref,
            };
            let slope = e.grad.dot(&step);
            // the gradient's size in force units (moments over L)
            let size = |g: &Vector3<f64>| g[0].abs().max(g[1].abs()).max(g[2].abs() / l);
            let g_now = size(&e.grad);
            let mut t = 1.0;
            let mut accepted = false;
            for _ in 0..60 {
                let trial = rho + step * t;
                let et = self.eval_roller(j, &trial, gi);
                // Armijo on Π, or (at Π's round-off floor) a halved gradient
                if et.pi <= e.pi + 1e-4 * t * slope + 1e-15 * e.pi.abs()
                    || size(&et.grad) < 0.5 * g_now
                {
                    rho = trial;
                    e = et;
                    accepted = true;
                    break;
                }
                t *= 0.5;
            }
            if !accepted {
                e = self.eval_roller(j, &rho, gi);
                break;
            }
        }
        self.rho[j] = rho;
        (e, iterations)
    }

    /// Evaluate every roller in its own equilibrium at the ring displacement `u`: the
    /// carried load, the condensed stiffness and the reduced potential.
    fn evaluate(&mut self, u: &Vector5<f64>) -> (Vector5<f64>, Matrix5<f64>, f64) {
        let mut f = Vector5::zeros();
        let mut k = Matrix5::zeros();
        let mut phi = 0.0;
        let (cg, sg, a0) = (self.cg, self.sg, self.arm0);
        for j in 0..self.frames.len() {
            let fr = self.frames[j];
            let mut gf = [0.0; MAX_RIBS];
            for (g, v) in gf.iter_mut().zip(&fr.gf) {
                *g = v.dot(u);
            }
            let gi = RingApproach {
                g0: fr.g0.dot(u),
                g1: fr.g1.dot(u),
                gf,
            };
            let (e, iterations) = self.solve_roller(j, &gi);
            phi += e.pi;
            f += fr.g0 * e.qi0 + fr.g1 * e.qi1;
            let g0g1 = fr.g0 * fr.g1.transpose();
            let mut kuu = fr.g0 * fr.g0.transpose() * e.s0
                + (g0g1 + g0g1.transpose()) * e.s1
                + fr.g1 * fr.g1.transpose() * e.s2;
            // K_uρ = Σ k g dᵀ, d_i = (−cos γ, sin γ, x − arm0); each rib's k_f g_f d_fᵀ
            let mut kur = Matrix5x3::zeros();
            let tilt = if self.hold_roller_tilt { 0.0 } else { 1.0 };
            let r0 = Vector3::new(-cg * e.s0, sg * e.s0, tilt * (e.s1 - a0 * e.s0));
            let r1 = Vector3::new(-cg * e.s1, sg * e.s1, tilt * (e.s2 - a0 * e.s1));
            kur += fr.g0 * r0.transpose() + fr.g1 * r1.transpose();
            let (mut inner_rib, mut outer_rib, mut p_rib) = (0.0, 0.0, 0.0_f64);
            let mut rib_approach = f64::NEG_INFINITY;
            let mut rib_stiff = 0.0;
            for (r, rib) in self.ribs.iter().enumerate() {
                let (q, k) = (e.qf[r], e.kf[r]);
                rib_approach = rib_approach.max(e.df[r]);
                if rib.inner {
                    inner_rib += q;
                    f += fr.gf[r] * q;
                } else {
                    outer_rib += q;
                }
                if q > 0.0 {
                    p_rib = p_rib.max(rib.law.pressure(q));
                }
                if k > 0.0 && rib.inner {
                    rib_stiff += k;
                    kuu += fr.gf[r] * fr.gf[r].transpose() * k;
                    let mut d = rib.d;
                    d[2] *= tilt;
                    kur += fr.gf[r] * d.transpose() * k;
                }
            }
            if e.s0 + rib_stiff > 0.0 {
                // static condensation; a roller with contacts has a positive definite K_ρρ
                // up to directions without stiffness, which the regularisation covers
                if let Some(ch) = self.regularised(&e.hess).0.cholesky() {
                    let x = ch.solve(&kur.transpose());
                    kuu -= kur * x;
                }
            }
            k += kuu;
            let rho = self.rho[j];
            self.rollers[j] = RibRollerLoad {
                azimuth_rad: fr.psi,
                outer_n: e.qo,
                inner_n: e.qi0,
                rib_n: inner_rib,
                outer_rib_n: outer_rib,
                tilt_rad: rho[2],
                translation_mm: [rho[0], rho[1]],
                rib_max_pressure_mpa: p_rib,
                skew_moment_nmm: 0.0,
                rib_approach_mm: rib_approach,
                max_approach_mm: e.max_o + e.max_i,
                iterations,
            };
        }
        // symmetrise the round-off of the condensation
        let k = (k + k.transpose()) * 0.5;
        (f, k, phi)
    }

    /// The load `(Fx, Fy, Fz, Mx, My)` (N, N·mm) the rollers carry at the inner-ring
    /// displacement `u` (mm, rad), each roller in its own equilibrium, and the condensed
    /// stiffness there.
    ///
    /// # Errors
    /// `u` must be finite (named `start.<component>`).
    pub fn load_at(&mut self, u: [f64; 5]) -> Result<([f64; 5], [[f64; 5]; 5])> {
        warm_start(&RingLoad::displacements(u), u, &[true; 5])?;
        // the rollers' tolerance: 1e-13 of the largest roller load of the last evaluation
        // (relative to a vanishing roller's own load it would never be met)
        let last = self
            .rollers
            .iter()
            .map(|r| r.outer_n.max(r.rib_n))
            .fold(0.0, f64::max);
        self.roller_scale = self.roller_scale.max(last);
        let (f, k, _) = self.evaluate(&Vector5::from(u));
        Ok((f.into(), to_rows(&k)))
    }

    /// Solve the inner ring's equilibrium under `load` from the closed-form start of the
    /// ISO model; every roller starts floating.
    ///
    /// # Errors
    /// As [`RollerBearingSolver::solve`].
    pub fn solve(&mut self, load: &RingLoad) -> Result<RollerSolution> {
        let radial = self.check_load(load)?;
        let mut start = self.iso.start(&radial);
        if let (Some(_), Dof::Force(fz)) = (self.arrangement, load.dofs[2]) {
            // a cylindrical bearing's axial load on its ribs: both ribs of a roller in series
            let z = self.bearing().rollers as f64;
            let closing = 2.0 * self.ribs[0].gap;
            start[2] =
                (2.0 * (fz.abs() / (z * self.ribs[0].k)).powf(2.0 / 3.0) + closing) * fz.signum();
        }
        for r in &mut self.rho {
            *r = Vector3::zeros();
        }
        Ok(self.iterate(load, start))
    }

    /// Solve from the ring displacement `start` (mm, rad), each roller from its last
    /// position (a warm start after a small load change).
    ///
    /// # Errors
    /// As [`RollerBearingSolver::solve_from`].
    pub fn solve_from(&mut self, load: &RingLoad, start: [f64; 5]) -> Result<RollerSolution> {
        self.check_load(load)?;
        let u = warm_start(load, start, &self.stiff)?;
        Ok(self.iterate(load, u))
    }

    /// The ISO model's checks of the load; for a cylindrical bearing its axial force is
    /// checked against the rib arrangement first and left out of the ISO check (returned
    /// load).
    fn check_load(&self, load: &RingLoad) -> Result<RingLoad> {
        // At speed the centrifugal force presses every roller onto the outer ring (and a
        // tapered one against the rib): with nothing applied the inner ring is not held
        // (no equilibrium, Newton would run to its limit).
        if self.centrifugal_n() > 0.0 && load.dofs.iter().all(|d| *d == Dof::Force(0.0)) {
            return Err(Error::invalid(
                "load.fz_n",
                0.0,
                "a load at speed: the centrifugal force presses every roller onto the outer ring, and with no force, moment or prescribed displacement the inner ring has no equilibrium",
            ));
        }
        let mut radial = *load;
        if let Some(arrangement) = self.arrangement {
            crate::equilibrium::check_finite(load)?;
            if let Dof::Force(fz) = load.dofs[2]
                && fz != 0.0
            {
                let (plus, minus) = arrangement.axial_directions();
                if !(if fz > 0.0 { plus } else { minus }) {
                    let name = arrangement.name();
                    let why = match arrangement {
                        RibArrangement::Nj => format!(
                            "a load >= 0 N: an {name} cylindrical roller bearing carries axial load in +z only (its one inner ring rib is at the −z end; NUP carries both ways)"
                        ),
                        _ => format!(
                            "0: an {name} cylindrical roller bearing carries no axial load (its ribs are on one ring only; NJ or NUP carry it)"
                        ),
                    };
                    return Err(Error::invalid("load.fz_n", fz, why));
                }
                radial.dofs[2] = Dof::Force(0.0);
            }
        }
        self.iso.check_load(&radial)?;
        Ok(radial)
    }

    fn iterate(&mut self, load: &RingLoad, u: Vector5<f64>) -> RollerSolution {
        let b = self.iso.bearing();
        let z = b.rollers as f64;
        let r = 0.5 * b.pitch_diameter_mm;
        let (free, target) = free_and_target(load, &self.stiff);
        let mut f_ref = load_scale(&target, r);
        if b.clearance_mm < 0.0 {
            f_ref = f_ref.max(z * b.roller_stiffness() * (-0.5 * b.clearance_mm).powf(EXP));
        }
        self.roller_scale = (f_ref / z).max(self.centrifugal_n);
        let (tolerance, max_iterations) = (self.tolerance, self.max_iterations);
        let Outcome {
            u,
            termination,
            iterations,
            residual,
            mut note,
            f,
            k,
            buffers_at_u,
        } = newton(self, free, target, u, f_ref, r, tolerance, max_iterations);
        if !buffers_at_u {
            self.evaluate(&u);
        }
        let q_max = self.rollers.iter().map(|r| r.outer_n).fold(0.0, f64::max);
        if termination == Termination::Converged && q_max == 0.0 {
            note = Some("every roller is lifted off: zero load");
        }
        let b = self.iso.bearing();
        RollerSolution {
            displacement: u.into(),
            load: f.into(),
            stiffness: to_rows(&k),
            status: SolveStatus::new(termination, iterations, residual),
            note,
            load_zone: load_zone(&u, b.contact_angle_rad, b.clearance_mm, false),
            max_roller_load_n: q_max,
        }
    }

    /// The largest rib load of the last solve, N.
    pub fn max_rib_load_n(&self) -> f64 {
        self.rollers.iter().map(|r| r.rib_n).fold(0.0, f64::max)
    }

    /// The largest Hertz pressure on the rib in the last solve, MPa.
    pub fn max_rib_pressure_mpa(&self) -> f64 {
        self.rollers
            .iter()
            .map(|r| r.rib_max_pressure_mpa)
            .fold(0.0, f64::max)
    }
}

/// The roller end/rib pair of `rib` on the roller of `bearing`, built by
/// `kontakt::bearing::RollerRib` with the common-apex section that has the bearing's cone
/// angle and roller half-angle: large-end radius `ρ_L = D/2 + (L/2) tan β_r` (the roller
/// `L_we` long, `D_we` its diameter at mid-length), inner raceway radius at the large end
/// `ρ_L sin α_i / tan β_r` (the true-rolling condition of `roller_rib` solved for it), bore
/// and outside diameter wide enough that their checks pass (no result depends on them).
fn rib_pair(bearing: &RollerBearing, rib: &RibContact) -> Result<RollerRib> {
    let beta_r = 0.5 * (bearing.contact_angle_rad - bearing.cone_angle_rad);
    let rho_l = 0.5 * bearing.roller_diameter_mm + 0.5 * bearing.effective_length_mm * beta_r.tan();
    let r_i = rho_l * bearing.cone_angle_rad.sin() / beta_r.tan();
    let section = TaperedRollerBearing {
        bore: r_i,
        outside_diameter: 2.0 * (r_i + 2.0 * rho_l + bearing.effective_length_mm) + 2.0,
        roller_half_angle_deg: beta_r.to_degrees(),
        roller_large_end_radius: rho_l,
        inner_raceway_radius: r_i,
    };
    let spec = RollerRibSpec {
        bearing: section,
        face: rib.face,
        rib: rib.rib,
        contact_height: rib.contact_height_mm,
    };
    RollerRib::new(spec).map_err(|e| {
        e.map_field(|f| {
            let key = match f {
                "contact_height" => "contact_height_mm",
                "face.radius" => "face.radius_mm",
                "face.eccentricity" => "face.eccentricity_mm",
                "rib.radius" => "rib.radius_mm",
                "bearing.roller_half_angle_deg" => "cup_angle_deg",
                "bearing.roller_large_end_radius" => "roller_diameter_mm",
                other => other,
            };
            format!("rib_contact.{key}")
        })
    })
}

impl ConvexRing for RibContactSolver {
    fn evaluate(&mut self, u: &Vector5<f64>) -> (Vector5<f64>, Matrix5<f64>, f64) {
        RibContactSolver::evaluate(self, u)
    }

    fn probe(&self) -> &Matrix5<f64> {
        &self.probe
    }

    fn reference(&self, f_ref: f64) -> (f64, f64) {
        let b = self.iso.bearing();
        let d = (f_ref / (b.rollers as f64 * b.roller_stiffness())).powf(0.9);
        let c_s = b.roller_stiffness() / b.slices as f64;
        (d, EXP * c_s * d.powf(1.0 / 9.0))
    }

    fn touch(&self, step: &Vector5<f64>, d_ref: f64) -> f64 {
        let frames = self.frames.iter().map(|f| (&f.g0, &f.g1));
        slice_touch(frames, &self.x, &self.series_approach, step, d_ref)
    }

    fn limit(&self) -> f64 {
        self.iso.bearing().roller_diameter_mm
    }
}

#[cfg(test)]
mod tests;
