//! Validation of the rib-contact roller model (docs/VALIDATION.md, bearing rows;
//! docs/bearing-model.md §15).

use super::*;
use crate::equilibrium::RollerBearingSolver;
use crate::test_support::assert_stiffness_matches_central_differences;
use kontakt::bearing::{TaperedKinematics, roller_loads};

/// The rib study's bearing (examples/bearing_rib_study_60mm.toml, its numbers).
fn rib_study_bearing() -> RollerBearing {
    let mut b = RollerBearing::tapered(
        74.141904,
        17,
        10.161476,
        16.0,
        25.481595648_f64.to_radians(),
        19.481595648_f64.to_radians(),
    );
    b.rib_angle_rad = Some(109.716252089_f64.to_radians());
    b
}

/// The rib study's pairing sphere-torus-57 at its contact height 2.75 mm.
fn sphere_torus_57() -> RibContact {
    RibContact {
        face: FaceShape::Sphere { radius: 57.0 },
        rib: RibShape::Torus { radius: 30.0 },
        contact_height_mm: 2.75,
    }
}

/// The bench's TRB (32216 geometry, 20 rollers × 31 slices) with a spherical face.
pub(super) fn trb() -> RollerBearing {
    let mut b = RollerBearing::tapered(
        108.5,
        20,
        17.0,
        20.7,
        16.0_f64.to_radians(),
        11.7_f64.to_radians(),
    );
    b.slices = 31;
    b
}

fn trb_rib() -> RibContact {
    RibContact {
        face: FaceShape::Sphere { radius: 80.0 },
        rib: RibShape::Cone,
        contact_height_mm: 4.5,
    }
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// The 2-D balance of the rib study (`kontakt::bearing::roller_loads`) on its own pair.
fn study_loads(axial: f64, centrifugal: f64) -> kontakt::bearing::RollerLoads {
    let pair = RollerRib::new(RollerRibSpec::builtin("sphere-torus-57").unwrap()).unwrap();
    let k = TaperedKinematics::of_roller_rib(&pair, 0.0, 0.0).unwrap();
    roller_loads(
        &k,
        &pair.contact.normal.into_inner(),
        axial,
        17,
        centrifugal,
    )
    .unwrap()
}

/// Pure axial load on the rib study's bearing: every roller's cup, cone and rib load equal
/// the rib study's 2-D balance to 1e-9 relative, also with a centrifugal force; the
/// rollers tilt (the rib force's moment) and stay in balance.
#[test]
fn pure_axial_load_gives_the_rib_studys_roller_loads() {
    for fc in [0.0, 150.0] {
        let mut s = RibContactSolver::new(rib_study_bearing(), sphere_torus_57()).unwrap();
        s.set_centrifugal_n(fc).unwrap();
        let sol = s
            .solve(&RingLoad::forces([0.0, 0.0, 15_000.0, 0.0, 0.0]).with_tilts_held())
            .unwrap();
        assert!(sol.status.converged(), "{sol:?}");
        let want = study_loads(15_000.0, fc);
        let mut worst: f64 = 0.0;
        for r in s.roller_loads() {
            worst = worst
                .max(rel(r.outer_n, want.outer_raceway))
                .max(rel(r.inner_n, want.inner_raceway))
                .max(rel(r.rib_n, want.rib));
            assert!(r.tilt_rad.abs() > 1e-7, "{r:?}");
        }
        eprintln!(
            "F_c {fc} N: rib {:.6} N (2-D {:.6}), tilt {:.3e} rad, p_rib {:.1} MPa, worst {worst:.2e}, {} iterations",
            s.roller_loads()[0].rib_n,
            want.rib,
            s.roller_loads()[0].tilt_rad,
            s.roller_loads()[0].rib_max_pressure_mpa,
            sol.status.iterations
        );
        assert!(worst < 1e-9, "{worst:e}");
    }
}

/// The comparison can fail: the rib normal of another pairing (sphere-cone-29, another
/// face radius) moves the rib load far beyond 1e-9.
#[test]
fn another_rib_normal_is_caught() {
    let mut b = rib_study_bearing();
    b.rib_angle_rad = None;
    let rib = RibContact {
        face: FaceShape::Sphere { radius: 29.0 },
        ..sphere_torus_57()
    };
    let mut s = RibContactSolver::new(b, rib).unwrap();
    s.solve(&RingLoad::forces([0.0, 0.0, 15_000.0, 0.0, 0.0]).with_tilts_held())
        .unwrap();
    let want = study_loads(15_000.0, 0.0);
    let dev = rel(s.roller_loads()[0].rib_n, want.rib);
    eprintln!(
        "sphere r_R = 29 mm: rib load {} vs {} N ({dev:.2e})",
        s.roller_loads()[0].rib_n,
        want.rib
    );
    assert!(dev > 1e-6, "{dev:e}");
}

/// Under a combined load with free tilts of the rollers every roller's net force and moment
/// (summed from the contact points and normals, independently of the solver's
/// derivatives) vanish to 1e-9 of the largest roller load (moments: times L_we), and the
/// ring carries the applied load to 1e-9.
#[test]
fn every_roller_is_in_force_and_moment_balance() {
    for fc in [0.0, 80.0] {
        let mut s = RibContactSolver::new(trb(), trb_rib()).unwrap();
        s.set_centrifugal_n(fc).unwrap();
        // F_a / (F_r tan α) = 1.14: a load zone of about half the ring
        let load = [20_000.0, 0.0, 6_500.0, 0.0, 0.0];
        let sol = s.solve(&RingLoad::forces(load).with_tilts_held()).unwrap();
        assert!(sol.status.converged(), "{sol:?}");
        assert!(sol.status.residual <= 1e-9);
        for (got, applied) in sol.load.iter().zip(&load).take(3) {
            assert!((got - applied).abs() <= 1e-9 * 20_000.0);
        }
        let q = sol.max_roller_load_n;
        let l = s.bearing().effective_length_mm;
        let mut worst: f64 = 0.0;
        for j in 0..s.roller_loads().len() {
            let [fr, fz, m] = s.roller_balance(j);
            worst = worst
                .max(fr.abs() / q)
                .max(fz.abs() / q)
                .max(m.abs() / (q * l));
        }
        let lifted = s
            .roller_loads()
            .iter()
            .filter(|r| r.outer_n == 0.0 && r.inner_n == 0.0 && r.rib_n == 0.0)
            .count();
        let inner = s.roller_loads().iter().map(|r| r.iterations).max();
        eprintln!(
            "F_c {fc}: worst roller residual {worst:.2e}, {lifted} rollers without cup load, {} iterations, roller iterations at most {inner:?}",
            sol.status.iterations
        );

        assert!(worst < 1e-9, "{worst:e}");
        if fc == 0.0 {
            assert!(lifted > 0, "the load zone should not cover the ring");
        } else {
            assert_eq!(
                lifted, 0,
                "the centrifugal force holds every roller on the cup"
            );
        }
    }
}

/// The balance check can fail: a roller's rib load changed by 1 % leaves a residual.
#[test]
fn a_roller_out_of_balance_is_caught() {
    let mut s = RibContactSolver::new(trb(), trb_rib()).unwrap();
    s.solve(&RingLoad::forces([20_000.0, 0.0, 10_000.0, 0.0, 0.0]).with_tilts_held())
        .unwrap();
    s.rib_load[0] *= 1.01;
    let [fr, fz, _] = s.roller_balance(0);
    assert!(fr.hypot(fz) > 1e-4 * s.rollers[0].outer_n);
}

/// The condensed ring stiffness equals central differences of the carried load (each
/// roller re-solved) to 1e-6, at a combined load with a ring tilt.
#[test]
fn condensed_stiffness_matches_central_differences() {
    let mut s = RibContactSolver::new(trb(), trb_rib()).unwrap();
    let sol = s
        .solve(&RingLoad::forces([20_000.0, 5_000.0, 12_000.0, 0.0, 0.0]).with_tilts_held())
        .unwrap();
    let mut u = sol.displacement;
    u[3] = 2e-5;
    u[4] = -1e-5;
    assert_stiffness_matches_central_differences(|u| s.load_at(u).unwrap(), u);
}

/// The check can fail: the uncondensed K_uu (rollers held) is stiffer than the solution's
/// derivative.
#[test]
fn the_uncondensed_stiffness_would_be_caught() {
    let mut s = RibContactSolver::new(trb(), trb_rib()).unwrap();
    let sol = s
        .solve(&RingLoad::forces([20_000.0, 0.0, 12_000.0, 0.0, 0.0]).with_tilts_held())
        .unwrap();
    let u = sol.displacement;
    let (_, k) = s.load_at(u).unwrap();
    let h = 1e-7;
    let (mut up, mut um) = (u, u);
    up[2] += h;
    um[2] -= h;
    let fp = s.load_at(up).unwrap().0[2];
    let fm = s.load_at(um).unwrap().0[2];
    let fd = (fp - fm) / (2.0 * h);
    // the condensed entry matches; the cone slices' stiffness alone would not
    assert!(rel(k[2][2], fd) < 1e-6);
    let b = s.bearing().clone();
    let mut iso = RollerBearingSolver::new(b).unwrap();
    let (_, k_iso) = iso.load_at(u);
    assert!(rel(k_iso[2][2], fd) > 1e-3);
}

/// With the rib made very stiff (× 1e8) and the rollers' tilt held, the model approaches
/// the ISO model: the same ring load gives roller loads within the measured tolerance.
#[test]
fn a_rigid_rib_without_tilt_approaches_the_iso_model() {
    let load = RingLoad::forces([20_000.0, 0.0, 12_000.0, 0.0, 0.0]).with_tilts_held();
    let mut iso = RollerBearingSolver::new(trb()).unwrap();
    let iso_sol = iso.solve(&load).unwrap();
    let deviation = |factor: f64, hold: bool| {
        let mut s = RibContactSolver::new(trb(), trb_rib()).unwrap();
        s.rib_stiffness_factor = factor;
        s.hold_roller_tilt = hold;
        // the ISO model's rib direction is the pair's
        let mut b = trb();
        b.rib_angle_rad = Some(s.rib_normal_angle());
        let mut iso = RollerBearingSolver::new(b).unwrap();
        iso.solve(&load).unwrap();
        let sol = s.solve(&load).unwrap();
        assert!(sol.status.converged(), "{sol:?}");
        let q = iso_sol.max_roller_load_n;
        let mut worst: f64 = 0.0;
        for (r, i) in s.roller_loads().iter().zip(iso.roller_loads()) {
            worst = worst
                .max((r.outer_n - i.outer_n).abs() / q)
                .max((r.inner_n - i.inner_n).abs() / q)
                .max((r.rib_n - i.rib_n).abs() / q);
        }
        let du = (sol.displacement[0] - iso_sol.displacement[0]).abs() / iso_sol.displacement[0];
        (worst, du)
    };
    let (stiff, du_stiff) = deviation(1e8, true);
    let (soft, du_soft) = deviation(1.0, false);
    eprintln!(
        "rigid rib, no tilt: roller loads within {stiff:.3e} of Q_max, dx {du_stiff:.3e}; Hertz rib, free tilt: {soft:.3e}, dx {du_soft:.3e}"
    );
    // measured: 3.9e-5 of Q_max and 3.6e-3 of δx (the cone approach is taken along the
    // cone normal, the ISO model's along the cup normal); the Hertz rib with free tilts
    // 1.7e-4 and 1.1e-2
    assert!(stiff < 1e-4, "{stiff:e}");
    assert!(du_stiff < 5e-3, "{du_stiff:e}");
    assert!(soft > stiff && du_soft > du_stiff);
}

/// Symmetry: a load in the x–z plane on a roller set symmetric about x gives mirrored
/// rollers (ψ and −ψ) with equal loads and tilts, and no y displacement.
#[test]
fn mirrored_rollers_carry_equal_loads() {
    let mut s = RibContactSolver::new(trb(), trb_rib()).unwrap();
    let sol = s
        .solve(&RingLoad::forces([20_000.0, 0.0, 12_000.0, 0.0, 0.0]).with_tilts_held())
        .unwrap();
    assert!(sol.displacement[1].abs() < 1e-12, "{:?}", sol.displacement);
    let r = s.roller_loads();
    let z = r.len();
    let q = sol.max_roller_load_n;
    for j in 1..z {
        let (a, b) = (r[j], r[z - j]);
        for (x, y) in [
            (a.outer_n, b.outer_n),
            (a.inner_n, b.inner_n),
            (a.rib_n, b.rib_n),
        ] {
            assert!((x - y).abs() <= 1e-9 * q, "{j}: {x} vs {y}");
        }
        assert!((a.tilt_rad - b.tilt_rad).abs() <= 1e-9 * r[0].tilt_rad.abs());
    }
    // the load along y gives the loads of the x load turned by 90°: same largest load
    let mut s2 = RibContactSolver::new(trb(), trb_rib()).unwrap();
    let sol2 = s2
        .solve(&RingLoad::forces([0.0, 20_000.0, 12_000.0, 0.0, 0.0]).with_tilts_held())
        .unwrap();
    assert!(rel(sol2.max_roller_load_n, q) < 1e-9);
    assert!(rel(sol2.displacement[1], sol.displacement[0]) < 1e-9);
}

/// Zero load: every roller lifted off, a converged status with a note, zero force.
#[test]
fn zero_load_lifts_every_roller_with_a_clear_status() {
    let mut b = trb();
    b.clearance_mm = 0.02;
    let mut s = RibContactSolver::new(b, trb_rib()).unwrap();
    let sol = s
        .solve(&RingLoad::forces([0.0; 5]).with_tilts_held())
        .unwrap();
    assert!(sol.status.converged(), "{sol:?}");
    assert_eq!(sol.note, Some("every roller is lifted off: zero load"));
    assert_eq!(sol.load, [0.0; 5]);
    assert!(s.roller_loads().iter().all(|r| r.outer_n == 0.0
        && r.inner_n == 0.0
        && r.rib_n == 0.0
        && r.max_approach_mm < 0.0));
}

/// A warm start after a 1 % load change converges in fewer ring iterations.
#[test]
fn a_warm_start_needs_fewer_iterations() {
    let mut s = RibContactSolver::new(trb(), trb_rib()).unwrap();
    let load =
        |f: f64| RingLoad::forces([20_000.0 * f, 0.0, 10_000.0 * f, 0.0, 0.0]).with_tilts_held();
    let cold = s.solve(&load(1.0)).unwrap();
    let warm = s.solve_from(&load(1.01), cold.displacement).unwrap();
    eprintln!(
        "cold {} iterations, warm {}",
        cold.status.iterations, warm.status.iterations
    );
    assert!(warm.status.converged());
    assert!(warm.status.iterations < cold.status.iterations);
}

/// Bad input is named: a cylindrical bearing, a rib angle that contradicts the pair, too
/// few slices, a negative centrifugal force, a contact height above the large end.
#[test]
fn bad_input_is_named() {
    let msg = |r: Result<RibContactSolver>| r.unwrap_err().to_string();
    let e = msg(RibContactSolver::new(
        RollerBearing::cylindrical(60.0, 14, 10.0, 12.0),
        trb_rib(),
    ));
    assert!(e.contains("invalid kind = cylindrical"), "{e}");
    let mut b = rib_study_bearing();
    b.rib_angle_rad = Some(110.0_f64.to_radians());
    let e = msg(RibContactSolver::new(b, sphere_torus_57()));
    assert!(e.starts_with("invalid rib_angle_rad"), "{e}");
    let mut b = trb();
    b.slices = 1;
    let e = msg(RibContactSolver::new(b, trb_rib()));
    assert!(e.starts_with("invalid slices = 1"), "{e}");
    let e = msg(RibContactSolver::new(
        trb(),
        RibContact {
            contact_height_mm: 20.0,
            ..trb_rib()
        },
    ));
    assert!(e.contains("rib_contact.contact_height_mm"), "{e}");
    let mut s = RibContactSolver::new(trb(), trb_rib()).unwrap();
    let e = s.set_centrifugal_n(-1.0).unwrap_err().to_string();
    assert!(e.starts_with("invalid centrifugal_n = -1"), "{e}");
}

// ---- cylindrical roller bearings with ribs (NU, NJ, NUP, N) ----

/// The crate's CRB (14 rollers 10 × 12 mm on a 60 mm pitch circle, ISO profile).
fn crb() -> RollerBearing {
    RollerBearing::cylindrical(60.0, 14, 10.0, 12.0)
}

/// Spherical end faces r_R = 60 mm touching the ribs 3.5 mm from the roller axis, 20 µm
/// end play.
fn crb_ribs() -> CylindricalRibs {
    CylindricalRibs {
        face_radius_mm: 60.0,
        contact_height_mm: 3.5,
        end_play_mm: 0.02,
    }
}

/// NJ under a pure axial load: every roller's inner and outer ring ribs carry
/// `F_a/(Z cos λ)` (λ = asin(h/r_R), the raceways take no axial force), the cup and the cone
/// the same radial load (the ribs' radial components cancel), and the raceway slices the
/// couple of the two rib forces, whose lines pass through the face spheres' centres
/// `±(L/2 − r_R)` on the roller axis: `2 Q (L/2 − r_R) sin λ` about the roller centre.
#[test]
fn nj_axial_load_passes_through_the_ribs_with_the_closed_form_couple() {
    let mut s = RibContactSolver::cylindrical(crb(), RibArrangement::Nj, crb_ribs()).unwrap();
    let fa = 3_000.0;
    let sol = s
        .solve(&RingLoad::forces([0.0, 0.0, fa, 0.0, 0.0]).with_tilts_held())
        .unwrap();
    assert!(sol.status.converged(), "{sol:?}");
    let lam = (3.5_f64 / 60.0).asin();
    let q = fa / (14.0 * lam.cos());
    let couple = 2.0 * q * (6.0 - 60.0) * lam.sin();
    let ns = s.slice_positions().len();
    let mut worst: f64 = 0.0;
    for (j, r) in s.roller_loads().iter().enumerate() {
        worst = worst
            .max(rel(r.rib_n, q))
            .max(rel(r.outer_rib_n, q))
            .max((r.outer_n - r.inner_n).abs() / q);
        let raceway: f64 = (0..ns)
            .map(|k| (s.cone_load[j * ns + k] - s.cup_load[j * ns + k]) * s.x[k])
            .sum();
        worst = worst.max(rel(raceway, couple));
    }
    eprintln!(
        "NJ {fa} N axial: rib {:.6} N (closed form {q:.6}), raceway couple vs {couple:.4} N mm, tilt {:.3e} rad, p_rib {:.0} MPa, {} iterations; worst {worst:.2e}",
        s.roller_loads()[0].rib_n,
        s.roller_loads()[0].tilt_rad,
        s.roller_loads()[0].rib_max_pressure_mpa,
        sol.status.iterations
    );
    assert!(worst < 1e-9, "{worst:e}");
}

/// NUP carries an axial load both ways, mirror images of each other; NJ refuses −z, NU and
/// N refuse any axial load, each naming `load.fz_n`.
#[test]
fn the_rib_arrangement_decides_the_axial_load() {
    let load = |fz: f64| RingLoad::forces([5_000.0, 0.0, fz, 0.0, 0.0]).with_tilts_held();
    let mut s = RibContactSolver::cylindrical(crb(), RibArrangement::Nup, crb_ribs()).unwrap();
    let plus = s.solve(&load(2_000.0)).unwrap();
    let a = s.roller_loads().to_vec();
    let minus = s.solve(&load(-2_000.0)).unwrap();
    assert!(plus.status.converged() && minus.status.converged());
    assert!((plus.displacement[2] + minus.displacement[2]).abs() < 1e-12);
    for (p, m) in a.iter().zip(s.roller_loads()) {
        let scale = plus.max_roller_load_n;
        assert!((p.rib_n - m.rib_n).abs() <= 1e-9 * scale);
        assert!((p.outer_n - m.outer_n).abs() <= 1e-9 * scale);
        // a roller that carries nothing (opposite the load: the ring moved away, the ribs
        // released by its tilt) has no defined tilt
        if p.outer_n + p.rib_n < 1e-6 * scale {
            continue;
        }
        assert!(
            (p.tilt_rad + m.tilt_rad).abs() <= 1e-9 * p.tilt_rad.abs().max(1e-12),
            "{} {}",
            p.tilt_rad,
            m.tilt_rad
        );
    }
    let msg = |arr: RibArrangement, fz: f64| {
        let mut s = RibContactSolver::cylindrical(crb(), arr, crb_ribs()).unwrap();
        s.solve(&load(fz)).unwrap_err().to_string()
    };
    let e = msg(RibArrangement::Nj, -1.0);
    assert!(
        e.starts_with("invalid load.fz_n = -1: expected a load >= 0 N: an NJ"),
        "{e}"
    );
    for arr in [RibArrangement::Nu, RibArrangement::N] {
        let e = msg(arr, 1.0);
        assert!(
            e.starts_with(&format!(
                "invalid load.fz_n = 1: expected 0: an {} ",
                arr.name()
            )),
            "{e}"
        );
    }
    // radial load alone on NU and N: solved, the ribs idle
    for arr in [RibArrangement::Nu, RibArrangement::N] {
        let mut s = RibContactSolver::cylindrical(crb(), arr, crb_ribs()).unwrap();
        let sol = s.solve(&load(0.0)).unwrap();
        assert!(sol.status.converged(), "{arr:?} {sol:?}");
        assert!(
            s.roller_loads()
                .iter()
                .all(|r| r.rib_n + r.outer_rib_n < 1e-9 * 5_000.0)
        );
    }
}

/// NJ under radial and axial load: every roller in force and moment balance, the
/// condensed stiffness (now with the axial direction through the ribs) against central
/// differences.
#[test]
fn nj_combined_load_balance_and_stiffness() {
    let mut s = RibContactSolver::cylindrical(crb(), RibArrangement::Nj, crb_ribs()).unwrap();
    let sol = s
        .solve(&RingLoad::forces([8_000.0, 0.0, 1_500.0, 0.0, 0.0]).with_tilts_held())
        .unwrap();
    assert!(sol.status.converged(), "{sol:?}");
    let q = sol.max_roller_load_n;
    let mut worst: f64 = 0.0;
    for j in 0..14 {
        let [fr, fz, m] = s.roller_balance(j);
        worst = worst
            .max(fr.abs() / q)
            .max(fz.abs() / q)
            .max(m.abs() / (q * 12.0));
    }
    eprintln!(
        "NJ 8 kN radial + 1.5 kN axial: worst roller residual {worst:.2e}, {} iterations, K_zz {:.4e} N/mm",
        sol.status.iterations, sol.stiffness[2][2]
    );
    assert!(worst < 1e-9, "{worst:e}");
    assert!(sol.stiffness[2][2] > 0.0);
    let mut u = sol.displacement;
    u[3] = 1e-5;
    assert_stiffness_matches_central_differences(|u| s.load_at(u).unwrap(), u);
}

/// Bad rib data is named.
#[test]
fn bad_cylindrical_ribs_are_named() {
    let e = |r: CylindricalRibs| {
        RibContactSolver::cylindrical(crb(), RibArrangement::Nj, r)
            .unwrap_err()
            .to_string()
    };
    let m = e(CylindricalRibs {
        contact_height_mm: 5.0,
        ..crb_ribs()
    });
    assert!(m.starts_with("invalid ribs.contact_height_mm = 5"), "{m}");
    let m = e(CylindricalRibs {
        face_radius_mm: 5.0,
        ..crb_ribs()
    });
    assert!(m.starts_with("invalid ribs.face_radius_mm = 5"), "{m}");
    let m = e(CylindricalRibs {
        end_play_mm: -0.01,
        ..crb_ribs()
    });
    assert!(m.starts_with("invalid ribs.end_play_mm = -0.01"), "{m}");
    let m = RibContactSolver::cylindrical(trb(), RibArrangement::Nj, crb_ribs())
        .unwrap_err()
        .to_string();
    assert!(m.starts_with("invalid kind = tapered"), "{m}");
}

/// The examples' warm starts (the Python test `test_a_warm_start_after_a_one_percent_load_change`
/// requires warm < cold iterations and a converged warm solve): the NJ CRB under 10 kN
/// radial and 1.5 kN axial, +1 %.
#[test]
fn nj_warm_start_after_a_one_percent_load_change() {
    let mut b = RollerBearing::cylindrical(60.0, 14, 11.0, 11.0);
    b.clearance_mm = 0.02;
    let mut s = RibContactSolver::cylindrical(b, RibArrangement::Nj, crb_ribs()).unwrap();
    let load =
        |f: f64| RingLoad::forces([10_000.0 * f, 0.0, 1_500.0 * f, 0.0, 0.0]).with_tilts_held();
    let first = s.solve(&load(1.0)).unwrap();
    let warm = s.solve_from(&load(1.01), first.displacement).unwrap();
    let cold = s.solve(&load(1.01)).unwrap();
    eprintln!(
        "NJ: cold {} iterations, warm {}, residual {:.1e}",
        cold.status.iterations, warm.status.iterations, warm.status.residual
    );
    assert!(warm.status.converged() && cold.status.converged());
    assert!(warm.status.iterations < cold.status.iterations);
    assert!(warm.status.residual < 1e-9);
}

/// Robustness: the bench TRB with clearance, zero clearance and preload under axial,
/// combined and moment loads from 10 N to 100 kN, and the NJ CRB under radial and axial
/// loads over the same range, all converge to a residual below 1e-9 with every roller in
/// balance.
#[test]
fn converges_over_four_decades_of_load() {
    let mut worst_it = 0;
    let mut cases = 0;
    for clearance in [-0.005, 0.0, 0.02] {
        for scale in [1e-3, 1e-2, 0.1, 1.0, 10.0] {
            for (f, held) in [
                ([0.0, 0.0, 10_000.0, 0.0, 0.0], true),
                ([20_000.0, 0.0, 12_000.0, 0.0, 0.0], true),
                ([0.0, 0.0, 10_000.0, 2.0e5, 0.0], false),
            ] {
                let mut b = trb();
                b.clearance_mm = clearance;
                let mut s = RibContactSolver::new(b, trb_rib()).unwrap();
                let f = f.map(|v| v * scale);
                let load = if held {
                    RingLoad::forces(f).with_tilts_held()
                } else {
                    RingLoad::forces(f)
                };
                let sol = s.solve(&load).unwrap();
                assert!(
                    sol.status.converged() && sol.status.residual < 1e-9,
                    "s {clearance} {f:?}: {sol:?}"
                );
                let q = sol.max_roller_load_n;
                for j in 0..20 {
                    let [fr, fz, m] = s.roller_balance(j);
                    assert!(fr.abs().max(fz.abs()).max(m.abs() / 20.7) <= 1e-9 * q);
                }
                worst_it = worst_it.max(sol.status.iterations);
                cases += 1;
            }
        }
    }
    for scale in [1e-3, 1e-2, 0.1, 1.0, 10.0] {
        let mut s = RibContactSolver::cylindrical(crb(), RibArrangement::Nj, crb_ribs()).unwrap();
        let f = [8_000.0 * scale, 0.0, 1_500.0 * scale, 0.0, 0.0];
        let sol = s.solve(&RingLoad::forces(f).with_tilts_held()).unwrap();
        assert!(
            sol.status.converged() && sol.status.residual < 1e-9,
            "{f:?}: {sol:?}"
        );
        worst_it = worst_it.max(sol.status.iterations);
        cases += 1;
    }
    eprintln!("{cases} cases converge, at most {worst_it} ring iterations");
    assert!(worst_it <= 40);
}

/// The rib contact point of the rib study's pair in the roller frame: h = 2.75 mm from the
/// roller axis toward the cone, and along the axis where the spherical face (r_R = 57 mm,
/// meeting the conical side at the large-end radius ρ_L = 5.5 mm) bulges past the large
/// end: `−L/2 − (√(r_R² − h²) − √(r_R² − ρ_L²))` from the roller centre (toward the small
/// end positive); the normal leans from the roller axis by asin(h/r_R).
#[test]
fn the_rib_contact_point_is_on_the_face_at_the_contact_height() {
    let s = RibContactSolver::new(rib_study_bearing(), sphere_torus_57()).unwrap();
    let b = s.bearing();
    let am = 0.5 * (b.contact_angle_rad + b.cone_angle_rad);
    let (t_m, n_m) = (
        Vector2::new(-am.sin(), am.cos()),
        Vector2::new(am.cos(), am.sin()),
    );
    let (_, point, _) = s.rib_contacts().next().unwrap();
    let p = Vector2::from(point);
    let (rr, h, rho_l, l): (f64, f64, f64, f64) = (57.0, 2.75, 5.5, 16.0);
    let along = -0.5 * l - ((rr * rr - h * h).sqrt() - (rr * rr - rho_l * rho_l).sqrt());
    eprintln!(
        "rib point: {:.9} mm along the axis (closed form {along:.9}), {:.9} mm from it",
        p.dot(&t_m),
        p.dot(&n_m)
    );
    // ρ_L of the bearing's numbers is 5.5 to 1e-7 (the example's diameters are rounded)
    assert!((p.dot(&t_m) - along).abs() < 1e-6);
    assert!((p.dot(&n_m) + h).abs() < 1e-9);
    let lean = (s.rib_normal_angle() - (am + std::f64::consts::FRAC_PI_2)).abs();
    assert!((lean - (h / rr).asin()).abs() < 1e-9, "{lean}");
}
