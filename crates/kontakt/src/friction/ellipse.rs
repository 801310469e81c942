//! The friction integral over a Hertz ellipse without a sampled pressure field.
//!
//! Over the ellipse of semi-axes `a`, `b` turned by `θ₀` in the grid frame, with the
//! semi-ellipsoidal pressure `p = p₀ √(1 − ρ²)`, the polar map `x' = a ρ cos θ`,
//! `y' = b ρ sin θ` gives `dA = a b ρ dρ dθ`, and `ρ = sin φ` removes the square root at the
//! rim:
//!
//! ```text
//! ∫ p g dA = p₀ a b ∫₀^{2π} ∫₀^{π/2} g sin φ cos² φ dφ dθ
//! ```
//!
//! The integrand is smooth in `φ` (Gauss-Legendre, [`EllipseRule`]'s radial nodes) and
//! periodic in `θ` (the trapezoid rule, spectrally accurate for smooth periodic functions).
//! The weights are scaled to sum to `2π/3`, so the normal force `2π p₀ a b / 3` and the
//! Coulomb force of a uniform sliding come out to round-off.
//! A sliding pole (`v = 0`) inside the ellipse makes the Coulomb direction non-smooth there;
//! the rule's accuracy is then algebraic, not spectral (docs/VALIDATION.md gives both).
//!
//! Units: mm, N, MPa, mm/s; power in W.

use super::integral::GridFriction;
use super::law::CellLaw;
use crate::error::{Error, Result};
use crate::geometry::VelocityField;
use wide::f64x4;

/// N·mm/s per W.
const MW_PER_W: f64 = 1e3;

/// A product rule on the unit disc for integrals weighted by the Hertz pressure
/// `√(1 − ρ²)`: `radial` Gauss-Legendre nodes in `φ` (`ρ = sin φ`) times `angular`
/// trapezoid nodes in `θ`.
#[derive(Debug, Clone, PartialEq)]
pub struct EllipseRule {
    /// Unit-disc abscissae `ρ cos θ`.
    ux: Vec<f64>,
    /// Unit-disc ordinates `ρ sin θ`.
    uy: Vec<f64>,
    /// Pressure over the central pressure, `√(1 − ρ²) = cos φ`.
    share: Vec<f64>,
    /// Weights `w_φ sin φ cos² φ · 2π / angular` (sum `2π/3`).
    weight: Vec<f64>,
}

impl EllipseRule {
    /// A rule of `radial` × `angular` nodes.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] (field `nodes`) for fewer than 1 radial or 3 angular nodes.
    pub fn new(radial: usize, angular: usize) -> Result<Self> {
        if radial < 1 || angular < 3 {
            return Err(Error::invalid(
                "nodes",
                format!("{radial} × {angular}"),
                "at least 1 radial and 3 angular nodes",
            ));
        }
        let half = std::f64::consts::FRAC_PI_4;
        let dtheta = std::f64::consts::TAU / angular as f64;
        let rings = crate::quadrature::gauss_legendre(radial)
            .into_iter()
            .map(|(t, w)| {
                // φ = π/4 (t + 1) on [0, π/2].
                let (sp, cp) = (half * (t + 1.0)).sin_cos();
                (sp, cp, w * half * sp * cp * cp * dtheta)
            });
        // The radial rule integrates sin φ cos² φ to 1e-8 (6 nodes) or better; the weights
        // are scaled to sum to 2π/3 exactly, so that a uniform Coulomb stress (any sliding
        // without spin) gives μ F to round-off.
        Ok(Self::of_rings(rings, radial, angular))
    }

    /// The product rule of `rings` (radius ρ, pressure share √(1 − ρ²), ring weight) with
    /// `angular` trapezoid nodes each, half a step off the axes (no node on a symmetry line
    /// of the ellipse), the weights scaled to sum to 2π/3 (exact for constants).
    fn of_rings(
        rings: impl Iterator<Item = (f64, f64, f64)>,
        radial: usize,
        angular: usize,
    ) -> Self {
        let dtheta = std::f64::consts::TAU / angular as f64;
        let n = radial * angular;
        let mut rule = EllipseRule {
            ux: Vec::with_capacity(n),
            uy: Vec::with_capacity(n),
            share: Vec::with_capacity(n),
            weight: Vec::with_capacity(n),
        };
        for (rho, share, weight) in rings {
            for m in 0..angular {
                let (st, ct) = ((m as f64 + 0.5) * dtheta).sin_cos();
                rule.ux.push(rho * ct);
                rule.uy.push(rho * st);
                rule.share.push(share);
                rule.weight.push(weight);
            }
        }
        let k = std::f64::consts::TAU / 3.0 / rule.weight.iter().sum::<f64>();
        rule.weight.iter_mut().for_each(|w| *w *= k);
        rule
    }

    /// A rule of `radial` × `angular` nodes with the pressure in the radial weight:
    /// Gauss–Jacobi in `t = ρ²` for the weight `√(1 − t)` (`∫ p g dA = ½ p₀ a b ∫₀^{2π}
    /// ∫₀¹ g √(1 − t) dt dθ`), exact for integrands polynomial of degree `2 radial − 1` in
    /// `t`. An even number of angular nodes pairs each node with its opposite, so the
    /// angular sums are even in `ρ`, i.e. functions of `t`: for a sliding field whose pole
    /// is far from the ellipse the error falls like `ρ_p^(−4 radial)` (`ρ_p` the pole's
    /// radius in the unit disc), against `ρ_p^(−1)` times the Legendre rule's error for
    /// the weight `sin φ cos² φ` of [`EllipseRule::new`]. Nodes by the Golub–Welsch
    /// eigenvalue method (Golub & Welsch 1969) on the Jacobi recurrence with α = ½, β = 0.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] (field `nodes`) for fewer than 1 radial or 2 angular nodes,
    /// or an odd number of angular nodes.
    pub fn pressure_weighted(radial: usize, angular: usize) -> Result<Self> {
        if radial < 1 || angular < 2 || !angular.is_multiple_of(2) {
            return Err(Error::invalid(
                "nodes",
                format!("{radial} × {angular}"),
                "at least 1 radial and an even number >= 2 of angular nodes",
            ));
        }
        // Monic Jacobi recurrence on x ∈ [−1, 1], weight (1 − x)^α (1 + x)^β.
        let (al, be) = (0.5_f64, 0.0_f64);
        let mut jac = nalgebra::DMatrix::<f64>::zeros(radial, radial);
        for k in 0..radial {
            let kf = k as f64;
            let s = 2.0 * kf + al + be;
            jac[(k, k)] = if k == 0 {
                (be - al) / (al + be + 2.0)
            } else {
                (be * be - al * al) / (s * (s + 2.0))
            };
            if k + 1 < radial {
                let m = kf + 1.0;
                let s1 = 2.0 * m + al + be;
                let b2 = 4.0 * m * (m + al) * (m + be) * (m + al + be)
                    / (s1 * s1 * (s1 + 1.0) * (s1 - 1.0));
                jac[(k, k + 1)] = b2.sqrt();
                jac[(k + 1, k)] = b2.sqrt();
            }
        }
        let eig = nalgebra::SymmetricEigen::new(jac);
        let rings = (0..radial).map(|i| {
            // t = (1 + x)/2; the weight is the first eigenvector component squared (the
            // total is scaled to 2π/3).
            let t = 0.5 * (1.0 + eig.eigenvalues[i]);
            let v0 = eig.eigenvectors[(0, i)];
            (t.sqrt(), (1.0 - t).sqrt(), v0 * v0)
        });
        Ok(Self::of_rings(rings, radial, angular))
    }

    /// Nodes of the rule.
    pub fn len(&self) -> usize {
        self.weight.len()
    }

    /// Whether the rule has no nodes (never for a rule built by [`EllipseRule::new`]).
    pub fn is_empty(&self) -> bool {
        self.weight.is_empty()
    }
}

/// The friction integral of `law` over the Hertz ellipse of semi-axes `semi_axes = [a, b]`
/// \[mm\], its `a` axis at `orientation` \[rad\] from the grid frame's x axis, centred at
/// the grid origin, central pressure `max_pressure` \[MPa\], with the sliding field `field`
/// (grid frame), by the rule `rule`. The same sums as [`super::grid_friction`] of the
/// sampled field (`normal_force` is `2π p₀ a b / 3` to round-off). Does not allocate.
///
/// # Errors
/// [`Error::InvalidInput`]: field `semi_axes` / `max_pressure` (not finite or negative),
/// `sliding` (not finite), `fluid` (the Newtonian law overflowed).
pub fn ellipse_friction(
    semi_axes: [f64; 2],
    orientation: f64,
    max_pressure: f64,
    field: &VelocityField,
    law: &CellLaw,
    rule: &EllipseRule,
) -> Result<GridFriction> {
    match checked(semi_axes, orientation, max_pressure, field)? {
        Some(map) => mapped_friction(&map, semi_axes, max_pressure, law, rule),
        None => Ok(GridFriction::default()),
    }
}

/// [`ellipse_friction`] for a sliding field that also varies with the square of the
/// grid-frame y: `v(x, y) = field.sliding_at(x, y) + curvature · y²`, `curvature` \[1/(mm·s)\]
/// (the differential slip across a curved contact, Heathcote 1921: a ball in its groove).
/// The sums run through the general loop of the same rule; `curvature = [0, 0]` is
/// [`ellipse_friction`] itself. Does not allocate.
///
/// # Errors
/// Those of [`ellipse_friction`], and field `curvature` (not finite).
pub fn ellipse_friction_curved(
    semi_axes: [f64; 2],
    orientation: f64,
    max_pressure: f64,
    field: &VelocityField,
    curvature: [f64; 2],
    law: &CellLaw,
    rule: &EllipseRule,
) -> Result<GridFriction> {
    if !curvature.iter().all(|c| c.is_finite()) {
        return Err(Error::invalid(
            "curvature",
            format!("{curvature:?}"),
            "finite coefficients in 1/(mm·s)",
        ));
    }
    match checked(semi_axes, orientation, max_pressure, field)? {
        Some(mut map) => {
            map.q = curvature;
            mapped_friction(&map, semi_axes, max_pressure, law, rule)
        }
        None => Ok(GridFriction::default()),
    }
}

/// The inputs of [`ellipse_friction`] checked, and the map of the unit disc onto the
/// ellipse with the sliding field on it; `None` where the friction is zero (no pressure,
/// a degenerate ellipse).
fn checked(
    semi_axes: [f64; 2],
    orientation: f64,
    max_pressure: f64,
    field: &VelocityField,
) -> Result<Option<DiscMap>> {
    let [a, b] = semi_axes;
    if !(a.is_finite() && b.is_finite() && a >= 0.0 && b >= 0.0 && orientation.is_finite()) {
        return Err(Error::invalid(
            "semi_axes",
            format!("{semi_axes:?} at {orientation} rad"),
            "finite semi-axes >= 0 mm and a finite angle",
        ));
    }
    if !(max_pressure.is_finite() && max_pressure >= 0.0) {
        return Err(Error::invalid(
            "max_pressure",
            max_pressure,
            "a finite pressure >= 0 MPa",
        ));
    }
    if !field.sliding.iter().flatten().all(|v| v.is_finite()) {
        return Err(Error::invalid(
            "sliding",
            format!("{:?}", field.sliding),
            "finite velocities in mm/s",
        ));
    }
    if max_pressure == 0.0 || a == 0.0 || b == 0.0 {
        return Ok(None);
    }
    Ok(Some(DiscMap::new(semi_axes, orientation, field)))
}

/// The unit disc mapped onto the ellipse (turned by `orientation` in the grid frame) and
/// the sliding field as an affine function on it.
#[derive(Debug, Clone, Copy)]
struct DiscMap {
    /// Grid-frame point of the unit-disc node (u, w): x = xu u + xw w, y = yu u + yw w
    /// \[mm\]: `[xu, xw, yu, yw]`.
    x: [f64; 4],
    /// Sliding velocity at the centre \[mm/s\].
    o: [f64; 2],
    /// Its change per unit of u and w: `[∂v_x/∂u, ∂v_x/∂w, ∂v_y/∂u, ∂v_y/∂w]` \[mm/s\].
    m: [f64; 4],
    /// The sliding's part in the square of the grid-frame y, `v += q y²` \[1/(mm·s)\]
    /// (zero but for [`ellipse_friction_curved`]).
    q: [f64; 2],
}

impl DiscMap {
    fn new([a, b]: [f64; 2], orientation: f64, field: &VelocityField) -> Self {
        let (s, c) = orientation.sin_cos();
        // x = c a u − s b w, y = s a u + c b w.
        let (xu, xw, yu, yw) = (c * a, -s * b, s * a, c * b);
        let [o, dx, dy] = field.sliding;
        DiscMap {
            x: [xu, xw, yu, yw],
            o,
            m: [
                xu * dx[0] + yu * dy[0],
                xw * dx[0] + yw * dy[0],
                xu * dx[1] + yu * dy[1],
                xw * dx[1] + yw * dy[1],
            ],
            q: [0.0; 2],
        }
    }

    /// [`sliding_pole_radius`].
    fn pole_radius(&self) -> f64 {
        let ([vxu, vxw, vyu, vyw], o) = (self.m, self.o);
        // M (u, w) = −o: (u, w) = −adj(M) o / det M.
        let det = vxu * vyw - vxw * vyu;
        let (nu, nw) = (vyw * o[0] - vxw * o[1], -vyu * o[0] + vxu * o[1]);
        let r = nu.hypot(nw) / det.abs();
        if r.is_nan() { f64::INFINITY } else { r }
    }

    /// [`sliding_smoothness`].
    fn smoothness(&self) -> f64 {
        let (o2, norm2) = self.smoothness_squared();
        let r = (o2 / norm2).sqrt();
        if r.is_nan() { f64::INFINITY } else { r }
    }

    /// `(|v(0)|², ‖M‖₂²)` of [`sliding_smoothness`] \[mm²/s²\].
    fn smoothness_squared(&self) -> (f64, f64) {
        let (m, o) = (self.m, self.o);
        // ‖M‖₂² = (|M|_F² + √(|M|_F⁴ − 4 det²)) / 2.
        let fro2 = m.iter().map(|v| v * v).sum::<f64>();
        let det = m[0] * m[3] - m[1] * m[2];
        let norm2 = 0.5 * (fro2 + (fro2 * fro2 - 4.0 * det * det).max(0.0).sqrt());
        (o[0] * o[0] + o[1] * o[1], norm2)
    }
}

/// The friction sums over the ellipse of `map` by `rule` (inputs checked).
fn mapped_friction(
    map: &DiscMap,
    [a, b]: [f64; 2],
    max_pressure: f64,
    law: &CellLaw,
    rule: &EllipseRule,
) -> Result<GridFriction> {
    let [xu, xw, yu, yw] = map.x;
    let o = map.o;
    let [vxu, vxw, vyu, vyw] = map.m;
    let (mb, eps2) = (law.boundary_coefficient(), law.regularisation_squared());
    let fluid = law.has_fluid();
    let q = map.q;
    // Sums over the nodes of w·k̂·(v_x, v_y, u v_y − … , |v|²) with k = p₀ k̂ for the boundary
    // part; the moment x τ_y − y τ_x is summed in the unit-disc coordinates u, w.
    if !fluid && q == [0.0; 2] {
        let [fx, fy, m, pw] = boundary_sums(
            rule,
            [o[0], vxu, vxw],
            [o[1], vyu, vyw],
            [xu, xw, yu, yw],
            mb,
            eps2,
        );
        let scale = max_pressure * a * b;
        return finish(GridFriction {
            force: [fx * scale, fy * scale],
            moment: m * scale,
            power: pw * scale / MW_PER_W,
            normal_force: std::f64::consts::TAU / 3.0 * scale,
        });
    }
    let (mut fx, mut fy, mut mu_, mut mw, mut pw) = (0.0, 0.0, 0.0, 0.0, 0.0);
    let n = rule.len();
    let (ux, uy, share, weight) = (
        &rule.ux[..n],
        &rule.uy[..n],
        &rule.share[..n],
        &rule.weight[..n],
    );
    for k in 0..n {
        let (u, w) = (ux[k], uy[k]);
        let y = yu * u + yw * w;
        let vx = o[0] + u * vxu + w * vxw + q[0] * y * y;
        let vy = o[1] + u * vyu + w * vyw + q[1] * y * y;
        let s2 = vx * vx + vy * vy;
        let d = (s2 + eps2).sqrt();
        // The weight carries the pressure's share: the boundary part is linear in p.
        let mut kk = if d > 0.0 { mb * weight[k] / d } else { 0.0 };
        if fluid && s2 > 0.0 {
            // The fluid part is not: the area weight alone (w / cos φ), the law at p.
            let p = max_pressure * share[k];
            kk += weight[k] / share[k] * law.fluid_part(p, s2.sqrt()) / max_pressure;
        }
        let (tx, ty) = (kk * vx, kk * vy);
        fx -= tx;
        fy -= ty;
        // x τ_y − y τ_x with x = xu u + xw w, y = yu u + yw w: collect the u and w parts.
        mu_ -= u * (xu * ty - yu * tx);
        mw -= w * (xw * ty - yw * tx);
        pw += kk * s2;
    }
    let scale = max_pressure * a * b;
    let sums = GridFriction {
        force: [fx * scale, fy * scale],
        moment: (mu_ + mw) * scale,
        power: pw * scale / MW_PER_W,
        normal_force: std::f64::consts::TAU / 3.0 * scale,
    };
    finish(sums)
}

/// The sums of [`ellipse_friction`] if finite, else the overflow error.
fn finish(sums: GridFriction) -> Result<GridFriction> {
    let all = [sums.force[0], sums.force[1], sums.moment, sums.power];
    if all.iter().all(|v| v.is_finite()) {
        Ok(sums)
    } else {
        Err(Error::invalid(
            "fluid",
            "a shear stress that overflows (Newtonian law with exp(alpha p) beyond f64)",
            "a bounded fluid law (Eyring or limiting shear) at these pressures",
        ))
    }
}

/// Independent accumulators of [`boundary_sums`] (no loop-carried sum: vector code).
const LANES: usize = 4;

/// The boundary (Coulomb) part alone over the rule's nodes, `[Σ τ_x, Σ τ_y, Σ (x τ_y − y τ_x),
/// Σ k |v|²]` in units of `p₀ a b` (the same sums as the general loop of
/// [`ellipse_friction`] without its fluid branch, so that the loop vectorises): `vx = [o_x,
/// ∂v_x/∂u, ∂v_x/∂w]`, `vy` likewise, `xy = [xu, xw, yu, yw]` the map of the unit disc,
/// `mb` the boundary coefficient, `eps2` the regularisation v_ε².
fn boundary_sums(
    rule: &EllipseRule,
    vx: [f64; 3],
    vy: [f64; 3],
    [xu, xw, yu, yw]: [f64; 4],
    mb: f64,
    eps2: f64,
) -> [f64; 4] {
    let n = rule.len();
    let (ux, uy, weight) = (&rule.ux[..n], &rule.uy[..n], &rule.weight[..n]);
    // LANES nodes at a time in packed lanes (`wide`: SSE2 on baseline x86-64, where LLVM
    // would keep the square roots and divisions scalar); every lane does the scalar
    // operations in the scalar order, so the sums are those of a scalar loop with LANES
    // accumulators. The tail is padded with nodes of weight 0, which add exact zeros.
    let splat = f64x4::splat;
    let (vx0, vx1, vx2) = (splat(vx[0]), splat(vx[1]), splat(vx[2]));
    let (vy0, vy1, vy2) = (splat(vy[0]), splat(vy[1]), splat(vy[2]));
    let (xu, xw, yu, yw) = (splat(xu), splat(xw), splat(yu), splat(yw));
    let (mb, eps2, floor) = (splat(mb), splat(eps2), splat(1e-300));
    let zero = f64x4::ZERO;
    let mut acc = [zero; 4];
    let mut chunk = |u: f64x4, w: f64x4, wt: f64x4| {
        let sx = vx0 + u * vx1 + w * vx2;
        let sy = vy0 + u * vy1 + w * vy2;
        let s2 = sx * sx + sy * sy;
        // k = μ w / √(s² + v_ε²). Without a branch: the root is 0 only where s_x = s_y = 0
        // (no regularisation), and there the floor keeps k finite (μ w ≤ 1e8) so that the
        // node adds exact zeros; every root > 0 is above the floor (≥ √(5e-324)).
        let kk = mb * wt / (s2 + eps2).sqrt().fast_max(floor);
        let (tx, ty) = (kk * sx, kk * sy);
        acc[0] -= tx;
        acc[1] -= ty;
        // x τ_y − y τ_x with x = xu u + xw w, y = yu u + yw w.
        acc[2] -= (xu * u + xw * w) * ty - (yu * u + yw * w) * tx;
        acc[3] += kk * s2;
    };
    let lanes = |x: &[f64]| f64x4::from(std::array::from_fn::<f64, LANES, _>(|l| x[l]));
    let chunks = ux
        .chunks_exact(LANES)
        .zip(uy.chunks_exact(LANES))
        .zip(weight.chunks_exact(LANES));
    for ((u, w), wt) in chunks {
        chunk(lanes(u), lanes(w), lanes(wt));
    }
    let full = n - n % LANES;
    if full < n {
        let pad = |x: &[f64]| {
            f64x4::from(std::array::from_fn::<f64, LANES, _>(|l| {
                x.get(full + l).copied().unwrap_or(0.0)
            }))
        };
        chunk(pad(ux), pad(uy), pad(weight));
    }
    let acc = acc.map(|a| a.to_array());
    acc.map(|a| (a[0] + a[1]) + (a[2] + a[3]))
}

/// Where the sliding velocity vanishes (the spin pole), as the radius `ρ_p` of the unit
/// disc that maps onto the ellipse (`ρ_p < 1`: inside the ellipse; infinity for a field
/// without spin). Same arguments as [`ellipse_friction`].
pub fn sliding_pole_radius(semi_axes: [f64; 2], orientation: f64, field: &VelocityField) -> f64 {
    DiscMap::new(semi_axes, orientation, field).pole_radius()
}

/// How smooth the sliding field is over the ellipse: `ρ_s = |v(0)| / ‖M‖₂`, the sliding
/// speed at the centre over the largest change of the sliding velocity per unit radius of
/// the unit disc (`M` the sliding gradient mapped onto the unit disc, `‖M‖₂` its spectral
/// norm). The Coulomb direction `v/|v|` is analytic in the disc stretched by about `ρ_s`
/// (the complex zeros of `|v|²` lie there), so the quadrature error falls geometrically
/// in `ρ_s`. `ρ_s ≤ ρ_p` ([`sliding_pole_radius`]); unlike `ρ_p` it also sees a thin
/// ellipse whose pole is far along the long axis's scale but near across it. Infinity
/// for a uniform sliding (no gradient), 0 where the centre does not slide. Same arguments
/// as [`ellipse_friction`].
pub fn sliding_smoothness(semi_axes: [f64; 2], orientation: f64, field: &VelocityField) -> f64 {
    DiscMap::new(semi_axes, orientation, field).smoothness()
}

/// The contact element's rules and the choice between them (accuracy in
/// docs/VALIDATION.md, "Friction over a Hertz ellipse"), by the smoothness `ρ_s` of
/// [`sliding_smoothness`]:
///
/// - boundary (Coulomb) law: the pressure-weighted rules of
///   [`EllipseRule::pressure_weighted`], 2 × 8 nodes for `ρ_s ≥ 8`, 2 × 12 for
///   `4 ≤ ρ_s < 8`, 3 × 16 for `2 ≤ ρ_s < 4` (the angular count sets the error, about
///   `ρ_s^(−angular)`; measured below 1e-8 of `∫|τ| dA` in every tier over random
///   ellipses, axis ratios down to 0.03, and poles);
/// - a fluid part, `ρ_s ≥ 2`: 16 × 16 (the fluid law's knee near the rim converges
///   algebraically: below 1.5e-3);
/// - a rougher field (the pole near or inside the ellipse, where the sliding direction
///   turns round the pole): 16 × 32 (below 2e-3 outside, 5e-3 inside).
#[derive(Debug, Clone, PartialEq)]
pub struct HertzFrictionRules {
    far: EllipseRule,
    mid: EllipseRule,
    near: EllipseRule,
    fluid: EllipseRule,
    careful: EllipseRule,
}

impl HertzFrictionRules {
    /// Build the rules (allocates; once per element).
    ///
    /// # Errors
    /// None in practice (those of [`EllipseRule::new`]).
    pub fn new() -> Result<Self> {
        Ok(HertzFrictionRules {
            far: EllipseRule::pressure_weighted(2, 8)?,
            mid: EllipseRule::pressure_weighted(2, 12)?,
            near: EllipseRule::pressure_weighted(3, 16)?,
            fluid: EllipseRule::new(16, 16)?,
            careful: EllipseRule::new(16, 32)?,
        })
    }

    /// The rule for this ellipse, sliding field and law.
    pub fn select(
        &self,
        semi_axes: [f64; 2],
        orientation: f64,
        field: &VelocityField,
        law: &CellLaw,
    ) -> &EllipseRule {
        self.select_on(&DiscMap::new(semi_axes, orientation, field), law)
    }

    fn select_on(&self, map: &DiscMap, law: &CellLaw) -> &EllipseRule {
        let (o2, norm2) = map.smoothness_squared();
        // ρ_s ≥ t on the squares (no square root or division); 0 ≥ 0 where nothing slides
        // nor varies (ρ_s = ∞ in `smoothness`).
        let at_least = |t: f64| o2 >= t * t * norm2;
        match law.has_fluid() {
            true if at_least(2.0) => &self.fluid,
            false if at_least(8.0) => &self.far,
            false if at_least(4.0) => &self.mid,
            false if at_least(2.0) => &self.near,
            _ => &self.careful,
        }
    }

    /// [`ellipse_friction`] by the rule [`HertzFrictionRules::select`] picks.
    ///
    /// # Errors
    /// Those of [`ellipse_friction`].
    pub fn friction(
        &self,
        semi_axes: [f64; 2],
        orientation: f64,
        max_pressure: f64,
        field: &VelocityField,
        law: &CellLaw,
    ) -> Result<GridFriction> {
        // One map for the choice and the sums.
        match checked(semi_axes, orientation, max_pressure, field)? {
            Some(map) => mapped_friction(
                &map,
                semi_axes,
                max_pressure,
                law,
                self.select_on(&map, law),
            ),
            None => Ok(GridFriction::default()),
        }
    }
}
