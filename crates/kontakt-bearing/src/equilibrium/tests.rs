//! Validation of the roller-bearing equilibrium (docs/VALIDATION.md, bearing rows).

use super::*;
use crate::load_zone::{LINE_EXPONENT, discrete, relative_load};
use crate::profile::Profile;
use crate::test_support::{
    assert_same_displacement, assert_same_load, assert_stiffness_matches_central_differences,
};

/// A cylindrical roller bearing of the NU 2xx class with straight rollers.
fn crb() -> RollerBearing {
    let mut b = RollerBearing::cylindrical(60.0, 14, 10.0, 12.0);
    b.roller_profile = Profile::Straight;
    b
}

/// A tapered roller bearing of the 32008 X class (Liu 2022's angles), straight rollers.
fn trb() -> RollerBearing {
    let mut b = RollerBearing::tapered(
        54.0,
        23,
        6.5,
        13.66,
        14.17_f64.to_radians(),
        11.17_f64.to_radians(),
    );
    b.roller_profile = Profile::Straight;
    b
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

#[test]
fn crb_radial_load_reproduces_the_sjovall_sums_across_the_load_zone() {
    let n = LINE_EXPONENT;
    let mut seen = Vec::new();
    for clearance in [-0.01, -0.003, 0.0, 0.002, 0.01] {
        for fr in [2_000.0, 20_000.0] {
            let mut b = crb();
            b.clearance_mm = clearance;
            let z = b.rollers;
            let mut s = RollerBearingSolver::new(b).unwrap();
            let sol = s
                .solve(&RingLoad::forces([fr, 0.0, 0.0, 0.0, 0.0]))
                .unwrap();
            assert!(sol.status.converged(), "{sol:?}");
            let eps = sol.load_zone.unwrap();
            seen.push(eps);
            let j = discrete(eps, n, z, 0.0).unwrap();
            let q_max = fr / (z as f64 * j.j_r);
            let rollers = s.roller_loads();
            assert!(
                rel(rollers[0].outer_n, q_max) < 1e-9,
                "s {clearance} F {fr}: {} vs {q_max}",
                rollers[0].outer_n
            );
            for r in rollers {
                let want = q_max * relative_load(r.azimuth_rad, eps, n);
                assert!((r.outer_n - want).abs() < 1e-9 * q_max, "{r:?} vs {want}");
            }
        }
    }
    // from a small load zone to a fully loaded ring
    let (lo, hi) = seen
        .iter()
        .fold((f64::MAX, 0.0_f64), |(a, b), &e| (a.min(e), b.max(e)));
    assert!(lo < 0.3 && hi > 1.0, "{seen:?}");
}

#[test]
fn crb_zero_clearance_gives_the_exact_finite_z_factor_at_half_load_zone() {
    let b = crb();
    let z = b.rollers as f64;
    let mut s = RollerBearingSolver::new(b).unwrap();
    let fr = 10_000.0;
    let sol = s
        .solve(&RingLoad::forces([fr, 0.0, 0.0, 0.0, 0.0]))
        .unwrap();
    assert!((sol.load_zone.unwrap() - 0.5).abs() < 1e-12);
    let factor = sol.max_roller_load_n * z / fr;
    let exact = 1.0 / discrete(0.5, LINE_EXPONENT, 14, 0.0).unwrap().j_r;
    assert!(rel(factor, exact) < 1e-9, "{factor} vs {exact}");
    // Z = 14 gives 4.0787..., near the integral's 4.0850
    assert!((factor - 4.08).abs() < 0.01, "{factor}");
}

#[test]
fn trb_pure_axial_load_is_shared_equally() {
    let mut b = trb();
    b.roller_profile = Profile::iso(b.effective_length_mm, b.roller_diameter_mm);
    b.clearance_mm = 0.005;
    let (z, alpha, ai) = (b.rollers as f64, b.contact_angle_rad, b.cone_angle_rad);
    let beta = b.rib_angle();
    let mut s = RollerBearingSolver::new(b).unwrap();
    let fa = 12_000.0;
    let sol = s
        .solve(&RingLoad::forces([0.0, 0.0, fa, 0.0, 0.0]))
        .unwrap();
    assert!(sol.status.converged(), "{sol:?}");
    let q = fa / (z * alpha.sin());
    for r in s.roller_loads() {
        assert!(rel(r.outer_n, q) < 1e-10, "{r:?} vs {q}");
        // the roller's force balance in its axial plane: Q_i n_i + Q_f n_f = Q_o n_o
        let bal_r = r.inner_n * ai.cos() + r.rib_n * beta.cos() - r.outer_n * alpha.cos();
        let bal_z = r.inner_n * ai.sin() + r.rib_n * beta.sin() - r.outer_n * alpha.sin();
        assert!(
            bal_r.abs() < 1e-12 * q && bal_z.abs() < 1e-12 * q,
            "{bal_r} {bal_z}"
        );
        assert!(r.rib_n > 0.0);
    }
    assert!(sol.load_zone.is_none());
}

#[test]
fn trb_combined_load_follows_jr_over_ja_over_the_whole_load_zone() {
    let n = LINE_EXPONENT;
    let b = trb();
    let (z, alpha) = (b.rollers, b.contact_angle_rad);
    let mut s = RollerBearingSolver::new(b).unwrap();
    let fr = 5_000.0;
    let mut seen = Vec::new();
    for ratio in [1.02, 1.1, 1.26, 1.6, 3.0, 10.0, 50.0] {
        let fa = ratio * fr * alpha.tan();
        let load = RingLoad::forces([fr, 0.0, fa, 0.0, 0.0]).with_tilts_held();
        let sol = s.solve(&load).unwrap();
        assert!(sol.status.converged(), "{ratio}: {sol:?}");
        let eps = sol.load_zone.unwrap();
        seen.push(eps);
        let j = discrete(eps, n, z, 0.0).unwrap();
        let lhs = fr * alpha.tan() / fa;
        assert!(
            rel(lhs, j.j_r / j.j_a) < 1e-9,
            "ratio {ratio}: {lhs} vs {}",
            j.j_r / j.j_a
        );
        let q_max = fr / (z as f64 * j.j_r * alpha.cos());
        assert!(rel(s.roller_loads()[0].outer_n, q_max) < 1e-9);
    }
    let (lo, hi) = seen
        .iter()
        .fold((f64::MAX, 0.0_f64), |(a, b), &e| (a.min(e), b.max(e)));
    assert!(lo < 0.15 && hi > 5.0, "{seen:?}");
}

/// A displacement with all five components, and the load that holds the ring there.
fn round_trip_case() -> (RollerBearingSolver, [f64; 5]) {
    let mut b = trb();
    b.roller_profile = Profile::iso(b.effective_length_mm, b.roller_diameter_mm);
    b.clearance_mm = 0.004;
    b.first_roller_azimuth_rad = 0.1;
    let s = RollerBearingSolver::new(b).unwrap();
    (s, [0.006, -0.003, 0.02, 2e-4, -3e-4])
}

#[test]
fn equilibrium_residual_and_round_trip() {
    let (mut s, u) = round_trip_case();
    let (f, _) = s.load_at(u);
    let sol = s.solve(&RingLoad::forces(f)).unwrap();
    assert!(sol.status.converged(), "{sol:?}");
    // the residual against an independent evaluation at the returned displacement
    let (g, _) = s.load_at(sol.displacement);
    assert_same_load(&g, &f, 27.0, 1e-9);
    // the displacement it came from: to 1e-11 mm and 1e-13 rad
    assert_same_displacement(&sol.displacement, &u);
    // a warm start from the solution takes at most one iteration
    let again = s
        .solve_from(&RingLoad::forces(f), sol.displacement)
        .unwrap();
    assert!(
        again.status.converged() && again.status.iterations <= 1,
        "{again:?}"
    );
}

#[test]
fn stiffness_matches_central_differences() {
    let (mut s, u) = round_trip_case();
    assert_stiffness_matches_central_differences(|u| s.load_at(u), u);
}

#[test]
fn slice_count_convergence() {
    // a crowned roller on a held tilt: the largest roller load and the edge slice load
    let mut out = Vec::new();
    for slices in [31, 61, 121, 481] {
        let mut b = trb();
        b.roller_profile = Profile::iso(b.effective_length_mm, b.roller_diameter_mm);
        b.slices = slices;
        let mut s = RollerBearingSolver::new(b).unwrap();
        let mut load = RingLoad::forces([4_000.0, 0.0, 6_000.0, 0.0, 0.0]);
        load.dofs[3] = Dof::Displacement(0.0);
        load.dofs[4] = Dof::Displacement(5e-4);
        let sol = s.solve(&load).unwrap();
        assert!(sol.status.converged(), "{sol:?}");
        out.push((sol.max_roller_load_n, sol.displacement[2]));
    }
    let (q_ref, z_ref) = out[3];
    let err: Vec<f64> = out[..3].iter().map(|(q, _)| rel(*q, q_ref)).collect();
    let errz: Vec<f64> = out[..3].iter().map(|(_, z)| rel(*z, z_ref)).collect();
    assert!(
        err[0] < 5e-3 && err[1] < err[0] && err[2] < err[1],
        "{err:?} {out:?}"
    );
    assert!(errz[0] < 5e-3 && errz[2] < errz[0], "{errz:?} {out:?}");
}

#[test]
fn mirrored_loads_give_mirrored_solutions() {
    let mut b = crb();
    b.roller_profile = Profile::iso(12.0, 10.0);
    b.clearance_mm = 0.003;
    let mut s = RollerBearingSolver::new(b).unwrap();
    let a = s
        .solve(&RingLoad::forces([7_000.0, 0.0, 0.0, 0.0, 3e4]))
        .unwrap();
    let qa: Vec<f64> = s.roller_loads().iter().map(|r| r.outer_n).collect();
    let m = s
        .solve(&RingLoad::forces([-7_000.0, 0.0, 0.0, 0.0, -3e4]))
        .unwrap();
    let qm: Vec<f64> = s.roller_loads().iter().map(|r| r.outer_n).collect();
    for i in 0..5 {
        assert!(
            (a.displacement[i] + m.displacement[i]).abs() < 1e-12,
            "{i}: {a:?} {m:?}"
        );
    }
    let z = qa.len();
    for j in 0..z {
        // roller j at ψ_j under +F matches roller j + Z/2 under -F, and ψ_j matches -ψ_j
        assert!((qa[j] - qm[(j + z / 2) % z]).abs() < 1e-9 * a.max_roller_load_n);
        assert!((qa[j] - qa[(z - j) % z]).abs() < 1e-9 * a.max_roller_load_n);
    }
    assert!(a.displacement[1].abs() < 1e-15 && a.displacement[3].abs() < 1e-15);
}

#[test]
fn loads_the_bearing_cannot_carry_are_named() {
    let mut s = RollerBearingSolver::new(crb()).unwrap();
    let e = s
        .solve(&RingLoad::forces([1e3, 0.0, 100.0, 0.0, 0.0]))
        .unwrap_err();
    assert!(e.to_string().starts_with("invalid load.fz_n = 100: expected 0: a cylindrical roller bearing carries no axial load"), "{e}");
    let e = s
        .solve(&RingLoad::forces([f64::NAN, 0.0, 0.0, 0.0, 0.0]))
        .unwrap_err();
    assert_eq!(
        e.to_string(),
        "invalid load.fx_n = NaN: expected a finite number"
    );
    let mut t = RollerBearingSolver::new(trb()).unwrap();
    let e = t
        .solve(&RingLoad::forces([1e3, 0.0, 100.0, 0.0, 0.0]))
        .unwrap_err();
    assert!(
        e.to_string()
            .starts_with("invalid load.fz_n = 100: expected an axial load > F_r tan(alpha)"),
        "{e}"
    );
    let e = t
        .solve(&RingLoad::forces([0.0, 0.0, -1.0, 0.0, 0.0]))
        .unwrap_err();
    assert!(e.to_string().starts_with("invalid load.fz_n = -1"), "{e}");
    let mut th = RollerBearingSolver::new(RollerBearing::thrust(60.0, 16, 6.0, 8.0)).unwrap();
    let e = th
        .solve(&RingLoad::forces([10.0, 0.0, 1e3, 0.0, 0.0]))
        .unwrap_err();
    assert!(
        e.to_string()
            .starts_with("invalid load.fx_n = 10: expected 0: a cylindrical roller thrust bearing"),
        "{e}"
    );
    // a single row with free tilts under a radial load: a status, not a wrong number
    let sol = t
        .solve(&RingLoad::forces([1e3, 0.0, 1e3, 0.0, 0.0]))
        .unwrap();
    if sol.status.converged() {
        let (g, _) = t.load_at(sol.displacement);
        assert!(
            (g[0] - 1e3).abs() < 1e-6 && g[3].abs() < 1e-3 && g[4].abs() < 1e-3,
            "{sol:?}"
        );
    } else {
        assert!(sol.note.is_some(), "{sol:?}");
    }
}

#[test]
fn zero_load_lifts_every_roller_off_and_preload_loads_them_all() {
    let mut b = crb();
    b.clearance_mm = 0.01;
    let mut s = RollerBearingSolver::new(b).unwrap();
    let sol = s.solve(&RingLoad::forces([0.0; 5])).unwrap();
    assert!(sol.status.converged());
    assert_eq!(sol.max_roller_load_n, 0.0);
    assert_eq!(sol.load, [0.0; 5]);
    assert!(sol.note.unwrap().contains("lifted off"));
    // a preloaded (negative clearance) bearing at zero load: every roller carries
    // c_l (|s|/2)^(10/9), the ring stays centred
    let mut b = crb();
    b.clearance_mm = -0.004;
    let cl = b.roller_stiffness();
    let mut s = RollerBearingSolver::new(b).unwrap();
    let sol = s.solve(&RingLoad::forces([0.0; 5])).unwrap();
    assert!(sol.status.converged(), "{sol:?}");
    let q = cl * 0.002_f64.powf(10.0 / 9.0);
    for r in s.roller_loads() {
        assert!(rel(r.outer_n, q) < 1e-12, "{r:?} vs {q}");
    }
    assert!(sol.displacement.iter().all(|v| v.abs() < 1e-15));
}

#[test]
fn thrust_bearing_under_axial_load_and_moment() {
    let b = RollerBearing::thrust(60.0, 16, 6.0, 8.0);
    let z = b.rollers as f64;
    let mut s = RollerBearingSolver::new(b).unwrap();
    let sol = s
        .solve(&RingLoad::forces([0.0, 0.0, 8_000.0, 0.0, 0.0]))
        .unwrap();
    assert!(sol.status.converged());
    for r in s.roller_loads() {
        assert!(rel(r.outer_n, 8_000.0 / z) < 1e-10);
    }
    let sol = s
        .solve(&RingLoad::forces([0.0, 0.0, 8_000.0, 5e4, 0.0]))
        .unwrap();
    assert!(sol.status.converged(), "{sol:?}");
    let (g, _) = s.load_at(sol.displacement);
    assert!((g[3] - 5e4).abs() < 1e-9 * 8_000.0 * 30.0);
}

#[test]
fn converges_over_five_decades_of_load_with_small_load_zones_and_moments() {
    // large clearance and small loads (one or two rollers in contact), preload, moments
    let mut worst = 0;
    for clearance in [-0.01, 0.0, 0.02, 0.1] {
        for f in [1.0, 1e2, 1e4, 1e5] {
            let mut b = crb();
            b.roller_profile = Profile::iso(12.0, 10.0);
            b.clearance_mm = clearance;
            b.first_roller_azimuth_rad = 0.3;
            let mut s = RollerBearingSolver::new(b).unwrap();
            for load in [
                [f, 0.3 * f, 0.0, 0.0, 0.0],
                [f, -f, 0.0, 2.0 * f, 1.0 * f],
                [0.0, 0.0, 0.0, 0.0, 5.0 * f],
            ] {
                let sol = s.solve(&RingLoad::forces(load)).unwrap();
                assert!(sol.status.converged(), "s {clearance} {load:?}: {sol:?}");
                let (g, _) = s.load_at(sol.displacement);
                let f_ref = load[..3].iter().fold(0.0_f64, |m, v| m.max(v.abs()));
                let f_ref = f_ref.max(load[3].hypot(load[4]) / 30.0);
                for i in 0..5 {
                    let scale = if i < 3 { f_ref } else { 30.0 * f_ref };
                    assert!((g[i] - load[i]).abs() <= 1e-9 * scale, "{load:?}: {g:?}");
                }
                worst = worst.max(sol.status.iterations);
            }
        }
    }
    assert!(worst <= 40, "{worst} iterations");
    // a tapered bearing, tilts free, combined load with a moment, over the decades
    for f in [1.0, 1e2, 1e4, 1e5] {
        let mut b = trb();
        b.roller_profile = Profile::iso(b.effective_length_mm, b.roller_diameter_mm);
        b.clearance_mm = 0.01;
        let mut s = RollerBearingSolver::new(b).unwrap();
        let load = [0.3 * f, 0.1 * f, f, 0.0, 2.0 * f];
        let sol = s.solve(&RingLoad::forces(load)).unwrap();
        assert!(sol.status.converged(), "{load:?}: {sol:?}");
    }
}

#[test]
fn pure_axial_roller_loads_match_todays_two_dimensional_roller_loads() {
    // kontakt::bearing::roller_loads (issue 11): the 2-D force balance of one representative
    // roller under pure axial load, in its own frame (z toward the apex, n_i = (cos α_i,
    // −sin α_i)); here z is mirrored, so its rib normal (d_x, d_z) is β = atan2(−d_z, d_x)
    use kontakt::bearing::{TaperedKinematics, roller_loads};
    use nalgebra::{Point3, Vector3};
    let (alpha_i, half) = (11.17_f64.to_radians(), 1.5_f64.to_radians());
    let k = TaperedKinematics::new(alpha_i, half, Point3::origin(), 40.0, 100.0, 0.0).unwrap();
    let e_r = k.directions(0.0).roller_axis;
    let (fa, z) = (9_000.0, 23usize);
    for tilt_deg in [0.0_f64, 2.0, -2.0, 5.0] {
        // the rib normal: back along the roller axis, turned in the section plane
        let (s, c) = tilt_deg.to_radians().sin_cos();
        let d = Vector3::new(-e_r.x * c - e_r.z * s, 0.0, e_r.x * s - e_r.z * c);
        let old = roller_loads(&k, &d, fa, z, 0.0).unwrap();
        let mut b = trb();
        b.rollers = z;
        b.cone_angle_rad = alpha_i;
        b.contact_angle_rad = k.outer_raceway_angle();
        b.rib_angle_rad = Some((-d.z).atan2(d.x));
        let mut solver = RollerBearingSolver::new(b).unwrap();
        let sol = solver
            .solve(&RingLoad::forces([0.0, 0.0, fa, 0.0, 0.0]))
            .unwrap();
        assert!(sol.status.converged());
        for r in solver.roller_loads() {
            assert!(
                rel(r.outer_n, old.outer_raceway) < 1e-9,
                "{tilt_deg}: {r:?} {old:?}"
            );
            assert!(
                rel(r.inner_n, old.inner_raceway) < 1e-9,
                "{tilt_deg}: {r:?} {old:?}"
            );
            assert!(rel(r.rib_n, old.rib) < 1e-9, "{tilt_deg}: {r:?} {old:?}");
        }
    }
}

#[test]
fn a_moment_beyond_what_the_axial_load_holds_ends_with_a_status_not_a_number() {
    // a thrust bearing: |M| > F_z R lifts every roller on one side and more; no equilibrium
    let mut s = RollerBearingSolver::new(RollerBearing::thrust(60.0, 16, 6.0, 8.0)).unwrap();
    // issue 28, bad input: beyond |M| < F_z (R + L_we/2) = 34 000 N mm no distribution of
    // the roller loads holds it: refused, naming the moment
    let e = s
        .solve(&RingLoad::forces([
            0.0,
            0.0,
            1_000.0,
            0.0,
            2.0 * 1_000.0 * 30.0,
        ]))
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("invalid load.my_nmm = 60000: expected |M| < F_z (d_m/2 + L_we/(2 sin alpha)) = 34000.000000 N mm"),
        "{e}"
    );
    // inside that bound but above F_z R: a status (or an equilibrium), finite numbers
    let sol = s
        .solve(&RingLoad::forces([0.0, 0.0, 1_000.0, 0.0, 33_000.0]))
        .unwrap();
    assert!(sol.status.converged() || sol.note.is_some(), "{sol:?}");
    let finite = |a: &[f64]| a.iter().all(|v| v.is_finite());
    assert!(finite(&sol.displacement) && finite(&sol.load) && sol.status.residual.is_finite());
    assert!(sol.stiffness.iter().all(|row| finite(row)));
}
