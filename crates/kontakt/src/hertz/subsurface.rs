//! Subsurface stresses on the load axis of a Hertz contact, their peaks, and first yield.
//!
//! Below the centre of a frictionless Hertz contact the shear stresses on the planes
//! `x = 0`, `y = 0` vanish by symmetry, so the normal stresses `sigma_x`, `sigma_y`,
//! `sigma_z` on the load axis (`x = y = 0`, depth `z >= 0`) are the principal stresses.
//! This module gives them in closed form for
//!
//! - the circular contact (Huber 1904; Johnson 1982 eqs 20a/b): [`axis_stress_circular`],
//! - the elliptical contact (Thomas & Hoersch 1930; here in Carlson's symmetric integral
//!   $R_D$, derived from the Hertz potential, see `docs/subsurface.md`):
//!   [`axis_stress_elliptical`],
//! - the plane-strain line contact (McEwen 1949; Johnson, *Contact Mechanics* eq. 4.49):
//!   [`axis_stress_line`],
//!
//! the maximum Tresca shear stress and von Mises stress over depth with their depths
//! ([`axis_stress_peaks`], [`line_stress_peaks`]), and the maximum pressure at first yield
//! ([`yield_pressure_ratio`], [`line_yield_pressure_ratio`]) with the loads that follow
//! from it and Johnson's rounded closed forms (Johnson 1982 eqs 21a/b) for comparison.
//!
//! # Conventions
//! Crate conventions (mm, N, MPa, *tension positive*, so the stresses here are negative).
//! Elliptical contact: semi-axes `a >= b`, `x` along the major semi-axis `a`, `y` along
//! the minor semi-axis `b`, `z` the depth into the body. Line contact: half-width `b`
//! across the strip along `x` (as in [`crate::hertz::line`]), `y` along the cylinder axis.
//! So as `b/a -> 0` the elliptical `sigma_y` tends to the line `sigma_x` and the
//! elliptical `sigma_x` to the line `sigma_y`.
//!
//! # Assumptions
//! Linear elastic, isotropic, homogeneous half-space (contact size much smaller than the
//! radii), frictionless Hertz pressure $p = p_0\sqrt{1 - x^2/a^2 - y^2/b^2}$ (line:
//! $p_0\sqrt{1 - x^2/b^2}$, plane strain). The peaks are searched on the load axis only.
//! For ν ≥ 0 these are the maxima of the whole half-space (Johnson, *Contact Mechanics*
//! 1985 §3.4, §3.5, §4.2). For auxetic materials the contact edge can be worse (circle:
//! the surface shear (1−2ν)p0/3 at r = a exceeds the axis Tresca peak for ν < −0.13 and
//! the von Mises peak for ν < −0.35); the yield ratios are then upper bounds.
//!
//! # Performance
//! One stress evaluation costs two Carlson $R_D$ integrals (about 0.2 µs). A peak search
//! samples 17 depths and refines each candidate maximum by Brent's method on the
//! analytic depth derivative: about 7 µs in a release build (line contact 1.5 µs).
//!
//! # References
//! - Johnson, K. L. (1982) "One hundred years of Hertz contact", Proc. IMechE 196,
//!   363-378, eqs (14), (20a/b), (21a/b).
//! - Johnson, K. L. (1985) *Contact Mechanics*, Cambridge University Press, §3.2
//!   (Boussinesq potentials), §3.4 eq. (3.45) (Huber), §3.5 (elliptical contact, Thomas &
//!   Hoersch), §4.2 eq. (4.49) (line contact), §6.2 (onset of yield). Section and equation numbers
//!   of the book are those of the 1985 edition as cited in `docs/subsurface.md`.
//! - Huber, M. T. (1904) "Zur Theorie der Berührung fester elastischer Körper", Ann.
//!   Physik 14, 153-163.
//! - Thomas, H. R. & Hoersch, V. A. (1930) "Stresses due to the pressure of one elastic
//!   solid upon another", Univ. Illinois Eng. Exp. Station Bull. 212.
//! - Sackfield, A. & Hills, D. A. (1983) "Some useful results in the classical Hertz
//!   contact problem", J. Strain Anal. 18(2), 101-105.
//! - McEwen, E. (1949) "Stresses in elastic cylinders in contact along a generatrix",
//!   Phil. Mag. 40, 454-459.
//! - Carlson, B. C. (1995) "Numerical computation of real or complex elliptic integrals",
//!   Numer. Algorithms 10, 13-26; DLMF eq. 19.16.5 ($R_D$) and §19.21 (sum rule).

use crate::error::{Error, Result};
use crate::units::{Megapascal, Millimetre, Newton, NewtonPerMillimetre};
use std::f64::consts::PI;

/// Principal stresses on the load axis (`x = y = 0`) at one depth, with the Tresca and
/// von Mises equivalents. Stresses in MPa, tension positive.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
pub struct AxisStress {
    /// Depth `z` below the surface \[mm\] (>= 0).
    pub depth: Millimetre,
    /// Normal stress along `x` \[MPa\]: along the major semi-axis `a` (point contact), or
    /// across the strip (line contact).
    pub sigma_x: Megapascal,
    /// Normal stress along `y` \[MPa\]: along the minor semi-axis `b` (point contact), or
    /// along the cylinder axis (line contact, `nu (sigma_x + sigma_z)`).
    pub sigma_y: Megapascal,
    /// Normal stress along the depth direction `z` \[MPa\].
    pub sigma_z: Megapascal,
    /// Tresca maximum shear stress: half the largest principal stress difference \[MPa\].
    pub max_shear: Megapascal,
    /// Von Mises equivalent stress
    /// $\sqrt{((\sigma_x-\sigma_y)^2+(\sigma_y-\sigma_z)^2+(\sigma_z-\sigma_x)^2)/2}$ \[MPa\].
    pub von_mises: Megapascal,
}

/// Maxima over depth of the Tresca shear stress and of the von Mises stress on the load
/// axis, with the depths where they occur.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
pub struct StressPeaks {
    /// Largest Tresca maximum shear stress on the axis \[MPa\].
    pub max_shear: Megapascal,
    /// Depth of `max_shear` \[mm\].
    pub max_shear_depth: Millimetre,
    /// Largest von Mises stress on the axis \[MPa\].
    pub max_von_mises: Megapascal,
    /// Depth of `max_von_mises` \[mm\].
    pub max_von_mises_depth: Millimetre,
}

/// Yield criterion for first yield below a contact.
///
/// - `Tresca`: yield when the largest principal stress difference reaches the yield
///   stress `Y` in simple tension, i.e. when the maximum shear stress reaches `k = Y/2`.
/// - `VonMises`: yield when the von Mises stress reaches `Y` (`k = Y/sqrt(3)` in shear).
///
/// Serialized as `"tresca"` / `"von_mises"`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum YieldCriterion {
    /// Maximum shear stress criterion (Tresca 1864): `sigma_1 - sigma_3 = Y`.
    Tresca,
    /// Distortion energy criterion (von Mises 1913): `sigma_vM = Y`.
    VonMises,
}

// ---------------------------------------------------------------------------------------
// Input validation
// ---------------------------------------------------------------------------------------

fn check_pressure(p0: f64) -> Result<f64> {
    crate::error::positive_as("p0", p0, "a finite maximum pressure > 0 MPa")
}

fn check_length(field: &'static str, value: f64) -> Result<f64> {
    crate::error::positive_as(field, value, "a finite length > 0 mm")
}

fn check_semi_axes(a: f64, b: f64) -> Result<()> {
    check_length("a", a)?;
    check_length("b", b)?;
    if b > a {
        return Err(Error::invalid(
            "b",
            b,
            format!("0 < b <= a = {a} mm (b is the minor semi-axis)"),
        ));
    }
    Ok(())
}

fn check_nu(nu: f64) -> Result<f64> {
    if nu.is_finite() && nu > -1.0 && nu <= 0.5 {
        Ok(nu)
    } else {
        Err(Error::invalid("nu", nu, "-1 < nu <= 0.5"))
    }
}

fn check_depth(z: f64) -> Result<f64> {
    crate::error::non_negative("z", z)
}

// ---------------------------------------------------------------------------------------
// Dimensionless kernels
// ---------------------------------------------------------------------------------------

/// Principal stresses `[sigma_x, sigma_y, sigma_z] / p0` and their derivatives with respect
/// to depth, in the length unit of the caller.
#[derive(Debug, Clone, Copy)]
struct Sample {
    s: [f64; 3],
    ds: [f64; 3],
}

/// Tresca maximum shear and von Mises stress of three principal stresses.
fn equivalents(s: [f64; 3]) -> (f64, f64) {
    let d01 = s[0] - s[1];
    let d12 = s[1] - s[2];
    let d20 = s[2] - s[0];
    let dmax = d01.abs().max(d12.abs()).max(d20.abs());
    if dmax == 0.0 {
        return (0.0, 0.0);
    }
    // Scaled so that the squares neither overflow nor underflow.
    let (e01, e12, e20) = (d01 / dmax, d12 / dmax, d20 / dmax);
    let vm = dmax * (0.5 * (e01 * e01 + e12 * e12 + e20 * e20)).sqrt();
    (0.5 * dmax, vm)
}

fn axis_stress_from(depth: f64, p0: f64, s: [f64; 3]) -> Result<AxisStress> {
    let (tau, vm) = equivalents(s);
    let out = AxisStress {
        depth,
        sigma_x: p0 * s[0],
        sigma_y: p0 * s[1],
        sigma_z: p0 * s[2],
        max_shear: p0 * tau,
        von_mises: p0 * vm,
    };
    let all = [
        out.sigma_x,
        out.sigma_y,
        out.sigma_z,
        out.max_shear,
        out.von_mises,
    ];
    if all.iter().all(|v| v.is_finite()) {
        Ok(out)
    } else {
        Err(crate::error::overflow("p0", p0))
    }
}

/// $1 - \zeta\arctan(1/\zeta)$ without cancellation for large $\zeta$.
///
/// For $\zeta \ge 1$ Euler's series $\arctan u = \frac{u}{1+u^2}\sum_{n\ge0}
/// \frac{(2n)!!}{(2n+1)!!} t^n$, $t = u^2/(1+u^2) = 1/(1+\zeta^2)$, gives
/// $1 - \zeta\arctan(1/\zeta) = t - (1-t)\sum_{n\ge1} c_n t^n$ with $c_n = c_{n-1}\,2n/(2n+1)$.
fn one_minus_zeta_atan(zeta: f64) -> f64 {
    if zeta == 0.0 {
        return 1.0;
    }
    if zeta < 1.0 {
        return 1.0 - zeta * (1.0 / zeta).atan();
    }
    let t = 1.0 / (1.0 + zeta * zeta);
    if t == 0.0 {
        return 0.0;
    }
    let mut c = 1.0;
    let mut tn = 1.0;
    let mut sum = 0.0;
    for n in 1..200 {
        let nf = n as f64;
        c *= 2.0 * nf / (2.0 * nf + 1.0);
        tn *= t;
        let term = c * tn;
        sum += term;
        if term < 1e-17 * sum {
            break;
        }
    }
    t - (1.0 - t) * sum
}

/// Huber's on-axis stresses / p0 at depth `zeta = z/a`: `[sigma_r, sigma_r, sigma_z]`.
fn huber(nu: f64, zeta: f64) -> [f64; 3] {
    let t = 1.0 / (1.0 + zeta * zeta);
    let sr = -((1.0 + nu) * one_minus_zeta_atan(zeta) - 0.5 * t);
    [sr, sr, -t]
}

/// Above this ratio of the major semi-axis to `sqrt(b² + z²)` the Carlson integrals are
/// evaluated at the ratio `A_CAP`: the terms they enter change by O(ln(a)/a²) relative,
/// i.e. by nothing in `f64`, and `a²` cannot overflow.
const A_CAP: f64 = 1e100;

fn carlson_rd(x: f64, y: f64, z: f64) -> Result<f64> {
    ellip::elliprd(x, y, z).map_err(|_| Error::NotConverged {
        what: "Carlson R_D in hertz::subsurface".into(),
        iterations: 50,
        residual: f64::NAN,
    })
}

/// On-axis stresses / p0 of the elliptical Hertz contact and their depth derivatives.
///
/// Lengths `a >= b > 0`, `z >= 0` in any unit in which `b² + z²` neither overflows nor
/// underflows (the callers use `b = 1` or `b² + z² = 1`); `a` may be `+inf`.
/// With $A = a^2+z^2$, $B = b^2+z^2$, $m = ab/\sqrt{AB}$, $u = \sqrt{B/A}$,
/// $U_a = \tfrac23 ab\,R_D(z^2, B, A)$, $U_b = \tfrac23 ab\,R_D(z^2, A, B)$,
/// $T_0 = 2m - z(U_a + U_b)$ (see `docs/subsurface.md`):
///
/// $\sigma_x/p_0 = \tfrac12[-2\nu T_0 + 2(1-\nu) z U_a - (1-2\nu)\,2mu/(1+u)]$,
/// $\sigma_y/p_0 = \tfrac12[-2\nu T_0 + 2(1-\nu) z U_b - (1-2\nu)\,2m/(1+u)]$,
/// $\sigma_z/p_0 = -m$.
fn elliptical_sample(a: f64, b: f64, z: f64, nu: f64) -> Result<Sample> {
    let z2 = z * z;
    let bb = b * b + z2;
    let sb = bb.sqrt();
    // a / sqrt(A) and sqrt(B) / sqrt(A), both safe for a = +inf.
    let r = 1.0 / 1.0f64.hypot(z / a);
    let u = sb / a.hypot(z);
    let m = r * (b / sb);
    let a_c = a.min(A_CAP * sb);
    let aa_c = a_c * a_c + z2;
    let k = 2.0 / 3.0 * a_c * b;
    let ua = k * carlson_rd(z2, bb, aa_c)?;
    let ub = k * carlson_rd(z2, aa_c, bb)?;
    let t0 = 2.0 * m - z * (ua + ub);
    let la = 2.0 * m * u / (1.0 + u);
    let lb = 2.0 * m / (1.0 + u);
    let sx = 0.5 * (-2.0 * nu * t0 + 2.0 * (1.0 - nu) * z * ua - (1.0 - 2.0 * nu) * la);
    let sy = 0.5 * (-2.0 * nu * t0 + 2.0 * (1.0 - nu) * z * ub - (1.0 - 2.0 * nu) * lb);
    let sz = -m;
    // Depth derivatives (all elementary: d/dz of the R_D terms is their integrand).
    let ia = z / (a * a + z2); // z / A (0 for a = inf)
    let ib = z / bb; // z / B
    let dm = -m * (ia + ib);
    let dzua = ua - 2.0 * m * ia;
    let dzub = ub - 2.0 * m * ib;
    let dt0 = 2.0 * dm - dzua - dzub;
    let dla = -2.0 * m * ia;
    let dlb = -2.0 * m * ib;
    let dsx = 0.5 * (-2.0 * nu * dt0 + 2.0 * (1.0 - nu) * dzua - (1.0 - 2.0 * nu) * dla);
    let dsy = 0.5 * (-2.0 * nu * dt0 + 2.0 * (1.0 - nu) * dzub - (1.0 - 2.0 * nu) * dlb);
    Ok(Sample {
        s: [sx, sy, sz],
        ds: [dsx, dsy, -dm],
    })
}

/// On-axis stresses / p0 of the line contact at `zeta = z/b` and their derivatives
/// d/d(zeta): `[across the strip, along the cylinder axis, depth]`.
///
/// With $s = \sqrt{1+\zeta^2}$, $w = s + \zeta$ the McEwen stresses are written without
/// cancellation: $(1+2\zeta^2)/s - 2\zeta = (s-\zeta)^2/s = 1/(s w^2)$ and
/// $s - \zeta = 1/w$.
fn line_sample(zeta: f64, nu: f64) -> Sample {
    let s = 1.0f64.hypot(zeta);
    let w = s + zeta;
    let sx = -1.0 / (s * w * w);
    let sz = -1.0 / s;
    let sy = -2.0 * nu / w;
    let dsx = (zeta / s + 2.0) / (s * s * w * w);
    let dsz = zeta / (s * s * s);
    let dsy = 2.0 * nu / (s * w);
    Sample {
        s: [sx, sy, sz],
        ds: [dsx, dsy, dsz],
    }
}

// ---------------------------------------------------------------------------------------
// Peak search
// ---------------------------------------------------------------------------------------

/// Sampling grid of the peak search, in units of the minor semi-axis (half-width) `b`.
const GRID_STEP: f64 = 0.25;
const GRID_POINTS: usize = 17; // depths 0, 0.25 b, ..., 4 b

/// A smooth function of depth whose maximum is sought: the signed half difference of two
/// principal stresses, or the von Mises invariant J = sigma_vM².
#[derive(Debug, Clone, Copy)]
enum Branch {
    Pair(usize, usize, f64),
    Mises,
}

impl Branch {
    fn value(self, p: &Sample) -> f64 {
        match self {
            Branch::Pair(i, j, sign) => 0.5 * sign * (p.s[i] - p.s[j]),
            Branch::Mises => {
                let (_, vm) = equivalents(p.s);
                vm * vm
            }
        }
    }

    fn slope(self, p: &Sample) -> f64 {
        match self {
            Branch::Pair(i, j, sign) => 0.5 * sign * (p.ds[i] - p.ds[j]),
            Branch::Mises => {
                let s = p.s;
                let d = p.ds;
                (s[0] - s[1]) * (d[0] - d[1])
                    + (s[1] - s[2]) * (d[1] - d[2])
                    + (s[2] - s[0]) * (d[2] - d[0])
            }
        }
    }
}

/// Location and value of a maximum (dimensionless).
#[derive(Debug, Clone, Copy)]
struct Peak {
    depth: f64,
    value: f64,
}

fn not_converged(what: &'static str, iterations: usize, residual: f64) -> Error {
    Error::NotConverged {
        what: what.into(),
        iterations,
        residual,
    }
}

/// Brent's method (Brent 1973, ch. 4) for a root of `f` in `[a, b]` with
/// `f(a) > 0 > f(b)`; absolute tolerance `tol`.
fn brent_root(
    f: &mut impl FnMut(f64) -> Result<f64>,
    mut a: f64,
    mut b: f64,
    mut fa: f64,
    mut fb: f64,
    tol: f64,
) -> Result<f64> {
    let mut c = b;
    let mut fc = fb;
    let mut d = b - a;
    let mut e = d;
    for _ in 0..100 {
        if (fb > 0.0) == (fc > 0.0) && fb != 0.0 && fc != 0.0 {
            c = a;
            fc = fa;
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        let tol1 = 2.0 * f64::EPSILON * b.abs() + 0.5 * tol;
        let xm = 0.5 * (c - b);
        if xm.abs() <= tol1 || fb == 0.0 {
            return Ok(b);
        }
        if e.abs() >= tol1 && fa.abs() > fb.abs() {
            // Inverse quadratic interpolation or secant step.
            let s = fb / fa;
            let (mut p, mut q);
            if a == c {
                p = 2.0 * xm * s;
                q = 1.0 - s;
            } else {
                let qq = fa / fc;
                let rr = fb / fc;
                p = s * (2.0 * xm * qq * (qq - rr) - (b - a) * (rr - 1.0));
                q = (qq - 1.0) * (rr - 1.0) * (s - 1.0);
            }
            if p > 0.0 {
                q = -q;
            } else {
                p = -p;
            }
            if 2.0 * p < (3.0 * xm * q - (tol1 * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = xm;
                e = d;
            }
        } else {
            d = xm;
            e = d;
        }
        a = b;
        fa = fb;
        b += if d.abs() > tol1 { d } else { tol1.copysign(xm) };
        fb = f(b)?;
    }
    Err(not_converged(
        "Brent root of the stress slope",
        100,
        fb.abs(),
    ))
}

/// Samples per resampled cell, and how often a cell may be resampled (cell widths
/// 0.25 b, 1/64 b, 1/1024 b, 1/16384 b).
const LOCAL_POINTS: usize = 17;
const MAX_RESAMPLING: u32 = 3;

/// Whether the cubic Hermite interpolant of a cell (values `v0`, `v1`, slopes `d0`, `d1`,
/// width `h`) has an interior local maximum, i.e. whether its derivative, the quadratic
/// $q(s) = d_0 + (d_1-d_0)s + C s(1-s)$, $C = 6(\bar m - (d_0+d_1)/2)$, $\bar m$ the mean
/// slope, changes sign from + to − on `0 < s < 1`. Catches a maximum hidden between two
/// samples of equal slope sign (a dip and a bump within one cell).
fn hermite_has_max(v0: f64, v1: f64, d0: f64, d1: f64, h: f64) -> bool {
    let c = 6.0 * ((v1 - v0) / h - 0.5 * (d0 + d1));
    let q = |x: f64| d0 + (d1 - d0) * x + c * x * (1.0 - x);
    let mut pts = [0.0, 1.0, 1.0];
    if c != 0.0 {
        let vertex = (d1 - d0 + c) / (2.0 * c);
        if vertex > 0.0 && vertex < 1.0 {
            pts[1] = vertex;
        }
    }
    pts.windows(2).any(|w| q(w[0]) > 0.0 && q(w[1]) <= 0.0)
}

/// The maximum over depth of one smooth branch, from its samples `(zs, ps)` (ascending
/// depths; `zs[0] = 0` for the top-level grid, `level = 0`).
///
/// Every cell whose end slopes change sign from + to − brackets a maximum, located by
/// Brent's method on the analytic slope. A cell whose Hermite interpolant shows a hidden
/// maximum (a dip and a bump within one cell, as near the surface for ν < 0) is resampled
/// and searched again. A decreasing start at the surface is a maximum at `z = 0`; a
/// branch still rising at the deepest sample is followed deeper. The result is never below
/// the best sample.
fn branch_max(
    eval: &impl Fn(f64) -> Result<Sample>,
    zs: &[f64],
    ps: &[Sample],
    branch: Branch,
    level: u32,
) -> Result<Peak> {
    let n = zs.len();
    let mut best = Peak {
        depth: zs[0],
        value: branch.value(&ps[0]),
    };
    for (z, p) in zs.iter().zip(ps.iter()).skip(1) {
        let v = branch.value(p);
        if v > best.value {
            best = Peak {
                depth: *z,
                value: v,
            };
        }
    }
    let mut slope = |z: f64| -> Result<f64> { Ok(branch.slope(&eval(z)?)) };
    let consider = |depth: f64, best: &mut Peak| -> Result<()> {
        let value = branch.value(&eval(depth)?);
        if value > best.value {
            *best = Peak { depth, value };
        }
        Ok(())
    };
    for i in 0..n - 1 {
        let (z0, z1) = (zs[i], zs[i + 1]);
        let (d0, d1) = (branch.slope(&ps[i]), branch.slope(&ps[i + 1]));
        if d0 > 0.0 && d1 <= 0.0 {
            let depth = if d1 == 0.0 {
                z1
            } else {
                brent_root(&mut slope, z0, z1, d0, d1, 1e-13 * z1.max(1.0))?
            };
            consider(depth, &mut best)?;
        } else if level < MAX_RESAMPLING
            && hermite_has_max(
                branch.value(&ps[i]),
                branch.value(&ps[i + 1]),
                d0,
                d1,
                z1 - z0,
            )
        {
            let h = (z1 - z0) / (LOCAL_POINTS - 1) as f64;
            let mut fine_z = [0.0; LOCAL_POINTS];
            let mut fine_p = [Sample {
                s: [0.0; 3],
                ds: [0.0; 3],
            }; LOCAL_POINTS];
            for (j, (fz, fp)) in fine_z.iter_mut().zip(fine_p.iter_mut()).enumerate() {
                *fz = if j + 1 == LOCAL_POINTS {
                    z1
                } else {
                    z0 + j as f64 * h
                };
                *fp = eval(*fz)?;
            }
            let p = branch_max(eval, &fine_z, &fine_p, branch, level + 1)?;
            if p.value > best.value {
                best = p;
            }
        }
    }
    let d_last = branch.slope(&ps[n - 1]);
    let v_last = branch.value(&ps[n - 1]);
    if level == 0 && d_last > 0.0 && v_last >= best.value - 0.1 * best.value.abs() {
        // Still rising near its best value at the deepest sample: march deeper until the
        // slope turns. (All stresses decay like 1/z² at depth, so a branch that is far
        // below its best at 4 b cannot come back; see docs/subsurface.md.)
        let mut lo = zs[n - 1];
        let mut s_lo = d_last;
        let mut step = GRID_STEP;
        while lo < 1e6 {
            let hi = lo + step;
            let s_hi = slope(hi)?;
            if s_hi <= 0.0 {
                let depth = if s_hi == 0.0 {
                    hi
                } else {
                    brent_root(&mut slope, lo, hi, s_lo, s_hi, 1e-13 * hi)?
                };
                consider(depth, &mut best)?;
                break;
            }
            lo = hi;
            s_lo = s_hi;
            step *= 2.0;
        }
    }
    Ok(best)
}

/// Dimensionless peaks `(tresca, von_mises)`: depths in units of `b`, stresses / p0.
fn find_peaks(eval: impl Fn(f64) -> Result<Sample>) -> Result<(Peak, Peak)> {
    let mut zs = [0.0; GRID_POINTS];
    let mut grid = [Sample {
        s: [0.0; 3],
        ds: [0.0; 3],
    }; GRID_POINTS];
    for i in 0..GRID_POINTS {
        zs[i] = i as f64 * GRID_STEP;
        grid[i] = eval(zs[i])?;
    }

    // Tresca: the maximum of max_pairs |s_i - s_j| / 2 is the largest of the maxima of the
    // six smooth signed branches ±(s_i - s_j) / 2, each refined separately (so that kinks
    // where the ordering of the principal stresses changes do not matter). A branch more
    // than 10 % below the best grid value cannot win (the grid resolves the branches to
    // far better than that).
    let signed_grid_max = |i: usize, j: usize, sign: f64| -> f64 {
        grid.iter()
            .map(|g| 0.5 * sign * (g.s[i] - g.s[j]))
            .fold(f64::NEG_INFINITY, f64::max)
    };
    let branches = [
        (0, 2, 1.0),
        (0, 2, -1.0),
        (1, 2, 1.0),
        (1, 2, -1.0),
        (0, 1, 1.0),
        (0, 1, -1.0),
    ];
    let grid_best = branches
        .iter()
        .map(|&(i, j, sign)| signed_grid_max(i, j, sign))
        .fold(0.0, f64::max);
    let mut tresca = Peak {
        depth: 0.0,
        value: 0.0,
    };
    for &(i, j, sign) in &branches {
        let gm = signed_grid_max(i, j, sign);
        if gm <= 0.0 || gm < 0.9 * grid_best {
            continue;
        }
        let p = branch_max(&eval, &zs, &grid, Branch::Pair(i, j, sign), 0)?;
        if p.value > tresca.value {
            tresca = p;
        }
    }

    let j = branch_max(&eval, &zs, &grid, Branch::Mises, 0)?;
    let mises = Peak {
        depth: j.depth,
        value: j.value.max(0.0).sqrt(),
    };
    Ok((tresca, mises))
}

fn peaks_from(p0: f64, length: f64, tresca: Peak, mises: Peak) -> Result<StressPeaks> {
    let out = StressPeaks {
        max_shear: p0 * tresca.value,
        max_shear_depth: length * tresca.depth,
        max_von_mises: p0 * mises.value,
        max_von_mises_depth: length * mises.depth,
    };
    if out.max_shear.is_finite() && out.max_von_mises.is_finite() {
        Ok(out)
    } else {
        Err(crate::error::overflow("p0", p0))
    }
}

// ---------------------------------------------------------------------------------------
// Public API
// ---------------------------------------------------------------------------------------

/// Stresses on the axis of a circular Hertz contact (Huber 1904).
///
/// $$\frac{\sigma_r}{p_0} = \frac{\sigma_\theta}{p_0} = -(1+\nu)\left[1 - \frac{z}{a}
/// \arctan\frac{a}{z}\right] + \frac{1}{2}\left(1 + \frac{z^2}{a^2}\right)^{-1},\qquad
/// \frac{\sigma_z}{p_0} = -\left(1 + \frac{z^2}{a^2}\right)^{-1}.$$
///
/// At `z = 0` the limit $z\arctan(a/z) \to 0$ is taken exactly: $\sigma_r = -(1+2\nu)p_0/2$,
/// $\sigma_z = -p_0$. For $z > a$ the bracket is evaluated by Euler's series for the
/// arctangent, so it keeps full relative precision at any depth.
///
/// # Arguments
/// - `p0` — $p_0$, maximum contact pressure \[MPa\], finite, > 0.
/// - `a` — contact radius \[mm\], finite, > 0.
/// - `nu` — Poisson's ratio of the body, −1 < ν ≤ 0.5.
/// - `z` — depth below the surface \[mm\], finite, ≥ 0.
///
/// # Returns
/// [`AxisStress`] with `sigma_x = sigma_y = sigma_r` \[MPa\].
///
/// # Errors
/// [`Error::InvalidInput`] naming `p0`, `a`, `nu` or `z` when out of range or not finite
/// (also `p0` when the stresses would overflow `f64`).
///
/// # Assumptions
/// Linear elastic isotropic half-space, frictionless Hertz pressure, $a \ll R$.
///
/// # Example
/// Steel (ν = 0.3) at half the contact radius below the surface:
/// ```
/// use kontakt::hertz::subsurface::axis_stress_circular;
/// let s = axis_stress_circular(1000.0, 1.0, 0.3, 0.5)?;
/// assert!((s.sigma_z + 800.0).abs() < 1e-9);          // -p0 / (1 + 0.25)
/// assert!((s.sigma_x + 180.353).abs() < 1e-3);
/// assert!((s.max_shear - 309.823).abs() < 1e-3);       // close to the peak 0.310 p0
/// # Ok::<(), kontakt::Error>(())
/// ```
///
/// # References
/// - Huber (1904), Ann. Physik 14, 153-163.
/// - Johnson (1982) eqs (20a/b) (the printed sign of the last term of 20a is a misprint:
///   it must be `-1/2 (1+z²/a²)⁻¹` inside the bracket so that σr(0) = −(1+2ν)p0/2).
/// - Johnson, *Contact Mechanics* (1985) §3.4, eq. (3.45).
pub fn axis_stress_circular(p0: f64, a: f64, nu: f64, z: f64) -> Result<AxisStress> {
    check_pressure(p0)?;
    check_length("a", a)?;
    check_nu(nu)?;
    check_depth(z)?;
    axis_stress_from(z, p0, huber(nu, z / a))
}

/// Stresses on the axis of an elliptical Hertz contact (Thomas & Hoersch 1930), in closed
/// form with Carlson's integral $R_D$.
///
/// With $A = a^2+z^2$, $B = b^2+z^2$, $m = ab/\sqrt{AB}$, $u = \sqrt{B/A}$ and
/// $U_a = \tfrac23 ab\,R_D(z^2,B,A)$, $U_b = \tfrac23 ab\,R_D(z^2,A,B)$,
/// $T_0 = 2m - z(U_a+U_b)$:
///
/// $$\frac{\sigma_x}{p_0} = -\nu T_0 + (1-\nu)\,zU_a - (1-2\nu)\frac{m u}{1+u},\qquad
/// \frac{\sigma_y}{p_0} = -\nu T_0 + (1-\nu)\,zU_b - (1-2\nu)\frac{m}{1+u},\qquad
/// \frac{\sigma_z}{p_0} = -m.$$
///
/// The form follows from Love's/Boussinesq's potential of the Hertz pressure
/// (derivation in `docs/subsurface.md`); it treats both semi-axes alike, is exact at
/// `z = 0` (via the sum rule $R_D(x,y,z)+R_D(y,z,x)+R_D(z,x,y) = 3/\sqrt{xyz}$), reduces to
/// Huber's result for `b = a` and to McEwen's line-contact result as `b/a -> 0`.
///
/// # Arguments
/// - `p0` — $p_0$, maximum contact pressure \[MPa\], finite, > 0.
/// - `a` — major semi-axis, along `x` \[mm\], finite, > 0.
/// - `b` — minor semi-axis, along `y` \[mm\], finite, 0 < b ≤ a.
/// - `nu` — Poisson's ratio of the body, −1 < ν ≤ 0.5.
/// - `z` — depth below the surface \[mm\], finite, ≥ 0.
///
/// # Returns
/// [`AxisStress`] \[MPa\]; `sigma_x` along the major axis, `sigma_y` along the minor axis.
///
/// # Errors
/// [`Error::InvalidInput`] naming `p0`, `a`, `b` (also when `b > a`), `nu` or `z`;
/// [`Error::NotConverged`] if an elliptic integral fails (not observed for valid input).
///
/// # Assumptions
/// Linear elastic isotropic half-space, frictionless Hertz pressure, contact small
/// compared with the radii of curvature.
///
/// # Example
/// An ellipse with b/a = 0.5 (ν = 0.3), at the depth of the maximum shear stress:
/// ```
/// use kontakt::hertz::subsurface::axis_stress_elliptical;
/// let s = axis_stress_elliptical(1.0, 2.0, 1.0, 0.3, 0.6306)?;
/// assert!((s.max_shear - 0.32414).abs() < 1e-5);
/// // b = a is Huber's circular contact:
/// let c = axis_stress_elliptical(1.0, 1.0, 1.0, 0.3, 0.5)?;
/// assert!((c.sigma_z + 0.8).abs() < 1e-14);
/// # Ok::<(), kontakt::Error>(())
/// ```
///
/// # References
/// - Thomas & Hoersch (1930), Univ. Illinois Eng. Exp. Station Bull. 212 (on-axis stresses).
/// - Sackfield & Hills (1983), J. Strain Anal. 18(2), 101-105 (full field, Legendre form).
/// - Johnson, *Contact Mechanics* (1985) §3.2 (potentials ψ1, ψ), §3.5 (elliptical contact).
/// - Carlson (1995); DLMF eq. 19.16.5 and §19.21.
pub fn axis_stress_elliptical(p0: f64, a: f64, b: f64, nu: f64, z: f64) -> Result<AxisStress> {
    check_pressure(p0)?;
    check_semi_axes(a, b)?;
    check_nu(nu)?;
    check_depth(z)?;
    // Work in the unit L = sqrt(b² + z²), so that b² + z² = 1: no overflow or underflow
    // for any finite input (a/L may overflow to +inf, which the kernel accepts).
    let big = b.max(z);
    let (bs, zs) = (b / big, z / big);
    let h = bs.hypot(zs);
    let sample = elliptical_sample(a / big / h, bs / h, zs / h, nu)?;
    axis_stress_from(z, p0, sample.s)
}

/// Stresses on the axis of a plane-strain Hertz line contact of half-width `b`
/// (McEwen 1949).
///
/// $$\frac{\sigma_x}{p_0} = -\frac{1}{b}\left[\frac{b^2+2z^2}{\sqrt{b^2+z^2}} - 2z\right],
/// \qquad \frac{\sigma_z}{p_0} = -\frac{b}{\sqrt{b^2+z^2}},\qquad
/// \sigma_y = \nu(\sigma_x + \sigma_z).$$
///
/// Evaluated without cancellation as $\sigma_x/p_0 = -1/(s w^2)$, $\sigma_y/p_0 = -2\nu/w$,
/// $\sigma_z/p_0 = -1/s$ with $s = \sqrt{1+\zeta^2}$, $w = s+\zeta$, $\zeta = z/b$.
///
/// # Arguments
/// - `p0` — $p_0$, maximum contact pressure \[MPa\], finite, > 0.
/// - `b` — half-width of the contact strip, along `x` \[mm\], finite, > 0.
/// - `nu` — Poisson's ratio of the body, −1 < ν ≤ 0.5.
/// - `z` — depth below the surface \[mm\], finite, ≥ 0.
///
/// # Returns
/// [`AxisStress`] \[MPa\]; `sigma_x` across the strip, `sigma_y` along the cylinder axis.
///
/// # Errors
/// [`Error::InvalidInput`] naming `p0`, `b`, `nu` or `z`.
///
/// # Assumptions
/// Plane strain (long contact, far from its ends), linear elastic isotropic half-space,
/// frictionless Hertz pressure, $b \ll R$.
///
/// # Example
/// At the depth of the maximum shear stress, 0.786 b:
/// ```
/// use kontakt::hertz::subsurface::axis_stress_line;
/// let s = axis_stress_line(1000.0, 0.1, 0.3, 0.0786)?;
/// assert!((s.max_shear - 300.283).abs() < 1e-3);
/// assert!((s.sigma_y - 0.3 * (s.sigma_x + s.sigma_z)).abs() < 1e-9);
/// # Ok::<(), kontakt::Error>(())
/// ```
///
/// # References
/// - McEwen (1949), Phil. Mag. 40, 454-459.
/// - Johnson, *Contact Mechanics* (1985) §4.2, eq. (4.49).
pub fn axis_stress_line(p0: f64, b: f64, nu: f64, z: f64) -> Result<AxisStress> {
    check_pressure(p0)?;
    check_length("b", b)?;
    check_nu(nu)?;
    check_depth(z)?;
    axis_stress_from(z, p0, line_sample(z / b, nu).s)
}

/// Maximum Tresca shear stress and maximum von Mises stress on the axis of an elliptical
/// (or, with `b = a`, circular) Hertz contact, and their depths.
///
/// $$\tau_{\max} = \max_{z\ge0}\tfrac12\max_{i,j}|\sigma_i-\sigma_j|,\qquad
/// \sigma_{vM,\max} = \max_{z\ge0}\sqrt{\tfrac12\textstyle\sum(\sigma_i-\sigma_j)^2}$$
/// with the stresses of [`axis_stress_elliptical`].
///
/// Search: 17 samples on `0 <= z <= 4 b`, separately for each smooth branch (the six
/// signed principal-stress differences and the von Mises invariant): every cell whose
/// end slopes (analytic depth derivatives) change from + to − is solved by Brent's method
/// on the slope to about 1e-13 b; a cell whose cubic Hermite interpolant hides a maximum
/// is resampled (up to three times); a decreasing start is a maximum at the surface
/// (e.g. for strongly negative ν); a branch still rising at 4 b is followed deeper.
/// Values are exact to rounding (~1e-15 relative).
///
/// # Arguments
/// - `p0` — maximum contact pressure \[MPa\], finite, > 0.
/// - `a` — major semi-axis \[mm\], finite, > 0.
/// - `b` — minor semi-axis \[mm\], finite, 0 < b ≤ a.
/// - `nu` — Poisson's ratio, −1 < ν ≤ 0.5.
///
/// # Returns
/// [`StressPeaks`]: stresses \[MPa\], depths \[mm\].
///
/// # Errors
/// [`Error::InvalidInput`] naming `p0`, `a`, `b` or `nu`; [`Error::NotConverged`] if the
/// search fails (not observed for valid input).
///
/// # Assumptions
/// As [`axis_stress_elliptical`]. Only the load axis is searched: for ν ≥ 0 the maxima of
/// the frictionless Hertz field lie there; for strongly negative ν the contact edge can be
/// more critical (see the module docs).
///
/// # Example
/// Circular contact, ν = 0.3: τmax = 0.310 p0 at z = 0.481 a (Johnson, *Contact
/// Mechanics*: 0.31 p0 at 0.48 a):
/// ```
/// use kontakt::hertz::subsurface::axis_stress_peaks;
/// let p = axis_stress_peaks(1.0, 1.0, 1.0, 0.3)?;
/// assert!((p.max_shear - 0.3100).abs() < 1e-4);
/// assert!((p.max_shear_depth - 0.4809).abs() < 1e-4);
/// assert!((p.max_von_mises - 0.6200).abs() < 1e-4);   // = 2 tau_max: sigma_r = sigma_theta
/// # Ok::<(), kontakt::Error>(())
/// ```
///
/// # References
/// - Johnson (1982) §3 (eqs 20a/b and text); Johnson, *Contact Mechanics* (1985) §3.4,
///   §3.5, §6.2.
/// - Thomas & Hoersch (1930).
pub fn axis_stress_peaks(p0: f64, a: f64, b: f64, nu: f64) -> Result<StressPeaks> {
    check_pressure(p0)?;
    check_semi_axes(a, b)?;
    check_nu(nu)?;
    let ratio = a / b; // >= 1, may be +inf for absurd aspect ratios
    let (t, m) = find_peaks(|zeta| elliptical_sample(ratio, 1.0, zeta, nu))?;
    peaks_from(p0, b, t, m)
}

/// Maximum Tresca shear stress and maximum von Mises stress on the axis of a plane-strain
/// Hertz line contact of half-width `b`, and their depths.
///
/// Same search as [`axis_stress_peaks`] on the stresses of [`axis_stress_line`]
/// (`sigma_y = nu (sigma_x + sigma_z)` enters both criteria).
///
/// # Arguments
/// - `p0` — maximum contact pressure \[MPa\], finite, > 0.
/// - `b` — half-width of the contact strip \[mm\], finite, > 0.
/// - `nu` — Poisson's ratio, −1 < ν ≤ 0.5.
///
/// # Returns
/// [`StressPeaks`]: stresses \[MPa\], depths \[mm\].
///
/// # Errors
/// [`Error::InvalidInput`] naming `p0`, `b` or `nu`.
///
/// # Assumptions
/// Plane strain, linear elastic isotropic half-space, frictionless Hertz pressure.
///
/// # Example
/// τmax = 0.300 p0 at z = 0.786 b (Johnson, *Contact Mechanics* §4.2):
/// ```
/// use kontakt::hertz::subsurface::line_stress_peaks;
/// let p = line_stress_peaks(1.0, 1.0, 0.3)?;
/// assert!((p.max_shear - 0.3003).abs() < 1e-4);
/// assert!((p.max_shear_depth - 0.7862).abs() < 1e-4);
/// assert!((p.max_von_mises - 0.5575).abs() < 1e-4);   // at z = 0.704 b
/// # Ok::<(), kontakt::Error>(())
/// ```
///
/// # References
/// - McEwen (1949); Johnson, *Contact Mechanics* (1985) §4.2, eq. (4.49).
pub fn line_stress_peaks(p0: f64, b: f64, nu: f64) -> Result<StressPeaks> {
    check_pressure(p0)?;
    check_length("b", b)?;
    check_nu(nu)?;
    let (t, m) = find_peaks(|zeta| Ok(line_sample(zeta, nu)))?;
    peaks_from(p0, b, t, m)
}

fn ratio_from(tresca: Peak, mises: Peak, criterion: YieldCriterion) -> Result<f64> {
    // Equivalent stress per unit p0 at the critical point: 2 tau_max (Tresca) or sigma_vM.
    let eq = match criterion {
        YieldCriterion::Tresca => 2.0 * tresca.value,
        YieldCriterion::VonMises => mises.value,
    };
    if eq > 0.0 && eq.is_finite() {
        Ok(1.0 / eq)
    } else {
        Err(not_converged("equivalent stress peak", 0, eq))
    }
}

/// Maximum contact pressure at first yield over the yield stress, $p_{0Y}/Y$, for an
/// elliptical (or circular) Hertz contact.
///
/// $$\frac{p_{0Y}}{Y} = \frac{1}{2\,\tau_{\max}/p_0}\ \text{(Tresca)},\qquad
/// \frac{p_{0Y}}{Y} = \frac{1}{\sigma_{vM,\max}/p_0}\ \text{(von Mises)},$$
/// with the peaks of [`axis_stress_peaks`]. Circular contact, ν = 0.3: 1.613 by both
/// criteria (on the axis σr = σθ, so σvM = 2τ exactly); Johnson rounds this to 1.60 Y.
///
/// # Arguments
/// - `b_over_a` — axis ratio b/a of the contact ellipse, 0 < b/a ≤ 1 (1: circle; for a
///   line contact use [`line_yield_pressure_ratio`]).
/// - `nu` — Poisson's ratio of the yielding body, −1 < ν ≤ 0.5.
/// - `criterion` — [`YieldCriterion`].
///
/// # Returns
/// $p_{0Y}/Y$ \[-\].
///
/// # Errors
/// [`Error::InvalidInput`] naming `b_over_a` or `nu`.
///
/// # Assumptions
/// As [`axis_stress_peaks`] (valid as the first-yield load for ν ≥ 0; an upper bound for
/// strongly negative ν); yield starts where the equivalent stress first reaches `Y`
/// (elastic-perfectly plastic material, no residual stress).
///
/// # Example
/// ```
/// use kontakt::hertz::subsurface::{yield_pressure_ratio, YieldCriterion};
/// let t = yield_pressure_ratio(1.0, 0.3, YieldCriterion::Tresca)?;
/// let m = yield_pressure_ratio(1.0, 0.3, YieldCriterion::VonMises)?;
/// assert!((t - 1.6128).abs() < 1e-4);
/// assert!((m - 1.6128).abs() < 1e-4);   // equal: sigma_r = sigma_theta on the axis
/// # Ok::<(), kontakt::Error>(())
/// ```
///
/// # References
/// - Johnson (1982) eq. (21a) and text; Johnson, *Contact Mechanics* (1985) §6.2.
pub fn yield_pressure_ratio(b_over_a: f64, nu: f64, criterion: YieldCriterion) -> Result<f64> {
    if !(b_over_a.is_finite() && b_over_a > 0.0 && b_over_a <= 1.0) {
        return Err(Error::invalid(
            "b_over_a",
            b_over_a,
            "0 < b/a <= 1 (use line_yield_pressure_ratio for a line contact)",
        ));
    }
    check_nu(nu)?;
    let (t, m) = find_peaks(|zeta| elliptical_sample(1.0 / b_over_a, 1.0, zeta, nu))?;
    ratio_from(t, m, criterion)
}

/// Maximum contact pressure at first yield over the yield stress, $p_{0Y}/Y$, for a
/// plane-strain Hertz line contact.
///
/// $p_{0Y}/Y = 1/(2\tau_{\max}/p_0)$ (Tresca) or $1/(\sigma_{vM,\max}/p_0)$ (von Mises)
/// with the peaks of [`line_stress_peaks`]. ν = 0.3: 1.665 (Tresca, Johnson: 1.67),
/// 1.794 (von Mises, Johnson: 1.79).
///
/// # Arguments
/// - `nu` — Poisson's ratio of the yielding body, −1 < ν ≤ 0.5.
/// - `criterion` — [`YieldCriterion`].
///
/// # Returns
/// $p_{0Y}/Y$ \[-\].
///
/// # Errors
/// [`Error::InvalidInput`] naming `nu`.
///
/// # Assumptions
/// As [`line_stress_peaks`]; elastic-perfectly plastic material, no residual stress.
///
/// # Example
/// ```
/// use kontakt::hertz::subsurface::{line_yield_pressure_ratio, YieldCriterion};
/// let t = line_yield_pressure_ratio(0.3, YieldCriterion::Tresca)?;
/// let m = line_yield_pressure_ratio(0.3, YieldCriterion::VonMises)?;
/// assert!((t - 1.6651).abs() < 1e-4);
/// assert!((m - 1.7937).abs() < 1e-4);
/// # Ok::<(), kontakt::Error>(())
/// ```
///
/// # References
/// - Johnson (1982) eq. (21b); Johnson, *Contact Mechanics* (1985) §4.2.
pub fn line_yield_pressure_ratio(nu: f64, criterion: YieldCriterion) -> Result<f64> {
    check_nu(nu)?;
    let (t, m) = find_peaks(|zeta| Ok(line_sample(zeta, nu)))?;
    ratio_from(t, m, criterion)
}

fn finite_load(v: f64, r_eff: f64, e_star: f64, y: f64) -> Result<f64> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(Error::invalid(
            "r_eff, e_star, y",
            format!("({r_eff}, {e_star}, {y})"),
            "values for which the load is a finite f64 > 0",
        ))
    }
}

/// Johnson's closed form for the normal load at first yield of a circular (sphere)
/// contact: $P_Y = 21\,R^2 Y^3/E^{*2}$.
///
/// The constant 21 is $\pi^3 (1.60)^3/6$ with Johnson's $p_{0Y} = 1.60\,Y$ (ν ≈ 0.3); the
/// exact load for any ν and criterion is [`first_yield_load_circular`].
///
/// # Arguments
/// - `r_eff` — effective radius of relative curvature R \[mm\], finite, > 0.
/// - `e_star` — contact modulus E* \[MPa\], finite, > 0.
/// - `y` — yield stress in simple tension Y \[MPa\], finite, > 0.
///
/// # Returns
/// $P_Y$ \[N\].
///
/// # Errors
/// [`Error::InvalidInput`] naming `r_eff`, `e_star` or `y` (or all three if the load
/// overflows).
///
/// # Assumptions
/// Circular Hertz contact, ν ≈ 0.3, first yield below the surface.
///
/// # Example
/// Steel ball R = 6.35 mm on a flat, E* = 115 385 MPa, Y = 1500 MPa:
/// ```
/// use kontakt::hertz::subsurface::first_yield_load_circular_johnson;
/// let p = first_yield_load_circular_johnson(6.35, 115_384.6, 1500.0)?;
/// assert!((p - 214.66).abs() < 0.01);   // N
/// # Ok::<(), kontakt::Error>(())
/// ```
///
/// # References
/// - Johnson (1982) eq. (21a); Johnson, *Contact Mechanics* (1985) §6.2.
pub fn first_yield_load_circular_johnson(r_eff: f64, e_star: f64, y: f64) -> Result<Newton> {
    crate::error::positive("r_eff", r_eff)?;
    crate::error::positive("e_star", e_star)?;
    crate::error::positive("y", y)?;
    finite_load(
        21.0 * r_eff * r_eff * (y / e_star) * (y / e_star) * y,
        r_eff,
        e_star,
        y,
    )
}

/// Johnson's closed form for the line load at first yield of a line (cylinder) contact:
/// $P'_Y = 8.8\,R\,Y^2/E^*$ \[N/mm\].
///
/// The constant 8.8 is $\pi (1.67)^2$ with the Tresca value $p_{0Y} = 1.67\,Y$; the
/// von Mises value $p_{0Y} = 1.79\,Y$ gives 10.1 instead. The exact load for any ν and
/// criterion is [`first_yield_line_load`].
///
/// # Arguments
/// - `r_eff` — effective radius of relative curvature R \[mm\], finite, > 0.
/// - `e_star` — contact modulus E* \[MPa\], finite, > 0.
/// - `y` — yield stress in simple tension Y \[MPa\], finite, > 0.
///
/// # Returns
/// $P'_Y$ \[N/mm\].
///
/// # Errors
/// [`Error::InvalidInput`] naming `r_eff`, `e_star` or `y`.
///
/// # Assumptions
/// Plane-strain line contact, ν ≈ 0.3, Tresca.
///
/// # Example
/// ```
/// use kontakt::hertz::subsurface::first_yield_line_load_johnson;
/// let p = first_yield_line_load_johnson(10.0, 115_384.6, 1500.0)?;
/// assert!((p - 1716.0).abs() < 0.1);  // N/mm
/// # Ok::<(), kontakt::Error>(())
/// ```
///
/// # References
/// - Johnson (1982) eq. (21b); Johnson, *Contact Mechanics* (1985) §4.2.
pub fn first_yield_line_load_johnson(
    r_eff: f64,
    e_star: f64,
    y: f64,
) -> Result<NewtonPerMillimetre> {
    crate::error::positive("r_eff", r_eff)?;
    crate::error::positive("e_star", e_star)?;
    crate::error::positive("y", y)?;
    finite_load(8.8 * r_eff * y * (y / e_star), r_eff, e_star, y)
}

/// Normal load at first yield of a circular (sphere) Hertz contact from the exact
/// [`yield_pressure_ratio`]:
/// $$P_Y = \frac{\pi^3 R^2 p_{0Y}^3}{6 E^{*2}},\qquad p_{0Y} = \frac{p_{0Y}}{Y}\,Y,$$
/// from $p_0 = (6 P E^{*2}/(\pi^3 R^2))^{1/3}$ (Johnson 1982 eq. 14).
///
/// # Arguments
/// - `r_eff` — effective radius R \[mm\], finite, > 0.
/// - `e_star` — contact modulus E* \[MPa\], finite, > 0.
/// - `y` — yield stress Y \[MPa\], finite, > 0.
/// - `nu` — Poisson's ratio of the yielding body, −1 < ν ≤ 0.5.
/// - `criterion` — [`YieldCriterion`].
///
/// # Returns
/// $P_Y$ \[N\].
///
/// # Errors
/// [`Error::InvalidInput`] naming the offending argument.
///
/// # Assumptions
/// As [`yield_pressure_ratio`] with b/a = 1.
///
/// # Example
/// For ν = 0.3 the exact $p_{0Y} = 1.6128\,Y$ gives $21.68\,R^2Y^3/E^{*2}$, 3.2 % above
/// Johnson's rounded 21 (which uses 1.60 Y):
/// ```
/// use kontakt::hertz::subsurface::{first_yield_load_circular, YieldCriterion};
/// let p = first_yield_load_circular(6.35, 115_384.6, 1500.0, 0.3, YieldCriterion::VonMises)?;
/// assert!((p - 221.60).abs() < 0.01);  // N; Johnson's eq. 21a: 214.66 N
/// assert!((p / 214.66 - 1.0).abs() < 0.035);
/// # Ok::<(), kontakt::Error>(())
/// ```
///
/// # References
/// - Johnson (1982) eqs (14), (21a).
pub fn first_yield_load_circular(
    r_eff: f64,
    e_star: f64,
    y: f64,
    nu: f64,
    criterion: YieldCriterion,
) -> Result<Newton> {
    crate::error::positive("r_eff", r_eff)?;
    crate::error::positive("e_star", e_star)?;
    crate::error::positive("y", y)?;
    let k = yield_pressure_ratio(1.0, nu, criterion)?;
    let q = k * y / e_star;
    finite_load(
        PI.powi(3) / 6.0 * r_eff * r_eff * q * q * (k * y),
        r_eff,
        e_star,
        y,
    )
}

/// Line load at first yield of a plane-strain line (cylinder) contact from the exact
/// [`line_yield_pressure_ratio`]:
/// $$P'_Y = \frac{\pi R\, p_{0Y}^2}{E^*},$$
/// from $p_0 = \sqrt{P'E^*/(\pi R)}$ (Johnson 1982 eq. 11).
///
/// # Arguments
/// - `r_eff` — effective radius R \[mm\], finite, > 0.
/// - `e_star` — contact modulus E* \[MPa\], finite, > 0.
/// - `y` — yield stress Y \[MPa\], finite, > 0.
/// - `nu` — Poisson's ratio of the yielding body, −1 < ν ≤ 0.5.
/// - `criterion` — [`YieldCriterion`].
///
/// # Returns
/// $P'_Y$ \[N/mm\].
///
/// # Errors
/// [`Error::InvalidInput`] naming the offending argument.
///
/// # Assumptions
/// As [`line_yield_pressure_ratio`].
///
/// # Example
/// Tresca reproduces Johnson's 8.8 R Y²/E* within 1.1 % (8.71 R Y²/E*):
/// ```
/// use kontakt::hertz::subsurface::{first_yield_line_load, YieldCriterion};
/// let p = first_yield_line_load(10.0, 115_384.6, 1500.0, 0.3, YieldCriterion::Tresca)?;
/// assert!((p - 1698.49).abs() < 0.01);   // N/mm; eq. 21b: 1716.0 N/mm
/// assert!((p / 1716.0 - 1.0).abs() < 0.015);
/// # Ok::<(), kontakt::Error>(())
/// ```
///
/// # References
/// - Johnson (1982) eqs (11), (21b).
pub fn first_yield_line_load(
    r_eff: f64,
    e_star: f64,
    y: f64,
    nu: f64,
    criterion: YieldCriterion,
) -> Result<NewtonPerMillimetre> {
    crate::error::positive("r_eff", r_eff)?;
    crate::error::positive("e_star", e_star)?;
    crate::error::positive("y", y)?;
    let k = line_yield_pressure_ratio(nu, criterion)?;
    finite_load(PI * r_eff * (k * y) * (k * y / e_star), r_eff, e_star, y)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn euler_series_matches_direct_formula() {
        for z in [1.0f64, 1.5, 2.0, 4.0, 10.0] {
            let direct = 1.0 - z * (1.0 / z).atan();
            let series = one_minus_zeta_atan(z);
            // Direct evaluation loses ~log10(3 z²) digits; 1e-13 covers z <= 10.
            assert!((direct - series).abs() <= 1e-13 * series, "z = {z}");
        }
        // Asymptote 1/(3 z²) - 1/(5 z⁴).
        let z = 1e4f64;
        let asym = 1.0 / (3.0 * z * z) - 1.0 / (5.0 * z.powi(4));
        assert!((one_minus_zeta_atan(z) - asym).abs() <= 1e-15 * asym);
        assert_eq!(one_minus_zeta_atan(f64::INFINITY), 0.0);
    }

    #[test]
    fn slopes_match_finite_differences() {
        // Central differences with h = 1e-6: truncation ~1e-12, rounding ~1e-10.
        let h = 1e-6;
        for &(a, nu) in &[(1.0, 0.3), (2.0, 0.25), (5.0, 0.5), (1e3, -0.5)] {
            for &z in &[0.1, 0.5, 1.3, 3.0] {
                let p = elliptical_sample(a, 1.0, z, nu).expect("valid");
                let hi = elliptical_sample(a, 1.0, z + h, nu).expect("valid");
                let lo = elliptical_sample(a, 1.0, z - h, nu).expect("valid");
                for i in 0..3 {
                    let fd = (hi.s[i] - lo.s[i]) / (2.0 * h);
                    assert!((fd - p.ds[i]).abs() < 1e-8, "a={a} z={z} i={i}");
                }
                let l = line_sample(z, nu);
                let lh = line_sample(z + h, nu);
                let ll = line_sample(z - h, nu);
                for i in 0..3 {
                    let fd = (lh.s[i] - ll.s[i]) / (2.0 * h);
                    assert!((fd - l.ds[i]).abs() < 1e-8, "line z={z} i={i}");
                }
            }
        }
    }

    #[test]
    fn peak_search_agrees_with_dense_scan() {
        // A brute-force scan with step 1e-4 b finds the maxima to ~1e-8 relative (the
        // functions are quadratic near the maximum); the search must not be below it.
        for &(ratio, nu) in &[
            (1.0, 0.3),
            (2.0, 0.3),
            (10.0, 0.0),
            (1.0, -0.9),
            (1.0, 0.5),
            // Two von Mises maxima within the first grid cell (surface and z = 0.23 b).
            (1.0 / 0.474552, -0.32445),
            (1.0 / 0.5314410000000002, -0.421885),
        ] {
            let (t, m) = find_peaks(|z| elliptical_sample(ratio, 1.0, z, nu)).expect("valid");
            let mut tmax = 0.0f64;
            let mut vmax = 0.0f64;
            for i in 0..=60_000 {
                let z = i as f64 * 1e-4;
                let s = elliptical_sample(ratio, 1.0, z, nu).expect("valid").s;
                let (tau, vm) = equivalents(s);
                tmax = tmax.max(tau);
                vmax = vmax.max(vm);
            }
            assert!(
                t.value >= tmax - 1e-14 && t.value - tmax < 1e-8,
                "{ratio} {nu}"
            );
            assert!(
                m.value >= vmax - 1e-14 && m.value - vmax < 1e-8,
                "{ratio} {nu}"
            );
        }
    }

    #[test]
    fn brent_finds_simple_root() {
        let mut f = |x: f64| -> Result<f64> { Ok(2.0 - x * x) };
        let r = brent_root(&mut f, 0.0, 2.0, 2.0, -2.0, 1e-15).expect("converges");
        assert!((r - 2f64.sqrt()).abs() < 1e-14);
    }
}
