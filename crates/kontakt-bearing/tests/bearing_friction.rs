//! Issue 29 §1-2: the friction torque of a whole roller bearing from its load distribution
//! (`kontakt_bearing::friction::torque`): the rib share against the rib friction of the
//! `kontakt friction` study, the 32008 X at Manjunath et al.'s (2023) conditions beside the
//! SKF model, and no allocation per operating point.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

#[path = "support/cases.rs"]
#[allow(dead_code)]
mod cases;
#[path = "../../kontakt/tests/support/counting_alloc.rs"]
mod counting_alloc;
#[path = "support/friction.rs"]
mod support;

use counting_alloc::allocations;
use kontakt::bearing::{PressureModel, RollerSet};
use kontakt::lubrication::Lubricant;
use kontakt_bearing::friction::skf2004::{SkfBearing, SkfOptions, TaperedSeries, skf2004};
use kontakt_bearing::friction::torque::{
    BearingFriction, BearingFrictionModel, DragModel, FrictionOperating, roller_cups,
};
use kontakt_bearing::friction::{Envelope, Lubrication, OperatingPoint, RPM_PER_RAD_S};
use kontakt_bearing::geometry::RollerBearing;
use support::{losses, rib_study, solved, vg68};

/// The bearing's friction at the inner-ring speed `w` \[rad/s\] (outer ring fixed).
fn at(
    model: &mut BearingFrictionModel,
    w: f64,
    (cup, cone): (&[f64], &[f64]),
    rib: Option<&[f64]>,
    basis: Option<(f64, f64)>,
) -> BearingFriction {
    model
        .evaluate(&FrictionOperating {
            inner_speed: w,
            outer_speed: 0.0,
            cup_slices: cup,
            cone_slices: cone,
            tilts: None,
            rib,
            drag: DragModel::None,
            coefficient_basis: basis,
        })
        .unwrap()
}

/// The rib study bearing (sphere-torus-57, 17 rollers) under 15 kN axial at 1500 r/min:
/// the rib share of the whole-bearing torque, from each roller's rib power of
/// `RibFrictionModel::evaluate_rollers` on the ISO model's cup loads, equals the
/// `kontakt friction` result of the same bearing under the same axial load (every roller
/// Q_e = F_a/(Z sin α_o)) to 1e-9, for each pressure model (Hertz, PimP, half-space).
#[test]
fn rib_share_equals_the_rib_friction_study() {
    let (rib, bearing) = rib_study(17);
    let fa = 15_000.0;
    let w = 1500.0 / RPM_PER_RAD_S;
    let (cup, cone, solver) = solved(&bearing, fa);
    let k = rib.kinematics(w, 0.0).unwrap();
    let loads = rib
        .roller_loads_on_cups(&k, &roller_cups(solver.roller_loads()))
        .unwrap();
    let mut model = BearingFrictionModel::new(bearing, losses(&vg68(), 70.0, true)).unwrap();
    let mut f = None;
    // every pressure model of the rib friction (the case's `operating.rib_pressure`)
    for pressure in PressureModel::ALL {
        let per_roller = rib.evaluate_rollers(pressure, &k, &loads).unwrap();
        let powers: Vec<f64> = per_roller.rollers.iter().map(|r| r.power()).collect();
        let g = at(&mut model, w, (&cup, &cone), Some(&powers), None);
        let study = rib
            .evaluate(
                pressure,
                &kontakt::bearing::rib_friction::Operating {
                    axial_load: fa,
                    inner_speed: w,
                    outer_speed: 0.0,
                },
            )
            .unwrap();
        println!(
            "{}: rib share {:.6} N·mm, evaluate_rollers {:.6}, kontakt friction {:.6}; raceways {:.3} N·mm",
            pressure.as_str(),
            g.rib_nmm,
            per_roller.torque,
            study.bearing_torque,
            g.cone.total_nmm() + g.cup.total_nmm()
        );
        assert!((g.rib_nmm / per_roller.torque - 1.0).abs() < 1e-12);
        assert!(
            (g.rib_nmm / study.bearing_torque - 1.0).abs() < 1e-9,
            "{}: {} vs {}",
            pressure.as_str(),
            g.rib_nmm,
            study.bearing_torque
        );
        if pressure == PressureModel::Hertz {
            f = Some(g);
        }
    }
    let f = f.unwrap();
    // the cage speed of the friction model is the rib study's kinematics
    assert!((f.cage_speed_rad_s / k.cage_speed - 1.0).abs() < 1e-12);
    // the bench's 20-roller variant of this bearing is valid
    let twenty = RollerSet {
        count: 20,
        ..RollerSet::default()
    };
    BearingFrictionModel::new(
        RollerBearing::of_roller_rib(rib.pair(), &twenty).unwrap(),
        losses(&vg68(), 70.0, true),
    )
    .unwrap();
}

/// The 32008 X (examples/bearing_32008x.toml geometry, Liu 2022 internal data) at
/// Manjunath et al.'s (2023) conditions: 12.85 kN axial, FVA 3A (ν40 = 90.02,
/// ν100 = 10.41 mm²/s, ρ = 884.1 kg/m³; α = 0.021 1/MPa assumed), 55 °C, 200-2200 r/min,
/// σ = 0.2 µm assumed, mixed law μ_b = 0.12; raceways only (no rib geometry in the case),
/// beside SKF 2004 (320 X, Y = 1.6, oil jet). Records the numbers; no pass/fail against
/// measurement. Checks the power balance at every speed.
#[test]
fn trb_32008x_at_manjunath_conditions_beside_skf() {
    let mut b = RollerBearing::tapered(
        54.0,
        23,
        6.4885,
        13.66,
        14.17_f64.to_radians(),
        11.17_f64.to_radians(),
    );
    b.slices = 31;
    let fa = 12_850.0;
    let (cup, cone, _) = solved(&b, fa);
    let oil = Lubricant::new(90.02, 10.41, 884.1, 0.021).unwrap();
    let t = 55.0;
    let nu = oil.kinematic_viscosity(t).unwrap();
    let mut model = BearingFrictionModel::new(b, losses(&oil, t, true)).unwrap();
    let skf_bearing = SkfBearing::TaperedRoller {
        series: TaperedSeries::S320X,
        y: 1.6,
    };
    let env = Envelope::new(40.0, 68.0, 19.0).unwrap();
    println!("32008 X, 12.85 kN axial, FVA 3A at 55 °C (ν = {nu:.2} mm²/s)");
    println!(
        "n r/min | cone roll | cup roll | cone slide | cup slide | total | SKF total (rr, sl) N·mm | min Λ"
    );
    for n in [200.0, 400.0, 600.0, 1000.0, 1400.0, 1800.0, 2200.0] {
        let w = n / RPM_PER_RAD_S;
        let f = at(&mut model, w, (&cup, &cone), None, Some((fa, 40.0)));
        let skf = skf2004(
            &skf_bearing,
            &env,
            &OperatingPoint {
                speed_rad_s: w,
                viscosity_mm2_s: nu,
                radial_load_n: 0.0,
                axial_load_n: fa,
                lubrication: Lubrication::OilJet,
            },
            &SkfOptions::default(),
        )
        .unwrap();
        println!(
            "{n:6.0} | {:8.1} | {:8.1} | {:8.3} | {:8.3} | {:7.1} | {:7.1} ({:.1}, {:.1}) | {:.2}",
            f.cone.rolling_nmm,
            f.cup.rolling_nmm,
            f.cone.sliding_nmm,
            f.cup.sliding_nmm,
            f.total_nmm,
            skf.total_nmm,
            skf.rolling_nmm,
            skf.sliding_nmm,
            f.min_lambda
        );
        assert!(f.total_nmm.is_finite() && f.total_nmm > 0.0);
        let balance = f.inner_ring_nmm * w * 1e-3;
        assert!((balance / f.power.total_w - 1.0).abs() < 1e-12);
    }
}

/// Issue 29, "Speed": after planning, one operating point allocates nothing.
#[test]
fn friction_of_an_operating_point_allocates_nothing() {
    let b = cases::trb();
    let (cup, cone, _) = solved(&b, 20_000.0);
    let mut model = BearingFrictionModel::new(b, losses(&vg68(), 70.0, true)).unwrap();
    let rib = vec![1.0; 20];
    let tilts = vec![1e-4; 20];
    let (r, n) = allocations(|| {
        let mut total = 0.0;
        for w in [0.0, 10.0, 100.0, 300.0] {
            total += model
                .evaluate(&FrictionOperating {
                    inner_speed: w,
                    outer_speed: 0.0,
                    cup_slices: &cup,
                    cone_slices: &cone,
                    tilts: Some(&tilts),
                    rib: Some(&rib),
                    drag: DragModel::Torque { nmm: 10.0 },
                    coefficient_basis: Some((20_000.0, 80.0)),
                })
                .unwrap()
                .total_nmm;
        }
        total
    });
    assert!(r.is_finite());
    assert_eq!(n, 0, "allocations per operating point");
}
