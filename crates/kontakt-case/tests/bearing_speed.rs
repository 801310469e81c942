//! Ball bearings at speed through the case (`[speed]`, `docs/bearing-model.md` §9): every
//! ball in its own equilibrium with its centrifugal force and gyroscopic moment, the
//! inner contacts balancing the applied load, the report's keys, warm solves, and errors
//! naming the case keys.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

use kontakt_case::bearing_case::BearingLoadSpec;
use kontakt_case::{BearingCase, BearingModel, BearingReport, Case, Outcome};
use std::path::PathBuf;

fn examples() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

fn run(text: &str) -> kontakt::Result<BearingReport> {
    match Case::from_toml_str(text)?.run(&examples())? {
        Outcome::Bearing(r) => Ok(*r),
        _ => panic!("not a bearing outcome"),
    }
}

fn example(name: &str) -> String {
    std::fs::read_to_string(examples().join(name)).unwrap()
}

/// The 7205 example at 15 000 r/min: the inner contacts carry the applied force,
/// `Σ Q_i (cos α_i cos ψ, cos α_i sin ψ, sin α_i) = F` to 1e-9; every ball balances
/// `Q_i n_i − Q_o n_o + F_c e_r + (2 M_g/D) t_o = 0` to 1e-9 of its outer load; the outer
/// angles fall below the free 40° and the inner ones rise; the speeds and the race control
/// are echoed, ε is reported; the JSON has the new keys.
#[test]
fn ball_bearing_at_speed_balances_every_ball() {
    let report = run(&example("bearing_7205_speed.toml")).unwrap();
    assert_eq!(report.ring_speeds_rpm, Some([15_000.0, 0.0]));
    let b = report.balls().unwrap();
    assert_eq!(b.race_control, Some("outer"));
    let d = 7.938;
    let mut f = [0.0; 3];
    for row in &b.ball_loads {
        let (s, c) = row.azimuth_deg.to_radians().sin_cos();
        let (si, ci) = row.inner_contact_angle_deg.to_radians().sin_cos();
        let (so, co) = row.outer_contact_angle_deg.to_radians().sin_cos();
        let (qi, qo) = (row.inner_load_n, row.outer_load_n);
        f[0] += qi * ci * c;
        f[1] += qi * ci * s;
        f[2] += qi * si;
        let to = 2.0 * row.gyroscopic_moment_nmm / d;
        let r = qi * ci - qo * co + row.centrifugal_force_n - to * so;
        let z = qi * si - qo * so + to * co;
        assert!(r.hypot(z) <= 1e-9 * qo, "{row:?}: {r} {z}");
        assert!(row.centrifugal_force_n > 10.0 && row.gyroscopic_moment_nmm < 0.0);
        assert!(row.outer_contact_angle_deg < 40.0 && row.inner_contact_angle_deg > 36.0);
        assert!(qo > qi);
        assert_eq!(row.load_n, qi);
        assert_eq!(row.contact_angle_deg, row.inner_contact_angle_deg);
    }
    for (i, want) in [2000.0, 0.0, 2000.0].iter().enumerate() {
        assert!((f[i] - want).abs() <= 1e-9 * 2000.0, "F[{i}] = {}", f[i]);
    }
    let eps = report.load_zone_epsilon.unwrap();
    // every ball keeps its inner contact at 15 000 r/min: a load zone beyond the half ring
    assert!(eps > 1.0, "{eps}");
    assert!(report.warnings.is_empty(), "{:?}", report.warnings);
    assert_eq!(report.contacts.len(), 2);
    let json = serde_json::to_value(&report).unwrap();
    for key in [
        "inner_load_n",
        "outer_load_n",
        "inner_contact_angle_deg",
        "outer_contact_angle_deg",
        "centrifugal_force_n",
        "gyroscopic_moment_nmm",
    ] {
        assert!(json["ball_loads"][0][key].is_f64(), "{key}");
    }
    assert_eq!(json["ring_speeds_rpm"][0], 15_000.0);
    assert_eq!(json["race_control"], "outer");
}

/// `[speed]` at rest is the quasi-static solver, bit for bit the report without the table;
/// a ball bearing at rest now reports its load zone; the new ball columns repeat the
/// ball's one load and angle.
#[test]
fn at_rest_the_speed_table_changes_nothing() {
    let plain = example("bearing_6205.toml");
    let with = plain.replace("[load]", "[speed]\ninner_rpm = 0.0\nouter_rpm = 0.0\n\n[load]");
    assert_ne!(plain, with);
    let (a, b) = (run(&plain).unwrap(), run(&with).unwrap());
    assert_eq!(
        serde_json::to_string(&a).unwrap(),
        serde_json::to_string(&b).unwrap()
    );
    assert_eq!(a.ring_speeds_rpm, None);
    assert!(a.load_zone_epsilon.unwrap() > 0.0);
    for row in &a.balls().unwrap().ball_loads {
        assert_eq!(row.inner_load_n, row.load_n);
        assert_eq!(row.outer_load_n, row.load_n);
        assert_eq!(row.outer_contact_angle_deg, row.contact_angle_deg);
        assert_eq!(row.centrifugal_force_n, 0.0);
    }
}

/// A warm solve of the model at speed gives the cold report to 1e-9 (a 1 % load change,
/// then back).
#[test]
fn warm_solves_at_speed_match_cold_ones() {
    let text = example("bearing_7205_speed.toml");
    let case = BearingCase::from_toml_str(&text).unwrap();
    let cold = run(&text).unwrap();
    let mut model = BearingModel::new(&case).unwrap();
    model.solve(&case.load).unwrap();
    let mut other: BearingLoadSpec = case.load;
    other.force_n[0] *= 1.01;
    model.solve(&other).unwrap();
    let warm = model.solve(&case.load).unwrap();
    assert!(warm.solver.iterations <= 3, "{}", warm.solver.iterations);
    for (w, c) in warm
        .balls()
        .unwrap()
        .ball_loads
        .iter()
        .zip(&cold.balls().unwrap().ball_loads)
    {
        assert!((w.inner_load_n - c.inner_load_n).abs() <= 1e-9 * 1000.0);
        assert!((w.outer_contact_angle_deg - c.outer_contact_angle_deg).abs() <= 1e-9);
    }
}

/// Errors name the key: a speed beyond ±100 000 r/min or not finite, a speed on a roller
/// bearing, an unknown key in `[speed]`, a density ≤ 0.
#[test]
fn speed_errors_name_the_case_key() {
    let acbb = example("bearing_7205_speed.toml");
    let err = |text: &str| run(text).unwrap_err();
    let e = err(&acbb.replace("inner_rpm = 15000.0", "inner_rpm = 2e5"));
    assert_eq!(e.field(), Some("speed.inner_rpm"), "{e}");
    assert!(
        e.to_string()
            .starts_with("invalid speed.inner_rpm = 200000: expected a finite speed"),
        "{e}"
    );
    let e = err(&acbb.replace("outer_rpm = 0.0", "outer_rpm = nan"));
    assert_eq!(e.field(), Some("speed.outer_rpm"), "{e}");
    let e = err(&acbb.replace("outer_rpm = 0.0", "rpm = 10.0"));
    assert!(e.to_string().contains("speed.rpm"), "{e}");
    let e = err(&acbb.replace("ball_density_kg_m3 = 7850.0", "ball_density_kg_m3 = -1.0"));
    assert_eq!(e.field(), Some("bearing.ball_density_kg_m3"), "{e}");
    let crb = example("bearing_nu_crb.toml");
    let e = err(&crb.replace("[load]", "[speed]\nouter_rpm = 100.0\n\n[load]"));
    assert_eq!(e.field(), Some("speed.outer_rpm"), "{e}");
    assert!(e.to_string().contains("ball bearings only"), "{e}");
}
