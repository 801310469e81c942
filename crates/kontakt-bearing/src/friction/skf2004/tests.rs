//! Tests of the SKF model. Reference numbers marked "Python" were computed with an
//! independent throw-away Python implementation of the catalogue formulas (written from
//! the equations in `docs/bearing-friction-catalogue.md`, not from this code).

use super::*;
use crate::friction::{Envelope, Lubrication, OperatingPoint, RPM_PER_RAD_S};

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

/// The 40 × 68 × 19 TRB of Manjunath et al. (2023) as SKF 32008 X (Y = 1.6 assumed).
fn trb() -> (SkfBearing, Envelope) {
    (
        SkfBearing::TaperedRoller {
            series: TaperedSeries::S320X,
            y: 1.6,
        },
        Envelope::new(40.0, 68.0, 19.0).unwrap(),
    )
}

fn point(rpm: f64) -> OperatingPoint {
    OperatingPoint {
        speed_rad_s: rpm / RPM_PER_RAD_S,
        viscosity_mm2_s: 70.11,
        radial_load_n: 0.0,
        axial_load_n: 12_850.0,
        lubrication: Lubrication::OilJet,
    }
}

#[test]
fn phi_bl_matches_the_reference_check_values() {
    // bearing-friction.md §3.2: d_m = 54 mm, ν = 70.11 mm²/s (Manjunath's FVA 3A at
    // 55 °C): φ_bl = 0.408, 0.094, 0.0153, 1.95e-4, 1.15e-6 at 200..1400 r/min.
    let printed = [
        (200.0, 0.408),
        (400.0, 0.094),
        (600.0, 0.0153),
        (1000.0, 1.95e-4),
        (1400.0, 1.15e-6),
    ];
    for (n, want) in printed {
        let got = phi_bl(n, 70.11, 54.0);
        // printed to 3 significant digits (0.094 to 2)
        assert!(rel(got, want) < 5e-3, "n = {n}: {got} vs {want}");
    }
}

#[test]
fn phi_bl_limits_and_mu_sl_bounds() {
    assert_eq!(phi_bl(0.0, 70.0, 54.0), 1.0);
    assert!(phi_bl(1e5, 500.0, 54.0) < 1e-300);
    let (b, e) = trb();
    // standstill: μ_sl is the starting boundary coefficient
    let start = skf2004(&b, &e, &point(0.0), &SkfOptions::default()).unwrap();
    assert_eq!(start.mu_sl, 0.15);
    assert_eq!(start.rolling_nmm, 0.0);
    assert!(start.warnings.starting);
    // far in full film: μ_sl → μ_EHL = 0.002 (TRB)
    let fast = skf2004(&b, &e, &point(20_000.0), &SkfOptions::default()).unwrap();
    assert!((fast.mu_sl - 0.002).abs() < 1e-15, "{}", fast.mu_sl);
    // slowly turning: μ_sl → μ_bl = 0.12
    let slow = skf2004(&b, &e, &point(1e-3), &SkfOptions::default()).unwrap();
    assert!((slow.mu_sl - 0.12).abs() < 1e-8, "{}", slow.mu_sl);
}

#[test]
fn trb_matches_an_independent_implementation() {
    // Python: 32008 X (R1 2.38e-6, R2 10.9, S1 0.014, S2 2, Y 1.6), F_a 12.85 kN,
    // 1000 r/min, ν 70.11 mm²/s, oil jet (K_rs 3e-8, K_Z 6).
    let (b, e) = trb();
    let t = skf2004(&b, &e, &point(1000.0), &SkfOptions::default()).unwrap();
    let want = [
        (t.g_rr, 1.439_837_511_912_385_6),
        (t.g_sl, 15_161.564_740_534_268),
        (t.phi_ish, 0.969_100_611_683_613_2),
        (t.phi_rs, 0.928_342_644_327_988_2),
        (t.phi_bl, 1.954_856_815_928_408e-4),
        (t.rolling_nmm, 1_046.787_752_238_504_5),
        (t.sliding_nmm, 30.672_866_001_511_977),
        (t.total_nmm, 1_077.460_618_240_016_4),
    ];
    for (got, w) in want {
        assert!(rel(got, w) < 1e-12, "{got} vs {w}");
    }
    assert!(t.warnings.unverified_constants);
    assert_eq!(t.drag_nmm, 0.0);
}

#[test]
fn rolling_scales_as_nu_n_to_the_0_6_with_the_factors_removed() {
    let (b, e) = trb();
    let o = SkfOptions::default();
    let base = skf2004(&b, &e, &point(300.0), &o).unwrap();
    let m0 = base.rolling_nmm / (base.phi_ish * base.phi_rs);
    for k in [2.0, 3.7, 10.0] {
        let t = skf2004(&b, &e, &point(300.0 * k), &o).unwrap();
        let m = t.rolling_nmm / (t.phi_ish * t.phi_rs);
        assert!(rel(m / m0, k.powf(0.6)) < 1e-12, "speed ×{k}");
        let p = OperatingPoint {
            viscosity_mm2_s: 70.11 * k,
            ..point(300.0)
        };
        let t = skf2004(&b, &e, &p, &o).unwrap();
        let m = t.rolling_nmm / (t.phi_ish * t.phi_rs);
        assert!(rel(m / m0, k.powf(0.6)) < 1e-12, "viscosity ×{k}");
    }
}

#[test]
fn starvation_factor_depends_on_the_lubrication_method() {
    let (b, e) = trb();
    let o = SkfOptions::default();
    let jet = skf2004(&b, &e, &point(2000.0), &o).unwrap();
    let grease = OperatingPoint {
        lubrication: Lubrication::Grease,
        ..point(2000.0)
    };
    let g = skf2004(&b, &e, &grease, &o).unwrap();
    // K_rs doubles: φ_rs(grease) = φ_rs(jet)²
    assert!(rel(g.phi_rs, jet.phi_rs * jet.phi_rs) < 1e-12);
    assert!(g.total_nmm < jet.total_nmm);
}

#[test]
fn oil_bath_drag_matches_an_independent_implementation() {
    // Python: same bearing, 1000 r/min, H = 10 mm, V_M = 3e-4, K_Z 6, K_L 0.7:
    // t = 1.61486 rad, f_t = 0.72251, R_s = 748.06, first term 2.0964 N·mm,
    // second 8.6056 N·mm.
    let (b, e) = trb();
    let o = SkfOptions {
        drag_factor_vm: Some(3e-4),
        ..SkfOptions::default()
    };
    let p = OperatingPoint {
        lubrication: Lubrication::OilBath { level_mm: 10.0 },
        ..point(1000.0)
    };
    let t = skf2004(&b, &e, &p, &o).unwrap();
    assert!(
        rel(t.drag_nmm, 10.701_955_309_528_424) < 1e-12,
        "{}",
        t.drag_nmm
    );
    assert!(!t.warnings.drag_omitted && !t.warnings.oil_level_above_centre);
    // without V_M: flagged, not silently zero
    let t = skf2004(&b, &e, &p, &SkfOptions::default()).unwrap();
    assert!(t.warnings.drag_omitted && t.drag_nmm == 0.0);
    // a level above the centre is flagged
    let high = OperatingPoint {
        lubrication: Lubrication::OilBath { level_mm: 40.0 },
        ..point(1000.0)
    };
    assert!(
        skf2004(&b, &e, &high, &o)
            .unwrap()
            .warnings
            .oil_level_above_centre
    );
    // no drag at standstill
    let still = OperatingPoint {
        lubrication: Lubrication::OilBath { level_mm: 10.0 },
        ..point(0.0)
    };
    assert_eq!(skf2004(&b, &e, &still, &o).unwrap().drag_nmm, 0.0);
}

#[test]
fn other_types_follow_their_table_formulas() {
    let e = Envelope::new(40.0, 80.0, 18.0).unwrap();
    let dm = 60.0;
    let (fr, fa, n) = (3000.0, 800.0, 1500.0);
    // cylindrical, series 2: G_rr = R1 d_m^2.41 F_r^0.31, G_sl = S1 d_m^0.9 F_a + S2 d_m F_r
    let crb = SkfBearing::CylindricalRoller {
        series: CylindricalSeries::S2,
    };
    let (grr, gsl) = geometry_variables(&crb, dm, n, fr, fa).unwrap();
    assert!(rel(grr, 1.09e-6 * 60f64.powf(2.41) * 3000f64.powf(0.31)) < 1e-14);
    assert!(rel(gsl, 0.16 * 60f64.powf(0.9) * 800.0 + 0.0015 * 60.0 * 3000.0) < 1e-14);
    // deep groove, series 62, F_a = 0 branch
    let dgbb = SkfBearing::DeepGrooveBall {
        series: DeepGrooveSeries::S62,
        c0_n: 19_000.0,
    };
    let (grr, gsl) = geometry_variables(&dgbb, dm, n, fr, 0.0).unwrap();
    assert!(rel(grr, 3.9e-7 * 60f64.powf(1.96) * 3000f64.powf(0.54)) < 1e-14);
    assert!(rel(gsl, 3.23e-3 * 60f64.powf(-0.26) * 3000f64.powf(5.0 / 3.0)) < 1e-14);
    // with F_a: α_F = 24.6 (F_a/C0)^0.24 degrees
    let (grr_a, _) = geometry_variables(&dgbb, dm, n, fr, fa).unwrap();
    let s = (24.6 * (800.0f64 / 19_000.0).powf(0.24)).to_radians().sin();
    assert!(
        rel(
            grr_a,
            3.9e-7 * 60f64.powf(1.96) * (3000.0 + 1.7 / s * 800.0).powf(0.54)
        ) < 1e-14
    );
    // angular contact: the centrifugal load F_g = R3 d_m^4 n² enters both variables
    let acbb = SkfBearing::AngularContactBall {
        series: AngularContactSeries::S73Becbp,
    };
    let (grr, _) = geometry_variables(&acbb, dm, n, fr, fa).unwrap();
    let fg = 1.84e-12 * 60f64.powi(4) * n * n;
    assert!(
        rel(
            grr,
            4.54e-7 * 60f64.powf(1.97) * (3000.0 + fg + 2.02 * 800.0).powf(0.54)
        ) < 1e-14
    );
    let t = skf2004(
        &acbb,
        &e,
        &OperatingPoint {
            speed_rad_s: n / RPM_PER_RAD_S,
            viscosity_mm2_s: 20.0,
            radial_load_n: fr,
            axial_load_n: fa,
            lubrication: Lubrication::OilAir,
        },
        &SkfOptions::default(),
    )
    .unwrap();
    assert!(
        !t.warnings.unverified_constants,
        "73 BECBP is cross-checked"
    );
    assert!(t.total_nmm.is_finite() && t.total_nmm > 0.0);
}

#[test]
fn tables_are_complete_and_parse_by_name() {
    assert_eq!(TaperedSeries::ALL.len(), 20);
    for s in TaperedSeries::ALL {
        let c = s.constants();
        assert_eq!(c.s2, 2.0);
        assert!(c.r2 == 10.9 || (*s == TaperedSeries::S330 && c.r2 == 11.3));
        assert_eq!(TaperedSeries::from_name(s.name()).unwrap(), *s);
    }
    assert_eq!(
        TaperedSeries::from_name("320x").unwrap(),
        TaperedSeries::S320X
    );
    let e = TaperedSeries::from_name("999").unwrap_err();
    assert_eq!(e.field(), Some("series"));
    assert!(e.to_string().contains("320 X"));
}

#[test]
fn bad_input_names_the_field() {
    let (b, e) = trb();
    let o = SkfOptions::default();
    let neg = OperatingPoint {
        speed_rad_s: -5.0,
        ..point(100.0)
    };
    let err = skf2004(&b, &e, &neg, &o).unwrap_err();
    assert_eq!(err.field(), Some("speed_rad_s"));
    assert!(err.to_string().contains("-5"));
    let dry = OperatingPoint {
        viscosity_mm2_s: 0.0,
        ..point(100.0)
    };
    assert_eq!(
        skf2004(&b, &e, &dry, &o).unwrap_err().field(),
        Some("viscosity_mm2_s")
    );
    let no_y = SkfBearing::TaperedRoller {
        series: TaperedSeries::S302,
        y: 0.0,
    };
    assert_eq!(
        skf2004(&no_y, &e, &point(100.0), &o).unwrap_err().field(),
        Some("y")
    );
    let bad_mu = SkfOptions { mu_bl: 1.5, ..o };
    assert_eq!(
        skf2004(&b, &e, &point(100.0), &bad_mu).unwrap_err().field(),
        Some("mu_bl")
    );
    // absurd speed: finite (φ_ish, φ_rs → 0 kill the rolling term), never NaN
    let huge = OperatingPoint {
        speed_rad_s: 1e300,
        ..point(100.0)
    };
    let t = skf2004(&b, &e, &huge, &o).unwrap();
    assert!(t.total_nmm.is_finite() && t.rolling_nmm == 0.0);
    // absurd load: the torque overflows, and the error names the load
    let heavy = OperatingPoint {
        axial_load_n: 1e308,
        ..point(100.0)
    };
    assert_eq!(
        skf2004(&b, &e, &heavy, &o).unwrap_err().field(),
        Some("axial_load_n")
    );
    let unloaded = OperatingPoint {
        axial_load_n: 0.0,
        ..point(100.0)
    };
    let t = skf2004(&b, &e, &unloaded, &o).unwrap();
    assert!(t.warnings.no_load && t.total_nmm == 0.0);
    assert_eq!(t.warnings.lines().len(), 2);
}
