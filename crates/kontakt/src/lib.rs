//! # kontakt — contact mechanics for rolling bearings
//!
//! kontakt computes the contact between elastic bodies the way a bearing engineer needs it:
//! exact Hertz theory (circular, elliptical, line), subsurface stresses and first yield,
//! impact and adhesion; and, in the modules that follow, the PimP method for the roller
//! end face against the rib, a coupled elastic half-space solver, tangential contact and
//! traction curves, and bearing kinematics.
//!
//! The API takes and returns plain data, holds no global state and never panics on user
//! input: every fallible function returns [`Result`]. Plan-once / solve-many types such as
//! [`hertz::HertzPointContact`] let a multi-body simulation evaluate a contact millions of
//! times cheaply.
//!
//! ## Quick example
//! A 12.7 mm steel ball (radius 6.35 mm) pressed onto a flat steel plate with 100 N:
//! ```
//! use kontakt::{hertz::{HertzPointContact, PointGeometry}, material::ElasticMaterial};
//! let geometry = PointGeometry::new([6.35, 6.35], [f64::INFINITY, f64::INFINITY], 0.0)?;
//! let steel = ElasticMaterial::STEEL;
//! let contact = HertzPointContact::new(geometry, steel, steel)?;
//! let s = contact.solve_force(100.0)?;
//! assert!((s.max_pressure - 1_855.60).abs() < 0.01); // MPa
//! assert!((s.semi_axes[0] - 0.160_409).abs() < 1e-6); // mm
//! # Ok::<(), kontakt::Error>(())
//! ```
//!
//! ## Conventions
//! These definitions hold for the whole crate; every module refers back here.
//!
//! **Units.** millimetre, newton, megapascal (N/mm²), second, radian. Derived: energy in
//! N·mm (= mJ), stiffness in N/mm, mass in tonnes (N·s²/mm), density in t/mm³ (steel
//! 7.85e-9), surface energy in N/mm (1 J/m² = 1e-3 N/mm). See [`units`]. Nothing inside
//! the library converts units.
//!
//! **Curvature signs.** A principal radius of curvature is *positive for a convex*
//! surface (a ball), *negative for a concave* one (a bearing groove, the inner side of an
//! outer race) and `f64::INFINITY` (either sign) for a flat direction. A radius of zero is
//! invalid.
//!
//! **Contact frame.** Origin at the first point of contact, `z` along the common normal
//! pointing *into* body 1 (so depth below the surface of body 1 is positive `z`), `x` along
//! the first principal direction of body 1, `y = z × x`. The angle between the principal
//! planes, `theta`, turns body 1's first principal direction into body 2's, positive
//! counter-clockwise about `z`. The separation of the undeformed surfaces is
//! `h(x, y) = A x'² + B y'²` with `A <= B` in the principal frame `x', y'` of the relative
//! curvature; the contact ellipse's major semi-axis `a` lies along `x'` (the direction of
//! *least* relative curvature) and the minor `b` along `y'`. Its orientation is reported
//! as the angle from `x` to `x'`.
//!
//! **Loading.** The approach `delta` is the distance by which distant points of the two
//! bodies move together; positive when the bodies are pressed into each other. The normal
//! force `F` is positive in compression. Pressure is positive in compression.
//! Stresses follow the elasticity convention: *tension positive*, so contact stresses
//! below the surface are negative (as in Johnson 1982, eqs 20a/b).
//!
//! **Moduli.** Each is defined once in [`material`]: Young's modulus `E`, Poisson's ratio
//! `nu` (-1 < nu <= 0.5), shear modulus `G = E / (2(1+nu))`, contact modulus
//! `1/E* = (1-nu1²)/E1 + (1-nu2²)/E2` (Hamrock's `E'` is `2 E*`), Dundurs' `alpha` and
//! `beta`. A parameter never changes its meaning depending on another argument.
//!
//! ## Modules
//! | module | what | status |
//! |---|---|---|
//! | [`material`] | elastic materials, E*, G, Dundurs' parameters | done |
//! | [`geometry`] | principal curvatures, relative curvature, sampling grids, analytic surfaces with ray casting and the contact point from poses | done |
//! | [`load`] | one load-control type (force, approach, line load) for every solver | done |
//! | [`solve`] | one termination status (converged, max iterations, stagnated, diverged) for every iterative solver | done |
//! | [`gap`] | the substitute geometry: `GapSource` (quadratic, any function, two placed surfaces), gap and height maps | done |
//! | [`field`] | one result type of the field solvers (`NormalSolution`), the zone's shape, the one adaptive-domain loop | done |
//! | [`hertz`] | exact point (elliptical/circular) and line contact, approximations, subsurface stress and yield, impact, JKR adhesion | done |
//! | [`impact`] | oblique impact with friction of a sphere on a flat: rigid-body regimes (Johnson 1982 eqs 39-40, 64-70) and the elastic Hertz + Mindlin-Deresiewicz analysis of Maw, Barber and Fawcett (rebound peripheral velocity, negative over a range of incidence below gross sliding) | done |
//! | [`gear`] | bending and contact deflection of a pair of spur-gear teeth (Johnson 1982 Appendix 2) | done |
//! | [`pimp`] | PimP: substitute geometry, Winkler bedding (published / corrected), force equilibrium, zone shape | done |
//! | [`halfspace`] | coupled elastic half-space: Love coefficients, FFT operator (free / periodic), Polonsky-Keer solver with warm start, any gap or gap map, adaptive domain | done |
//! | [`tangential`] | Cattaneo-Mindlin partial slip and Mindlin-Deresiewicz loading history, Carter's creep curve, Kalker's creep coefficients and linear theory, FASTSIM; traction curves | done |
//! | [`rolling`] | exact (Kalker) tangential contact on the half-space grid: Cerruti's influence coefficients for uniform tractions on cells, the FFT tangential operator, the shift (Cattaneo) problem under a shift or a force, steady rolling with creepages and spin (Kalker's discretisation, semismooth Newton on the steady equations); dissimilar bodies (Kalker's `K`) in the shift problem and in steady rolling under creepage or force control | done, validated against Cattaneo, Kalker's C11/C22/C23, Carter's strips, CONTACT's reference outputs (`tractcurv`, `fastsim`, `spence35`, `bentall`) and Bentall & Johnson's free-rolling creepage; the traction model `kalker_exact` (dissimilar bodies as an option: `coupling`); not yet: 10 ms per point with spin at 35² (issue 17) |
//! | [`rough`] | statistical rough surfaces: Greenwood-Williamson (Gaussian and exponential summit heights, load, real area and contact count against separation and its inverse, plasticity index) and Greenwood-Tripp's rough sphere (smoothed pressure, effective radius, approach against α and μ); seeded self-affine surfaces with the exact target spectrum; periodic rough contact on the half-space solver (real area, κ, patches, mean gap; Persson's area) | done |
//! | [`traction`] | asperity-based traction curves: periodic spherical asperities on a rough line or circular Hertz contact, Mindlin partial slip per asperity (the thesis "Study of the traction curves", §3.1.2.2) | done |
//! | [`lubrication`] | lubricant (ASTM D341 viscosity-temperature, ISO VG grades), film parameter Λ, EHL film thickness (Hamrock-Dowson central and minimum film, entrainment at any angle via R_e/R_s, regime groups U, G, W, k, Moes M, L, g_V, g_E, validity warnings) | lubricant, Λ and Hamrock-Dowson film done; Chittenden (1985) and Nijenbanning-Venner-Moes (1994) not implemented (constants unverified, see docs/film.md) |
//! | [`friction`] | mixed-friction law per cell (Coulomb, load sharing exp(−BΛ^C), Newtonian / Eyring / limiting-shear fluid, regularised direction) and its integral over any pressure field: force, moments, power | done |
//! | [`element`] | a contact element for multi-body codes: two surfaces on two bodies, poses and twists in, force, moments, friction and status out (Hertz, PimP or half-space back-end) | element, status, damping, load control, stiffness, the `kontakt mbs` study and a C API (crate `kontakt-capi`) done; the speed targets of issue 12 not yet met (docs/PERFORMANCE.md) |
//! | [`bearing`] | roller end face / rib pair of a tapered roller bearing (Wirsching et al. (2020) Table 1) ; kinematics (cage, roller spin, sliding and entrainment velocities); rib load, rib friction torque and power of the whole bearing | done |
//!
//! Case files (TOML), the runner `Case::run` and the JSON reports live in the
//! `kontakt-case` crate, so this crate holds physics only.
//!
//! Plots live in the `kontakt-plot` crate. See `ARCHITECTURE.md`.
//!
//! ## References
//! The bibliography is in `docs/references.md`; each item's docs cite equation numbers.

#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod bearing;
pub mod element;
pub mod error;
pub mod field;
pub mod friction;
pub mod gap;
pub mod gear;
pub mod geometry;
pub mod halfspace;
pub mod hertz;
pub mod impact;
pub mod load;
pub mod lubrication;
pub mod material;
pub mod pimp;
pub mod quadrature;
pub mod rolling;
pub mod rough;
pub mod solve;
pub mod tangential;
pub mod traction;
pub mod units;

pub use error::{Error, Result};

/// The version of this crate, echoed in every serialized result.
pub const VERSION: &str = env!("CARGO_PKG_VERSION");

/// Most threads any solver or sweep of kontakt accepts (a documented bound, so that a typo
/// such as `threads = 100000` is an error rather than an attempt to start that many).
pub const MAX_THREADS: usize = 256;

/// The README's Rust example is compiled and run as a doctest, so it stays true.
#[doc = include_str!("../../../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;
