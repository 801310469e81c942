//! Traction curves from asperity micro-slip: the thesis' model of a rough rolling contact
//! (§3.1.2.2 of the master thesis "Study of the traction curves"), for a rough line contact
//! (rectangular) and a circular contact.
//!
//! Periodic spherical asperities cover the nominal Hertz contact; each carries its share
//! of the nominal pressure; rolling with a slide-to-roll ratio $\xi$ displaces each
//! asperity pair tangentially by $\xi$ times the distance it has travelled from the
//! leading edge, and Mindlin's partial-slip law turns that displacement into a tangential
//! force that saturates at $\mu F_i$. The sum over the asperities is the traction curve
//! $F_T / (\mu F_N)$ against $\xi$:
//!
//! $$\frac{F_T}{\mu F_N}(\xi) = \frac{1}{F_N}\sum_i n_i F_i
//!   \left[1 - \left(1 - \min\!\left(\frac{\xi_{\mathrm{eff}}\,d_i}{\delta^*_i},
//! 1\right)\right)^{3/2}\right],   \qquad \delta^*_i = \frac{3(2-\nu)\,\mu F_i}{8\,G\,a_i}.$$
//!
//! [`AsperityTraction::new`] plans the model once (lattice, loads, contact radii,
//! gross-slip ratios); [`AsperityTraction::traction_ratio`] and
//! [`AsperityTraction::curve`] then cost one pass over the asperities. The per-asperity
//! values of the thesis' Annex B are public: [`AsperityState`] (load, radius, entry
//! distance) and [`AsperityForce`] (displacement, B, Y, F_T at one slide-to-roll ratio).
//!
//! # Conventions
//! These add to the crate-level *Conventions* (mm, N, MPa). The slide-to-roll ratio is
//! $\xi = \Delta V / V_r = (V_1 - V_2)/((V_1 + V_2)/2) \ge 0$, a fraction (the thesis
//! tabulates it in percent). `x` is the rolling direction: material enters the contact at
//! the leading edge `x = +a` and leaves at `x = -a` (the crate's tangential convention;
//! the thesis runs the other way). Forces are magnitudes.
//!
//! The options that reproduce the thesis' printed tables are explained, with the
//! derivation and the validation table, in `docs/traction-asperity.md`.
//!
//! # Example
//! A circular steel contact (radius 0.4 mm, 680 N) with Hertzian asperities of radius
//! 0.02 mm every 0.05 mm:
//! ```
//! use kontakt::traction::{AsperityTraction, AsperityTractionParams, NominalContact};
//! use kontakt::material::ElasticMaterial;
//! let nominal = NominalContact::Circular { half_width: 0.4, max_pressure: None };
//! let params = AsperityTractionParams::new(
//!     nominal, 680.0, 0.3, ElasticMaterial::STEEL, [0.02, 0.02], 0.05);
//! let model = AsperityTraction::new(params)?;
//! assert_eq!(model.asperities().len(), 208);
//! let curve = model.curve(&[0.0, 1e-3, 1e-2, 1.0])?;
//! assert_eq!(curve[0], 0.0);
//! assert!(curve.windows(2).all(|w| w[0] <= w[1]));
//! assert!((curve[3] - 1.0).abs() < 1e-12); // every asperity slides
//! # Ok::<(), kontakt::Error>(())
//! ```

pub mod asperity;
mod cells;
pub mod curve;

pub use asperity::{
    AsperityContactLaw, AsperityForce, AsperityState, AsperityTraction, AsperityTractionParams,
    ContactShape, LoadSharing, NominalContact, SlipReference,
};
pub use curve::{AsperityCurve, nominal_of_ellipse, rolling_axis};
