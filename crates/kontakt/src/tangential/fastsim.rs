//! Kalker's FASTSIM: the simplified theory of rolling contact on an elliptical contact,
//! solved strip by strip.
//!
//! # Model
//! The simplified theory replaces the elastic half-space by a bed of independent
//! tangential springs: the relative surface displacement is `u = L q` with one
//! flexibility per creepage, chosen so that the theory reproduces Kalker's linear theory
//! ([`super::KalkerLinear`]) at small creepage:
//!
//! $$L_1 = \frac{8a}{3C_{11}G},\qquad L_2 = \frac{8a}{3C_{22}G},\qquad
//!   L_3 = \frac{\pi a\sqrt{a/b}}{4C_{23}G}$$
//!
//! \[mm/MPa\] (`docs/tangential.md` derives them from the full-adhesion traction
//! `q = -(w/L)(a(y) - x)`). In steady rolling the slip of body 1 over body 2, divided by
//! the rolling speed, is `s = w - du/dx` with the rigid slip `w = (xi_x - phi y,
//! xi_y + phi x)` (module *Conventions* of [`super`]), and Coulomb's law bounds the
//! traction by `g = mu p`. Kalker (1982) uses the parabolic pressure
//! `p = 2P/(pi a b) (1 - x²/a² - y²/b²)`, the exact normal solution of the simplified
//! theory ([`PressureShape::Parabolic`], the default); the Hertz ellipsoid is available as
//! [`PressureShape::Elliptic`].
//!
//! # Algorithm
//! The ellipse is cut into `ny` strips of equal width `dy` along `y`; the strip at `y_j`
//! runs from the leading edge `a_j = a sqrt(1 - y_j²/b²)` to the trailing edge `-a_j` in
//! `nx` elements of length `dx_j = 2 a_j/nx`. Starting from `q = 0` at the leading edge,
//! the traction at each element centre `x_i` is
//!
//! $$q^H_i = q_{i-1} - \frac{w(\bar x)}{L}\,(x_{i-1} - x_i),\qquad
//!   q_i = \begin{cases} q^H_i & |q^H_i| \le g_i \text{ (adhesion)}\\
//!   g_i\, q^H_i/|q^H_i| & \text{else (slip)}\end{cases}$$
//!
//! with `x̄` the midpoint of the step (exact for the linear rigid slip). Forces and the
//! spin moment are midpoint sums over the elements. The cell pressures are scaled so that
//! their sum is exactly `P`, so full slip gives exactly `|F| = mu P`.
//!
//! # Accuracy and cost
//! At vanishing creepage the force is exact up to the midpoint rule in `y` (relative
//! error `+1/(2 ny²)`: 0.02 % at 50 strips). Over the whole curve the error against the
//! closed-form solution of the simplified theory ([`longitudinal_simplified_theory`])
//! is 2.5e-4 of `mu P` at 50x50 and falls at second order (1.6e-3 at 20x20, 1e-5 at
//! 200x200; `tests/tangential.rs`). One creepage point costs one pass over the
//! `nx·ny` cells and allocates nothing (about 10 µs at 50x50 on a 2-core EPYC VM;
//! `docs/tangential.md`).
//!
//! # Assumptions
//! Those of [`super::KalkerLinear`], plus the simplified theory's local
//! displacement-traction law: its largest deviations from the exact theory are in the spin
//! moment and the spin-lateral coupling (Kalker 1982); only the pure-creepage behaviour
//! and the linear limits are validated here.
//!
//! # References
//! - Kalker (1982), "A fast algorithm for the simplified theory of rolling contact",
//!   Vehicle System Dynamics 11, 1-13. doi:10.1080/00423118208968684
//! - Kalker (1973), "Simplified theory of rolling contact", Delft Progress Report 1, 1-10.
//! - Kalker, *Three-dimensional elastic bodies in rolling contact* (1990), §3.4.

use super::kalker::{CreepCoefficients, KalkerMaterial, creep_coefficients};
use super::{ContactEllipse, Creepage, TractionCurve, check_creepage, check_friction};
use crate::error::{Error, Result};
use crate::material::ElasticMaterial;
use crate::units::{Megapascal, Millimetre, Newton, NewtonMillimetre};
use std::f64::consts::PI;

/// The normal pressure FASTSIM uses for the traction bound `mu p`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum PressureShape {
    /// `p = 2P/(pi a b) (1 - x²/a² - y²/b²)`: Kalker's choice, the normal solution of the
    /// simplified theory.
    #[default]
    Parabolic,
    /// The Hertz pressure `p = 3P/(2 pi a b) sqrt(1 - x²/a² - y²/b²)`.
    Elliptic,
}

/// Options of [`Fastsim`]: the discretisation and the pressure shape.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct FastsimOptions {
    /// Elements `[nx, ny]`: `nx` per strip along the rolling direction, `ny` strips;
    /// each 1..=4096. Default `[50, 50]`.
    pub elements: [usize; 2],
    /// Pressure for the traction bound. Default [`PressureShape::Parabolic`].
    pub pressure: PressureShape,
}

impl Default for FastsimOptions {
    fn default() -> Self {
        FastsimOptions {
            elements: [50, 50],
            pressure: PressureShape::Parabolic,
        }
    }
}

impl FastsimOptions {
    /// Largest number of elements along one direction.
    pub const MAX_ELEMENTS: usize = 4096;

    /// Check the options.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `elements[0]` or `elements[1]` outside 1..=4096.
    pub fn validate(&self) -> Result<()> {
        for (k, n) in self.elements.into_iter().enumerate() {
            if !(1..=Self::MAX_ELEMENTS).contains(&n) {
                return Err(Error::invalid(
                    if k == 0 { "elements[0]" } else { "elements[1]" },
                    n,
                    "1..=4096 elements",
                ));
            }
        }
        Ok(())
    }
}

/// One strip of the FASTSIM grid.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
struct Strip {
    /// Lateral position of the strip centre \[mm\].
    y: Millimetre,
    /// Half-length `a_j` \[mm\].
    half_length: Millimetre,
    /// Element length `dx_j` \[mm\].
    dx: Millimetre,
}

/// The result of one FASTSIM creepage point.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct FastsimSolution {
    /// Forces `[Fx, Fy]` \[N\] on body 1.
    pub forces: [Newton; 2],
    /// Spin moment `Mz` about the contact centre \[N·mm\] on body 1.
    pub spin_moment: NewtonMillimetre,
    /// Area of the adhesion (stick) elements \[mm²\].
    pub adhesion_area: f64,
    /// Adhesion area over the contact area of the grid \[-\], 1 = full adhesion.
    pub adhesion_fraction: f64,
}

/// Traction field of one FASTSIM creepage point, for [`Fastsim::solve_field`]. Cells are
/// stored strip by strip (`index = j nx + i`, `i` from the leading edge); their centres
/// come from [`Fastsim::cell_centre`].
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct FastsimField {
    /// Traction `[q_x, q_y]` \[MPa\] on body 1 at each cell centre.
    pub traction: Vec<[Megapascal; 2]>,
    /// Whether each cell adheres (`true`) or slips.
    pub adhesion: Vec<bool>,
}

/// A planned FASTSIM contact: ellipse, materials, friction, flexibilities and the grid
/// with its traction bound. Plan once with [`Fastsim::new`]; every
/// [`solve`](Self::solve) then runs one allocation-free pass over the cells.
///
/// # Example
/// A circular steel contact, a = b = 0.5 mm, 1000 N, mu = 0.3. At a tiny creepage the
/// force equals Kalker's linear theory; at a large one it saturates at mu P.
/// ```
/// use kontakt::material::ElasticMaterial;
/// use kontakt::tangential::{ContactEllipse, Creepage, Fastsim, FastsimOptions, KalkerLinear};
/// let s = ElasticMaterial::STEEL;
/// let e = ContactEllipse::new(0.5, 0.5, 1000.0)?;
/// let f = Fastsim::new(e, &s, &s, 0.3, FastsimOptions::default())?;
/// let k = KalkerLinear::new(e, &s, &s, 0.3)?;
/// let xi = Creepage::longitudinal(1e-7);
/// let fx = f.solve(&xi)?.forces[0];
/// assert!((fx / k.forces(&xi)?[0] - 1.0).abs() < 1e-3);
/// let sat = f.solve(&Creepage::longitudinal(0.05))?;
/// assert!((sat.forces[0] + 300.0).abs() < 1e-9 && sat.adhesion_fraction == 0.0);
/// # Ok::<(), kontakt::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Fastsim {
    ellipse: ContactEllipse,
    friction: f64,
    material: KalkerMaterial,
    coefficients: CreepCoefficients,
    flexibility: [f64; 3],
    options: FastsimOptions,
    strips: Vec<Strip>,
    dy: Millimetre,
    /// Traction bound `mu p` at each cell centre \[MPa\].
    bound: Vec<Megapascal>,
    grid_area: f64,
}

impl Fastsim {
    /// Plan FASTSIM for an ellipse (`a` along the rolling direction), two materials, the
    /// friction coefficient `mu` \[-\] (> 0) and the options.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `friction_coefficient`, `elements[0|1]`,
    /// `materials` (two rigid bodies) or `poisson_ratio` (combined nu outside 0..=0.5).
    pub fn new(
        ellipse: ContactEllipse,
        body1: &ElasticMaterial,
        body2: &ElasticMaterial,
        mu: f64,
        options: FastsimOptions,
    ) -> Result<Self> {
        let friction = check_friction(mu)?;
        options.validate()?;
        let material = KalkerMaterial::new(body1, body2)?;
        let coefficients = creep_coefficients(ellipse.axis_ratio(), material.poisson_ratio)?;
        let (a, b) = (ellipse.a(), ellipse.b());
        let g = material.shear_modulus;
        let flexibility = [
            8.0 * a / (3.0 * coefficients.c11 * g),
            8.0 * a / (3.0 * coefficients.c22 * g),
            PI * a * (a / b).sqrt() / (4.0 * coefficients.c23 * g),
        ];
        let [nx, ny] = options.elements;
        let dy = 2.0 * b / ny as f64;
        let strips: Vec<Strip> = (0..ny)
            .map(|j| {
                let y = -b + (j as f64 + 0.5) * dy;
                let half_length = a * (1.0 - (y / b).powi(2)).sqrt();
                Strip {
                    y,
                    half_length,
                    dx: 2.0 * half_length / nx as f64,
                }
            })
            .collect();
        let mut bound = Vec::with_capacity(nx * ny);
        let mut load = 0.0;
        let mut grid_area = 0.0;
        for s in &strips {
            grid_area += 2.0 * s.half_length * dy;
            for i in 0..nx {
                let x = s.half_length - (i as f64 + 0.5) * s.dx;
                let r = (1.0 - (x / a).powi(2) - (s.y / b).powi(2)).max(0.0);
                let p = match options.pressure {
                    PressureShape::Parabolic => r,
                    PressureShape::Elliptic => r.sqrt(),
                };
                load += p * s.dx * dy;
                bound.push(p);
            }
        }
        // Scale the discrete pressure to carry exactly P, and multiply by mu.
        let scale = friction * ellipse.normal_force() / load;
        for p in &mut bound {
            *p *= scale;
        }
        Ok(Fastsim {
            ellipse,
            friction,
            material,
            coefficients,
            flexibility,
            options,
            strips,
            dy,
            bound,
            grid_area,
        })
    }

    /// The contact ellipse.
    pub fn ellipse(&self) -> &ContactEllipse {
        &self.ellipse
    }
    /// The friction coefficient `mu` \[-\].
    pub fn friction_coefficient(&self) -> f64 {
        self.friction
    }
    /// Kalker's combined material.
    pub fn material(&self) -> KalkerMaterial {
        self.material
    }
    /// The creepage coefficients behind the flexibilities.
    pub fn coefficients(&self) -> CreepCoefficients {
        self.coefficients
    }
    /// The flexibilities `[L1, L2, L3]` \[mm/MPa\].
    pub fn flexibilities(&self) -> [f64; 3] {
        self.flexibility
    }
    /// The options.
    pub fn options(&self) -> FastsimOptions {
        self.options
    }
    /// Number of cells `nx · ny`.
    pub fn cell_count(&self) -> usize {
        self.bound.len()
    }
    /// Centre `[x, y]` \[mm\] of cell `index` (`j nx + i`, see [`FastsimField`]).
    ///
    /// # Panics
    /// If `index >= cell_count()`.
    pub fn cell_centre(&self, index: usize) -> [Millimetre; 2] {
        let nx = self.options.elements[0];
        let s = &self.strips[index / nx];
        [s.half_length - ((index % nx) as f64 + 0.5) * s.dx, s.y]
    }
    /// Area of cell `index` \[mm²\].
    ///
    /// # Panics
    /// If `index >= cell_count()`.
    pub fn cell_area(&self, index: usize) -> f64 {
        self.strips[index / self.options.elements[0]].dx * self.dy
    }

    /// A traction field sized for this plan (the one allocation).
    pub fn new_field(&self) -> FastsimField {
        FastsimField {
            traction: vec![[0.0; 2]; self.cell_count()],
            adhesion: vec![false; self.cell_count()],
        }
    }

    /// Forces, spin moment and adhesion area for the creepages `creepage`. Allocates
    /// nothing.
    ///
    /// # Errors
    /// A non-finite creepage component (see [`Creepage::validate`]).
    pub fn solve(&self, creepage: &Creepage) -> Result<FastsimSolution> {
        creepage.validate()?;
        self.march_any(creepage, |_, _, _| {})
    }

    /// As [`solve`](Self::solve), also writing the traction and adhesion of every cell
    /// into `field` (from [`new_field`](Self::new_field)).
    ///
    /// # Errors
    /// A non-finite creepage component; [`Error::InvalidInput`] naming `field` if it was
    /// sized for another grid.
    pub fn solve_field(
        &self,
        creepage: &Creepage,
        field: &mut FastsimField,
    ) -> Result<FastsimSolution> {
        creepage.validate()?;
        let n = self.cell_count();
        if field.traction.len() != n || field.adhesion.len() != n {
            return Err(Error::invalid(
                "field",
                format!("{} cells", field.traction.len()),
                format!("{n} cells (use Fastsim::new_field)"),
            ));
        }
        self.march_any(creepage, |k, q, stick| {
            field.traction[k] = q;
            field.adhesion[k] = stick;
        })
    }

    /// [`march`](Self::march) for any finite creepage. Creepages above
    /// [`HUGE_CREEPAGE`] (spin: times the larger semi-axis) are scaled down together,
    /// keeping their ratios: FASTSIM's traction then slides in every cell, and a sliding
    /// cell's traction depends only on the direction of its slip, so the result is the
    /// same, without the overflow (`inf · 0 = NaN`) that the unscaled slip would cause.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `creepage` when a scaled creepage still adheres
    /// somewhere (a friction coefficient of 1e90 or so) or the result is not finite.
    fn march_any(
        &self,
        creepage: &Creepage,
        visit: impl FnMut(usize, [f64; 2], bool),
    ) -> Result<FastsimSolution> {
        let reach = self.ellipse.a().max(self.ellipse.b());
        let largest = creepage
            .longitudinal
            .abs()
            .max(creepage.lateral.abs())
            .max(creepage.spin.abs() * reach);
        let scale = if largest > HUGE_CREEPAGE {
            HUGE_CREEPAGE / largest
        } else {
            1.0
        };
        let scaled = Creepage {
            longitudinal: creepage.longitudinal * scale,
            lateral: creepage.lateral * scale,
            spin: creepage.spin * scale,
        };
        let s = self.march(&scaled, visit);
        let finite = s.forces.iter().all(|f| f.is_finite()) && s.spin_moment.is_finite();
        if finite && (scale == 1.0 || s.adhesion_area == 0.0) {
            Ok(s)
        } else {
            Err(Error::invalid(
                "creepage",
                largest,
                format!(
                    "a creepage up to {HUGE_CREEPAGE:e} or one at which FASTSIM slides \
                     everywhere (the traction is then saturated)"
                ),
            ))
        }
    }

    /// The strip-by-strip marching; `visit(cell, traction, adheres)` sees every cell.
    ///
    /// Strips are independent and all have `nx` cells, so [`LANES`] strips march in
    /// lockstep: the per-cell recurrence is a serial chain (a square root and a division
    /// in slip), and interleaving strips hides its latency and lets the compiler use SIMD.
    /// The slip projection is branch-free: `f = min(1, g/|q|)`.
    #[inline]
    fn march(
        &self,
        creepage: &Creepage,
        mut visit: impl FnMut(usize, [f64; 2], bool),
    ) -> FastsimSolution {
        let [l1, l2, l3] = self.flexibility;
        let (wx0, wy0, spin) = (
            creepage.longitudinal / l1,
            creepage.lateral / l2,
            creepage.spin / l3,
        );
        let nx = self.options.elements[0];
        let (mut fx, mut fy, mut mz, mut stick_area) = (0.0, 0.0, 0.0, 0.0);
        for (chunk_index, chunk) in self.strips.chunks(LANES).enumerate() {
            let j0 = chunk_index * LANES;
            let live = chunk.len();
            // Lane data; missing lanes repeat the last strip with zero weight.
            let lane = |l: usize| &chunk[l.min(live - 1)];
            let hl: [f64; LANES] = std::array::from_fn(|l| lane(l).half_length);
            let dx: [f64; LANES] = std::array::from_fn(|l| lane(l).dx);
            let y: [f64; LANES] = std::array::from_fn(|l| lane(l).y);
            let weight: [f64; LANES] =
                std::array::from_fn(|l| if l < live { lane(l).dx * self.dy } else { 0.0 });
            let wx: [f64; LANES] = std::array::from_fn(|l| wx0 - spin * y[l]);
            let base: [usize; LANES] = std::array::from_fn(|l| (j0 + l.min(live - 1)) * nx);
            let mut qx = [0.0; LANES];
            let mut qy = [0.0; LANES];
            let (mut sx, mut sy, mut sm) = ([0.0; LANES], [0.0; LANES], [0.0; LANES]);
            let mut stick_cells = [0.0; LANES];
            for i in 0..nx {
                // First step: leading edge to the first centre (dx/2); then dx.
                let step = if i == 0 { 0.5 } else { 1.0 };
                let centre = i as f64 + 0.5;
                let mut stick = [false; LANES];
                for l in 0..LANES {
                    let x = hl[l] - centre * dx[l];
                    let h = step * dx[l];
                    let xm = x + 0.5 * h;
                    let g = self.bound[base[l] + i];
                    let tx = qx[l] - h * wx[l];
                    let ty = qy[l] - h * (wy0 + spin * xm);
                    let n2 = tx * tx + ty * ty;
                    stick[l] = n2 <= g * g;
                    let f = (g / n2.sqrt()).min(1.0);
                    qx[l] = tx * f;
                    qy[l] = ty * f;
                    sx[l] += qx[l];
                    sy[l] += qy[l];
                    sm[l] += x * qy[l];
                    stick_cells[l] += f64::from(u8::from(stick[l]));
                }
                for l in 0..live {
                    visit(base[l] + i, [qx[l], qy[l]], stick[l]);
                }
            }
            for l in 0..LANES {
                fx += sx[l] * weight[l];
                fy += sy[l] * weight[l];
                mz += (sm[l] - y[l] * sx[l]) * weight[l];
                stick_area += stick_cells[l] * weight[l];
            }
        }
        FastsimSolution {
            forces: [fx, fy],
            spin_moment: mz,
            adhesion_area: stick_area,
            adhesion_fraction: stick_area / self.grid_area,
        }
    }
}

/// Strips marched in lockstep by [`Fastsim::solve`].
const LANES: usize = 4;

/// Creepage \[-\] above which [`Fastsim`] scales the creepages down to it (see
/// `Fastsim::march_any`): far beyond saturation for any physical friction coefficient
/// (saturation is at about 3.4 mu P / (G c² C11), 1e-3 for steel), far below an overflow of
/// the slip `creepage · dx / L`.
pub const HUGE_CREEPAGE: f64 = 1e50;

impl TractionCurve for Fastsim {
    fn name(&self) -> &'static str {
        "fastsim"
    }

    /// `-Fx/(mu P)` under pure longitudinal creepage.
    fn normalized_force(&self, creepage: f64) -> Result<f64> {
        check_creepage(creepage)?;
        let s = self.march_any(&Creepage::longitudinal(creepage), |_, _, _| {})?;
        // The bound sums to mu P up to rounding (1e-15): a sliding contact saturates at
        // exactly 1, never above.
        let f = (-s.forces[0] / (self.friction * self.ellipse.normal_force())).clamp(-1.0, 1.0);
        // No negative zero at zero creepage.
        Ok(if f == 0.0 { 0.0 } else { f })
    }
}

/// The exact solution of Kalker's simplified theory (the model FASTSIM discretises) for
/// pure longitudinal creepage with the parabolic traction bound, in closed form:
///
/// $$\frac{F_T}{\mu P} = \frac{8}{3\pi}\Big[\frac{3\pi}{8} + \kappa s\Big(\frac{13}{4} +
///   \frac{\kappa^2}{2}\Big) - \Big(3\kappa^2 + \frac34\Big)\arccos\kappa\Big],\qquad
///   \kappa = \frac{3\pi}{32}u,\quad s = \sqrt{1-\kappa^2},$$
///
/// for the normalized creepage `u = G c² C11 |xi|/(mu P)` \[-\] up to `u = 32/(3 pi)`
/// (`kappa = 1`), and 1 beyond. It does not depend on the axis ratio. Each strip `y`
/// adheres at the leading edge and slides behind, with the strip force
/// `(4/3) mu p_c(y) a(y) [1 - (1 - k)³]`, `k = kappa/sqrt(1 - y²/b²)`; the outer strips
/// saturate first. Derivation in `docs/tangential.md`. Slope 1 at `u = 0` (Kalker's
/// linear theory), saturation at `u = 3.395`, later than the Vermeulen-Johnson cubic
/// (`u = 3`).
///
/// Returns `F_T/(mu P)` \[-\], signed like `normalized_creepage`.
///
/// # Errors
/// [`Error::InvalidInput`] naming `creepage` for a non-finite value.
///
/// # Example
/// ```
/// use kontakt::tangential::fastsim::longitudinal_simplified_theory;
/// assert!((longitudinal_simplified_theory(1e-6)? - 1e-6).abs() < 1e-12);
/// assert_eq!(longitudinal_simplified_theory(3.5)?, 1.0);
/// # Ok::<(), kontakt::Error>(())
/// ```
pub fn longitudinal_simplified_theory(normalized_creepage: f64) -> Result<f64> {
    check_creepage(normalized_creepage)?;
    let kappa = 3.0 * PI / 32.0 * normalized_creepage.abs();
    if kappa >= 1.0 {
        return Ok(normalized_creepage.signum());
    }
    let s = ((1.0 - kappa) * (1.0 + kappa)).sqrt();
    let bracket = 0.375 * PI + kappa * s * (3.25 + 0.5 * kappa * kappa)
        - (3.0 * kappa * kappa + 0.75) * kappa.acos();
    Ok(normalized_creepage.signum() * 8.0 / (3.0 * PI) * bracket)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The closed form against a direct quadrature of the strip forces.
    #[test]
    fn closed_form_matches_strip_quadrature() {
        for u in [0.05, 0.5, 1.0, 2.0, 3.0, 3.3] {
            let kappa = 3.0 * PI / 32.0 * u;
            let n = 200_000;
            let mut sum = 0.0;
            for k in 0..n {
                let eta = -1.0 + (k as f64 + 0.5) * 2.0 / n as f64;
                let w = (1.0 - eta * eta).powf(1.5);
                let kk = (kappa / (1.0 - eta * eta).sqrt()).min(1.0);
                sum += w * (1.0 - (1.0 - kk).powi(3)) * 2.0 / n as f64;
            }
            let quad = 8.0 / (3.0 * PI) * sum;
            let closed = longitudinal_simplified_theory(u).unwrap();
            assert!((quad - closed).abs() < 1e-7, "u={u}: {quad} vs {closed}");
        }
    }

    #[test]
    fn options_validation() {
        let o = FastsimOptions {
            elements: [0, 10],
            ..FastsimOptions::default()
        };
        assert_eq!(o.validate().unwrap_err().field(), Some("elements[0]"));
    }
}
