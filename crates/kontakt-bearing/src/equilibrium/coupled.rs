//! Coupled slices: the slices of one roller contact interact through the elastic
//! half-space, so that the pressure along a crowned or tilted roller and the edge peak at
//! its ends come out (strip model in the manner of de Mul, Kalker & Vree 1998 and Teutsch &
//! Sauer 2004; derivation in `docs/bearing-model.md` §12).
//!
//! **Strips.** Slice j (width `w = L/n`, centre `x_j`) carries the load `q_j` (N) as a
//! pressure uniform along the slice and semi-elliptical across it,
//! `p = p_j √(1 − y²/b_j²)`, with the local Hertz half-width of its line load
//! `P_j = q_j/w`: `b_j = √(4 P_j R/(π E*))`, `p_j = 2 P_j/(π b_j) = √(P_j E*/(π R))`
//! (R the reduced radius across the contact, E* the contact modulus). Its surface
//! displacement (both bodies together, Boussinesq) at the centre line point `(x, 0)` is
//!
//! ```text
//! u(x) = 4 q_j/(π² E* w) [Φ((x_j − x + w/2)/b_j) − Φ((x_j − x − w/2)/b_j)],
//! Φ(t) = ∫₀^{π/2} cos²θ asinh(t/sin θ) dθ   (odd in t),
//! Φ'(t) = √(1 + t²) (K(k) − E(k)),  k² = 1/(1 + t²)   (complete elliptic integrals),
//! ```
//!
//! Φ is tabulated once per process from its closed-form derivative (cubic Hermite in
//! `ln t`, exact asymptotes beyond: `(π/4)(ln 4t + ½) + π/(64 t²)` for large t,
//! `t ln(4/t)` for small t), so its derivative is the exact derivative of the interpolant.
//!
//! **Approach.** A roller's two contacts carry the same slice loads (the roller is rigid and
//! its cup and cone loads are along one line, as in the ISO model), so the compliance of
//! both adds. The half-space line contact has no finite approach of its own (its
//! displacement grows with `ln(L/b)`), so the reference is fixed by the ISO/TS 16281 law:
//! the approach of slice i is
//!
//! ```text
//! G_i(q) = Σ_j C_ij(b_j) q_j + δ_ISO(Q) − ū(Q),   Q = Σ q_j,
//! δ_ISO(Q) = (Q/c_l)^(9/10),   ū(Q) = (1/n) Σ_ij C_ij(b̄) Q/n  (b̄ at the uniform load Q/n),
//! ```
//!
//! i.e. the half-space supplies how the approach varies along the roller relative to a
//! uniformly loaded straight roller, whose mean approach is the ISO law's. The term
//! `δ_ISO − ū` is uniform along the roller: the pressure distribution at a given roller
//! load is the half-space's. Contact: `G_i = δ_i` where `q_i > 0`, `G_i ≥ δ_i` where
//! `q_i = 0`, with δ_i the rigid interference of slice i (the ISO model's slice approach).
//! Solved per roller by Newton's method with an active set, warm-started from the last
//! solution; its Jacobian also gives the roller's stiffness for the ring's Newton.

use super::{
    RingLoad, RollerBearingSolver, RollerLoad, RollerSolution, free_and_target, load_scale,
    load_zone, roller_solution, warm_start,
};
use crate::geometry::RollerBearingKind;
use crate::newton::{reaction_scale, relative_residual, to_rows};
use kontakt::solve::{SolveStatus, Termination};
use kontakt::{Error, Result};
use nalgebra::{Matrix5, Vector5};
use std::f64::consts::PI;
use std::sync::OnceLock;

/// The contact modulus of steel on steel (E = 210 000 MPa, ν = 0.3), MPa:
/// `E* = E/(2(1 − ν²))`, the material the ISO/TS 16281 slice law is written for.
pub const STEEL_CONTACT_MODULUS_MPA: f64 = 210_000.0 / (2.0 * (1.0 - 0.09));

// ---------------------------------------------------------------------------------------
// The strip function Φ

const U_MIN: f64 = -14.0;
const U_MAX: f64 = 14.0;
const PER_UNIT: f64 = 32.0;

/// `Φ'(t) = √(1 + t²) (K(k) − E(k))`, `k² = 1/(1 + t²)`, for `t > 0`, by the
/// arithmetic-geometric mean (`K − E = K Σ 2^(n−1) c_n²`, no cancellation).
pub fn strip_slope(t: f64) -> f64 {
    let s1 = (1.0 + t * t).sqrt();
    let (mut a, mut b, mut c) = (1.0, t / s1, 1.0 / s1);
    let mut pow = 0.5;
    let mut sum = pow * c * c;
    for _ in 0..60 {
        if c.abs() <= 1e-15 * a {
            break;
        }
        let an = 0.5 * (a + b);
        let bn = (a * b).sqrt();
        c = 0.5 * (a - b);
        a = an;
        b = bn;
        pow *= 2.0;
        sum += pow * c * c;
    }
    s1 * (PI / (2.0 * a)) * sum
}

struct StripTable {
    /// Φ at `u_k = U_MIN + k/PER_UNIT` (u = ln t).
    val: Vec<f64>,
    /// dΦ/du = t Φ'(t) there.
    der: Vec<f64>,
}

impl StripTable {
    fn build() -> Self {
        let nodes = ((U_MAX - U_MIN) * PER_UNIT).round() as usize;
        let h = 1.0 / PER_UNIT;
        let rule = kontakt::quadrature::gauss_legendre(10);
        let slope_u = |u: f64| {
            let t = u.exp();
            t * strip_slope(t)
        };
        let mut val = Vec::with_capacity(nodes + 1);
        let mut der = Vec::with_capacity(nodes + 1);
        let t0 = U_MIN.exp();
        // Φ(t) = t ln(4/t) + O(t³ ln t) for small t
        let mut v = t0 * (4.0f64.ln() - U_MIN);
        for k in 0..=nodes {
            let u = U_MIN + k as f64 * h;
            val.push(v);
            der.push(slope_u(u));
            let mid = u + 0.5 * h;
            let step: f64 = rule
                .iter()
                .map(|&(x, wgt)| wgt * slope_u(mid + 0.5 * h * x))
                .sum();
            v += 0.5 * h * step;
        }
        StripTable { val, der }
    }
}

fn table() -> &'static StripTable {
    static TABLE: OnceLock<StripTable> = OnceLock::new();
    TABLE.get_or_init(StripTable::build)
}

/// `(Φ, dΦ/du)` at `u = ln t` (t > 0).
#[inline]
fn strip_at(tab: &StripTable, u: f64) -> (f64, f64) {
    if u >= U_MAX {
        let e = (-2.0 * u).exp();
        (
            0.25 * PI * (4.0f64.ln() + u + 0.5) + PI / 64.0 * e,
            0.25 * PI - PI / 32.0 * e,
        )
    } else if u <= U_MIN {
        let t = u.exp();
        let l = 4.0f64.ln() - u;
        (t * l, t * (l - 1.0))
    } else {
        let s = (u - U_MIN) * PER_UNIT;
        let i = (s as usize).min(tab.val.len() - 2);
        let x = s - i as f64;
        let h = 1.0 / PER_UNIT;
        let (v0, v1) = (tab.val[i], tab.val[i + 1]);
        let (d0, d1) = (tab.der[i] * h, tab.der[i + 1] * h);
        let x2 = x * x;
        let x3 = x2 * x;
        let v = (2.0 * x3 - 3.0 * x2 + 1.0) * v0
            + (x3 - 2.0 * x2 + x) * d0
            + (-2.0 * x3 + 3.0 * x2) * v1
            + (x3 - x2) * d1;
        let dv = (6.0 * x2 - 6.0 * x) * v0
            + (3.0 * x2 - 4.0 * x + 1.0) * d0
            + (-6.0 * x2 + 6.0 * x) * v1
            + (3.0 * x2 - 2.0 * x) * d1;
        (v, dv * PER_UNIT)
    }
}

/// `Φ(t) = ∫₀^{π/2} cos²θ asinh(t/sin θ) dθ` (odd in t), from the table.
pub fn strip_function(t: f64) -> f64 {
    if t == 0.0 {
        return 0.0;
    }
    t.signum() * strip_at(table(), t.abs().ln()).0
}

// ---------------------------------------------------------------------------------------
// One roller's coupled slices

/// The roller's contact response: load, moment about the roller centre and their
/// derivatives with respect to the rigid approach `a0 + a1 x`.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ContactResponse {
    /// Roller load Q = Σ q, N.
    pub load_n: f64,
    /// Σ q x, N·mm.
    pub moment_nmm: f64,
    /// `[[∂Q/∂a0, ∂Q/∂a1], [∂M/∂a0, ∂M/∂a1]]`.
    pub stiffness: [[f64; 2]; 2],
    /// Newton iterations of the slice solve.
    pub iterations: usize,
}

/// The coupled slices of one roller contact (one or two contacts in series carrying the
/// same slice loads): the influence data and the scratch of its solve, allocated once.
#[derive(Debug, Clone)]
pub struct SliceContact {
    n: usize,
    w: f64,
    x: Vec<f64>,
    e_star: f64,
    radii: Vec<f64>,
    /// `ln(4R/(π E* w))` per contact: `ln b = (ln q + this)/2`.
    ln_a: Vec<f64>,
    /// `ln((m + ½) w)`, m = 0..n.
    lx: Vec<f64>,
    /// `4/(π² E* w)`.
    kw: f64,
    c_l: f64,
    g: Vec<f64>,
    gap: Vec<f64>,
    jac: Vec<f64>,
    lu: Vec<f64>,
    perm: Vec<usize>,
    idx: Vec<usize>,
    rhs: Vec<f64>,
    col_phi: Vec<f64>,
    col_psi: Vec<f64>,
}

impl SliceContact {
    /// Slices of a contact of effective length `length_mm` (mm), `slices` of them, with
    /// the reduced radii across the contact `radii_mm` (mm, one per contact in series),
    /// the contact modulus `e_star_mpa` (MPa) and the ISO roller stiffness `c_l`
    /// (N/mm^(10/9)) that fixes the approach reference.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a non-positive or non-finite number, no contact, or
    /// fewer than one slice.
    pub fn new(
        length_mm: f64,
        slices: usize,
        radii_mm: &[f64],
        e_star_mpa: f64,
        c_l: f64,
    ) -> Result<Self> {
        let positive = |name: &'static str, v: f64| {
            if v.is_finite() && v > 0.0 {
                Ok(())
            } else {
                Err(Error::invalid(name, v, "a finite number > 0"))
            }
        };
        positive("length_mm", length_mm)?;
        positive("e_star_mpa", e_star_mpa)?;
        positive("roller_stiffness", c_l)?;
        if slices == 0 {
            return Err(Error::invalid("slices", 0.0, "at least 1"));
        }
        if radii_mm.is_empty() || radii_mm.len() > 2 {
            return Err(Error::invalid(
                "radii_mm",
                radii_mm.len() as f64,
                "one or two contacts",
            ));
        }
        for &r in radii_mm {
            positive("radii_mm", r)?;
        }
        let n = slices;
        let w = length_mm / n as f64;
        let x = (0..n)
            .map(|k| -0.5 * length_mm + (k as f64 + 0.5) * w)
            .collect();
        Ok(SliceContact {
            n,
            w,
            x,
            e_star: e_star_mpa,
            radii: radii_mm.to_vec(),
            ln_a: radii_mm
                .iter()
                .map(|r| (4.0 * r / (PI * e_star_mpa * w)).ln())
                .collect(),
            lx: (0..n).map(|m| ((m as f64 + 0.5) * w).ln()).collect(),
            kw: 4.0 / (PI * PI * e_star_mpa * w),
            c_l,
            g: vec![0.0; n],
            gap: vec![0.0; n],
            jac: vec![0.0; n * n],
            lu: vec![0.0; n * n],
            perm: vec![0; n],
            idx: vec![0; n],
            rhs: vec![0.0; 2 * n],
            col_phi: vec![0.0; n],
            col_psi: vec![0.0; n],
        })
    }

    /// Slice centres from the roller centre, mm.
    pub fn positions(&self) -> &[f64] {
        &self.x
    }

    /// Slice width, mm.
    pub fn width(&self) -> f64 {
        self.w
    }

    /// The peak pressure (MPa) of a slice carrying `q` (N) on contact `c` (the order of
    /// the radii given): `√(P E*/(π R))`, `P = q/w`.
    pub fn pressure(&self, q: f64, c: usize) -> f64 {
        (q.max(0.0) / self.w * self.e_star / (PI * self.radii[c])).sqrt()
    }

    /// The half-width (mm) of a slice carrying `q` (N) on contact `c`.
    pub fn half_width(&self, q: f64, c: usize) -> f64 {
        (4.0 * q.max(0.0) / self.w * self.radii[c] / (PI * self.e_star)).sqrt()
    }

    /// `δ_ISO(Q) − ū(Q)` and its derivative in Q (Q > 0).
    fn reference(&self, tab: &StripTable, q_total: f64) -> (f64, f64) {
        let n = self.n as f64;
        let qbar = q_total / n;
        let lq = qbar.ln();
        let (mut s, mut ds) = (0.0, 0.0);
        for &la in &self.ln_a {
            let lb = 0.5 * (lq + la);
            for &lx in &self.lx {
                let (p, d) = strip_at(tab, lx - lb);
                s += p;
                ds += p - 0.5 * d;
            }
        }
        let ubar = 2.0 * self.kw * qbar * s / n;
        let dubar = 2.0 * self.kw * ds / (n * n);
        let d_iso = (q_total / self.c_l).powf(0.9);
        (d_iso - ubar, 0.9 * d_iso / q_total - dubar)
    }

    /// Accumulate the column of slice j (load `qj`, floored for the half-width) into the
    /// approach `g` and the Jacobian column.
    fn column(&mut self, tab: &StripTable, j: usize, qj: f64, q_floor: f64) {
        let n = self.n;
        // below the floor the half-width is held: the Jacobian is the plain coefficient
        let floored = qj < q_floor;
        let lq = qj.max(q_floor).ln();
        for v in self.col_phi.iter_mut().chain(self.col_psi.iter_mut()) {
            *v = 0.0;
        }
        for &la in &self.ln_a {
            let lb = 0.5 * (lq + la);
            let mut prev = (0.0, 0.0);
            for m in 0..n {
                let (p, d) = strip_at(tab, self.lx[m] - lb);
                let psi = p - 0.5 * d;
                // c(0) = 2Φ((w/2)/b), c(m) = Φ((m+½)w/b) − Φ((m−½)w/b)
                let (cp, cs) = if m == 0 {
                    (2.0 * p, 2.0 * psi)
                } else {
                    (p - prev.0, psi - prev.1)
                };
                self.col_phi[m] += cp;
                self.col_psi[m] += cs;
                prev = (p, psi);
            }
        }
        for i in 0..n {
            let m = i.abs_diff(j);
            self.g[i] += self.kw * qj * self.col_phi[m];
            self.jac[i * n + j] = self.kw
                * if floored {
                    self.col_phi[m]
                } else {
                    self.col_psi[m]
                };
        }
    }

    /// Solve the slice loads `q` (N; in: the start, out: the solution) for the rigid
    /// interference `delta` (mm) of every slice; returns the roller's load, moment and
    /// stiffness. A roller with no positive interference carries nothing.
    ///
    /// `c_start` (N/mm^(10/9)) is the ISO slice stiffness of a cold start.
    ///
    /// # Errors
    /// [`Error::NotConverged`] when the iteration does not settle within 100 steps (its
    /// residual the largest gap over the largest interference), [`Error::InvalidInput`]
    /// naming `slices` when the system is singular (neither expected; reported rather than
    /// returning a wrong load).
    pub fn solve(&mut self, delta: &[f64], q: &mut [f64], c_start: f64) -> Result<ContactResponse> {
        let n = self.n;
        let tab = table();
        let dmax = delta.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        if !(dmax > 0.0) {
            q.iter_mut().for_each(|v| *v = 0.0);
            return Ok(ContactResponse::default());
        }
        if q.iter().all(|&v| v <= 0.0) {
            // a cold start: the ISO slice law
            for (qi, &d) in q.iter_mut().zip(delta) {
                *qi = if d > 0.0 {
                    c_start * d.powf(10.0 / 9.0)
                } else {
                    0.0
                };
            }
        }
        let tol = 1e-14 * dmax;
        let mut best = f64::INFINITY;
        for it in 0..100 {
            let q_total: f64 = q.iter().sum();
            let q_floor = 1e-9 * q_total / n as f64;
            self.g.iter_mut().for_each(|v| *v = 0.0);
            // columns of every loaded slice and of every penetrating one
            let (dref, dref_q) = self.reference(tab, q_total);
            for (j, &qj) in q.iter().enumerate() {
                if qj > 0.0 {
                    self.column(tab, j, qj, q_floor);
                }
            }
            let mut worst: f64 = 0.0;
            let mut m = 0;
            for i in 0..n {
                self.gap[i] = self.g[i] + dref - delta[i];
                if q[i] > 0.0 {
                    worst = worst.max(self.gap[i].abs());
                } else {
                    worst = worst.max((-self.gap[i]).max(0.0));
                }
            }
            for (i, &qi) in q.iter().enumerate() {
                if qi > 0.0 || self.gap[i] < -tol {
                    if qi <= 0.0 {
                        // a slice closing: its half-width from a small fraction of the mean
                        self.column(tab, i, 0.0, 1e-2 * q_total / n as f64);
                    }
                    self.idx[m] = i;
                    m += 1;
                }
            }
            let settled = worst <= tol || (worst <= 1e-10 * dmax && worst >= 0.5 * best);
            best = best.min(worst);
            // the Jacobian on the active set
            for a in 0..m {
                for b in 0..m {
                    self.lu[a * m + b] = self.jac[self.idx[a] * n + self.idx[b]] + dref_q;
                }
            }
            if !lu_factor(&mut self.lu[..m * m], m, &mut self.perm[..m]) {
                return Err(Error::invalid(
                    "slices",
                    n as f64,
                    "a coupled slice system that is not singular (the influence matrix lost rank)",
                ));
            }
            if settled && m == q.iter().filter(|&&v| v > 0.0).count() {
                return Ok(self.response(q, m, it));
            }
            for a in 0..m {
                self.rhs[a] = -self.gap[self.idx[a]];
            }
            lu_solve(
                &self.lu[..m * m],
                m,
                &self.perm[..m],
                &mut self.rhs[..m],
                false,
            );
            for a in 0..m {
                let i = self.idx[a];
                q[i] = (q[i] + self.rhs[a]).max(0.0);
            }
            if q.iter().all(|&v| v <= 0.0) {
                // everything let go in one step: restart from the ISO law
                for (qi, &d) in q.iter_mut().zip(delta) {
                    *qi = if d > 0.0 {
                        c_start * d.powf(10.0 / 9.0)
                    } else {
                        0.0
                    };
                }
            }
        }
        Err(Error::NotConverged {
            what: "the coupled slice solve of a roller".into(),
            iterations: 100,
            residual: best / dmax,
        })
    }

    /// Load, moment and their derivatives from the factorised active-set Jacobian.
    fn response(&mut self, q: &[f64], m: usize, iterations: usize) -> ContactResponse {
        let load: f64 = q.iter().sum();
        let moment: f64 = q.iter().zip(&self.x).map(|(a, b)| a * b).sum();
        // y = J⁻ᵀ 1, z = J⁻ᵀ x: ∂Q/∂a = yᵀ(1, x), ∂M/∂a = zᵀ(1, x)
        let (y, z) = self.rhs.split_at_mut(self.n);
        for a in 0..m {
            y[a] = 1.0;
            z[a] = self.x[self.idx[a]];
        }
        lu_solve(&self.lu[..m * m], m, &self.perm[..m], &mut y[..m], true);
        lu_solve(&self.lu[..m * m], m, &self.perm[..m], &mut z[..m], true);
        let mut k = [[0.0; 2]; 2];
        for a in 0..m {
            let xa = self.x[self.idx[a]];
            k[0][0] += y[a];
            k[0][1] += y[a] * xa;
            k[1][0] += z[a];
            k[1][1] += z[a] * xa;
        }
        ContactResponse {
            load_n: load,
            moment_nmm: moment,
            stiffness: k,
            iterations,
        }
    }
}

/// In-place LU factorisation with partial pivoting of the row-major `m × m` matrix `a`:
/// `P A = L U`, with `swaps[k]` the row exchanged with row k at step k (LAPACK's `ipiv`).
/// False when singular.
fn lu_factor(a: &mut [f64], m: usize, swaps: &mut [usize]) -> bool {
    for k in 0..m {
        let mut piv = k;
        let mut big = a[k * m + k].abs();
        for i in k + 1..m {
            if a[i * m + k].abs() > big {
                big = a[i * m + k].abs();
                piv = i;
            }
        }
        if !(big > 0.0) || !big.is_finite() {
            return false;
        }
        swaps[k] = piv;
        if piv != k {
            for c in 0..m {
                a.swap(k * m + c, piv * m + c);
            }
        }
        let d = a[k * m + k];
        for i in k + 1..m {
            let f = a[i * m + k] / d;
            a[i * m + k] = f;
            if f != 0.0 {
                for c in k + 1..m {
                    a[i * m + c] -= f * a[k * m + c];
                }
            }
        }
    }
    true
}

/// Solve `A x = b` (or `Aᵀ x = b` when `transposed`) in place with the factors of
/// [`lu_factor`].
fn lu_solve(lu: &[f64], m: usize, swaps: &[usize], b: &mut [f64], transposed: bool) {
    if !transposed {
        // P b, then L (unit) forward and U backward
        for (k, &p) in swaps.iter().enumerate() {
            b.swap(k, p);
        }
        for i in 0..m {
            let s: f64 = (0..i).map(|c| lu[i * m + c] * b[c]).sum();
            b[i] -= s;
        }
        for i in (0..m).rev() {
            let s: f64 = (i + 1..m).map(|c| lu[i * m + c] * b[c]).sum();
            b[i] = (b[i] - s) / lu[i * m + i];
        }
    } else {
        // Aᵀ = Uᵀ Lᵀ P: Uᵀ forward, Lᵀ (unit) backward, then Pᵀ
        for i in 0..m {
            let s: f64 = (0..i).map(|c| lu[c * m + i] * b[c]).sum();
            b[i] = (b[i] - s) / lu[i * m + i];
        }
        for i in (0..m).rev() {
            let s: f64 = (i + 1..m).map(|c| lu[c * m + i] * b[c]).sum();
            b[i] -= s;
        }
        for (k, &p) in swaps.iter().enumerate().rev() {
            b.swap(k, p);
        }
    }
}

// ---------------------------------------------------------------------------------------
// The ring with coupled slices

/// The reduced radii (mm) across the inner and the outer raceway contact of a roller at
/// its mean diameter: `R = (D/2)(1 ∓ D cos α/d_m)` (Harris & Kotzalas 2006), the cone
/// angle for the inner raceway of a tapered roller; a thrust roller runs on flat washers.
pub fn raceway_radii(bearing: &crate::geometry::RollerBearing) -> [f64; 2] {
    let d = bearing.roller_diameter_mm;
    let dm = bearing.pitch_diameter_mm;
    let gi = d * bearing.cone_angle_rad.cos() / dm;
    let go = d * bearing.contact_angle_rad.cos() / dm;
    [0.5 * d * (1.0 - gi), 0.5 * d * (1.0 + go)]
}

/// The ring equilibrium of a roller bearing with coupled slices: the frames, profiles and
/// start of [`RollerBearingSolver`] (whose ISO solution is the start), a [`SliceContact`]
/// per bearing, and per-slice buffers, all allocated once.
#[derive(Debug, Clone)]
pub struct CoupledSliceSolver {
    iso: RollerBearingSolver,
    contact: SliceContact,
    q: Vec<f64>,
    approach: Vec<f64>,
    pressure_inner: Vec<f64>,
    pressure_outer: Vec<f64>,
    delta: Vec<f64>,
    rollers: Vec<RollerLoad>,
    slice_iterations: usize,
    /// Largest relative residual accepted as converged (default 1e-11).
    pub tolerance: f64,
    /// Iteration limit of the ring's Newton (default 50).
    pub max_iterations: usize,
}

impl CoupledSliceSolver {
    /// Validate the bearing and set up the coupled slices (steel, E* = 115 385 MPa).
    ///
    /// # Errors
    /// As [`RollerBearingSolver::new`].
    pub fn new(bearing: crate::geometry::RollerBearing) -> Result<Self> {
        let iso = RollerBearingSolver::new(bearing)?;
        let b = iso.bearing();
        let contact = SliceContact::new(
            b.effective_length_mm,
            b.slices,
            &raceway_radii(b),
            STEEL_CONTACT_MODULUS_MPA,
            b.roller_stiffness(),
        )?;
        let n = b.rollers * b.slices;
        let ns = b.slices;
        Ok(CoupledSliceSolver {
            contact,
            q: vec![0.0; n],
            approach: vec![0.0; n],
            pressure_inner: vec![0.0; n],
            pressure_outer: vec![0.0; n],
            delta: vec![0.0; ns],
            rollers: vec![RollerLoad::default(); b.rollers],
            iso,
            slice_iterations: 0,
            tolerance: 1e-11,
            max_iterations: 50,
        })
    }

    /// The bearing.
    pub fn bearing(&self) -> &crate::geometry::RollerBearing {
        self.iso.bearing()
    }

    /// Slice centres from the roller centre, mm.
    pub fn slice_positions(&self) -> &[f64] {
        self.iso.slice_positions()
    }

    /// Slice loads of the last evaluation, N, roller-major (`[j * slices + k]`).
    pub fn slice_loads(&self) -> &[f64] {
        &self.q
    }

    /// The rigid interference of every slice (the ISO model's slice approach), mm.
    pub fn slice_approaches(&self) -> &[f64] {
        &self.approach
    }

    /// Peak pressure per slice on the inner raceway, MPa, roller-major.
    pub fn inner_pressures(&self) -> &[f64] {
        &self.pressure_inner
    }

    /// Peak pressure per slice on the outer raceway, MPa, roller-major.
    pub fn outer_pressures(&self) -> &[f64] {
        &self.pressure_outer
    }

    /// Per-roller loads of the last solve.
    pub fn roller_loads(&self) -> &[RollerLoad] {
        &self.rollers
    }

    /// The most slice iterations one roller needed in the last evaluation.
    pub fn slice_iterations(&self) -> usize {
        self.slice_iterations
    }

    /// The coupled slices of one roller.
    pub fn slice_contact(&self) -> &SliceContact {
        &self.contact
    }

    /// The carried load `(Fx, Fy, Fz, Mx, My)` (N, N·mm) at the inner-ring displacement
    /// `u` (mm, rad) and its Jacobian.
    ///
    /// # Errors
    /// When a roller's slice solve does not converge.
    pub fn load_at(&mut self, u: [f64; 5]) -> Result<([f64; 5], [[f64; 5]; 5])> {
        let (f, k) = self.evaluate(&Vector5::from(u))?;
        Ok((f.into(), to_rows(&k)))
    }

    fn evaluate(&mut self, u: &Vector5<f64>) -> Result<(Vector5<f64>, Matrix5<f64>)> {
        let ns = self.delta.len();
        let c_s = self.iso.c_s;
        let mut f = Vector5::zeros();
        let mut k = Matrix5::zeros();
        self.slice_iterations = 0;
        for (j, fr) in self.iso.frames.iter().enumerate() {
            let a0 = fr.g0.dot(u);
            let a1 = fr.g1.dot(u);
            for kk in 0..ns {
                let d = a0 + a1 * self.iso.x[kk] - self.iso.offset[kk];
                self.delta[kk] = d;
                self.approach[j * ns + kk] = d;
            }
            let q = &mut self.q[j * ns..(j + 1) * ns];
            let r = self.contact.solve(&self.delta, q, c_s)?;
            self.slice_iterations = self.slice_iterations.max(r.iterations);
            f += fr.g0 * r.load_n + fr.g1 * r.moment_nmm;
            let s = r.stiffness;
            k += fr.g0 * (fr.g0 * s[0][0] + fr.g1 * s[0][1]).transpose()
                + fr.g1 * (fr.g0 * s[1][0] + fr.g1 * s[1][1]).transpose();
        }
        Ok((f, k))
    }

    /// Solve the inner ring's equilibrium under `load`, starting from the ISO slice
    /// solution (the same bearing, the same load). A load the ISO model ends with
    /// `Diverged` or `MaxIterations` on returns that solution, its status and note (the
    /// slice buffers are then not the coupled model's).
    ///
    /// # Errors
    /// As [`RollerBearingSolver::solve`]; [`Error::NotConverged`] for a roller's slice
    /// solve that does not converge.
    pub fn solve(&mut self, load: &RingLoad) -> Result<RollerSolution> {
        let start = self.iso.solve(load)?;
        if !matches!(
            start.status.termination,
            Termination::Converged | Termination::Stagnated
        ) {
            // a load the ISO model cannot carry: its status and note
            return Ok(start);
        }
        self.q.copy_from_slice(self.iso.slice_loads());
        self.iterate(load, Vector5::from(start.displacement))
    }

    /// Solve from the displacement `start` (mm, rad) and the slice loads of the last
    /// solve (a warm start after a small load change).
    ///
    /// # Errors
    /// As [`CoupledSliceSolver::solve`], and `start` must be finite.
    pub fn solve_from(&mut self, load: &RingLoad, start: [f64; 5]) -> Result<RollerSolution> {
        self.iso.check_load(load)?;
        let u = warm_start(load, start, &self.iso.stiff)?;
        self.iterate(load, u)
    }

    fn iterate(&mut self, load: &RingLoad, mut u: Vector5<f64>) -> Result<RollerSolution> {
        let bearing = self.iso.bearing();
        let r = 0.5 * bearing.pitch_diameter_mm;
        let clearance = bearing.clearance_mm;
        let preload = bearing.rollers as f64 * bearing.roller_stiffness();
        let (free, target) = free_and_target(load, &self.iso.stiff);
        let mut f_ref = load_scale(&target, r);
        if clearance < 0.0 {
            f_ref = f_ref.max(preload * (-0.5 * clearance).powf(10.0 / 9.0));
        }
        let (mut f, mut k) = self.evaluate(&u)?;
        if f_ref == 0.0 {
            f_ref = reaction_scale(&f, r);
        }
        let scaled = |f: &Vector5<f64>| -> f64 {
            (0..5)
                .filter(|&i| free[i])
                .map(|i| {
                    let s = if i < 3 { f_ref } else { f_ref * r };
                    ((f[i] - target[i]) / s).powi(2)
                })
                .sum()
        };
        let mut termination = if f_ref == 0.0 {
            Termination::Converged
        } else {
            Termination::MaxIterations
        };
        let (mut note, mut iterations) = (None, 0);
        let mut res = relative_residual(&f, &target, &free, f_ref, r);
        while termination == Termination::MaxIterations && iterations < self.max_iterations {
            if res <= self.tolerance {
                termination = Termination::Converged;
                break;
            }
            iterations += 1;
            let mut jac = k;
            let mut rhs = Vector5::zeros();
            let diag = (0..5).map(|i| jac[(i, i)].abs()).fold(0.0, f64::max);
            for i in 0..5 {
                if free[i] {
                    rhs[i] = target[i] - f[i];
                    jac[(i, i)] += 1e-13 * diag;
                } else {
                    for j in 0..5 {
                        jac[(i, j)] = 0.0;
                        jac[(j, i)] = 0.0;
                    }
                    jac[(i, i)] = 1.0;
                }
            }
            let Some(step) = jac.lu().solve(&rhs) else {
                termination = Termination::Diverged;
                note = Some("the Newton system is singular: the load cannot be carried");
                break;
            };
            let merit = scaled(&f);
            let mut t = 1.0;
            let mut accepted = false;
            for _ in 0..40 {
                let trial = u + step * t;
                let (f2, k2) = self.evaluate(&trial)?;
                let merit2 = scaled(&f2);
                if merit2 <= (1.0 - 1e-4 * t) * merit {
                    u = trial;
                    f = f2;
                    k = k2;
                    res = relative_residual(&f, &target, &free, f_ref, r);
                    accepted = true;
                    break;
                }
                t *= 0.5;
            }
            if !accepted {
                termination = if res <= 1e3 * self.tolerance {
                    Termination::Stagnated
                } else {
                    Termination::Diverged
                };
                note = Some(
                    "the line search found no decrease (round-off floor or a load the bearing cannot carry)",
                );
                self.evaluate(&u)?;
                break;
            }
        }
        if termination == Termination::MaxIterations && res <= self.tolerance {
            termination = Termination::Converged;
        }
        if termination == Termination::MaxIterations {
            note = Some("the iteration limit was reached before the tolerance");
        }
        Ok(self.finish(u, f, k, termination, iterations, res, note))
    }

    #[allow(clippy::too_many_arguments)]
    fn finish(
        &mut self,
        u: Vector5<f64>,
        f: Vector5<f64>,
        k: Matrix5<f64>,
        termination: Termination,
        iterations: usize,
        res: f64,
        note: Option<&'static str>,
    ) -> RollerSolution {
        let ns = self.delta.len();
        let mut qmax: f64 = 0.0;
        for (j, fr) in self.iso.frames.iter().enumerate() {
            let q: f64 = self.q[j * ns..(j + 1) * ns].iter().sum();
            let dmax = self.approach[j * ns..(j + 1) * ns]
                .iter()
                .copied()
                .fold(f64::NEG_INFINITY, f64::max);
            for kk in 0..ns {
                let qk = self.q[j * ns + kk];
                self.pressure_inner[j * ns + kk] = self.contact.pressure(qk, 0);
                self.pressure_outer[j * ns + kk] = self.contact.pressure(qk, 1);
            }
            self.rollers[j] = RollerLoad {
                azimuth_rad: (-fr.g1[3]).atan2(fr.g1[4]),
                outer_n: q,
                inner_n: q * self.iso.inner_ratio,
                rib_n: q * self.iso.rib_ratio,
                max_approach_mm: dmax,
            };
            qmax = qmax.max(q);
        }
        let bearing = self.iso.bearing();
        let load_zone = load_zone(
            &u,
            bearing.contact_angle_rad,
            bearing.clearance_mm,
            bearing.kind == RollerBearingKind::Thrust,
        );
        let status = SolveStatus::new(termination, iterations, res);
        roller_solution(u, f, &k, status, note, qmax, load_zone)
    }
}

#[cfg(test)]
#[path = "coupled_tests.rs"]
mod tests;
