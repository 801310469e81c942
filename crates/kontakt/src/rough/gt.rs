//! Greenwood-Tripp (1967): a smooth elastic sphere pressed onto a nominally flat rough
//! surface (or two rough spheres reduced to that), solved numerically for the smoothed
//! pressure distribution.
//!
//! # Formulation
//! The rough surface is a Greenwood-Williamson layer ([`GreenwoodWilliamson`](super::GreenwoodWilliamson),
//! Gaussian summit heights of standard deviation $\sigma$, density $\eta$, tip radius
//! $\beta$) on an elastic half-space. At radius $r$ the mean plane of the summits and the
//! sphere are separated by
//!
//! $$g(r) = -d + \frac{r^2}{2R} + w(r),\qquad
//!   p(r) = \tfrac43\eta E^*\beta^{1/2}\sigma^{3/2}\,F_{3/2}\!\left(\frac{g(r)}{\sigma}\right),$$
//!
//! where $d$ is the approach (measured from the position at which the undeformed sphere
//! touches the mean summit plane), $w$ the combined elastic displacement of the smoothed
//! pressure (compliance $1/E^*$) and $P = 2\pi\int_0^\infty p\,r\,dr$.
//! The axisymmetric displacement is (Johnson 1985 eq. 3.96a)
//!
//! $$w(r) = \frac{4}{\pi E^*}\int_0^\infty p(s)\,\frac{s}{s+r}\,K(k)\,ds,\qquad
//!   k^2 = \frac{4rs}{(r+s)^2}.$$
//!
//! In Hertz units ($\rho = r/a_0$, $\hat p = p/p_0$, lengths over $\delta_0$; $a_0$,
//! $p_0 = 2E^*a_0/(\pi R)$ and $\delta_0 = a_0^2/R$ the smooth Hertz values at the same
//! load) the problem depends on two numbers only:
//!
//! $$\alpha = \frac{\sigma}{\delta_0} = \sigma\left(\frac{16E^{*2}R}{9P^2}\right)^{1/3},
//!   \qquad \mu = \tfrac83\,\eta\sigma\sqrt{2R\beta},$$
//!
//! $$\hat p = \frac{\pi\mu\sqrt\alpha}{4\sqrt2}\,F_{3/2}(\hat g),\quad
//!   \hat g = \frac{-\hat d + \rho^2/2 + \hat w}{\alpha},\quad
//!   \hat w = \frac{8}{\pi^2}\int_0^\infty \hat p(t)\frac{t}{t+\rho}K\,dt,\quad
//!   \int_0^\infty \rho\,\hat p\,d\rho = \tfrac13 .$$
//!
//! Johnson (1982) eq. (41) prints $\sigma(16E^*R/9P)^{1/3}$, which is not dimensionless:
//! the squares on $E^*$ and $P$ were lost. With $\delta_0 = (9P^2/(16RE^{*2}))^{1/3}$ the
//! definition $\alpha = \sigma/\delta_0 = \sigma R/a_0^2$ gives the form above.
//!
//! # Numerical method
//! Piecewise-linear pressure on a uniform radial grid of `nodes` intervals over
//! $[0, \rho_{max}]$; the displacement of each hat function at each node is integrated
//! once per solver (Carlson's $R_F$ for $K$, the 15-point Kronrod rule on regular elements,
//! tanh-sinh on the two elements with the logarithmic singularity) on a grid of unit
//! spacing and scaled by the spacing (the displacement is homogeneous of degree one in
//! length). The unknowns are the gaps $\hat g_i$ and the approach $\hat d$; Newton's
//! method with a backtracking line search solves the $N+2$ equations (gap equation at
//! each node, load balance) from the Hertz displacement as a start. The outer radius is
//! chosen so that $\hat g \ge 7$ beyond it ($F_{3/2}(7) \approx 2\times10^{-13}$, bounded
//! using $\hat w \ge 0$), and enlarged and solved again if the converged approach asks
//! for more. $F_{3/2}$ and $F_{1/2}$ come from a cubic Hermite table of $\ln F_n$
//! (1e-9 relative).
//!
//! # Assumptions
//! Those of GW for the asperities (no interaction except through the bulk), linear
//! elastic half-spaces, frictionless, $a_0 \ll R$; the statistical treatment needs many
//! summits within the contact (say $\eta\pi a_0^2 \gg 1$). The roughness $\sigma$ is the
//! standard deviation of the *summit* heights of the combined surface; Johnson uses the
//! combined rms roughness, a few tens of per cent larger for typical surfaces.
//!
//! # References
//! - Greenwood and Tripp (1967), "The elastic contact of rough spheres", J. Appl. Mech.
//!   34, 153-159. doi:10.1115/1.3607616
//! - Johnson (1982), "One hundred years of Hertz contact", Proc. IMechE 196, 363-378, §8,
//!   eq. (41), Fig. 12.
//! - Johnson, *Contact Mechanics* (1985), §13.4 and eq. (3.96a).

use super::heights::GaussTable;
use crate::error::{Error, Result, positive_as};
use crate::solve::{SolveStatus, Termination};
use crate::units::{Megapascal, Millimetre, Newton};
use nalgebra::{DMatrix, DVector};
use std::f64::consts::{PI, SQRT_2};

/// Standardised gap beyond which the pressure is negligible ($F_{3/2}(7) \approx 2\cdot10^{-13}$).
const G_CUT: f64 = 7.0;

/// Inputs of a Greenwood-Tripp solve.
/// Serialized but not deserialized: build it with [`new`](Self::new), which validates.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct GreenwoodTrippParams {
    load: Newton,
    radius: Millimetre,
    e_star: Megapascal,
    roughness: Millimetre,
    summit_density: f64,
    summit_radius: Millimetre,
}

impl GreenwoodTrippParams {
    /// A rough-sphere contact.
    ///
    /// # Arguments
    /// - `load` — $P$ \[N\], finite, > 0.
    /// - `radius` — sphere radius $R$ \[mm\] (relative radius of two spheres), finite, > 0.
    /// - `e_star` — contact modulus $E^*$ \[MPa\], finite, > 0.
    /// - `roughness` — $\sigma$, standard deviation of the summit heights of the combined
    ///   roughness \[mm\], finite, > 0.
    /// - `summit_density` — $\eta$ \[1/mm²\], finite, > 0.
    /// - `summit_radius` — $\beta$ \[mm\], finite, > 0.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the first argument out of range.
    pub fn new(
        load: Newton,
        radius: Millimetre,
        e_star: Megapascal,
        roughness: Millimetre,
        summit_density: f64,
        summit_radius: Millimetre,
    ) -> Result<Self> {
        positive_as("load", load, "a finite load > 0 N")?;
        positive_as("radius", radius, "a finite radius > 0 mm")?;
        positive_as("e_star", e_star, "a finite modulus > 0 MPa")?;
        positive_as("roughness", roughness, "a finite roughness > 0 mm")?;
        positive_as(
            "summit_density",
            summit_density,
            "a finite density > 0 per mm²",
        )?;
        positive_as("summit_radius", summit_radius, "a finite radius > 0 mm")?;
        let p = GreenwoodTrippParams {
            load,
            radius,
            e_star,
            roughness,
            summit_density,
            summit_radius,
        };
        let (a, b) = (p.alpha(), p.mu());
        if !(a.is_finite() && b.is_finite() && p.hertz_radius() > 0.0 && a > 0.0 && b > 0.0) {
            return Err(Error::invalid(
                "load",
                load,
                "inputs whose Hertz radius, alpha and mu are finite and > 0",
            ));
        }
        Ok(p)
    }

    /// Smooth Hertz contact radius $a_0 = (3PR/4E^*)^{1/3}$ \[mm\].
    pub fn hertz_radius(&self) -> Millimetre {
        (0.75 * self.load * self.radius / self.e_star).cbrt()
    }

    /// Smooth Hertz approach $\delta_0 = a_0^2/R = (9P^2/(16RE^{*2}))^{1/3}$ \[mm\].
    pub fn hertz_approach(&self) -> Millimetre {
        self.hertz_radius().powi(2) / self.radius
    }

    /// Smooth Hertz maximum pressure $p_0 = 2E^*a_0/(\pi R)$ \[MPa\].
    pub fn hertz_pressure(&self) -> Megapascal {
        2.0 * self.e_star * self.hertz_radius() / (PI * self.radius)
    }

    /// Johnson's roughness parameter $\alpha = \sigma/\delta_0 = \sigma R/a_0^2$ \[-\]
    /// (Johnson 1982 eq. 41 with its squares restored).
    pub fn alpha(&self) -> f64 {
        self.roughness / self.hertz_approach()
    }

    /// Greenwood and Tripp's second parameter $\mu = \tfrac83\eta\sigma\sqrt{2R\beta}$ \[-\].
    pub fn mu(&self) -> f64 {
        8.0 / 3.0
            * self.summit_density
            * self.roughness
            * (2.0 * self.radius * self.summit_radius).sqrt()
    }
}

/// Johnson's roughness parameter $\alpha = \sigma\,(16E^{*2}R/(9P^2))^{1/3}$ \[-\] for
/// load $P$ \[N\], radius $R$ \[mm\], contact modulus $E^*$ \[MPa\] and roughness
/// $\sigma$ \[mm\].
///
/// # Errors
/// [`Error::InvalidInput`] naming the first argument that is not finite and > 0.
///
/// # Example
/// ```
/// let alpha = kontakt::rough::roughness_parameter(100.0, 10.0, 115_000.0, 1e-4)?;
/// // δ0 = (9 P² / (16 R E*²))^(1/3)
/// let d0 = (9.0 * 1e4 / (16.0 * 10.0 * 115_000.0f64.powi(2))).cbrt();
/// assert!((alpha - 1e-4 / d0).abs() < 1e-12);
/// # Ok::<(), kontakt::Error>(())
/// ```
pub fn roughness_parameter(
    load: Newton,
    radius: Millimetre,
    e_star: Megapascal,
    roughness: Millimetre,
) -> Result<f64> {
    positive_as("load", load, "a finite load > 0 N")?;
    positive_as("radius", radius, "a finite radius > 0 mm")?;
    positive_as("e_star", e_star, "a finite modulus > 0 MPa")?;
    positive_as("roughness", roughness, "a finite roughness > 0 mm")?;
    let a = roughness * (16.0 * e_star * e_star * radius / (9.0 * load * load)).cbrt();
    if a.is_finite() && a > 0.0 {
        Ok(a)
    } else {
        Err(Error::invalid(
            "load",
            load,
            "a load for which alpha is finite and > 0",
        ))
    }
}

/// Numerical options of [`GreenwoodTripp`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
pub struct GreenwoodTrippOptions {
    /// Intervals of the radial grid, 16 to 2000 (default 64: grid-converged to about 1e-4 in p(0) and a*, see docs/rough.md).
    pub nodes: usize,
    /// Newton tolerance on the largest gap-equation residual (in units of $\delta_0$)
    /// and the relative load error (default 1e-10; 1e-14 to 1e-2).
    pub tolerance: f64,
    /// Most Newton iterations per grid (default 60).
    pub max_iterations: usize,
}

impl Default for GreenwoodTrippOptions {
    fn default() -> Self {
        GreenwoodTrippOptions {
            nodes: 64,
            tolerance: 1e-10,
            max_iterations: 60,
        }
    }
}

/// The Greenwood-Tripp solver: the displacement kernel of one grid, built once
/// (a few ms), then any number of solves (about 0.5 ms each with the default 64
/// intervals). Converges in 2-6 Newton steps for α from 1e-5 to 1e4 and μ from 0.1 to
/// 1000 (tested).
///
/// # Example
/// A steel ball of radius 10 mm under 100 N on a ground surface (σ = 1 µm summit
/// standard deviation, β = 20 µm, η = 2000 summits/mm²):
/// ```
/// use kontakt::rough::{GreenwoodTripp, GreenwoodTrippOptions, GreenwoodTrippParams};
/// let params = GreenwoodTrippParams::new(100.0, 10.0, 115_000.0, 1e-3, 2000.0, 0.02)?;
/// let solver = GreenwoodTripp::new(GreenwoodTrippOptions::default())?;
/// let s = solver.solve(&params)?;
/// assert!(s.status.converged());
/// assert!((s.alpha - 0.2865).abs() < 1e-4);          // σ/δ0: noticeably rough
/// assert!(s.centre_pressure < 0.85 * s.hertz_pressure); // MPa
/// assert!(s.effective_radius > 1.15 * s.hertz_radius);  // mm
/// assert!((s.load - 100.0).abs() < 1e-6);              // N
/// # Ok::<(), kontakt::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct GreenwoodTripp {
    options: GreenwoodTrippOptions,
    /// Displacement (Hertz units, grid spacing 1) at node i of the hat at node j.
    kernel: DMatrix<f64>,
    /// $\int \rho\,\phi_j\,d\rho$ on the unit grid (load weights).
    w1: Vec<f64>,
    /// $\int \rho^3\,\phi_j\,d\rho$ on the unit grid (second-moment weights).
    w3: Vec<f64>,
}

/// The smoothed pressure distribution of a Greenwood-Tripp solve.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
pub struct GreenwoodTrippSolution {
    /// Grid radii \[mm\], from 0 to the outer radius.
    pub radii: Vec<Millimetre>,
    /// Smoothed (nominal) pressure at `radii` \[MPa\]; piecewise linear in between, zero
    /// beyond.
    pub pressure: Vec<Megapascal>,
    /// $p(0)$ \[MPa\].
    pub centre_pressure: Megapascal,
    /// Approach $d$ \[mm\]: displacement of the sphere from first touching the mean
    /// summit plane (may be negative for very rough surfaces).
    pub approach: Millimetre,
    /// Effective radius $a^* = \sqrt{\tfrac52\langle r^2\rangle}$ \[mm\] with
    /// $\langle r^2\rangle = \int r^2 p\,dA/P$: the radius of the Hertz distribution with
    /// the same load and second moment (so $a^* = a_0$ for a smooth sphere).
    pub effective_radius: Millimetre,
    /// Radius of the circle that carries 95 % of the load \[mm\] (Hertz: $0.9297\,a_0$).
    pub radius_95: Millimetre,
    /// Smooth Hertz radius $a_0$ \[mm\].
    pub hertz_radius: Millimetre,
    /// Smooth Hertz maximum pressure $p_0$ \[MPa\].
    pub hertz_pressure: Megapascal,
    /// Smooth Hertz approach $\delta_0$ \[mm\].
    pub hertz_approach: Millimetre,
    /// $\alpha = \sigma/\delta_0$ \[-\].
    pub alpha: f64,
    /// $\mu = \tfrac83\eta\sigma\sqrt{2R\beta}$ \[-\].
    pub mu: f64,
    /// $2\pi\int p\,r\,dr$ of the returned distribution \[N\].
    pub load: Newton,
    /// How the Newton iteration ended; residual = max(gap residual / $\delta_0$, relative
    /// load error).
    pub status: SolveStatus,
}

/// Hertz displacement in units of $\delta_0$ at $\rho = r/a_0$.
fn hertz_displacement(rho: f64) -> f64 {
    if rho <= 1.0 {
        1.0 - 0.5 * rho * rho
    } else {
        ((2.0 - rho * rho) * (1.0 / rho).asin() + (rho * rho - 1.0).sqrt()) / PI
    }
}

/// Tanh-sinh nodes on [0, 1]: (distance from 0, distance from 1, weight).
fn tanh_sinh() -> Vec<(f64, f64, f64)> {
    let step = 1.0 / 16.0;
    let mut out = Vec::new();
    let mut k = -56i32;
    while k <= 56 {
        let t = k as f64 * step;
        let u = 0.5 * PI * t.sinh();
        let from0 = 1.0 / (1.0 + (-2.0 * u).exp());
        let from1 = 1.0 / (1.0 + (2.0 * u).exp());
        let w = step * 0.25 * PI * t.cosh() / u.cosh().powi(2);
        if from0 > 0.0 && from1 > 0.0 && w > 0.0 {
            out.push((from0, from1, w));
        }
        k += 1;
    }
    out
}

/// $R_F(0, k'^2, 1) = K(k)$ with $k' = $ `gap / sum`.
fn k_of(gap: f64, sum: f64) -> f64 {
    let kp = gap / sum;
    ellip::elliprf(0.0, kp * kp, 1.0).unwrap_or(f64::INFINITY)
}

impl GreenwoodTripp {
    /// A solver on a grid of `options.nodes` intervals.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for `nodes` outside \[16, 2000\], `tolerance` outside
    /// \[1e-14, 1e-2\] or `max_iterations` of 0.
    pub fn new(options: GreenwoodTrippOptions) -> Result<Self> {
        let n = options.nodes;
        if !(16..=2000).contains(&n) {
            return Err(Error::invalid("nodes", n, "16 to 2000 radial intervals"));
        }
        if !(options.tolerance >= 1e-14 && options.tolerance <= 1e-2) {
            return Err(Error::invalid(
                "tolerance",
                options.tolerance,
                "1e-14 to 1e-2",
            ));
        }
        if options.max_iterations == 0 {
            return Err(Error::invalid("max_iterations", 0, "at least 1"));
        }
        let gl = super::quadrature::kronrod15_rule();
        let ts = tanh_sinh();
        let m = n + 1;
        let mut kernel = DMatrix::zeros(m, m);
        let c = 8.0 / (PI * PI);
        for i in 0..m {
            let rho = i as f64;
            for j in 0..m {
                let mut v = 0.0;
                // elements [j-1, j] (shape rising) and [j, j+1] (shape falling)
                for (e, rising) in [(j as f64 - 1.0, true), (j as f64, false)] {
                    if e < 0.0 || e + 1.0 > n as f64 {
                        continue;
                    }
                    let shape = |t: f64| if rising { t - e } else { e + 1.0 - t };
                    if i == 0 {
                        // K(0) = π/2, t/(t+0) = 1: ∫ shape = 1/2
                        v += 0.5 * PI * 0.5;
                    } else if rho == e || rho == e + 1.0 {
                        for &(d0, d1, w) in &ts {
                            let (t, gap) = if rho == e {
                                (e + d0, d0)
                            } else {
                                (e + 1.0 - d1, d1)
                            };
                            v += w * t / (t + rho) * k_of(gap, t + rho) * shape(t);
                        }
                    } else {
                        for &(x, w) in &gl {
                            let t = e + 0.5 * (x + 1.0);
                            v +=
                                0.5 * w * t / (t + rho) * k_of((t - rho).abs(), t + rho) * shape(t);
                        }
                    }
                }
                kernel[(i, j)] = c * v;
            }
        }
        // moment weights of the hats on the unit grid, exact (Kronrod 15 on each element)
        let mut w1 = vec![0.0; m];
        let mut w3 = vec![0.0; m];
        for e in 0..n {
            for &(x, w) in &gl {
                let t = e as f64 + 0.5 * (x + 1.0);
                let (fall, rise) = (e as f64 + 1.0 - t, t - e as f64);
                w1[e] += 0.5 * w * t * fall;
                w1[e + 1] += 0.5 * w * t * rise;
                w3[e] += 0.5 * w * t.powi(3) * fall;
                w3[e + 1] += 0.5 * w * t.powi(3) * rise;
            }
        }
        Ok(GreenwoodTripp {
            options,
            kernel,
            w1,
            w3,
        })
    }

    /// The options this solver was built with.
    pub fn options(&self) -> GreenwoodTrippOptions {
        self.options
    }

    /// Solve one contact: the smoothed pressure distribution at load `params.load`.
    ///
    /// A solve that stops without converging is reported in
    /// [`status`](GreenwoodTrippSolution::status), not as an error.
    ///
    /// # Errors
    /// [`Error::NotConverged`] only if no finite iterate exists (never seen in tests).
    pub fn solve(&self, params: &GreenwoodTrippParams) -> Result<GreenwoodTrippSolution> {
        let alpha = params.alpha();
        let mu = params.mu();
        let c = PI * mu * alpha.sqrt() / (4.0 * SQRT_2);
        let table = GaussTable::get();
        let n = self.options.nodes;
        let m = n + 1;
        // Start: Hertz displacement, approach from the load balance (1-D).
        let mut rho_max = 1.5f64;
        let mut g = vec![0.0; m];
        let mut d = 0.0;
        let mut status = SolveStatus::new(Termination::MaxIterations, 0, f64::INFINITY);
        let mut total_iterations = 0;
        for pass in 0..4 {
            let dx = rho_max / n as f64;
            let rho: Vec<f64> = (0..m).map(|i| i as f64 * dx).collect();
            let w1: Vec<f64> = self.w1.iter().map(|w| w * dx * dx).collect();
            let w_hertz: Vec<f64> = rho.iter().map(|&r| hertz_displacement(r)).collect();
            // 1-D solve for d with the Hertz displacement (monotone: bisection)
            let load_at = |d: f64| -> f64 {
                w1.iter()
                    .zip(rho.iter().zip(&w_hertz))
                    .map(|(w, (r, wh))| w * c * table.f32((-d + 0.5 * r * r + wh) / alpha))
                    .sum::<f64>()
            };
            let (mut lo, mut hi) = (-50.0 * alpha - 10.0, 50.0 * alpha + 10.0);
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if load_at(mid) > 1.0 / 3.0 {
                    hi = mid;
                } else {
                    lo = mid;
                }
                // a start for Newton: 1e-9 δ0 is plenty
                if hi - lo < 1e-9 {
                    break;
                }
            }
            d = 0.5 * (lo + hi);
            if pass == 0 {
                // domain from the bound g >= (-d + ρ²/2)/α (w >= 0), then restart there
                let want = (2.0 * (d + G_CUT * alpha)).max(0.0).sqrt().max(1.2);
                if (want - rho_max).abs() > 1e-9 * want {
                    rho_max = want;
                    continue;
                }
            }
            for i in 0..m {
                g[i] = (-d + 0.5 * rho[i] * rho[i] + w_hertz[i]) / alpha;
            }
            let kernel = &self.kernel * dx;
            let (st, it) = self.newton(&kernel, &rho, &w1, alpha, c, &mut g, &mut d);
            total_iterations += it;
            status = SolveStatus::new(st.termination, total_iterations, st.residual);
            let want = (2.0 * (d + G_CUT * alpha)).max(0.0).sqrt();
            if g[n] >= G_CUT || want <= rho_max * (1.0 + 1e-9) || !status.converged() {
                break;
            }
            rho_max = want * 1.02;
        }
        let dx = rho_max / n as f64;
        let a0 = params.hertz_radius();
        let p0 = params.hertz_pressure();
        let delta0 = params.hertz_approach();
        let p_hat: Vec<f64> = g.iter().map(|&gi| c * table.f32(gi)).collect();
        if p_hat.iter().any(|p| !p.is_finite()) || !d.is_finite() {
            return Err(Error::NotConverged {
                what: "Greenwood-Tripp pressure".into(),
                iterations: status.iterations,
                residual: status.residual,
            });
        }
        let load_hat: f64 = self
            .w1
            .iter()
            .zip(&p_hat)
            .map(|(w, p)| w * dx * dx * p)
            .sum();
        let m2: f64 = self
            .w3
            .iter()
            .zip(&p_hat)
            .map(|(w, p)| w * dx.powi(4) * p)
            .sum();
        let effective = (2.5 * m2 / load_hat).sqrt();
        // radius with 95 % of the load: cumulative ∫ ρ p dρ over elements, exact for linear p
        let partial = |e: usize, x: f64| {
            // ∫_{ρe}^{ρe + x} ρ (p_e + (p_{e+1}-p_e) s/dx) dρ, s = ρ - ρe
            let r0 = e as f64 * dx;
            let (pa, pb) = (p_hat[e], p_hat[e + 1]);
            let slope = (pb - pa) / dx;
            pa * (r0 * x + 0.5 * x * x) + slope * (0.5 * r0 * x * x + x * x * x / 3.0)
        };
        let target = 0.95 * load_hat;
        let mut acc = 0.0;
        let mut r95 = rho_max;
        for e in 0..n {
            let full = partial(e, dx);
            if acc + full >= target {
                let (mut lo, mut hi) = (0.0, dx);
                for _ in 0..60 {
                    let mid = 0.5 * (lo + hi);
                    if acc + partial(e, mid) >= target {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                r95 = e as f64 * dx + 0.5 * (lo + hi);
                break;
            }
            acc += full;
        }
        Ok(GreenwoodTrippSolution {
            radii: (0..m).map(|i| i as f64 * dx * a0).collect(),
            pressure: p_hat.iter().map(|p| p * p0).collect(),
            centre_pressure: p_hat[0] * p0,
            approach: d * delta0,
            effective_radius: effective * a0,
            radius_95: r95 * a0,
            hertz_radius: a0,
            hertz_pressure: p0,
            hertz_approach: delta0,
            alpha,
            mu,
            load: 3.0 * load_hat * params.load,
            status,
        })
    }

    /// Newton's method with backtracking on the gaps `g` and approach `d`; returns the
    /// status and the iterations used.
    #[allow(clippy::too_many_arguments)]
    fn newton(
        &self,
        kernel: &DMatrix<f64>,
        rho: &[f64],
        w1: &[f64],
        alpha: f64,
        c: f64,
        g: &mut [f64],
        d: &mut f64,
    ) -> (SolveStatus, usize) {
        let table = GaussTable::get();
        let m = g.len();
        let tol = self.options.tolerance;
        // residual vector (m gap equations, then the load row scaled to relative)
        let residual = |g: &[f64], d: f64, f: &mut Vec<f64>, f12: &mut Vec<f64>| -> DVector<f64> {
            f.clear();
            f12.clear();
            for &gi in g {
                let (a, b) = table.f32_f12(gi);
                f.push(c * a);
                f12.push(c * b);
            }
            let p = DVector::from_column_slice(f);
            let w = kernel * &p;
            let mut r = DVector::zeros(m + 1);
            for i in 0..m {
                r[i] = alpha * g[i] + d - 0.5 * rho[i] * rho[i] - w[i];
            }
            let load: f64 = w1.iter().zip(f.iter()).map(|(w, p)| w * p).sum();
            r[m] = 3.0 * load - 1.0;
            r
        };
        let norm = |r: &DVector<f64>| r.iter().fold(0.0f64, |a, x| a.max(x.abs()));
        let (mut f, mut f12) = (Vec::with_capacity(m), Vec::with_capacity(m));
        let mut r = residual(g, *d, &mut f, &mut f12);
        let mut rn = norm(&r);
        for it in 0..self.options.max_iterations {
            if !rn.is_finite() {
                return (SolveStatus::new(Termination::Diverged, it, rn), it);
            }
            if rn <= tol {
                return (SolveStatus::new(Termination::Converged, it, rn), it);
            }
            // Jacobian: α I + K diag(1.5 c F_1/2) | 1 ; load row -3 w1 1.5 c F_1/2 | 0
            let mut jac = DMatrix::zeros(m + 1, m + 1);
            for j in 0..m {
                let s = 1.5 * f12[j];
                for i in 0..m {
                    jac[(i, j)] = kernel[(i, j)] * s;
                }
                jac[(j, j)] += alpha;
                jac[(m, j)] = -3.0 * w1[j] * s;
                jac[(j, m)] = 1.0;
            }
            let Some(step) = jac.lu().solve(&(-&r)) else {
                return (SolveStatus::new(Termination::Diverged, it, rn), it);
            };
            // backtracking: accept the first step length that lowers the max residual
            let mut lambda = 1.0;
            let g_old: Vec<f64> = g.to_vec();
            let d_old = *d;
            loop {
                for i in 0..m {
                    g[i] = g_old[i] + lambda * step[i];
                }
                *d = d_old + lambda * step[m];
                let r_new = residual(g, *d, &mut f, &mut f12);
                let n_new = norm(&r_new);
                if n_new.is_finite() && (n_new < (1.0 - 1e-4 * lambda) * rn || lambda < 1e-3) {
                    r = r_new;
                    rn = n_new;
                    break;
                }
                lambda *= 0.5;
            }
        }
        let n_it = self.options.max_iterations;
        let term = if rn <= tol {
            Termination::Converged
        } else {
            Termination::MaxIterations
        };
        (SolveStatus::new(term, n_it, rn), n_it)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The kernel applied to the Hertz pressure gives the Hertz displacement (inside and
    /// outside the contact), to the discretisation error of the square-root edge.
    #[test]
    fn kernel_reproduces_hertz_displacement() {
        let n = 200;
        let solver = GreenwoodTripp::new(GreenwoodTrippOptions {
            nodes: n,
            ..Default::default()
        })
        .expect("valid");
        let rho_max = 2.0;
        let dx = rho_max / n as f64;
        let p = DVector::from_iterator(
            n + 1,
            (0..=n).map(|i| (1.0 - (i as f64 * dx).powi(2)).max(0.0).sqrt()),
        );
        let w = &solver.kernel * dx * &p;
        let mut worst: f64 = 0.0;
        for i in 0..=n {
            let r = i as f64 * dx;
            worst = worst.max((w[i] - hertz_displacement(r)).abs());
        }
        assert!(worst < 2e-3, "worst {worst:e}");
        // load weights: ∫ ρ sqrt(1-ρ²) dρ = 1/3
        let load: f64 = solver
            .w1
            .iter()
            .zip(p.iter())
            .map(|(w, p)| w * dx * dx * p)
            .sum();
        assert!((load - 1.0 / 3.0).abs() < 2e-3, "{load}");
    }
}
