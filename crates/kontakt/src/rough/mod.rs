//! Statistical rough-surface contact: Greenwood-Williamson (1966) for nominally flat
//! surfaces and Greenwood-Tripp (1967) for a smooth sphere on a rough flat.
//!
//! Units: mm, N, MPa (summit density in 1/mm²). Derivations, the numerical method and
//! what is validated are in `docs/rough.md`.
//!
//! | item | model |
//! |---|---|
//! | [`height_integral`], [`SummitHeights`] | $F_n(h)$ for Gaussian and exponential summit heights |
//! | [`GreenwoodWilliamson`], [`GwState`], [`plasticity_index`] | load, real area and contact count per nominal area against separation, and the inverse; $\psi$ |
//! | [`GreenwoodTripp`], [`GreenwoodTrippParams`], [`GreenwoodTrippSolution`], [`roughness_parameter`] | smoothed pressure of a rough sphere, effective radius, approach, $\alpha$ and $\mu$ |
//!
//! # References
//! - Greenwood and Williamson (1966), Proc. R. Soc. Lond. A 295, 300-319.
//! - Greenwood and Tripp (1967), J. Appl. Mech. 34, 153-159.
//! - Johnson (1982), "One hundred years of Hertz contact", Proc. IMechE 196, §8.
//! - Johnson, *Contact Mechanics* (1985), §13.2-13.4.

mod gt;
mod gw;
mod heights;
mod quadrature;

pub use gt::{
    GreenwoodTripp, GreenwoodTrippOptions, GreenwoodTrippParams, GreenwoodTrippSolution,
    roughness_parameter,
};
pub use gw::{GreenwoodWilliamson, GwState, plasticity_index};
pub use heights::{SummitHeights, height_integral, height_integral_quadrature};
