//! Friction over a pressure field: force, moment and dissipated power of the shear
//! stresses of a [`CellLaw`] over every loaded cell.
//!
//! For cells `k` of area `ΔA` at the in-plane points `(x_k, y_k)` of the grid frame, with
//! pressure `p_k` and sliding velocity `v_k` of body 1 relative to body 2:
//!
//! ```text
//! τ_k = −k(p_k, |v_k|) v_k                       shear stress on body 1 [MPa]
//! F   = Σ τ_k ΔA                                 friction force on body 1 [N]
//! M_O = Σ (x_k τ_y,k − y_k τ_x,k) ΔA · n         moment about the grid origin [N·mm]
//! P   = −Σ τ_k · v_k ΔA = Σ k |v_k|² ΔA ≥ 0      dissipated power [N·mm/s = 1e-3 W]
//! ```
//!
//! The moment of in-plane stresses about a point of the plane is along its normal `n`.
//! The moment about any axis through a point `Q` with direction `a` is
//! `a · (M_O + (O − Q) × F)` ([`ContactFriction::moment_about`]). The power does not depend
//! on the frame: `P` is the rate of work of the friction stresses on the relative motion.
//!
//! Works on any [`NormalSolution`]: Hertz sampled on a grid, PimP or the half-space
//! solver. Cells with `p ≤ 0` carry no stress. Units: mm, N, MPa, mm/s; power in W.

use super::law::CellLaw;
use crate::error::{Error, Result};
use crate::field::NormalSolution;
use crate::geometry::{ContactFrame, ContactPair, Grid2, VelocityField};
use nalgebra::{Point3, Unit, Vector3};

/// Sums of the friction integral in the grid frame.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct GridFriction {
    /// Friction force on body 1 `[x, y]` in the grid frame \[N\].
    pub force: [f64; 2],
    /// Moment of the friction stresses on body 1 about the grid origin, component along
    /// the normal \[N·mm\].
    pub moment: f64,
    /// Dissipated power \[W\], ≥ 0.
    pub power: f64,
    /// Normal force `Σ p ΔA` \[N\].
    pub normal_force: f64,
    /// `Σ p |v| ΔA` \[W\]: the power a unit friction coefficient would dissipate (so that
    /// constant-μ Coulomb friction gives `power = μ · pressure_sliding`).
    pub pressure_sliding: f64,
    /// Loaded cells (p > 0).
    pub cells: usize,
}

impl GridFriction {
    /// Effective friction coefficient `|F| / N` (0 for an unloaded field).
    pub fn coefficient(&self) -> f64 {
        if self.normal_force > 0.0 {
            self.force[0].hypot(self.force[1]) / self.normal_force
        } else {
            0.0
        }
    }

    /// Pressure-weighted mean sliding speed `Σ p |v| ΔA / Σ p ΔA` \[mm/s\].
    pub fn mean_sliding_speed(&self) -> f64 {
        if self.normal_force > 0.0 {
            self.pressure_sliding * MW_PER_W / self.normal_force
        } else {
            0.0
        }
    }
}

/// N·mm/s per W.
const MW_PER_W: f64 = 1e3;

fn check_field(grid: &Grid2, pressure: &[f64], field: &VelocityField) -> Result<()> {
    if pressure.len() != grid.len() {
        return Err(Error::invalid(
            "pressure",
            format!("{} cells", pressure.len()),
            format!("{} cells ({} × {})", grid.len(), grid.nx(), grid.ny()),
        ));
    }
    let finite = |a: &[[f64; 2]; 3]| a.iter().flatten().all(|v| v.is_finite());
    if !finite(&field.sliding) {
        return Err(Error::invalid(
            "sliding",
            format!("{:?}", field.sliding),
            "finite velocities in mm/s",
        ));
    }
    Ok(())
}

/// The friction integral over `pressure` \[MPa\] on `grid` \[mm\] with the sliding field
/// `field` (grid frame) and the law `law`. Does not allocate.
///
/// # Errors
/// [`Error::InvalidInput`]: field `pressure` (length not the grid's, or a value not finite),
/// `sliding` (not finite), `fluid` (the Newtonian law overflowed: `exp(α p)` too large for
/// `f64`; use a bounded law).
pub fn grid_friction(
    grid: &Grid2,
    pressure: &[f64],
    field: &VelocityField,
    law: &CellLaw,
) -> Result<GridFriction> {
    check_field(grid, pressure, field)?;
    let [o, dx, dy] = field.sliding;
    let (mut fx, mut fy, mut m, mut power, mut load, mut ps) = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    let mut cells = 0;
    for j in 0..grid.ny() {
        let y = grid.y(j);
        let row = &pressure[j * grid.nx()..(j + 1) * grid.nx()];
        let (ox, oy) = (o[0] + y * dy[0], o[1] + y * dy[1]);
        for (i, &p) in row.iter().enumerate() {
            if !(p > 0.0) {
                continue;
            }
            let x = grid.x(i);
            let (vx, vy) = (ox + x * dx[0], oy + x * dx[1]);
            let speed2 = vx * vx + vy * vy;
            let speed = speed2.sqrt();
            cells += 1;
            load += p;
            ps += p * speed;
            if speed > 0.0 {
                let k = law.drag(p, speed);
                let (tx, ty) = (-k * vx, -k * vy);
                fx += tx;
                fy += ty;
                m += x * ty - y * tx;
                power += k * speed2;
            }
        }
    }
    let area = grid.cell_area();
    let sums = GridFriction {
        force: [fx * area, fy * area],
        moment: m * area,
        power: power * area / MW_PER_W,
        normal_force: load * area,
        pressure_sliding: ps * area / MW_PER_W,
        cells,
    };
    let all = [
        sums.force[0],
        sums.force[1],
        sums.moment,
        sums.power,
        sums.normal_force,
        sums.pressure_sliding,
    ];
    if all.iter().all(|v| v.is_finite()) {
        Ok(sums)
    } else if !load.is_finite() {
        Err(Error::invalid(
            "pressure",
            "a non-finite value",
            "finite pressures in MPa",
        ))
    } else {
        Err(Error::invalid(
            "fluid",
            "a shear stress that overflows (Newtonian law with exp(alpha p) beyond f64)",
            "a bounded fluid law (Eyring or limiting shear) at these pressures",
        ))
    }
}

/// The dissipated power density `τ · v` per cell \[W/mm²\] (0 where `p ≤ 0`), the layout of
/// `pressure`. Does not allocate.
///
/// # Errors
/// Those of [`grid_friction`] for the inputs; field `density` when `out` does not have the
/// grid's cell count.
pub fn power_density(
    grid: &Grid2,
    pressure: &[f64],
    field: &VelocityField,
    law: &CellLaw,
    out: &mut [f64],
) -> Result<()> {
    check_field(grid, pressure, field)?;
    if out.len() != grid.len() {
        return Err(Error::invalid(
            "density",
            format!("a buffer of {} cells", out.len()),
            format!("{} cells", grid.len()),
        ));
    }
    for j in 0..grid.ny() {
        for i in 0..grid.nx() {
            let k = j * grid.nx() + i;
            let p = pressure[k];
            out[k] = if p > 0.0 {
                let [vx, vy] = field.sliding_at(grid.x(i), grid.y(j));
                let s2 = vx * vx + vy * vy;
                let d = if s2 > 0.0 {
                    law.drag(p, s2.sqrt()) * s2
                } else {
                    0.0
                };
                d / MW_PER_W
            } else {
                0.0
            };
        }
    }
    if out.iter().all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err(Error::invalid(
            "fluid",
            "a shear stress that overflows",
            "a bounded fluid law (Eyring or limiting shear) at these pressures",
        ))
    }
}

/// Friction of a contact in the world: the grid-frame sums placed by the contact frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactFriction {
    /// The grid-frame sums.
    pub grid: GridFriction,
    /// The grid origin (the contact frame's origin) \[mm\], world frame.
    pub origin: Point3<f64>,
    /// Friction force on body 1 \[N\], world frame.
    pub force: Vector3<f64>,
    /// Moment of the friction stresses on body 1 about `origin` \[N·mm\], world frame.
    pub moment: Vector3<f64>,
    /// The asperity share φ(Λ) of the law.
    pub asperity_share: f64,
}

impl ContactFriction {
    /// Moment \[N·mm\] of the friction on body 1 about the axis through `point` \[mm\] with
    /// direction `axis` (world frame), `a · (M_O + (O − Q) × F)`. On body 2 it is the
    /// negative.
    pub fn moment_about(&self, point: &Point3<f64>, axis: &Unit<Vector3<f64>>) -> f64 {
        axis.dot(&(self.moment + (self.origin - point).cross(&self.force)))
    }
}

/// The friction of the contact `solution` between the bodies of `pair` (body 1 is the body
/// of the solution's gap source's body 1), whose gap source lies in `frame`: the sliding
/// field is evaluated on the solution's grid (turned by `solution.orientation`). Does not
/// allocate.
///
/// # Errors
/// Those of [`ContactPair::velocity_field`] and [`grid_friction`].
pub fn contact_friction<D>(
    solution: &NormalSolution<D>,
    frame: &ContactFrame,
    pair: &ContactPair,
    law: &CellLaw,
) -> Result<ContactFriction> {
    let field = pair.velocity_field(frame, solution.orientation)?;
    let sums = grid_friction(&solution.grid, &solution.pressure, &field, law)?;
    let (s, c) = solution.orientation.sin_cos();
    let (ex, ey) = (frame.ex.into_inner(), frame.ey.into_inner());
    let gx = ex * c + ey * s;
    let gy = -ex * s + ey * c;
    Ok(ContactFriction {
        grid: sums,
        origin: frame.origin,
        force: gx * sums.force[0] + gy * sums.force[1],
        moment: frame.normal.into_inner() * sums.moment,
        asperity_share: law.asperity_share(),
    })
}
