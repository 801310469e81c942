//! The mixed-friction law: shear stress per cell from the pressure, the sliding speed and
//! the lubricant film.
//!
//! ```text
//! τ = φ(Λ) μ_b p ŝ(v) + (1 − φ(Λ)) τ_f(p, γ̇) v/|v|,   γ̇ = |v| / h,
//! ŝ(v) = v / √(|v|² + v_ε²)                              (regularised direction)
//! ```
//!
//! acting on body 1 against its sliding velocity `v` (of body 1 relative to body 2).
//!
//! - Load sharing `φ(Λ)`, the fraction of the load carried by asperity contact
//!   ([`LoadSharing`]): `1` (boundary / dry Coulomb friction), or `exp(−B Λ^C)`. Aihara
//!   (1987) uses `B = 1.8`, `C = 1.2` after Patir & Cheng for the rib (with `Λ` from
//!   `h₀ = 1.25 h_min`), Zhou & Hoeprich (1991) fit `B` and `C` to measured roughness, and
//!   Wingertszahn et al. (2023) use `B = 1.90`, `C = 0.99` for the rib of a 32216 bearing.
//! - Boundary friction: Coulomb, coefficient `μ_b` (Aihara: 0.2 at the rib start-up;
//!   SKF's model: 0.12-0.15).
//! - Fluid shear `τ_f` ([`FluidShear`]) with the Barus viscosity `η(p) = η₀ exp(α p)`:
//!   Newtonian `η γ̇`; Eyring `τ₀ asinh(η γ̇ / τ₀)`; or the steady limiting-shear form of
//!   Bair & Winer (1979) `τ_L (1 − exp(−η γ̇ / τ_L))` with `τ_L = τ_L0 + γ_L p`. The last two
//!   stay bounded at large shear rates (the Newtonian law does not: use it only where
//!   `η γ̇` is small, i.e. thick films and low pressure).
//! - Regularisation: the Coulomb part turns with `ŝ(v)`, smooth (C^∞) through `v = 0`, so
//!   that the force is continuous for implicit integrators. It differs from the exact
//!   direction by the factor `|v|/√(|v|² + v_ε²)`: `1 − v_ε²/(2|v|²)` for `|v| ≫ v_ε`
//!   (5e-5 at `|v| = 100 v_ε`). `v_ε = 0` gives plain Coulomb friction. The fluid part is
//!   already continuous (`τ_f → 0` as `v → 0`) and is not regularised.
//!
//! Assumptions: the film thickness `h` and `Λ` are those of the contact as a whole (one
//! film formula at the contact centre, as in Aihara (1987) and Wingertszahn et al. (2023));
//! isothermal; the shear rate is `|v|/h` across the whole film (Couette flow).
//!
//! Units: p, τ, τ₀, τ_L in MPa; v in mm/s; h in mm; η in MPa·s; α in 1/MPa; γ̇ in 1/s.
//! Derivations and sources: docs/friction.md.

use crate::error::{Error, Result};

/// How the load is shared between asperity contact and the fluid film.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(tag = "kind", rename_all = "snake_case"))]
pub enum LoadSharing {
    /// `φ = 1`: every cell carries its pressure by asperity contact (dry or boundary
    /// lubrication; the fluid law is not used).
    Boundary,
    /// `φ = exp(−b Λ^c)` (Aihara 1987: b = 1.8, c = 1.2; Wingertszahn et al. 2023, rib:
    /// b = 1.90, c = 0.99).
    Exponential {
        /// `B` > 0.
        b: f64,
        /// `C` > 0.
        c: f64,
    },
}

impl LoadSharing {
    /// The asperity share `φ(Λ)` in \[0, 1\] for the film parameter `lambda` ≥ 0.
    pub fn asperity_share(&self, lambda: f64) -> f64 {
        match *self {
            LoadSharing::Boundary => 1.0,
            LoadSharing::Exponential { b, c } => (-b * lambda.powf(c)).exp(),
        }
    }
}

/// The shear stress of the lubricant film.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(tag = "kind", rename_all = "snake_case"))]
pub enum FluidShear {
    /// No fluid shear (Aihara 1987 neglects it at the rib).
    None,
    /// Newtonian `τ = η(p) γ̇` (unbounded: thick films, low pressure only).
    Newtonian,
    /// Eyring `τ = τ₀ asinh(η(p) γ̇ / τ₀)`.
    Eyring {
        /// Eyring stress τ₀ \[MPa\] (mineral oils ≈ 2-10 MPa).
        #[cfg_attr(feature = "serde", serde(rename = "tau0_mpa"))]
        tau0: f64,
    },
    /// Limiting shear `τ = τ_L (1 − exp(−η(p) γ̇ / τ_L))`, `τ_L = tau_l0 + slope p`
    /// (the steady form of Bair & Winer 1979).
    LimitingShear {
        /// Limiting shear stress at zero pressure τ_L0 \[MPa\], > 0.
        #[cfg_attr(feature = "serde", serde(rename = "tau_l0_mpa"))]
        tau_l0: f64,
        /// Its growth with pressure γ_L (dimensionless), ≥ 0.
        #[cfg_attr(feature = "serde", serde(rename = "tau_l_slope"))]
        slope: f64,
    },
}

/// The lubricant film of a contact as the friction law needs it.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct FilmState {
    /// Film thickness h that sets the shear rate |v|/h \[mm\] (the central film).
    #[cfg_attr(feature = "serde", serde(rename = "thickness_mm"))]
    pub thickness: f64,
    /// Film parameter Λ = h / σ (dimensionless).
    pub lambda: f64,
    /// Viscosity at the inlet temperature and zero pressure η₀ \[MPa·s\].
    #[cfg_attr(feature = "serde", serde(rename = "viscosity_mpa_s"))]
    pub viscosity: f64,
    /// Pressure-viscosity coefficient α \[1/MPa\] (Barus).
    #[cfg_attr(feature = "serde", serde(rename = "alpha_per_mpa"))]
    pub alpha: f64,
}

impl FilmState {
    /// A film from its thickness \[mm\], film parameter, viscosity \[MPa·s\] and
    /// pressure-viscosity coefficient \[1/MPa\].
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the field: `thickness` and `lambda` finite and ≥ 0,
    /// `viscosity` finite and > 0, `alpha` finite and ≥ 0 (0: no piezoviscosity).
    pub fn new(thickness: f64, lambda: f64, viscosity: f64, alpha: f64) -> Result<Self> {
        let film = FilmState {
            thickness,
            lambda,
            viscosity,
            alpha,
        };
        film.check()?;
        Ok(film)
    }

    /// No film (dry contact or zero entrainment): `h = 0`, `Λ = 0`, so any exponential
    /// sharing gives `φ = 1` and the contact is in boundary friction.
    pub fn dry() -> Self {
        FilmState {
            thickness: 0.0,
            lambda: 0.0,
            viscosity: 1.0,
            alpha: 0.0,
        }
    }

    fn check(&self) -> Result<()> {
        for (name, v) in [("thickness", self.thickness), ("lambda", self.lambda)] {
            if !(v.is_finite() && v >= 0.0) {
                return Err(Error::invalid(name, v, "a finite value >= 0"));
            }
        }
        if !(self.viscosity.is_finite() && self.viscosity > 0.0) {
            return Err(Error::invalid(
                "viscosity",
                self.viscosity,
                "a finite viscosity > 0 MPa·s",
            ));
        }
        if !(self.alpha.is_finite() && self.alpha >= 0.0) {
            return Err(Error::invalid(
                "alpha",
                self.alpha,
                "a finite pressure-viscosity coefficient >= 0 1/MPa",
            ));
        }
        Ok(())
    }
}

/// A mixed-friction law (see the module docs for the formula).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct FrictionLaw {
    /// Boundary (asperity) friction coefficient μ_b, 0 ≤ μ_b ≤ 1.
    #[cfg_attr(feature = "serde", serde(rename = "mu"))]
    pub boundary_coefficient: f64,
    /// Load sharing φ(Λ).
    pub sharing: LoadSharing,
    /// Fluid shear law τ_f.
    pub fluid: FluidShear,
    /// Regularisation speed v_ε \[mm/s\] of the Coulomb direction, ≥ 0 (0: exact Coulomb).
    #[cfg_attr(feature = "serde", serde(rename = "regularisation_speed_mm_s"))]
    pub regularisation_speed: f64,
}

/// Default regularisation speed v_ε \[mm/s\]: 1 mm/s, three orders below the rib's
/// sliding speeds (0.1-1 m/s at 1000 r/min), so the Coulomb force is within 5e-5 of its
/// exact value above 100 mm/s.
pub const REGULARISATION_SPEED: f64 = 1.0;

impl FrictionLaw {
    /// Plain Coulomb friction `τ = μ p ŝ(v)` with the default regularisation speed.
    ///
    /// # Errors
    /// Those of [`FrictionLaw::check`].
    pub fn coulomb(mu: f64) -> Result<Self> {
        let law = FrictionLaw {
            boundary_coefficient: mu,
            sharing: LoadSharing::Boundary,
            fluid: FluidShear::None,
            regularisation_speed: REGULARISATION_SPEED,
        };
        law.check()?;
        Ok(law)
    }

    /// Aihara's (1987) rib law: `μ = 0.2 exp(−1.8 Λ^1.2)`, no fluid shear. Aihara takes
    /// `Λ` from `h₀ = 1.25 h_min` (Hamrock-Dowson); give the [`FilmState`] accordingly.
    pub fn aihara() -> Self {
        FrictionLaw {
            boundary_coefficient: 0.2,
            sharing: LoadSharing::Exponential { b: 1.8, c: 1.2 },
            fluid: FluidShear::None,
            regularisation_speed: REGULARISATION_SPEED,
        }
    }

    /// The rib law of Wingertszahn et al. (2023): `φ = exp(−1.90 Λ^0.99)` with a boundary
    /// coefficient `mu` and a limiting-shear fluid `τ_L = 2 MPa + 0.07 p` (a typical mineral
    /// oil; the paper's Bair-Winer parameters are temperature-dependent fits).
    ///
    /// # Errors
    /// Those of [`FrictionLaw::check`].
    pub fn mixed(mu: f64) -> Result<Self> {
        let law = FrictionLaw {
            boundary_coefficient: mu,
            sharing: LoadSharing::Exponential { b: 1.90, c: 0.99 },
            fluid: FluidShear::LimitingShear {
                tau_l0: 2.0,
                slope: 0.07,
            },
            regularisation_speed: REGULARISATION_SPEED,
        };
        law.check()?;
        Ok(law)
    }

    /// Check every parameter.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the field: `boundary_coefficient` in \[0, 1\];
    /// `sharing.b`, `sharing.c` finite and > 0; `fluid.tau0`, `fluid.tau_l0` finite and
    /// > 0, `fluid.slope` finite and ≥ 0; `regularisation_speed` finite and ≥ 0 mm/s.
    pub fn check(&self) -> Result<()> {
        let mu = self.boundary_coefficient;
        if !(mu.is_finite() && (0.0..=1.0).contains(&mu)) {
            return Err(Error::invalid(
                "boundary_coefficient",
                mu,
                "a friction coefficient in [0, 1]",
            ));
        }
        if let LoadSharing::Exponential { b, c } = self.sharing {
            for (name, v) in [("sharing.b", b), ("sharing.c", c)] {
                if !(v.is_finite() && v > 0.0) {
                    return Err(Error::invalid(name, v, "a finite value > 0"));
                }
            }
        }
        match self.fluid {
            FluidShear::Eyring { tau0 } if !(tau0.is_finite() && tau0 > 0.0) => {
                return Err(Error::invalid(
                    "fluid.tau0",
                    tau0,
                    "a finite stress > 0 MPa",
                ));
            }
            FluidShear::LimitingShear { tau_l0, slope } => {
                if !(tau_l0.is_finite() && tau_l0 > 0.0) {
                    return Err(Error::invalid(
                        "fluid.tau_l0",
                        tau_l0,
                        "a finite stress > 0 MPa",
                    ));
                }
                if !(slope.is_finite() && slope >= 0.0) {
                    return Err(Error::invalid("fluid.slope", slope, "a finite value >= 0"));
                }
            }
            _ => {}
        }
        let v = self.regularisation_speed;
        if !(v.is_finite() && v >= 0.0) {
            return Err(Error::invalid(
                "regularisation_speed",
                v,
                "a finite speed >= 0 mm/s",
            ));
        }
        Ok(())
    }

    /// The law evaluated for one film: the per-cell kernel of the friction integral.
    ///
    /// # Errors
    /// Those of [`FrictionLaw::check`] and [`FilmState::new`].
    pub fn with_film(&self, film: &FilmState) -> Result<CellLaw> {
        self.check()?;
        film.check()?;
        let phi = self.sharing.asperity_share(film.lambda);
        // No film: the fluid part has no shear rate to work with; φ(0) = 1 for every
        // sharing law, so this only removes the 0·∞ of η|v|/0.
        let fluid = if phi < 1.0 && film.thickness > 0.0 {
            self.fluid
        } else {
            FluidShear::None
        };
        Ok(CellLaw {
            boundary: phi * self.boundary_coefficient,
            fluid_share: 1.0 - phi,
            fluid,
            eta_over_h: film.viscosity / film.thickness.max(f64::MIN_POSITIVE),
            alpha: film.alpha,
            eps2: self.regularisation_speed * self.regularisation_speed,
            asperity_share: phi,
        })
    }
}

/// A [`FrictionLaw`] with its film folded in: `τ(p, v)` per cell without further checks.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CellLaw {
    boundary: f64,
    fluid_share: f64,
    fluid: FluidShear,
    eta_over_h: f64,
    alpha: f64,
    eps2: f64,
    asperity_share: f64,
}

impl CellLaw {
    /// The asperity share φ(Λ) of this film.
    pub fn asperity_share(&self) -> f64 {
        self.asperity_share
    }

    /// `φ μ_b`: the boundary part's coefficient (the integral's vectorised kernel).
    pub(crate) fn boundary_coefficient(&self) -> f64 {
        self.boundary
    }

    /// `v_ε²` \[mm²/s²\].
    pub(crate) fn regularisation_squared(&self) -> f64 {
        self.eps2
    }

    /// Whether the fluid part contributes.
    pub(crate) fn has_fluid(&self) -> bool {
        self.fluid_share > 0.0 && !matches!(self.fluid, FluidShear::None)
    }

    /// `(1 − φ) τ_f / |v|`, the fluid part of [`CellLaw::drag`].
    #[inline]
    pub(crate) fn fluid_part(&self, p: f64, speed: f64) -> f64 {
        self.fluid_share * self.fluid_drag(p, speed)
    }

    /// The Barus factor `exp(α p)` of this law's film at the pressure `p` \[MPa\].
    #[inline]
    pub(crate) fn barus(&self, p: f64) -> f64 {
        (self.alpha * p).exp()
    }

    /// [`CellLaw::fluid_part`] with `barus` = [`CellLaw::barus`] of `p` given: the same
    /// number bit for bit (for a law with a fluid part).
    #[inline]
    pub(crate) fn fluid_part_with_barus(&self, p: f64, speed: f64, barus: f64) -> f64 {
        self.fluid_share * self.fluid_drag_barus(p, speed, self.alpha * p, barus)
    }

    /// The factor `k` \[MPa·s/mm\] with `τ = −k v` the shear stress on body 1 for the
    /// pressure `p` \[MPa\] and the sliding velocity `v` of body 1 \[mm/s\] with speed
    /// `speed = |v|`. `k ≥ 0`; the dissipated power density is `k |v|²` \[MPa·mm/s\]. At
    /// `speed = 0` the stress is zero whatever `k` is; `k` is finite there.
    #[inline]
    pub fn drag(&self, p: f64, speed: f64) -> f64 {
        let mut k = self.boundary_drag(p, speed);
        if self.fluid_share > 0.0 {
            k += self.fluid_share * self.fluid_drag(p, speed);
        }
        k
    }

    /// The boundary part of [`CellLaw::drag`]: `φ μ_b p / √(|v|² + v_ε²)`.
    #[inline(always)]
    fn boundary_drag(&self, p: f64, speed: f64) -> f64 {
        if self.boundary > 0.0 {
            let d = (speed * speed + self.eps2).sqrt();
            if d > 0.0 {
                return self.boundary * p / d;
            }
        }
        0.0
    }

    /// `τ_f(p, γ̇) / |v|`, with its limit `η(p)/h` at `|v| = 0`. Where `exp(α p)`
    /// overflows, the bounded laws take their large-stress forms (`asinh r = ln 2r`,
    /// `τ = τ_L`); the Newtonian law returns infinity, which the friction integral refuses.
    #[inline]
    fn fluid_drag(&self, p: f64, speed: f64) -> f64 {
        if let FluidShear::None = self.fluid {
            return 0.0;
        }
        let g = self.alpha * p;
        self.fluid_drag_barus(p, speed, g, g.exp())
    }

    /// [`CellLaw::drag`] with the Barus factor `barus` = `exp(α p)` of this law's film
    /// (α the [`FilmState`]'s) given: the same number bit for bit when `barus` is that
    /// exponential, without computing it. For integrals over fixed pressures whose film
    /// changes (a speed sweep over one load distribution: the factors are computed once).
    #[inline]
    pub fn drag_with_barus(&self, p: f64, speed: f64, barus: f64) -> f64 {
        let mut k = self.boundary_drag(p, speed);
        if self.fluid_share > 0.0 {
            k += self.fluid_share
                * match self.fluid {
                    FluidShear::None => 0.0,
                    _ => self.fluid_drag_barus(p, speed, self.alpha * p, barus),
                };
        }
        k
    }

    /// `τ_f / |v|` of [`CellLaw::fluid_drag`] with `g = α p` and `barus = exp(g)` given.
    #[inline(always)]
    fn fluid_drag_barus(&self, p: f64, speed: f64, g: f64, barus: f64) -> f64 {
        let eta_h = self.eta_over_h * barus;
        // x = η γ̇ = η |v| / h: the Newtonian stress.
        let x = eta_h * speed;
        match self.fluid {
            FluidShear::None | FluidShear::Newtonian => eta_h,
            FluidShear::Eyring { tau0 } => {
                let r = x / tau0;
                if !r.is_finite() {
                    let ln_r = g + (self.eta_over_h * speed / tau0).ln();
                    tau0 * (std::f64::consts::LN_2 + ln_r) / speed
                } else if r > 1e-8 {
                    tau0 * r.asinh() / speed
                } else {
                    eta_h
                }
            }
            FluidShear::LimitingShear { tau_l0, slope } => {
                let tau_l = tau_l0 + slope * p;
                let r = x / tau_l;
                // 1 − e^(−r): exactly 1 in f64 beyond r = 40; `exp` (faster than `exp_m1`)
                // loses at most 2 digits of 16 above r = 0.01; `exp_m1` below.
                if !r.is_finite() || r > 40.0 {
                    tau_l / speed
                } else if r > 1e-2 {
                    tau_l * (1.0 - (-r).exp()) / speed
                } else if r > 1e-8 {
                    -tau_l * (-r).exp_m1() / speed
                } else {
                    eta_h
                }
            }
        }
    }

    /// Magnitude of the shear stress \[MPa\] at pressure `p` \[MPa\] and sliding speed
    /// `speed` \[mm/s\].
    pub fn shear_stress(&self, p: f64, speed: f64) -> f64 {
        self.drag(p, speed) * speed
    }
}
