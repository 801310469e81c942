//! Aihara (1987), "A New Running Torque Formula for Tapered Roller Bearings Under Axial
//! Load", J. Tribol. 109:471-478: the running torque of a tapered roller bearing under a
//! purely axial load as EHL rolling resistance of the raceways plus sliding at the rib.
//!
//! Aihara's simplified model treats the bearing as a cylindrical roller bearing with an
//! inner-ring rib: rollers of mean diameter D_a, raceway radii R_i, R_o at the roller
//! centres (R_o ≈ R_i + D_a). The torque on the outer ring is (eq. 26)
//!
//! `M = (z/D_a)(R_o M_i + R_i M_o) + e μ0 cos β F_a exp(−1.8 Λ_r^1.2)` = `M_R + M_S`,
//!
//! with the rolling resistance of each raceway contact (eq. 27)
//!
//! `M_{i,o} = [176 / (1 + 0.29 L^0.78)] (1/α0) (G U)^0.658 W^0.31 R_e² l`,
//!
//! `U = η0 u/(E' R_e)`, `W = Q/(l E' R_e)`, `G = α0 E'`, thermal loading
//! `L = η0 β_T u²/k`, roller load `Q = F_a/(z sin α)` (eq. 2, α the cup half angle), μ0 = 0.2
//! (Coulomb friction at the rib), Λ_r the film parameter of the rib contact with
//! `h0 = 1.25 h_min` (Hamrock-Dowson minimum film, eqs 16-17; [`rib_film_parameter`]).
//!
//! **Where 176 comes from** (so that it can be checked): eq. 22 `M = 2 R_e t_r l`
//! (per unit length t_r, Appendix 1), eq. 19 `t_r0 = (4.318/α0)(GU)^0.658 W^0.0126 R_e`
//! (Goksem & Hargreaves after Crook), and the measured load correction of eq. 25,
//! `20.4 W^0.3`: `2 × 4.318 × 20.4 = 176.17`, and `W^(0.0126 + 0.3) ≈ W^0.31`. The W of
//! eq. 25 uses D_a/2 for the radius, eq. 27's bracket is evaluated per contact: we use the
//! contact's R_e in both U and W (as Manjunath et al. 2023, Table 1, transcribe it).
//!
//! **Kinematics** (derived): with the outer ring fixed, pure rolling at both raceways
//! gives the cage speed `ω_c = ω R_i/(R_i + R_o)` and the same rolling (entrainment)
//! speed at both contacts, `u = (ω − ω_c) R_i = ω_c R_o = ω R_i R_o/(R_i + R_o)`.
//! Reduced radii in the rolling direction: `R_e,i = r R_i/(R_i + r)` (convex-convex),
//! `R_e,o = r R_o/(R_o − r)` (concave outer race), `r = D_a/2`.
//!
//! Range (as published): bearings of 17-120 mm bore, axial loads 1-14 kN, to 3300 r/min,
//! oil circulated at a fixed temperature, every roller loaded. The formula omits cage
//! friction and oil drag (small at the tested speeds, the paper says), elastic hysteresis,
//! and any radial load (valid for combined loads only while every roller is loaded).
//!
//! Units: mm, N, MPa, N·mm, dynamic viscosity MPa·s (1 Pa·s = 10⁻⁶ MPa·s), α0 1/MPa,
//! speeds rad/s and mm/s, thermal conductivity W/(m·K) (= N/(s·K), which makes L
//! dimensionless with MPa·s and mm/s).

use super::{finite_or, non_negative_as};
use kontakt::error::positive_as;
use kontakt::{Error, Result};

/// The coefficient of eq. 27 as printed (1.76 × 10²).
pub const COEFFICIENT: f64 = 176.0;

/// Coulomb friction coefficient of the rib contact μ0 (Aihara 1987, eq. 15).
pub const MU0: f64 = 0.2;

/// The factor of Aihara's rib film: `h0 = 1.25 h_min` (eq. 16).
pub const RIB_FILM_FACTOR: f64 = 1.25;

/// The tapered roller bearing in Aihara's simplified model.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct AiharaBearing {
    /// Number of rollers z, ≥ 1.
    pub rollers: u32,
    /// Mean roller diameter D_a \[mm\].
    pub roller_diameter_mm: f64,
    /// Inner raceway radius at the roller centre R_i \[mm\].
    pub inner_radius_mm: f64,
    /// Outer raceway radius at the roller centre R_o \[mm\], > D_a/2.
    pub outer_radius_mm: f64,
    /// Effective roller length l \[mm\].
    pub effective_length_mm: f64,
    /// Outer raceway (cup) half angle α \[rad\], 0 < α < π/2.
    pub cup_angle_rad: f64,
    /// Roller half angle β \[rad\] (roller head angle 2β), 0 ≤ β < π/4.
    pub roller_half_angle_rad: f64,
    /// Height e of the roller-end/rib contact above the raceway \[mm\], ≥ 0.
    pub rib_height_mm: f64,
    /// Reduced modulus E' = 2/\[(1 − ν₁²)/E₁ + (1 − ν₂²)/E₂\] \[MPa\] (Hamrock-Dowson's E').
    pub reduced_modulus_mpa: f64,
}

/// The lubricant properties the formula needs, at the operating temperature.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct AiharaLubricant {
    /// Dynamic viscosity at ambient pressure η0 \[MPa·s\].
    pub viscosity_mpa_s: f64,
    /// Pressure-viscosity coefficient α0 \[1/MPa\].
    pub pressure_viscosity_per_mpa: f64,
    /// Temperature-viscosity coefficient β_T \[1/K\], ≥ 0 (0: isothermal).
    pub temperature_viscosity_per_k: f64,
    /// Thermal conductivity k \[W/(m·K)\].
    pub thermal_conductivity_w_mk: f64,
}

/// The rolling resistance of one raceway contact.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RacewayResistance {
    /// Reduced radius in the rolling direction R_e \[mm\].
    pub reduced_radius_mm: f64,
    /// Speed parameter U.
    pub u: f64,
    /// Load parameter W (per unit length).
    pub w: f64,
    /// Thermal loading parameter L.
    pub thermal_loading: f64,
    /// Rolling resistance moment M_i or M_o on one roller \[N·mm\].
    pub moment_nmm: f64,
}

/// Aihara's running torque and its parts.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct AiharaTorque {
    /// Rolling (entrainment) speed at both raceways u \[mm/s\].
    pub rolling_speed_mm_s: f64,
    /// Roller load Q = F_a/(z sin α) \[N\].
    pub roller_load_n: f64,
    /// Material parameter G = α0 E'.
    pub g: f64,
    /// Inner raceway contact.
    pub inner: RacewayResistance,
    /// Outer raceway contact.
    pub outer: RacewayResistance,
    /// Rib friction coefficient μ = μ0 exp(−1.8 Λ_r^1.2).
    pub rib_friction: f64,
    /// Rolling resistance torque M_R \[N·mm\].
    pub rolling_nmm: f64,
    /// Rib sliding torque M_S \[N·mm\].
    pub rib_nmm: f64,
    /// Total M \[N·mm\].
    pub total_nmm: f64,
}

/// Aihara's rib film parameter `Λ_r = 1.25 h_min / σ` from the Hamrock-Dowson minimum film
/// of the rib contact `h_min_mm` (e.g. `kontakt::lubrication::film::film_thickness` with
/// `FilmFormula::HamrockDowson`) and the composite roughness `sigma_mm`.
///
/// # Errors
/// [`Error::InvalidInput`] naming `h_min_mm` (finite, ≥ 0) or `sigma_mm` (finite, > 0).
pub fn rib_film_parameter(h_min_mm: f64, sigma_mm: f64) -> Result<f64> {
    let h = non_negative_as("h_min_mm", h_min_mm, "a finite film thickness >= 0 mm")?;
    let s = positive_as("sigma_mm", sigma_mm, "a finite composite roughness > 0 mm")?;
    Ok(RIB_FILM_FACTOR * h / s)
}

impl AiharaBearing {
    fn check(&self) -> Result<()> {
        if self.rollers == 0 {
            return Err(Error::invalid("rollers", 0, "a number of rollers >= 1"));
        }
        let da = positive_as(
            "roller_diameter_mm",
            self.roller_diameter_mm,
            "a finite diameter > 0 mm",
        )?;
        positive_as(
            "inner_radius_mm",
            self.inner_radius_mm,
            "a finite radius > 0 mm",
        )?;
        let ro = positive_as(
            "outer_radius_mm",
            self.outer_radius_mm,
            "a finite radius > 0 mm",
        )?;
        if ro <= 0.5 * da {
            return Err(Error::invalid(
                "outer_radius_mm",
                ro,
                format!("a radius > half the roller diameter, {} mm", 0.5 * da),
            ));
        }
        positive_as(
            "effective_length_mm",
            self.effective_length_mm,
            "a finite length > 0 mm",
        )?;
        let a = self.cup_angle_rad;
        if !(a.is_finite() && a > 0.0 && a < std::f64::consts::FRAC_PI_2) {
            return Err(Error::invalid("cup_angle_rad", a, "0 < α < π/2 rad"));
        }
        let b = self.roller_half_angle_rad;
        if !(b.is_finite() && (0.0..std::f64::consts::FRAC_PI_4).contains(&b)) {
            return Err(Error::invalid(
                "roller_half_angle_rad",
                b,
                "0 <= β < π/4 rad",
            ));
        }
        non_negative_as(
            "rib_height_mm",
            self.rib_height_mm,
            "a finite height >= 0 mm",
        )?;
        positive_as(
            "reduced_modulus_mpa",
            self.reduced_modulus_mpa,
            "a finite modulus E' > 0 MPa",
        )?;
        Ok(())
    }
}

impl AiharaLubricant {
    fn check(&self) -> Result<()> {
        positive_as(
            "viscosity_mpa_s",
            self.viscosity_mpa_s,
            "a finite dynamic viscosity > 0 MPa·s",
        )?;
        positive_as(
            "pressure_viscosity_per_mpa",
            self.pressure_viscosity_per_mpa,
            "a finite pressure-viscosity coefficient > 0 1/MPa",
        )?;
        non_negative_as(
            "temperature_viscosity_per_k",
            self.temperature_viscosity_per_k,
            "a finite temperature-viscosity coefficient >= 0 1/K",
        )?;
        positive_as(
            "thermal_conductivity_w_mk",
            self.thermal_conductivity_w_mk,
            "a finite thermal conductivity > 0 W/(m·K)",
        )?;
        Ok(())
    }
}

/// Aihara's running torque of `bearing` lubricated by `oil`, inner ring at `speed_rad_s`
/// (outer ring fixed), axial load `axial_load_n`, rib film parameter `rib_lambda` (0 at
/// standstill: then M = e μ0 cos β F_a, Aihara's starting torque).
///
/// # Errors
/// [`Error::InvalidInput`] naming the field: those of [`AiharaBearing`] and
/// [`AiharaLubricant`], `speed_rad_s`, `axial_load_n`, `rib_lambda` (finite, ≥ 0); a
/// torque that overflows names `speed_rad_s`.
pub fn aihara(
    bearing: &AiharaBearing,
    oil: &AiharaLubricant,
    speed_rad_s: f64,
    axial_load_n: f64,
    rib_lambda: f64,
) -> Result<AiharaTorque> {
    bearing.check()?;
    oil.check()?;
    let omega = non_negative_as("speed_rad_s", speed_rad_s, "a finite speed >= 0 rad/s")?;
    let fa = non_negative_as("axial_load_n", axial_load_n, "a finite load >= 0 N")?;
    let lambda = non_negative_as("rib_lambda", rib_lambda, "a finite film parameter >= 0")?;

    let (ri, ro) = (bearing.inner_radius_mm, bearing.outer_radius_mm);
    let r = 0.5 * bearing.roller_diameter_mm;
    let z = f64::from(bearing.rollers);
    let l = bearing.effective_length_mm;
    let e_prime = bearing.reduced_modulus_mpa;
    let u = omega * ri * ro / (ri + ro);
    let q = fa / (z * bearing.cup_angle_rad.sin());
    let alpha0 = oil.pressure_viscosity_per_mpa;
    let g = alpha0 * e_prime;
    let thermal = oil.viscosity_mpa_s * oil.temperature_viscosity_per_k * u * u
        / oil.thermal_conductivity_w_mk;
    let contact = |re: f64| -> RacewayResistance {
        let u_param = oil.viscosity_mpa_s * u / (e_prime * re);
        let w_param = q / (l * e_prime * re);
        let moment = COEFFICIENT / (1.0 + 0.29 * thermal.powf(0.78)) / alpha0
            * (g * u_param).powf(0.658)
            * w_param.powf(0.31)
            * re
            * re
            * l;
        RacewayResistance {
            reduced_radius_mm: re,
            u: u_param,
            w: w_param,
            thermal_loading: thermal,
            moment_nmm: moment,
        }
    };
    let inner = contact(r * ri / (ri + r));
    let outer = contact(r * ro / (ro - r));
    let rolling = z / bearing.roller_diameter_mm * (ro * inner.moment_nmm + ri * outer.moment_nmm);
    let rolling = finite_or("speed_rad_s", speed_rad_s, rolling)?;
    let mu = MU0 * (-1.8 * lambda.powf(1.2)).exp();
    let rib = bearing.rib_height_mm * mu * bearing.roller_half_angle_rad.cos() * fa;
    let total = finite_or("axial_load_n", fa, rolling + rib)?;
    Ok(AiharaTorque {
        rolling_speed_mm_s: u,
        roller_load_n: q,
        g,
        inner,
        outer,
        rib_friction: mu,
        rolling_nmm: rolling,
        rib_nmm: rib,
        total_nmm: total,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 32008-class TRB with the geometry of Liu Y. et al. (2022, Table 1) as in
    /// bearing-friction.md §1.3; R_i, R_o from d_m = 54.3 mm.
    fn bearing() -> AiharaBearing {
        let da = (6.131 + 6.846) / 2.0;
        let ri = 27.15 - da / 2.0;
        AiharaBearing {
            rollers: 23,
            roller_diameter_mm: da,
            inner_radius_mm: ri,
            outer_radius_mm: ri + da,
            effective_length_mm: 13.66,
            cup_angle_rad: 0.2473,
            roller_half_angle_rad: 0.0262,
            rib_height_mm: 1.0,
            reduced_modulus_mpa: 210_000.0 / (1.0 - 0.278 * 0.278),
        }
    }

    /// FVA 3 at 50 °C (η0 0.0525 Pa·s, α 20.96 1/GPa, λ 0.134 W/(m K), bearing-friction.md
    /// §2.2) with an assumed β_T = 0.035 1/K.
    fn oil() -> AiharaLubricant {
        AiharaLubricant {
            viscosity_mpa_s: 0.0525e-6,
            pressure_viscosity_per_mpa: 0.02096,
            temperature_viscosity_per_k: 0.035,
            thermal_conductivity_w_mk: 0.134,
        }
    }

    fn rpm(n: f64) -> f64 {
        n * 2.0 * std::f64::consts::PI / 60.0
    }

    fn rel(a: f64, b: f64) -> f64 {
        ((a - b) / b).abs()
    }

    #[test]
    fn the_coefficient_is_the_product_of_its_derivation() {
        // eq. 22 × eq. 19 × eq. 25: 2 · 4.318 · 20.4 = 176.17, printed 1.76e2
        assert!(rel(2.0 * 4.318 * 20.4, COEFFICIENT) < 1e-3);
    }

    #[test]
    fn matches_an_independent_implementation() {
        // Python (throw-away, from the equations above): 1000 r/min, F_a 10 kN, Λ_r 2.59
        let t = aihara(&bearing(), &oil(), rpm(1000.0), 10_000.0, 2.59).unwrap();
        let want = [
            (t.rolling_speed_mm_s, 1_401.272_480_999_828_5),
            (t.inner.reduced_radius_mm, 2.856_583_036_372_007_3),
            (t.outer.reduced_radius_mm, 3.631_916_963_627_993),
            (t.inner.u, 1.131_576_189_205_038_6e-10),
            (t.inner.w, 2.000_023_155_337_762_6e-4),
            (t.inner.thermal_loading, 0.026_925_745_448_049_435),
            (t.inner.moment_nmm, 4.931_108_077_985_115),
            (t.outer.moment_nmm, 6.317_872_089_962_701),
            (t.rolling_nmm, 1_066.648_448_103_61),
            (t.rib_nmm, 7.107_623_952_168_704),
            (t.total_nmm, 1_073.756_072_055_778_8),
        ];
        for (got, w) in want {
            assert!(rel(got, w) < 1e-12, "{got} vs {w}");
        }
    }

    #[test]
    fn rib_term_reproduces_the_reference_sweep() {
        // bearing-friction.md §3.4: e = 1 mm, F_a = 10 kN, M_rib = e μ F_a (β = 0):
        // Λ 0.11..2.59 → 1.75, 1.23, 0.84, 0.44, 0.14, 0.007 N·m (printed from rounded Λ)
        let b = AiharaBearing {
            roller_half_angle_rad: 0.0,
            ..bearing()
        };
        let printed = [
            (0.11, 1750.0),
            (0.34, 1230.0),
            (0.54, 840.0),
            (0.87, 440.0),
            (1.39, 140.0),
            (2.59, 7.0),
        ];
        for (lambda, m) in printed {
            let t = aihara(&b, &oil(), rpm(100.0), 10_000.0, lambda).unwrap();
            assert!(rel(t.rib_nmm, m) < 0.02, "Λ {lambda}: {} vs {m}", t.rib_nmm);
        }
        // standstill: Aihara's starting torque e μ0 cos β F_a, no rolling resistance
        let s = aihara(&bearing(), &oil(), 0.0, 10_000.0, 0.0).unwrap();
        assert_eq!(s.rolling_nmm, 0.0);
        assert!(rel(s.total_nmm, 1.0 * 0.2 * 0.0262f64.cos() * 10_000.0) < 1e-14);
    }

    #[test]
    fn exact_scaling_laws() {
        let iso = AiharaLubricant {
            temperature_viscosity_per_k: 0.0,
            ..oil()
        };
        let a = aihara(&bearing(), &iso, rpm(500.0), 5000.0, 3.0).unwrap();
        for k in [2.0, 5.0] {
            // isothermal: M_R ∝ (η0 u)^0.658, ∝ F_a^0.31
            let b = aihara(&bearing(), &iso, rpm(500.0 * k), 5000.0, 3.0).unwrap();
            assert!(rel(b.rolling_nmm / a.rolling_nmm, k.powf(0.658)) < 1e-12);
            let c = aihara(&bearing(), &iso, rpm(500.0), 5000.0 * k, 3.0).unwrap();
            assert!(rel(c.rolling_nmm / a.rolling_nmm, k.powf(0.31)) < 1e-12);
        }
        // thermal factor 1/(1 + 0.29 L^0.78) on both contacts
        let hot = aihara(&bearing(), &oil(), rpm(500.0), 5000.0, 3.0).unwrap();
        let l = hot.inner.thermal_loading;
        assert!(
            rel(
                hot.rolling_nmm / a.rolling_nmm,
                1.0 / (1.0 + 0.29 * l.powf(0.78))
            ) < 1e-12
        );
        assert_eq!(rib_film_parameter(2e-4, 2.5e-4).unwrap(), 1.0);
    }

    #[test]
    fn bad_input_names_the_field() {
        let e = aihara(&bearing(), &oil(), -1.0, 1000.0, 1.0).unwrap_err();
        assert_eq!(e.field(), Some("speed_rad_s"));
        let dry = AiharaLubricant {
            viscosity_mpa_s: 0.0,
            ..oil()
        };
        assert_eq!(
            aihara(&bearing(), &dry, 10.0, 1000.0, 1.0)
                .unwrap_err()
                .field(),
            Some("viscosity_mpa_s")
        );
        let flat = AiharaBearing {
            cup_angle_rad: 0.0,
            ..bearing()
        };
        assert_eq!(
            aihara(&flat, &oil(), 10.0, 1000.0, 1.0)
                .unwrap_err()
                .field(),
            Some("cup_angle_rad")
        );
        assert_eq!(
            aihara(&bearing(), &oil(), 10.0, 1000.0, f64::NAN)
                .unwrap_err()
                .field(),
            Some("rib_lambda")
        );
        assert_eq!(
            rib_film_parameter(1e-4, 0.0).unwrap_err().field(),
            Some("sigma_mm")
        );
    }
}
