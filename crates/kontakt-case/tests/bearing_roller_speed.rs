//! `[speed]` for roller bearings with `roller_model = "rib_contact"` (docs/bearing-model.md
//! §15.7): every roller carries `F_c = m ω_c² r_c`. At rest nothing changes (bit for bit);
//! a radially loaded NU CRB's rollers balance `Q_o − Q_i = F_c`; the rib study's TRB under
//! pure axial load at speed gives the rib study's own 2-D roller loads with the rib study's
//! own centrifugal force (to 1e-9); F_c ∝ ω² and ∝ ρ; the ISO model at speed solves the
//! load distribution at rest with a warning giving the way out; a sweep over `speed.inner_rpm` plans every speed, its rows the reports'.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

use arrow_array::{Array, Float64Array, RecordBatch, StringArray};
use kontakt::bearing::{RollerRib, RollerRibSpec, RollerSet, TaperedKinematics, roller_loads};
use kontakt_case::sweep::Sweep;
use kontakt_case::{Case, run_bearing_case};

#[path = "support/bearing_examples.rs"]
mod bearing_examples;
use bearing_examples::{example, examples, run};

/// `text` with a `[speed]` table before `[load]`.
fn at_speed(text: &str, inner_rpm: f64, outer_rpm: f64) -> String {
    text.replacen(
        "\n[load]\n",
        &format!("\n[speed]\ninner_rpm = {inner_rpm:?}\nouter_rpm = {outer_rpm:?}\n\n[load]\n"),
        1,
    )
}

/// The CRB example as an NU bearing under a pure radial load of 10 kN.
fn nu_radial() -> String {
    let text = example("bearing_nj_crb_rib_contact.toml")
        .replace("arrangement = \"nj\"", "arrangement = \"nu\"")
        .replace(
            "force_n = [10000.0, 0.0, 1500.0]",
            "force_n = [10000.0, 0.0, 0.0]",
        );
    assert!(text.contains("\"nu\"") && text.contains("[10000.0, 0.0, 0.0]"));
    text
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// At rest the report is the same, bit for bit (serde's numbers), whether or not the case
/// has a `[speed]` at zero and a roller density: no new keys, no changed numbers.
#[test]
fn zero_speed_changes_nothing() {
    for text in [example("bearing_rib_contact_60mm.toml"), nu_radial()] {
        let plain = serde_json::to_value(run(&text).unwrap()).unwrap();
        let edited = at_speed(&text, 0.0, 0.0).replacen(
            "roller_model = \"rib_contact\"\n",
            "roller_model = \"rib_contact\"\nroller_density_kg_m3 = 3200.0\n",
            1,
        );
        assert!(edited.contains("[speed]") && edited.contains("3200.0"));
        let zero = serde_json::to_value(run(&edited).unwrap()).unwrap();
        assert_eq!(plain, zero);
        assert!(plain.get("ring_speeds_rpm").is_none());
        assert!(
            plain["roller_loads"][0]
                .get("centrifugal_force_n")
                .is_none()
        );
    }
}

/// An NU CRB under a pure radial load at 8000 r/min of the inner ring: F_c in closed form
/// (m = ρ π D² L/4, ω_c = ½ ω_i (1 − D/d_m), r_c = d_m/2) on every roller, and every
/// roller's force balance `Q_o − Q_i = F_c` to 1e-9 of the largest load; the rollers out of
/// the load zone ride on the cup with `Q_o = F_c`.
#[test]
fn crb_radial_load_at_speed_balances_the_centrifugal_force() {
    let report = run(&at_speed(&nu_radial(), 8000.0, 0.0)).unwrap();
    assert_eq!(report.ring_speeds_rpm, Some([8000.0, 0.0]));
    let r = report.rollers().unwrap();
    let (d, l, dm) = (11.0, 11.0, 60.0);
    let m = 7850e-12 * std::f64::consts::PI * d * d * l / 4.0;
    let wc = 0.5 * 8000.0 * std::f64::consts::PI / 30.0 * (1.0 - d / dm);
    let fc = m * wc * wc * dm / 2.0;
    let q_max = r
        .roller_loads
        .iter()
        .fold(0.0f64, |a, row| a.max(row.outer_load_n));
    let mut worst = 0.0f64;
    let mut riding = 0;
    for row in &r.roller_loads {
        let f = row.centrifugal_force_n.unwrap();
        assert!(rel(f, fc) < 1e-13, "{f} {fc}");
        worst = worst.max((row.outer_load_n - row.inner_load_n - f).abs() / q_max);
        assert_eq!(row.rib_load_n, 0.0);
        if row.inner_load_n == 0.0 {
            riding += 1;
            assert!(rel(row.outer_load_n, fc) < 1e-9);
        }
    }
    eprintln!(
        "F_c {fc:.6} N, Q_o,max {q_max:.3} N, {riding} rollers on the cup alone, balance {worst:.2e}"
    );
    assert!(fc > 10.0 && riding > 0);
    assert!(worst < 1e-9, "{worst:e}");
}

/// The rib study's TRB (pair sphere-torus-57, 17 rollers 16 mm long, steel) under its
/// 15 kN axial load at 6000 r/min: the rib study's own F_c (`RollerSet::mass`,
/// `TaperedKinematics`, m ω_c² r_c) equals the bearing's to 1e-12, and every roller's cup,
/// cone and rib loads equal `roller_loads` with that F_c to 1e-9. The diameters are derived
/// from the pair at full precision (the example rounds them to 1e-6 mm).
#[test]
fn trb_axial_load_at_speed_gives_the_rib_studys_loads() {
    let pair = RollerRib::new(RollerRibSpec::builtin("sphere-torus-57").unwrap()).unwrap();
    let rpm = 6000.0;
    let w = rpm * std::f64::consts::PI / 30.0;
    let k = TaperedKinematics::of_roller_rib(&pair, w, 0.0).unwrap();
    let mass = RollerSet::default().mass(&pair).unwrap();
    let fc_study = mass.mass * k.cage_speed * k.cage_speed * mass.radius * 1e-3;
    let want = roller_loads(
        &k,
        &pair.contact.normal.into_inner(),
        15_000.0,
        17,
        fc_study,
    )
    .unwrap();
    // the bearing's numbers from the pair (examples/bearing_rib_study_60mm.toml's comments)
    let (beta, big) = (
        pair.spec.bearing.roller_half_angle_deg.to_radians(),
        pair.spec.bearing.roller_large_end_radius,
    );
    let ai = pair.raceway_angle_deg.to_radians();
    let mean = 2.0 * (big - 8.0 * beta.tan());
    let pitch = 2.0 * (big / beta.tan() - 8.0) * (ai + beta).sin();
    let text = example("bearing_rib_study_60mm.toml")
        .replace("slices = 31\n", "slices = 31\nroller_model = \"rib_contact\"\n\n[bearing.rib_contact]\npairing = \"sphere-torus-57\"\n")
        .replace("pitch_diameter_mm = 74.141904", &format!("pitch_diameter_mm = {pitch:?}"))
        .replace("roller_diameter_mm = 10.161476", &format!("roller_diameter_mm = {mean:?}"))
        .replace("cup_angle_deg = 25.481595648", &format!("cup_angle_deg = {:?}", (ai + 2.0 * beta).to_degrees()))
        .replace("cone_angle_deg = 19.481595648", &format!("cone_angle_deg = {:?}", ai.to_degrees()));
    for rounded in [
        "= 74.141904\n",
        "= 10.161476\n",
        "= 25.481595648\n",
        "= 19.481595648\n",
    ] {
        assert!(!text.contains(rounded), "{rounded}");
    }
    let report = run(&at_speed(&text, rpm, 0.0)).unwrap();
    let r = report.rollers().unwrap();
    let mut worst = 0.0f64;
    let fc = r.roller_loads[0].centrifugal_force_n.unwrap();
    for row in &r.roller_loads {
        worst = worst
            .max(rel(row.outer_load_n, want.outer_raceway))
            .max(rel(row.inner_load_n, want.inner_raceway))
            .max(rel(row.rib_load_n, want.rib));
    }
    eprintln!(
        "F_c {fc:.9} N (rib study {fc_study:.9} N, {:.1e}), cup {:.6} N (2-D {:.6}), cone {:.6} ({:.6}), rib {:.6} ({:.6}), largest deviation {worst:.2e}",
        rel(fc, fc_study),
        r.roller_loads[0].outer_load_n,
        want.outer_raceway,
        r.roller_loads[0].inner_load_n,
        want.inner_raceway,
        r.roller_loads[0].rib_load_n,
        want.rib
    );
    assert!(rel(fc, fc_study) < 1e-12, "{fc} {fc_study}");
    assert!(worst < 1e-9, "{worst:e}");
    // the speed matters: at rest the rib load differs by far more than the tolerance
    let rest = run(&text).unwrap();
    let rib0 = rest.rollers().unwrap().roller_loads[0].rib_load_n;
    assert!(rel(rib0, want.rib) > 1e-4, "{rib0} {}", want.rib);
}

/// F_c ∝ ω² (either ring) and ∝ ρ exactly, in the report.
#[test]
fn centrifugal_force_scales_with_speed_squared_and_density() {
    let text = example("bearing_rib_contact_60mm_speed.toml");
    let fc = |t: &str| {
        run(t).unwrap().rollers().unwrap().roller_loads[3]
            .centrifugal_force_n
            .unwrap()
    };
    let base = fc(&text);
    assert!(base > 1.0);
    let fast = fc(&text.replace("inner_rpm = 6000.0", "inner_rpm = 12000.0"));
    assert!(rel(fast, 4.0 * base) < 1e-14, "{fast} {base}");
    let light = fc(&text.replace(
        "roller_density_kg_m3 = 7850.0",
        "roller_density_kg_m3 = 3925.0",
    ));
    assert!(rel(light, 0.5 * base) < 1e-14, "{light} {base}");
    let backward = fc(&text.replace("inner_rpm = 6000.0", "inner_rpm = -6000.0"));
    assert!(rel(backward, base) < 1e-15);
}

/// The ISO model at speed (TRB and CRB, ISO and coupled slices): the load distribution is
/// the one at rest bit for bit (the model has no centrifugal force), the report carries the
/// ring speeds and, first among its warnings, the one saying so with the way out; a sweep's
/// rows carry the same warning as the report.
#[test]
fn iso_model_at_speed_warns_and_keeps_the_load_distribution_at_rest() {
    for (name, coupled) in [
        ("bearing_rib_study_60mm.toml", false),
        ("bearing_nu_crb.toml", false),
        ("bearing_32216.toml", true),
    ] {
        let mut rest = example(name);
        if coupled {
            rest = rest.replacen("[bearing]\n", "[bearing]\nslice_model = \"coupled\"\n", 1);
        }
        let r0 = run(&rest).unwrap();
        for (ni, no) in [(3000.0, 0.0), (0.0, -50.0)] {
            let r = run(&at_speed(&rest, ni, no)).unwrap();
            assert_eq!(r.displacement_mm, r0.displacement_mm, "{name}");
            assert_eq!(r.tilt_rad, r0.tilt_rad, "{name}");
            assert_eq!(r.ring_speeds_rpm, Some([ni, no]), "{name}");
            assert_eq!(r.warnings.len(), r0.warnings.len() + 1, "{name}");
            assert_eq!(r.warnings[1..], r0.warnings[..], "{name}");
            let w = &r.warnings[0];
            assert!(
                w.contains("without the rollers' centrifugal force")
                    && w.contains("use roller_model = \"rib_contact\""),
                "{w}"
            );
        }
        assert!(r0.ring_speeds_rpm.is_none());
    }
    let dir = std::env::temp_dir().join(format!("kontakt-iso-speed-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let base = dir.join("case.toml");
    let text = at_speed(&example("bearing_rib_study_60mm.toml"), 3000.0, 0.0);
    std::fs::write(&base, &text).unwrap();
    let s = Sweep::from_toml_str(
        &format!(
            "base = \"{}\"\n[[parameter]]\nkey = \"speed.inner_rpm\"\nvalues = [0.0, 3000.0]\n",
            base.display()
        ),
        &dir,
    )
    .unwrap();
    let batch = s.chunk_table(0).unwrap();
    let warnings = column::<StringArray>(&batch, "warnings");
    let report = run(&text).unwrap();
    assert_eq!(warnings.value(1), report.warnings.join("; "));
    assert!(warnings.is_null(0) || !warnings.value(0).contains("centrifugal"));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Thrust bearings at speed, a bad speed or density: one error naming the key.
#[test]
fn bad_speed_and_density_are_named() {
    let err = |t: &str| run(t).unwrap_err();
    let e = err(&example("bearing_nu_crb.toml").replacen(
        "\n[load]\n",
        "\n[speed]\nouter_rpm = nan\n\n[load]\n",
        1,
    ));
    assert_eq!(e.field(), Some("speed.outer_rpm"), "{e}");
    let e = err(&at_speed(&example("bearing_81107_thrust.toml"), 100.0, 0.0));
    assert!(e.to_string().contains("type = \"thrust\""), "{e}");
    let text = example("bearing_rib_contact_60mm_speed.toml");
    for bad in ["0.0", "-7850.0", "nan", "inf"] {
        let e = err(&text.replace(
            "roller_density_kg_m3 = 7850.0",
            &format!("roller_density_kg_m3 = {bad}"),
        ));
        assert_eq!(e.field(), Some("bearing.roller_density_kg_m3"), "{e}");
    }
    let e = err(&text.replace("roller_density_kg_m3", "roller_density"));
    assert!(e.to_string().contains("roller_density"), "{e}");
}

fn column<'a, T: 'static>(b: &'a RecordBatch, name: &str) -> &'a T {
    b.column_by_name(name)
        .unwrap_or_else(|| panic!("no {name}"))
        .as_any()
        .downcast_ref::<T>()
        .unwrap()
}

/// A sweep over `speed.inner_rpm` of the rib-contact TRB at speed plans every speed: each
/// row is the cold report of its case (displacement, largest roller load) with the
/// report's warnings, the rows differ with the speed.
#[test]
fn a_speed_sweep_of_a_rib_contact_bearing_plans_each_speed() {
    let speeds = [0.0, 3000.0, 6000.0, 12000.0];
    let dir = examples().join("sweeps");
    let s = Sweep::from_toml_str(
        &format!(
            "base = \"../bearing_rib_contact_60mm_speed.toml\"\n[[parameter]]\nkey = \"speed.inner_rpm\"\nvalues = {speeds:?}\n"
        ),
        &dir,
    )
    .unwrap();
    let batch = s.chunk_table(0).unwrap();
    let dz = column::<Float64Array>(&batch, "displacement_mm[2]");
    let q = column::<Float64Array>(&batch, "max_element_load_n");
    let warnings = column::<StringArray>(&batch, "warnings");
    let text = example("bearing_rib_contact_60mm_speed.toml");
    let mut last = f64::NAN;
    for (i, n) in speeds.iter().enumerate() {
        let case = text.replace("inner_rpm = 6000.0", &format!("inner_rpm = {n:?}"));
        let Case::Bearing(c) = Case::from_toml_str(&case).unwrap() else {
            panic!("not a bearing case")
        };
        let r = run_bearing_case(&c).unwrap();
        assert!(
            (dz.value(i) - r.displacement_mm[2]).abs() <= 1e-9 * r.displacement_mm[2].abs(),
            "{n} r/min: sweep {}, report {}",
            dz.value(i),
            r.displacement_mm[2]
        );
        let q_report = r
            .rollers()
            .unwrap()
            .roller_loads
            .iter()
            .fold(0.0f64, |a, row| a.max(row.outer_load_n));
        assert!(
            rel(q.value(i), q_report) < 1e-9,
            "{n}: {} {q_report}",
            q.value(i)
        );
        let w = (!warnings.is_null(i)).then(|| warnings.value(i).to_string());
        let want = (!r.warnings.is_empty()).then(|| r.warnings.join("; "));
        assert_eq!(w, want, "{n} r/min");
        assert!(
            q.value(i) != last,
            "{n}: the same row as the previous speed"
        );
        last = q.value(i);
    }
}
