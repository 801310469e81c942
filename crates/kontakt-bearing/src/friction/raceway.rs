//! Losses of a raceway line contact, slice by slice: the film, the hydrodynamic rolling
//! resistance and the sliding traction of one slice of a roller on its raceway, and the
//! power each dissipates. The bearing's friction torque is the sum of these over the slices
//! and rollers of a solved load distribution (issue 29; not here yet).
//!
//! For a slice of width Δl carrying the load per unit length w, rolling with the mean
//! speed u and sliding with v_s (roller surface relative to the raceway, along the rolling
//! direction):
//!
//! 1. Film (`kontakt::lubrication::line_film_thickness`): isothermal Dowson-Higginson
//!    minimum and Dowson-Toyoda central film, times the Zhu-Cheng inlet-heating factor φ_T
//!    (when the viscosity's temperature slope is given; S = |v_s|/u) and the film
//!    starvation factor φ_s: h = φ_T φ_s h_iso. Λ = h_c/σ.
//! 2. Rolling resistance (`kontakt::lubrication::rolling_resistance`): F_r = φ_T φ_r f Δl,
//!    Zhou & Hoeprich (1991) or Biboulet & Houpert (2010), φ_r the Biboulet-Houpert
//!    starvation factor of the degree S_a = h_a/h_min (1 if not given); moment F_r R about
//!    the roller-side centre of curvature, power 2 F_r u.
//! 3. Sliding traction: the existing mixed law `kontakt::friction::FrictionLaw` with the
//!    slice's film (its φ(Λ) load sharing, boundary Coulomb part and fluid part) integrated
//!    over the Hertz strip p(x) = p_h √(1 − x²/b²):
//!    F_s = −v_s Δl ∫ k(p(x), |v_s|) dx = −v_s Δl b ∫ k(p_h cos θ, |v_s|) cos θ dθ
//!    (x = b sin θ, 32-point Gauss-Legendre in θ), power |F_s| |v_s|.
//!
//! Units: mm, N, N/mm, MPa, mm/s, MPa·s; moments N·mm; power W. Derivations, sources and
//! validity: `docs/raceway-losses.md`.

use kontakt::error::positive_as as positive;
use kontakt::friction::{CellLaw, FilmState, FluidShear, FrictionLaw, LoadSharing};
use kontakt::lubrication::{
    LineFilm, LineFilmContact, LineFilmFormula, LineFilmPowers, LineFilmRegime, LineFilmWarnings,
    RollingResistanceModel, biboulet_houpert_starvation, film_starvation_factor, line_film_regime,
    line_film_thickness, line_film_with, rolling_resistance, thermal_loading,
    zhu_cheng_thermal_factor,
};
use kontakt::{Error, Result};

/// Gauss-Legendre points of the traction integral across the Hertz strip.
pub const TRACTION_POINTS: usize = 32;

/// One slice of a roller-raceway line contact.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RacewaySlice {
    /// Load per unit length w = slice load / slice width \[N/mm\], finite and ≥ 0 (0: an
    /// unloaded slice, no losses).
    pub load_per_length: f64,
    /// Slice width Δl along the roller \[mm\], finite and > 0.
    pub width: f64,
    /// Reduced radius in the rolling direction R \[mm\] (1/R = 1/r_roller + 1/R_raceway,
    /// R_raceway < 0 for the outer ring), finite and > 0.
    pub radius: f64,
    /// Mean (entrainment) speed u = (u_roller + u_raceway)/2 relative to the contact
    /// \[mm/s\], finite and ≥ 0.
    pub entrainment_speed: f64,
    /// Sliding speed v_s of the roller surface relative to the raceway, along the rolling
    /// direction \[mm/s\], finite, any sign.
    pub sliding_speed: f64,
    /// Contact modulus E* \[MPa\], finite and > 0.
    pub reduced_modulus: f64,
}

/// The lubricant and friction data of the raceway contacts.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RacewayLubrication {
    /// Inlet viscosity η₀ at the contact's inlet temperature \[MPa·s\], finite and > 0.
    pub viscosity: f64,
    /// Pressure-viscosity coefficient α \[1/MPa\], finite and > 0.
    pub alpha: f64,
    /// Temperature slope of the inlet viscosity ∂η/∂T \[MPa·s/K\] (≤ 0;
    /// `kontakt::lubrication::viscosity_temperature_slope`). `None`: isothermal, φ_T = 1.
    pub viscosity_slope: Option<f64>,
    /// Thermal conductivity of the oil K \[W/(m·K)\], > 0 (mineral oils ≈ 0.13-0.14; used
    /// only with `viscosity_slope`).
    pub conductivity: f64,
    /// Film starvation factor φ_s in (0, 1] (1 = fully flooded).
    pub film_starvation: f64,
    /// Degree of starvation S_a = h_a/h_min of Biboulet & Houpert (2010) for the rolling
    /// resistance (≥ 0); `None`: fully flooded.
    pub starvation_degree: Option<f64>,
    /// Composite rms roughness σ = √(σ₁² + σ₂²) \[mm\], finite and > 0.
    pub roughness: f64,
    /// The mixed-friction law (boundary coefficient, load sharing φ(Λ), fluid shear).
    pub law: FrictionLaw,
    /// The rolling-resistance fit.
    pub rolling: RollingResistanceModel,
}

/// Validity flags of a slice result: `Copy`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SliceWarnings {
    /// The flags of the film formula.
    pub film: LineFilmWarnings,
    /// S_a below the most starved case that Biboulet & Houpert computed (S = 2).
    pub starvation_extrapolated: bool,
}

/// Losses of one slice.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SliceLosses {
    /// The isothermal, fully flooded film and its regime (`None` for an unloaded slice).
    pub film: Option<LineFilm>,
    /// Zhu-Cheng thermal factor φ_T (1 if isothermal).
    pub thermal_factor: f64,
    /// Central film φ_T φ_s h_c \[mm\].
    pub central_film: f64,
    /// Minimum film φ_T φ_s h_min \[mm\].
    pub minimum_film: f64,
    /// Film parameter Λ = central film / σ.
    pub lambda: f64,
    /// Asperity share of the load φ(Λ) of the friction law.
    pub asperity_share: f64,
    /// Rolling-resistance force F_r \[N\], ≥ 0, opposing the rolling.
    pub rolling_force: f64,
    /// Its moment about the roller's centre of curvature F_r R \[N·mm\].
    pub rolling_moment: f64,
    /// Power dissipated by the rolling resistance 2 F_r u \[W\].
    pub rolling_power: f64,
    /// Sliding traction on the roller along the rolling direction \[N\], opposite to
    /// `sliding_speed`.
    pub sliding_force: f64,
    /// Power dissipated by the sliding traction |F_s| |v_s| \[W\].
    pub sliding_power: f64,
    /// Validity flags.
    pub warnings: SliceWarnings,
}

impl SliceLosses {
    /// Total dissipated power \[W\].
    pub fn power(&self) -> f64 {
        self.rolling_power + self.sliding_power
    }
}

/// The speed-independent part of one loaded slice's losses ([`RacewayLosses::plan_slice`]):
/// what a speed sweep over one load distribution computes once per slice. `Copy`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlicePlan {
    load_per_length: f64,
    radius: f64,
    reduced_modulus: f64,
    regime: LineFilmRegime,
    powers: LineFilmPowers,
    barus: Option<[f64; TRACTION_POINTS / 2]>,
}

/// The raceway-loss model: the checked lubrication data and the quadrature rule, made once;
/// [`RacewayLosses::slice`] then allocates nothing.
#[derive(Debug, Clone, PartialEq)]
pub struct RacewayLosses {
    lubrication: RacewayLubrication,
    rule: [(f64, f64); TRACTION_POINTS],
}

impl RacewayLosses {
    /// Check `lubrication` and build the model.
    ///
    /// # Errors
    /// `Error::InvalidInput` naming the field: `viscosity`, `alpha`, `conductivity`,
    /// `roughness` (finite, > 0), `viscosity_slope` (finite, ≤ 0), `starvation_factor`
    /// (in (0, 1]), `starvation_degree` (finite, ≥ 0), and the law's own fields.
    pub fn new(lubrication: RacewayLubrication) -> Result<Self> {
        let l = &lubrication;
        positive("viscosity", l.viscosity, "a finite viscosity > 0 MPa·s")?;
        positive(
            "alpha",
            l.alpha,
            "a finite pressure-viscosity coefficient > 0 1/MPa",
        )?;
        positive(
            "conductivity",
            l.conductivity,
            "a finite thermal conductivity > 0 W/(m·K)",
        )?;
        positive(
            "roughness",
            l.roughness,
            "a finite composite rms roughness > 0 mm",
        )?;
        if let Some(s) = l.viscosity_slope {
            thermal_loading(s, 0.0, l.conductivity)?;
        }
        film_starvation_factor(l.film_starvation)?;
        if let Some(s) = l.starvation_degree {
            biboulet_houpert_starvation(s)?;
        }
        l.law.check()?;
        let mut rule = [(0.0, 0.0); TRACTION_POINTS];
        let half_pi = std::f64::consts::FRAC_PI_2;
        for (slot, (x, w)) in rule
            .iter_mut()
            .zip(kontakt::quadrature::gauss_legendre(TRACTION_POINTS))
        {
            // θ = (π/2) x on [−π/2, π/2]; store (cos θ, weight · π/2 · cos θ).
            let c = (half_pi * x).cos();
            *slot = (c, w * half_pi * c);
        }
        // The rule is symmetric: θ and −θ share cos θ and the weight. The computed nodes
        // already agree bit for bit (checked in the tests); the mirror makes it certain, so
        // that `traction_per_length` may evaluate the kernel once per pair.
        for i in TRACTION_POINTS / 2..TRACTION_POINTS {
            rule[i] = rule[TRACTION_POINTS - 1 - i];
        }
        Ok(RacewayLosses { lubrication, rule })
    }

    /// The lubrication data.
    pub fn lubrication(&self) -> &RacewayLubrication {
        &self.lubrication
    }

    /// Sliding traction per unit length on the roller \[N/mm\] of a Hertz strip of semi-width
    /// `half_width` b \[mm\] and peak pressure `max_pressure` p_h \[MPa\] sliding at
    /// `sliding_speed` v_s \[mm/s\] under the cell law `law` (a [`FrictionLaw`] with its film):
    /// −v_s b ∫ k(p_h cos θ, |v_s|) cos θ dθ over [−π/2, π/2]. No checks, no allocation.
    ///
    /// The kernel (an `exp` of the Barus viscosity and one of the limiting shear per node)
    /// is evaluated once per symmetric pair of nodes, 16 times instead of 32; the terms are
    /// summed over all 32 nodes in their order, so the sum is the plain rule's bit for bit.
    pub fn traction_per_length(
        &self,
        law: &CellLaw,
        half_width: f64,
        max_pressure: f64,
        sliding_speed: f64,
    ) -> f64 {
        self.traction(law, half_width, max_pressure, sliding_speed, None)
    }

    /// [`RacewayLosses::traction_per_length`], with the Barus factors exp(α p_h cos θ) of
    /// the first half of the nodes given (a [`SlicePlan`]'s) or computed.
    fn traction(
        &self,
        law: &CellLaw,
        half_width: f64,
        max_pressure: f64,
        sliding_speed: f64,
        barus: Option<&[f64; TRACTION_POINTS / 2]>,
    ) -> f64 {
        let speed = sliding_speed.abs();
        let mut half = [0.0; TRACTION_POINTS / 2];
        match barus {
            None => {
                for (t, &(c, wc)) in half.iter_mut().zip(&self.rule) {
                    *t = wc * law.drag(max_pressure * c, speed);
                }
            }
            Some(barus) => {
                for ((t, &(c, wc)), &e) in half.iter_mut().zip(&self.rule).zip(barus) {
                    *t = wc * law.drag_with_barus(max_pressure * c, speed, e);
                }
            }
        }
        let sum: f64 = half.iter().chain(half.iter().rev()).sum();
        -sliding_speed * half_width * sum
    }

    /// The losses of `slice`.
    ///
    /// # Errors
    /// `Error::InvalidInput` naming the slice's field (`load_per_length` finite and ≥ 0,
    /// `width` finite and > 0, `sliding_speed` finite, and those of
    /// `kontakt::lubrication::line_film_thickness`), or `thermal_loading` where the
    /// Zhu-Cheng factor leaves its fit.
    pub fn slice(&self, slice: &RacewaySlice) -> Result<SliceLosses> {
        let l = &self.lubrication;
        check_slice(slice)?;
        if slice.load_per_length == 0.0 {
            return Ok(SliceLosses {
                film: None,
                thermal_factor: 1.0,
                central_film: 0.0,
                minimum_film: 0.0,
                lambda: 0.0,
                asperity_share: 0.0,
                rolling_force: 0.0,
                rolling_moment: 0.0,
                rolling_power: 0.0,
                sliding_force: 0.0,
                sliding_power: 0.0,
                warnings: SliceWarnings::default(),
            });
        }
        let film = line_film_thickness(
            &contact(slice),
            l.viscosity,
            l.alpha,
            LineFilmFormula::DowsonHigginson,
        )?;
        self.losses(slice, film, None)
    }

    /// The speed-independent part of the losses of `slice` (its load, radius and modulus;
    /// its speeds only need to be valid): the line film's groups G and W, the Hertz
    /// semi-width and peak pressure, the powers of G and W in the film formula, and the
    /// Barus factors of the traction nodes when the law has a fluid part. `None` for an
    /// unloaded slice. [`RacewayLosses::slice_planned`] then gives the losses of the same
    /// slice at any speeds with 4 `powf`, 2 `sqrt` and 16 `exp` fewer, bit for bit those of
    /// [`RacewayLosses::slice`]. No allocation.
    ///
    /// # Errors
    /// Those of [`RacewayLosses::slice`] at the slice's speeds.
    pub fn plan_slice(&self, slice: &RacewaySlice) -> Result<Option<SlicePlan>> {
        let l = &self.lubrication;
        check_slice(slice)?;
        if slice.load_per_length == 0.0 {
            return Ok(None);
        }
        let regime = line_film_regime(&contact(slice), l.viscosity, l.alpha)?;
        let fluid = !matches!(l.law.fluid, FluidShear::None)
            && !matches!(l.law.sharing, LoadSharing::Boundary);
        let barus = fluid.then(|| {
            let mut e = [0.0; TRACTION_POINTS / 2];
            for (e, &(c, _)) in e.iter_mut().zip(&self.rule) {
                *e = (l.alpha * (regime.max_pressure * c)).exp();
            }
            e
        });
        Ok(Some(SlicePlan {
            load_per_length: slice.load_per_length,
            radius: slice.radius,
            reduced_modulus: slice.reduced_modulus,
            regime,
            powers: LineFilmPowers::of(&regime, LineFilmFormula::DowsonHigginson),
            barus,
        }))
    }

    /// The losses of `slice` from the speed-independent part `plan`
    /// ([`RacewayLosses::plan_slice`] of a slice with the same load per length, radius and
    /// modulus; any other slice is computed by [`RacewayLosses::slice`]): bit for bit
    /// [`RacewayLosses::slice`].
    ///
    /// # Errors
    /// As [`RacewayLosses::slice`].
    pub fn slice_planned(&self, slice: &RacewaySlice, plan: &SlicePlan) -> Result<SliceLosses> {
        let same = slice.load_per_length.to_bits() == plan.load_per_length.to_bits()
            && slice.radius.to_bits() == plan.radius.to_bits()
            && slice.reduced_modulus.to_bits() == plan.reduced_modulus.to_bits();
        if !same {
            return self.slice(slice);
        }
        check_slice(slice)?;
        let c = contact(slice);
        let regime = plan.regime.at_speed(&c, self.lubrication.viscosity)?;
        let film = line_film_with(&c, &regime, &plan.powers)?;
        self.losses(slice, film, plan.barus.as_ref())
    }

    /// The losses of the loaded, checked `slice` with its isothermal film `film`.
    fn losses(
        &self,
        slice: &RacewaySlice,
        film: LineFilm,
        barus: Option<&[f64; TRACTION_POINTS / 2]>,
    ) -> Result<SliceLosses> {
        let l = &self.lubrication;
        let u = slice.entrainment_speed;
        let thermal_factor = match l.viscosity_slope {
            Some(slope) if u > 0.0 => {
                let lt = thermal_loading(slope, u, l.conductivity)?;
                zhu_cheng_thermal_factor(
                    film.regime.max_pressure,
                    slice.reduced_modulus,
                    lt,
                    slice.sliding_speed.abs() / u,
                )?
            }
            _ => 1.0,
        };
        let reduction = thermal_factor * l.film_starvation;
        let central_film = reduction * film.central;
        let minimum_film = reduction * film.minimum;
        let lambda = central_film / l.roughness;

        let (starve, extrapolated) = match l.starvation_degree {
            Some(s) => biboulet_houpert_starvation(s)?,
            None => (1.0, false),
        };
        let rr = rolling_resistance(
            &film.regime,
            slice.radius,
            slice.reduced_modulus,
            u,
            l.rolling,
        )?;
        let factor = thermal_factor * starve * slice.width;
        let rolling_force = rr.force_per_length * factor;

        let state = FilmState::new(central_film, lambda, l.viscosity, l.alpha)?;
        let cell = l.law.with_film(&state)?;
        let per_length = self.traction(
            &cell,
            film.regime.half_width,
            film.regime.max_pressure,
            slice.sliding_speed,
            barus,
        );
        let sliding_force = per_length * slice.width;
        // N · mm/s = 1e-3 W.
        let sliding_power = (sliding_force * slice.sliding_speed).abs() * 1e-3;
        if !(sliding_force.is_finite() && sliding_power.is_finite()) {
            return Err(Error::invalid(
                "sliding_speed",
                slice.sliding_speed,
                "a sliding speed for which the traction is a finite f64 (a Newtonian fluid \
                 law diverges at high pressure: use Eyring or limiting shear)",
            ));
        }
        Ok(SliceLosses {
            film: Some(film),
            thermal_factor,
            central_film,
            minimum_film,
            lambda,
            asperity_share: cell.asperity_share(),
            rolling_force,
            rolling_moment: rolling_force * slice.radius,
            rolling_power: rr.power_per_length * factor,
            sliding_force,
            sliding_power,
            warnings: SliceWarnings {
                film: film.warnings,
                starvation_extrapolated: extrapolated,
            },
        })
    }
}

/// The film contact of `slice`.
fn contact(slice: &RacewaySlice) -> LineFilmContact {
    LineFilmContact {
        radius: slice.radius,
        entrainment_speed: slice.entrainment_speed,
        load_per_length: slice.load_per_length,
        reduced_modulus: slice.reduced_modulus,
    }
}

/// The checks of [`RacewayLosses::slice`] before the film's: `width`, `sliding_speed`,
/// `load_per_length`.
fn check_slice(slice: &RacewaySlice) -> Result<()> {
    positive("width", slice.width, "a finite slice width > 0 mm")?;
    if !(slice.sliding_speed.is_finite()) {
        return Err(Error::invalid(
            "sliding_speed",
            slice.sliding_speed,
            "a finite sliding speed in mm/s",
        ));
    }
    let w = slice.load_per_length;
    if !(w.is_finite() && w >= 0.0) {
        return Err(Error::invalid(
            "load_per_length",
            w,
            "a finite load per unit length >= 0 N/mm",
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lub(law: FrictionLaw) -> RacewayLubrication {
        RacewayLubrication {
            viscosity: 0.03e-6,
            alpha: 0.02,
            viscosity_slope: None,
            conductivity: 0.134,
            film_starvation: 1.0,
            starvation_degree: None,
            roughness: 0.2e-3,
            law,
            rolling: RollingResistanceModel::BibouletHoupert,
        }
    }

    fn slice() -> RacewaySlice {
        RacewaySlice {
            load_per_length: 500.0,
            width: 1.5,
            radius: 6.0,
            entrainment_speed: 5_000.0,
            sliding_speed: 50.0,
            reduced_modulus: 115_000.0,
        }
    }

    /// Newtonian, Eyring (τ₀ 5 MPa) and limiting-shear (2 MPa + 0.07 p) fluids.
    fn fluids() -> [FluidShear; 3] {
        [
            FluidShear::Newtonian,
            FluidShear::Eyring { tau0: 5.0 },
            FluidShear::LimitingShear {
                tau_l0: 2.0,
                slope: 0.07,
            },
        ]
    }

    /// μ_b = 0.12 with the sharing exp(−b Λ^c) of `(b, c)`, `fluid`, v_ε `eps`.
    fn mixed_with(fluid: FluidShear, (b, c): (f64, f64), eps: f64) -> FrictionLaw {
        FrictionLaw {
            boundary_coefficient: 0.12,
            sharing: LoadSharing::Exponential { b, c },
            fluid,
            regularisation_speed: eps,
        }
    }

    fn rel(a: f64, b: f64) -> f64 {
        (a / b - 1.0).abs()
    }

    fn boundary(mu: f64, eps: f64) -> FrictionLaw {
        FrictionLaw {
            boundary_coefficient: mu,
            sharing: LoadSharing::Boundary,
            fluid: FluidShear::None,
            regularisation_speed: eps,
        }
    }

    /// Coulomb friction over the strip: ∫ μ p dx = μ w exactly (v_ε = 0), 1e-13; the
    /// regularised law is within v_ε²/(2v²) of it; the force opposes the sliding.
    #[test]
    fn coulomb_traction_is_mu_times_the_slice_load() {
        let m = RacewayLosses::new(lub(boundary(0.1, 0.0))).unwrap();
        let s = slice();
        let r = m.slice(&s).unwrap();
        assert!(
            rel(r.sliding_force, -0.1 * 500.0 * 1.5) < 1e-13,
            "{}",
            r.sliding_force
        );
        assert!(rel(r.sliding_power, 75.0 * 50.0 * 1e-3) < 1e-13);
        let back = m
            .slice(&RacewaySlice {
                sliding_speed: -50.0,
                ..s
            })
            .unwrap();
        assert!(rel(back.sliding_force, 75.0) < 1e-13);
        let m = RacewayLosses::new(lub(boundary(0.1, 1.0))).unwrap();
        let r = m.slice(&s).unwrap();
        assert!(rel(r.sliding_force, -75.0) < 0.5 / 2500.0 + 1e-12);
        assert_eq!(r.asperity_share, 1.0);
    }

    /// Newtonian fluid without piezoviscosity (α → 0 in the law's film: FilmState with
    /// α = 0 is not reachable through the slice, so the kernel is tested directly):
    /// ∫ η v/h dx = 2b η v/h, 1e-13.
    #[test]
    fn isoviscous_newtonian_traction_is_the_couette_force() {
        let law = FrictionLaw {
            boundary_coefficient: 0.0,
            sharing: LoadSharing::Exponential { b: 1.0, c: 1.0 },
            fluid: FluidShear::Newtonian,
            regularisation_speed: 0.0,
        };
        let m = RacewayLosses::new(lub(law)).unwrap();
        let film = FilmState::new(1e-3, 1e6, 0.03e-6, 0.0).unwrap();
        let cell = law.with_film(&film).unwrap();
        let f = m.traction_per_length(&cell, 0.1, 1000.0, 200.0);
        let want = -2.0 * 0.1 * 0.03e-6 * 200.0 / 1e-3;
        assert!(rel(f, want) < 1e-13, "{f} vs {want}");
    }

    /// Barus-Newtonian and limiting-shear fluids against an independent midpoint rule in x
    /// (200 000 cells, 1e-4), and the limiting-shear bound ∫ τ_L dx = 2b τ_L0 + γ_L w at
    /// a large sliding speed (1e-9).
    #[test]
    fn piezoviscous_traction_matches_an_independent_integral() {
        let (b, ph, v) = (0.1, 800.0, 30.0);
        let w = std::f64::consts::PI / 2.0 * ph * b;
        for fluid in fluids() {
            let law = mixed_with(fluid, (2.32, 0.97), 0.0);
            let m = RacewayLosses::new(lub(law)).unwrap();
            let film = FilmState::new(0.5e-3, 1.2, 0.03e-6, 0.015).unwrap();
            let cell = law.with_film(&film).unwrap();
            let got = m.traction_per_length(&cell, b, ph, v);
            let n = 200_000;
            let dx = 2.0 * b / n as f64;
            let want: f64 = -(0..n)
                .map(|i| {
                    let x = -b + (i as f64 + 0.5) * dx;
                    cell.shear_stress(ph * (1.0 - x * x / (b * b)).sqrt(), v) * dx
                })
                .sum::<f64>();
            println!(
                "{fluid:?}: {got:.6} vs {want:.6} N/mm, rel {:.1e}",
                rel(got, want)
            );
            assert!(rel(got, want) < 1e-4, "{fluid:?}: {got} vs {want}");
            if let FluidShear::LimitingShear { .. } = fluid {
                let fast = m.traction_per_length(&cell, b, ph, 1e9);
                let phi = cell.asperity_share();
                let bound = phi * 0.12 * w + (1.0 - phi) * (2.0 * b * 2.0 + 0.07 * w);
                assert!(rel(-fast, bound) < 1e-9, "{fast} vs {bound}");
            }
        }
    }

    /// The slice: films and Λ from the line film, φ(Λ) of the law, rolling force = f Δl,
    /// power 2F_r u, thermal and starvation factors applied, zero speed and zero load.
    #[test]
    fn slice_combines_film_rolling_and_sliding() {
        let law = FrictionLaw::mixed(0.12).unwrap();
        let m = RacewayLosses::new(lub(law)).unwrap();
        let s = slice();
        let r = m.slice(&s).unwrap();
        let f = r.film.unwrap();
        assert_eq!(r.central_film, f.central);
        assert!(rel(r.lambda, f.central / 0.2e-3) < 1e-14);
        assert!(rel(r.asperity_share, (-1.90 * r.lambda.powf(0.99)).exp()) < 1e-14);
        let rr = rolling_resistance(
            &f.regime,
            6.0,
            115_000.0,
            5_000.0,
            RollingResistanceModel::BibouletHoupert,
        )
        .unwrap();
        assert!(rel(r.rolling_force, rr.force_per_length * 1.5) < 1e-14);
        assert!(rel(r.rolling_power, 2.0 * r.rolling_force * 5.0) < 1e-14);
        assert!(r.sliding_force < 0.0 && r.power() > r.rolling_power);
        println!(
            "slice: h_c {:.3} µm, Λ {:.2}, φ {:.3}, F_r {:.4} N, F_s {:.4} N, P {:.4} W",
            r.central_film * 1e3,
            r.lambda,
            r.asperity_share,
            r.rolling_force,
            r.sliding_force,
            r.power()
        );
        // Thermal and starvation factors.
        let mut l = lub(law);
        l.viscosity_slope = Some(-1.7e-9);
        l.film_starvation = 0.8;
        l.starvation_degree = Some(20.0);
        let t = RacewayLosses::new(l).unwrap().slice(&s).unwrap();
        assert!(t.thermal_factor < 1.0 && t.thermal_factor > 0.5);
        assert!(rel(t.central_film, 0.8 * t.thermal_factor * f.central) < 1e-14);
        let (st, _) = biboulet_houpert_starvation(20.0).unwrap();
        assert!(rel(t.rolling_force, r.rolling_force * t.thermal_factor * st) < 1e-14);
        // Zero speed: no film, boundary friction only; zero load: nothing.
        let z = m
            .slice(&RacewaySlice {
                entrainment_speed: 0.0,
                ..s
            })
            .unwrap();
        assert_eq!(
            (z.central_film, z.rolling_force, z.asperity_share),
            (0.0, 0.0, 1.0)
        );
        assert!(rel(-z.sliding_force, 0.12 * 750.0) < 1e-3);
        let e = m
            .slice(&RacewaySlice {
                load_per_length: 0.0,
                ..s
            })
            .unwrap();
        assert_eq!(e.power(), 0.0);
    }

    /// The computed Gauss-Legendre rule is symmetric bit for bit (what the mirror in
    /// `RacewayLosses::new` relies on to keep the traction sum unchanged), and the folded
    /// traction equals the plain 32-node sum bit for bit at Newtonian, limiting-shear and
    /// Eyring kernels, sliding and rolling.
    #[test]
    fn folded_traction_is_the_plain_rule_bit_for_bit() {
        let half_pi = std::f64::consts::FRAC_PI_2;
        let rule = kontakt::quadrature::gauss_legendre(TRACTION_POINTS);
        for i in 0..TRACTION_POINTS {
            let (a, b) = (rule[i], rule[TRACTION_POINTS - 1 - i]);
            assert_eq!(a.0.to_bits(), (-b.0).to_bits(), "node {i}");
            assert_eq!(a.1.to_bits(), b.1.to_bits(), "weight {i}");
            assert_eq!(
                (half_pi * a.0).cos().to_bits(),
                (half_pi * b.0).cos().to_bits()
            );
        }
        for fluid in fluids() {
            let law = mixed_with(fluid, (1.9, 0.99), 1.0);
            let m = RacewayLosses::new(lub(law)).unwrap();
            let film = FilmState::new(0.3e-3, 1.5, 0.03e-6, 0.02).unwrap();
            let cell = law.with_film(&film).unwrap();
            for v in [-300.0_f64, -1e-10, 0.0, 2e-13, 0.7, 50.0] {
                let (b, ph) = (0.12, 900.0);
                let plain: f64 = rule
                    .iter()
                    .map(|&(x, w)| {
                        let c = (half_pi * x).cos();
                        w * half_pi * c * cell.drag(ph * c, v.abs())
                    })
                    .sum();
                let got = m.traction_per_length(&cell, b, ph, v);
                assert_eq!(got.to_bits(), (-v * b * plain).to_bits(), "{fluid:?} v {v}");
            }
        }
    }

    /// A planned slice's losses at other speeds are those of the plain computation bit for
    /// bit: every law (boundary, Newtonian, Eyring, limiting shear), thermal factor and
    /// starvation on and off, zero and large entrainment, sliding both ways; a plan of
    /// another slice (other load) falls back to the plain computation; an unloaded slice
    /// has no plan. Also the film's own parts: `LineFilmRegime::at_speed` and
    /// `line_film_with` against `line_film_regime` and `line_film_thickness`.
    #[test]
    fn planned_slices_are_the_plain_slices_bit_for_bit() {
        let laws = [
            boundary(0.1, 1.0),
            FrictionLaw::mixed(0.12).unwrap(),
            FrictionLaw {
                fluid: FluidShear::Newtonian,
                ..FrictionLaw::mixed(0.12).unwrap()
            },
            FrictionLaw {
                fluid: FluidShear::Eyring { tau0: 5.0 },
                ..FrictionLaw::mixed(0.12).unwrap()
            },
        ];
        let mut checked = 0;
        for law in laws {
            for thermal in [false, true] {
                let mut l = lub(law);
                if thermal {
                    l.viscosity_slope = Some(-1.7e-9);
                    l.film_starvation = 0.8;
                    l.starvation_degree = Some(20.0);
                }
                let m = RacewayLosses::new(l).unwrap();
                let plan = m.plan_slice(&slice()).unwrap().unwrap();
                assert_eq!(plan.barus.is_some(), law.fluid != FluidShear::None);
                for (u, v) in [
                    (5_000.0, 50.0),
                    (0.0, 3.0),
                    (1.0, -0.2),
                    (20_000.0, 1e-11),
                    (700.0, -400.0),
                ] {
                    let s = RacewaySlice {
                        entrainment_speed: u,
                        sliding_speed: v,
                        ..slice()
                    };
                    let (Ok(want), Ok(got)) = (m.slice(&s), m.slice_planned(&s, &plan)) else {
                        panic!("{law:?} u {u} v {v}");
                    };
                    assert_eq!(got, want, "{law:?} thermal {thermal} u {u} v {v}");
                    assert_eq!(got.sliding_power.to_bits(), want.sliding_power.to_bits());
                    assert_eq!(got.rolling_power.to_bits(), want.rolling_power.to_bits());
                    let c = contact(&s);
                    let r = line_film_regime(&c, l.viscosity, l.alpha).unwrap();
                    assert_eq!(plan.regime.at_speed(&c, l.viscosity).unwrap(), r);
                    let powers = LineFilmPowers::of(&plan.regime, LineFilmFormula::DowsonHigginson);
                    assert_eq!(
                        line_film_with(&c, &r, &powers).unwrap(),
                        line_film_thickness(
                            &c,
                            l.viscosity,
                            l.alpha,
                            LineFilmFormula::DowsonHigginson
                        )
                        .unwrap()
                    );
                    checked += 1;
                }
                // another slice's plan: the plain computation
                let other = RacewaySlice {
                    load_per_length: 300.0,
                    ..slice()
                };
                assert_eq!(
                    m.slice_planned(&other, &plan).unwrap(),
                    m.slice(&other).unwrap()
                );
                let empty = RacewaySlice {
                    load_per_length: 0.0,
                    ..slice()
                };
                assert!(m.plan_slice(&empty).unwrap().is_none());
            }
        }
        assert_eq!(checked, 40);
    }

    #[test]
    fn bad_input_names_the_field() {
        let law = FrictionLaw::mixed(0.12).unwrap();
        let field = |e: Error| e.field().unwrap_or_default().to_string();
        let mut l = lub(law);
        l.roughness = 0.0;
        assert_eq!(field(RacewayLosses::new(l).unwrap_err()), "roughness");
        let mut l = lub(law);
        l.viscosity_slope = Some(1.0);
        assert_eq!(field(RacewayLosses::new(l).unwrap_err()), "viscosity_slope");
        let mut l = lub(law);
        l.film_starvation = 0.0;
        assert_eq!(
            field(RacewayLosses::new(l).unwrap_err()),
            "starvation_factor"
        );
        let m = RacewayLosses::new(lub(law)).unwrap();
        for (s, want) in [
            (
                RacewaySlice {
                    width: 0.0,
                    ..slice()
                },
                "width",
            ),
            (
                RacewaySlice {
                    sliding_speed: f64::NAN,
                    ..slice()
                },
                "sliding_speed",
            ),
            (
                RacewaySlice {
                    load_per_length: -1.0,
                    ..slice()
                },
                "load_per_length",
            ),
            (
                RacewaySlice {
                    radius: -1.0,
                    ..slice()
                },
                "radius",
            ),
        ] {
            assert_eq!(field(m.slice(&s).unwrap_err()), want);
        }
    }
}
