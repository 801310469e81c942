//! The force law of the roller end/rib contact in the rib-contact roller balance
//! (docs/bearing-model.md §15.8): Hertz's closed form (the default) or a load-approach
//! curve of kontakt's own PimP (Wirsching et al. 2020) or FFT half-space solver, tabulated
//! once at plan time.
//!
//! **Why a table.** In the balance the rib contact's point and normal are those of the
//! unloaded construction (§15), so its force is a function of the approach alone,
//! `Q_f(δ)`. The roller Newton evaluates it (with `dQ_f/dδ` and the potential
//! `W = ∫ Q_f dδ` for its line search) 673 times in a cold solve of the bench's 20-roller
//! TRB (172 warm); the contact element's PimP path (18-20 µs a call) would cost some
//! 13 ms, against issue 29's 2 ms for the whole friction step. The curve is therefore solved at
//! `n` loads once and interpolated.
//!
//! **Interpolant.** With `s = √δ`, Hertz's law `Q = K s³` is a cubic: the table is a
//! piecewise cubic Hermite `Q(s)` through the solved knots `(s_k, Q_k)`, its knot slopes
//! from the three-point derivative of `ln Q` over `ln s` (nearly linear: exponent ≈ 3),
//! limited after Fritsch & Carlson (1980) so that `Q` rises monotonically (the potential
//! stays convex). Below the first and above the last knot it continues as the power law
//! `Q_k (s/s_k)^m_k` with the end knot's exponent `m_k = s Q'/Q` (C¹ at the knots). The
//! derivative `dQ/dδ = Q'(s)/(2s)` and the potential
//! `W(δ) = ∫₀^s Q(σ) 2σ dσ` (a polynomial per segment) are exact for the interpolant, so
//! the Newton and its line search see one consistent law. The maximum pressure is
//! interpolated as `p/Q^(1/3)` (constant for Hertz), linearly in `ln Q`.
//!
//! Units: mm, N, MPa.

use kontakt::gap::GapSource;
use kontakt::halfspace::{Bem, BemOptions};
use kontakt::pimp::{Pimp, PimpOptions};
use kontakt::{Error, Result};

/// Which model gives the rib contact's force law in the roller balance.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum RibModel {
    /// Hertz's point contact at the contact point (closed form; the default).
    #[default]
    Hertz,
    /// PimP (Wirsching et al. 2020), corrected bedding, 64 × 64 adaptive grid, tabulated.
    Pimp,
    /// kontakt's FFT half-space solver (default options), tabulated: the accuracy
    /// reference (a plan costs one half-space solve per knot).
    HalfSpace,
}

impl RibModel {
    /// The name as the case file spells it: `"hertz"`, `"pimp"`, `"halfspace"`.
    pub fn as_str(&self) -> &'static str {
        match self {
            RibModel::Hertz => "hertz",
            RibModel::Pimp => "pimp",
            RibModel::HalfSpace => "halfspace",
        }
    }
}

/// The load range and knot count of a tabulated rib law, given as pressures (so that it
/// fits any pair and bearing): the first knot lies at the load where the rib contact's
/// Hertz pressure is `min_pressure_mpa`, the last at the smaller of the load where it is
/// `max_pressure_mpa` and the load at which the roller's line contact (length `L_we`,
/// radius `D_we/2`, steel) reaches `max_pressure_mpa` — a rib carries a fraction of its
/// roller's load, and on a conformal pair Hertz's pressure would put the last knot at
/// loads no rib sees; the knots between are spaced geometrically in load.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RibTableRange {
    /// Hertz pressure of the first knot, MPa (> 0; default 100).
    pub min_pressure_mpa: f64,
    /// Hertz pressure of the last knot, MPa (> min; default 5000, above the ISO 76 limit
    /// of 4000 MPa for roller contacts).
    pub max_pressure_mpa: f64,
    /// Knots (4..=200; default 24).
    pub knots: usize,
}

impl Default for RibTableRange {
    fn default() -> Self {
        RibTableRange {
            min_pressure_mpa: 100.0,
            max_pressure_mpa: 5000.0,
            knots: 24,
        }
    }
}

impl RibTableRange {
    /// # Errors
    /// [`Error::InvalidInput`] naming `rib_table.<field>` out of range.
    pub fn validate(&self) -> Result<()> {
        if !(self.min_pressure_mpa.is_finite() && self.min_pressure_mpa > 0.0) {
            return Err(Error::invalid(
                "rib_table.min_pressure_mpa",
                self.min_pressure_mpa,
                "a finite pressure > 0 MPa",
            ));
        }
        if !(self.max_pressure_mpa.is_finite() && self.max_pressure_mpa > self.min_pressure_mpa) {
            return Err(Error::invalid(
                "rib_table.max_pressure_mpa",
                self.max_pressure_mpa,
                format!(
                    "a finite pressure > min_pressure_mpa = {} MPa",
                    self.min_pressure_mpa
                ),
            ));
        }
        if !(4..=200).contains(&self.knots) {
            return Err(Error::invalid(
                "rib_table.knots",
                self.knots,
                "4 <= knots <= 200",
            ));
        }
        Ok(())
    }
}

/// A tabulated load-approach curve `Q(δ)` of a rib contact (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct RibTable {
    /// Knots `s_k = √δ_k`, mm^½, increasing.
    s: Vec<f64>,
    /// Loads at the knots, N.
    q: Vec<f64>,
    /// `dQ/ds` at the knots, N/mm^½.
    dq: Vec<f64>,
    /// Potential `W(δ_k)`, N·mm.
    w: Vec<f64>,
    /// `ln Q_k` and `p_k / Q_k^(1/3)` (MPa/N^⅓).
    ln_q: Vec<f64>,
    ratio: Vec<f64>,
}

impl RibTable {
    /// The table through the solved knots `(approach mm, load N, max pressure MPa)`,
    /// increasing in load.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] (`rib_table.knots`) with fewer than 4 knots or knots that
    /// do not rise in approach and load.
    pub fn from_knots(knots: &[(f64, f64, f64)]) -> Result<Self> {
        let n = knots.len();
        let ok = n >= 4
            && knots
                .iter()
                .all(|&(d, q, p)| d > 0.0 && q > 0.0 && p > 0.0 && d.is_finite() && q.is_finite())
            && knots.windows(2).all(|w| w[1].0 > w[0].0 && w[1].1 > w[0].1);
        if !ok {
            return Err(Error::invalid(
                "rib_table.knots",
                n,
                "at least 4 solved knots, rising in approach and load",
            ));
        }
        let s: Vec<f64> = knots.iter().map(|k| k.0.sqrt()).collect();
        let q: Vec<f64> = knots.iter().map(|k| k.1).collect();
        let x: Vec<f64> = s.iter().map(|v| v.ln()).collect();
        let y: Vec<f64> = q.iter().map(|v| v.ln()).collect();
        // three-point derivative of ln Q over ln s (one-sided at the ends)
        let sec: Vec<f64> = (0..n - 1)
            .map(|k| (y[k + 1] - y[k]) / (x[k + 1] - x[k]))
            .collect();
        let h: Vec<f64> = (0..n - 1).map(|k| x[k + 1] - x[k]).collect();
        let mut m = vec![0.0; n];
        for k in 1..n - 1 {
            m[k] = (h[k - 1] * sec[k] + h[k] * sec[k - 1]) / (h[k - 1] + h[k]);
        }
        m[0] = ((2.0 * h[0] + h[1]) * sec[0] - h[0] * sec[1]) / (h[0] + h[1]);
        let (a, b) = (h[n - 2], h[n - 3]);
        m[n - 1] = ((2.0 * a + b) * sec[n - 2] - a * sec[n - 3]) / (a + b);
        let mut dq: Vec<f64> = (0..n).map(|k| m[k].max(0.0) * q[k] / s[k]).collect();
        // Fritsch & Carlson (1980): a monotone cubic on every segment
        for k in 0..n - 1 {
            let d = (q[k + 1] - q[k]) / (s[k + 1] - s[k]);
            let (al, be) = (dq[k] / d, dq[k + 1] / d);
            let r = al.hypot(be);
            if r > 3.0 {
                dq[k] *= 3.0 / r;
                dq[k + 1] *= 3.0 / r;
            }
        }
        let mut table = RibTable {
            ln_q: y,
            ratio: knots.iter().map(|k| k.2 / k.1.cbrt()).collect(),
            w: vec![0.0; n],
            s,
            q,
            dq,
        };
        let m0 = table.exponent(0);
        table.w[0] = 2.0 * table.q[0] * table.s[0].powi(2) / (m0 + 2.0);
        for k in 0..n - 1 {
            table.w[k + 1] = table.w[k] + table.segment(k, table.s[k + 1]).2;
        }
        Ok(table)
    }

    /// Knot approaches and loads `(δ_k mm, Q_k N)`.
    pub fn knots(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        self.s.iter().zip(&self.q).map(|(s, q)| (s * s, *q))
    }

    /// The end knot's exponent `s Q'/Q` (Hertz: 3).
    fn exponent(&self, k: usize) -> f64 {
        self.s[k] * self.dq[k] / self.q[k]
    }

    /// On segment k at `s`: `(Q, dQ/ds, ∫_{s_k}^s Q 2σ dσ)`.
    fn segment(&self, k: usize, s: f64) -> (f64, f64, f64) {
        let hk = self.s[k + 1] - self.s[k];
        let d = (self.q[k + 1] - self.q[k]) / hk;
        let (c0, c1) = (self.q[k], self.dq[k]);
        let c2 = (3.0 * d - 2.0 * self.dq[k] - self.dq[k + 1]) / hk;
        let c3 = (self.dq[k] + self.dq[k + 1] - 2.0 * d) / (hk * hk);
        let t = s - self.s[k];
        let q = c0 + t * (c1 + t * (c2 + t * c3));
        let dq = c1 + t * (2.0 * c2 + t * 3.0 * c3);
        let sk = self.s[k];
        let i0 = t * (c0 + t * (c1 / 2.0 + t * (c2 / 3.0 + t * c3 / 4.0)));
        let i1 = t * t * (c0 / 2.0 + t * (c1 / 3.0 + t * (c2 / 4.0 + t * c3 / 5.0)));
        (q, dq, 2.0 * sk * i0 + 2.0 * i1)
    }

    /// `(Q N, dQ/dδ N/mm, W N·mm)` at the approach `delta > 0` (mm).
    pub fn eval(&self, delta: f64) -> (f64, f64, f64) {
        let s = delta.sqrt();
        let n = self.s.len();
        if s <= self.s[0] {
            let m = self.exponent(0);
            let q = self.q[0] * (s / self.s[0]).powf(m);
            return (q, 0.5 * m * q / delta, 2.0 * q * delta / (m + 2.0));
        }
        if s >= self.s[n - 1] {
            let m = self.exponent(n - 1);
            let q = self.q[n - 1] * (s / self.s[n - 1]).powf(m);
            let d_top = self.s[n - 1] * self.s[n - 1];
            let w = self.w[n - 1] + 2.0 * (q * delta - self.q[n - 1] * d_top) / (m + 2.0);
            return (q, 0.5 * m * q / delta, w);
        }
        let k = self.s.partition_point(|&v| v <= s) - 1;
        let (q, dq, w) = self.segment(k, s);
        (q, 0.5 * dq / s, self.w[k] + w)
    }

    /// The maximum pressure at the load `q > 0` N, MPa.
    pub fn pressure(&self, q: f64) -> f64 {
        let n = self.q.len();
        let y = q.ln();
        let r = if y <= self.ln_q[0] {
            self.ratio[0]
        } else if y >= self.ln_q[n - 1] {
            self.ratio[n - 1]
        } else {
            let k = self.ln_q.partition_point(|&v| v <= y) - 1;
            let t = (y - self.ln_q[k]) / (self.ln_q[k + 1] - self.ln_q[k]);
            self.ratio[k] + t * (self.ratio[k + 1] - self.ratio[k])
        };
        r * q.cbrt()
    }
}

/// Solve `gap` by `model` at the knots of `range` (Hertz pressures through `p0`, the Hertz
/// pressure at 1 N in MPa; `line_load_limit(p)` the roller's load at the line-contact
/// pressure p, N) and tabulate. Knots where the solver fails (a zone beyond the
/// face's edge at the largest loads) end the table there; at least 4 must remain.
///
/// # Errors
/// `rib_table.*` out of range; `rib_contact.model` when fewer than 4 knots solve (the
/// first solver error quoted); `rib_contact.model` for [`RibModel::Hertz`] (not
/// tabulated).
pub fn tabulate(
    model: RibModel,
    gap: &dyn GapSource,
    p0: f64,
    line_load_limit: &dyn Fn(f64) -> f64,
    range: &RibTableRange,
) -> Result<RibTable> {
    range.validate()?;
    let steel = kontakt::material::ElasticMaterial::STEEL;
    let solve: Box<dyn Fn(f64) -> Result<(f64, f64)> + '_> = match model {
        RibModel::Hertz => {
            return Err(Error::invalid(
                "rib_contact.model",
                "hertz",
                "pimp or halfspace for a tabulated law (Hertz is closed-form)",
            ));
        }
        RibModel::Pimp => {
            let pimp = Pimp::new(steel, steel, PimpOptions::default())?;
            Box::new(move |q| {
                let s = pimp.solve_force(gap, q)?;
                Ok((s.approach, s.max_pressure))
            })
        }
        RibModel::HalfSpace => {
            let bem = Bem::new(steel, steel, BemOptions::default())?
                .with_estimate(kontakt::pimp::zone_estimate(steel, steel)?);
            Box::new(move |q| {
                let s = bem.solve_force(gap, q)?;
                Ok((s.approach, s.max_pressure))
            })
        }
    };
    let n = range.knots;
    let q_lo = (range.min_pressure_mpa / p0).powi(3);
    let q_hi = (range.max_pressure_mpa / p0)
        .powi(3)
        .min(line_load_limit(range.max_pressure_mpa));
    if !(q_hi > q_lo) {
        return Err(Error::invalid(
            "rib_table.max_pressure_mpa",
            range.max_pressure_mpa,
            format!(
                "a pressure whose roller line-contact load ({q_hi:.4} N) exceeds the rib's load at min_pressure_mpa ({q_lo:.4} N)"
            ),
        ));
    }
    let mut knots = Vec::with_capacity(n);
    let mut first_error = None;
    for k in 0..n {
        let q = q_lo * (q_hi / q_lo).powf(k as f64 / (n - 1) as f64);
        match solve(q) {
            Ok((d, p)) => knots.push((d, q, p)),
            Err(e) => {
                first_error = Some(e);
                break;
            }
        }
    }
    if knots.len() < 4 {
        return Err(Error::invalid(
            "rib_contact.model",
            model.as_str(),
            format!(
                "a model that solves the rib contact at its loads: {} of {n} knots solved ({})",
                knots.len(),
                first_error.map_or_else(String::new, |e| e.to_string())
            ),
        ));
    }
    RibTable::from_knots(&knots)
}

/// The rib contact's law in the balance.
#[derive(Debug, Clone)]
pub(crate) enum RibLaw {
    /// `Q = k δ^(3/2)`, `p = p0 Q^(1/3)`.
    Hertz {
        k: f64,
        p0: f64,
    },
    Table(Box<RibTable>),
}

impl RibLaw {
    /// `(Q, dQ/dδ, W)` at the approach `delta > 0`, scaled by `factor`.
    #[inline]
    pub(crate) fn eval(&self, delta: f64, factor: f64) -> (f64, f64, f64) {
        match self {
            RibLaw::Hertz { k, .. } => {
                let kf = k * factor;
                let sq = delta.sqrt();
                let q = kf * delta * sq;
                (q, 1.5 * kf * sq, 0.4 * q * delta)
            }
            RibLaw::Table(t) => {
                let (q, k, w) = t.eval(delta);
                (q * factor, k * factor, w * factor)
            }
        }
    }

    /// The maximum pressure at the load `q > 0`, MPa.
    pub(crate) fn pressure(&self, q: f64) -> f64 {
        match self {
            RibLaw::Hertz { p0, .. } => p0 * q.cbrt(),
            RibLaw::Table(t) => t.pressure(q),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Knots of Hertz's law `Q = K δ^1.5`, `p = p0 Q^(1/3)`: the table reproduces it (a
    /// cubic in s) and its potential and derivative are those of the law.
    #[test]
    fn a_table_of_hertz_knots_reproduces_hertz() {
        let (k, p0) = (2.0e5, 300.0);
        let knots: Vec<(f64, f64, f64)> = (0..12)
            .map(|i| {
                let q = 10.0 * 2f64.powi(i);
                ((q / k).powf(2.0 / 3.0), q, p0 * q.cbrt())
            })
            .collect();
        let t = RibTable::from_knots(&knots).unwrap();
        let law = RibLaw::Hertz { k, p0 };
        for &d in &[1e-6, 3e-5, 1.7e-4, 5e-4, 2e-3, 1e-2] {
            let (q, dq, w) = t.eval(d);
            let (qh, dqh, wh) = law.eval(d, 1.0);
            assert!((q / qh - 1.0).abs() < 1e-3, "Q at {d}: {q} vs {qh}");
            assert!((dq / dqh - 1.0).abs() < 1e-3, "dQ at {d}: {dq} vs {dqh}");
            assert!((w / wh - 1.0).abs() < 1e-3, "W at {d}: {w} vs {wh}");
            assert!((t.pressure(q) / law.pressure(q) - 1.0).abs() < 1e-12);
        }
    }

    /// The derivative and the potential are those of the interpolant: central
    /// differences of W give Q, of Q give dQ/dδ, inside segments and past the ends.
    #[test]
    fn derivative_and_potential_are_consistent() {
        // a law that is not Hertz: Q = 1e5 δ^1.5 (1 + 30 δ^0.5)
        let f = |d: f64| 1e5 * d.powf(1.5) * (1.0 + 30.0 * d.sqrt());
        let knots: Vec<(f64, f64, f64)> = (0..10)
            .map(|i| {
                let d = 1e-5 * 1.8f64.powi(i);
                (d, f(d), 1000.0)
            })
            .collect();
        let t = RibTable::from_knots(&knots).unwrap();
        for &d in &[5e-6, 2.3e-5, 1.1e-4, 7e-4, 3e-3, 9e-3] {
            let h = 1e-6 * d;
            let (q, dq, _) = t.eval(d);
            let (qp, _, wp) = t.eval(d + h);
            let (qm, _, wm) = t.eval(d - h);
            assert!(((wp - wm) / (2.0 * h) / q - 1.0).abs() < 1e-6, "W' at {d}");
            assert!(((qp - qm) / (2.0 * h) / dq - 1.0).abs() < 1e-6, "Q' at {d}");
            if (1e-5..1.9e-3).contains(&d) {
                assert!((q / f(d) - 1.0).abs() < 2e-3, "Q at {d}: {q} vs {}", f(d));
            }
        }
        // monotone
        let mut last = 0.0;
        for i in 1..2000 {
            let q = t.eval(1e-6 * 1.005f64.powi(i)).0;
            assert!(q > last);
            last = q;
        }
    }

    /// The bench's TRB with the torus-cone-28 pairing (far from Hertz) and the PimP law:
    /// the condensed stiffness matches central differences of the solved load (the
    /// table's derivative is that of its force), at a combined load with a ring tilt.
    #[test]
    fn pimp_condensed_stiffness_matches_central_differences() {
        use crate::equilibrium::RingLoad;
        use crate::roller_equilibrium::{RibContact, RibContactSolver};
        let b = crate::roller_equilibrium::tests::trb();
        let spec = kontakt::bearing::RollerRibSpec::builtin("torus-cone-28").unwrap();
        let rc = RibContact {
            face: spec.face,
            rib: spec.rib,
            contact_height_mm: spec.contact_height,
        };
        let mut s = RibContactSolver::new(b, rc).unwrap();
        s.set_rib_model(RibModel::Pimp, &RibTableRange::default())
            .unwrap();
        let sol = s
            .solve(&RingLoad::forces([20_000.0, 5_000.0, 12_000.0, 0.0, 0.0]).with_tilts_held())
            .unwrap();
        assert!(sol.status.converged(), "{:?}", sol.status);
        let mut u = sol.displacement;
        u[3] = 2e-5;
        u[4] = -1e-5;
        crate::test_support::assert_stiffness_matches_central_differences(
            |u| s.load_at(u).unwrap(),
            u,
        );
    }

    #[test]
    fn bad_tables_are_named() {
        let e = RibTable::from_knots(&[(1e-4, 1.0, 1.0), (2e-4, 2.0, 1.0)]).unwrap_err();
        assert!(e.to_string().contains("rib_table.knots"), "{e}");
        let r = RibTableRange {
            knots: 2,
            ..RibTableRange::default()
        };
        assert!(
            r.validate()
                .unwrap_err()
                .to_string()
                .contains("rib_table.knots")
        );
    }
}
