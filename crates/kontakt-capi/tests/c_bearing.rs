//! The C example `examples/c/bearing.c` (the bearing element), compiled and run on
//! examples/bearing_7205.toml (an angular-contact ball bearing) and
//! examples/bearing_32008x.toml (a tapered roller bearing): its printed force and moment
//! must be minus the load of the Rust `BearingModel` solve with the same five displacements
//! prescribed, and its stiffness that solve's, to 1e-12 relative; the stiffness must match
//! the C program's central differences of the force (1e-6 of `sqrt(K_ii K_jj)`); the damping
//! must be `−β K v`; pulled out of every contact the status is lifted off with zero force;
//! and every error path gives its code and a message naming the argument. With
//! examples/bearing_32008x_friction.toml (a lubricated TRB) the friction fields equal the
//! Rust `BearingElement`'s at the same displacement and ring speeds to 1e-12, at the case's
//! speed, at rest and with both rings turning; a NaN speed is refused naming `outer_rad_s`.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

#[path = "support/c_program.rs"]
mod c_program;

use c_program::{Section, numbers, run_c_program, sections};
use kontakt_capi::{
    KONTAKT_BEARING_LIFTED_OFF, KONTAKT_BEARING_LOADED, KONTAKT_FRICTION_OFF,
    KONTAKT_FRICTION_RUNNING, KONTAKT_FRICTION_STARTING, KONTAKT_INVALID_INPUT,
    KONTAKT_NULL_OR_UTF8,
};
use kontakt_case::bearing_model::prescribed_load;
use kontakt_case::{BearingCase, BearingModel};
use std::path::PathBuf;

fn example(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples")
        .join(name)
}

/// The carried load `(Fx, Fy, Fz, Mx, My)` and the stiffness of the Rust `BearingModel`
/// with every degree of freedom prescribed at `u`.
fn rust_solution(path: &PathBuf, u: &[f64]) -> ([f64; 5], [[f64; 5]; 5]) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut model = BearingModel::new(&BearingCase::from_toml_str(&text).unwrap()).unwrap();
    let r = model
        .solve(&prescribed_load([u[0], u[1], u[2], u[3], u[4]]))
        .unwrap();
    let (f, m) = (r.force_n, r.moment_nmm);
    ([f[0], f[1], f[2], m[0], m[1]], r.stiffness_matrix)
}

/// The section's force and moment as `(Fx, Fy, Fz, Mx, My)`, and its `Mz`.
fn reaction(s: &Section) -> ([f64; 5], f64) {
    let f = numbers(s, "force");
    let m = numbers(s, "moment");
    ([f[0], f[1], f[2], m[0], m[1]], m[2])
}

/// |a − b| <= tol · scale per component, forces and moments scaled separately.
fn assert_close(what: &str, a: &[f64], b: &[f64], tol: f64) {
    for range in [0..3, 3..5] {
        let scale = a[range.clone()]
            .iter()
            .chain(&b[range.clone()])
            .fold(0.0_f64, |m, x| m.max(x.abs()));
        assert!(scale > 0.0, "{what}: zero");
        for i in range {
            assert!(
                (a[i] - b[i]).abs() <= tol * scale,
                "{what}[{i}]: C {a:?}, Rust {b:?}"
            );
        }
    }
}

fn code(s: &Section) -> i32 {
    numbers(s, "code")[0] as i32
}

/// An error section: its code, and the message contains every one of `needles`.
fn assert_error(s: &Section, want: i32, needles: &[&str]) {
    assert_eq!(code(s), want, "{s:?}");
    let message = &s["error"];
    for n in needles {
        assert!(message.contains(n), "`{n}` not in `{message}`");
    }
}

#[test]
fn c_bearing_element_matches_the_rust_bearing_model() {
    let ball = example("bearing_7205.toml");
    let trb = example("bearing_32008x.toml");
    let lubricated = example("bearing_32008x_friction.toml");
    let stdout = run_c_program(
        "bearing.c",
        &[ball.as_os_str(), trb.as_os_str(), lubricated.as_os_str()],
    );
    println!("{stdout}");
    let all = sections(&stdout);
    let section = |label: &str| {
        all.get(label)
            .unwrap_or_else(|| panic!("no section `{label}` in\n{stdout}"))
    };
    for (name, path, diameter) in [("ball", &ball, "7.938"), ("tapered", &trb, "6.4885")] {
        // 1. minus the prescribed-displacement solution, to 1e-12
        let s = section(&format!("{name} loaded"));
        assert_eq!(code(s), 0);
        assert_eq!(
            numbers(s, "status"),
            vec![f64::from(KONTAKT_BEARING_LOADED)]
        );
        let u = numbers(s, "displacement");
        let (load, k) = rust_solution(path, &u);
        let (r, mz) = reaction(s);
        assert_eq!(mz, 0.0);
        assert_eq!(
            numbers(s, "friction_status"),
            vec![f64::from(KONTAKT_FRICTION_OFF)]
        );
        assert_eq!(numbers(s, "friction_torque"), vec![0.0]);
        assert_close(&format!("{name} reaction"), &r, &load.map(|f| -f), 1e-12);
        let kc = numbers(s, "stiffness");
        let kmax = k.iter().flatten().fold(0.0_f64, |m, x| m.max(x.abs()));
        for i in 0..5 {
            for j in 0..5 {
                assert!(
                    (kc[5 * i + j] - k[i][j]).abs() <= 1e-12 * kmax,
                    "{name} K[{i}][{j}]: C {}, Rust {}",
                    kc[5 * i + j],
                    k[i][j]
                );
            }
        }
        assert!(numbers(s, "max_element_load")[0] > 100.0);
        assert_eq!(numbers(s, "iterations"), vec![0.0]);
        assert_eq!(numbers(s, "damping"), vec![0.0; 5]);
        // a ball bearing pressed axially and radially carries a real load: |F| of the order
        // of kN at tens of µm
        assert!(r[2] < -100.0 && r[0] < 0.0, "{name}: {r:?}");

        // 2. the stiffness against the C program's central differences of the force
        let fd = numbers(
            section(&format!("{name} central differences")),
            "fd_stiffness",
        );
        let mut worst: f64 = 0.0;
        for i in 0..5 {
            for j in 0..5 {
                let scale = (k[i][i] * k[j][j]).sqrt();
                let err = (fd[5 * i + j] - k[i][j]).abs() / scale;
                worst = worst.max(err);
                assert!(
                    err <= 1e-6,
                    "{name} K[{i}][{j}] = {} vs central difference {}",
                    k[i][j],
                    fd[5 * i + j]
                );
            }
        }
        println!("{name}: largest central-difference error {worst:e} of sqrt(K_ii K_jj)");

        // 3. damped: R = −F − β K v
        assert_eq!(code(section(&format!("{name} set damping"))), 0);
        let s = section(&format!("{name} damped"));
        let v = numbers(s, "velocity");
        let beta = 1e-4;
        let kv: Vec<f64> = (0..5)
            .map(|i| (0..5).map(|j| k[i][j] * v[j]).sum::<f64>())
            .collect();
        let want: Vec<f64> = (0..5).map(|i| -load[i] - beta * kv[i]).collect();
        assert_close(&format!("{name} damped"), &reaction(s).0, &want, 1e-12);
        let damping = numbers(s, "damping");
        let want_d: Vec<f64> = kv.iter().map(|x| -beta * x).collect();
        assert_close(&format!("{name} damping"), &damping, &want_d, 1e-12);

        // 4. lifted off: a status, zero force and stiffness, a message
        let s = section(&format!("{name} lifted off"));
        assert_eq!(code(s), 0);
        assert_eq!(
            numbers(s, "status"),
            vec![f64::from(KONTAKT_BEARING_LIFTED_OFF)]
        );
        assert_eq!(numbers(s, "force"), vec![0.0; 3]);
        assert_eq!(numbers(s, "moment"), vec![0.0; 3]);
        assert_eq!(numbers(s, "stiffness"), vec![0.0; 25]);
        assert!(s["message"].contains("lifted off"), "{s:?}");

        // 5. errors, each naming its argument
        let invalid = KONTAKT_INVALID_INPUT;
        assert_error(
            section(&format!("{name} nan")),
            invalid,
            &["displacement[3] = NaN"],
        );
        assert_error(
            section(&format!("{name} inf velocity")),
            invalid,
            &["velocity[1] = inf"],
        );
        assert_error(
            section(&format!("{name} beyond validity")),
            invalid,
            &["displacement[0] = 20", diameter],
        );
        assert_error(
            section(&format!("{name} negative damping")),
            invalid,
            &["damping_s = -1"],
        );
        let null = KONTAKT_NULL_OR_UTF8;
        for what in ["element", "displacement", "velocity", "out"] {
            assert_error(
                section(&format!("{name} null {what}")),
                null,
                &[&format!("{what} is a null pointer")],
            );
        }

        // 6. the errors left the element as it was
        let again = section(&format!("{name} again"));
        assert_eq!(
            reaction(again),
            reaction(section(&format!("{name} damped")))
        );
    }
    friction_matches_rust(&section, &lubricated);
    assert_error(section("bad case"), KONTAKT_INVALID_INPUT, &["bearing"]);
    assert_eq!(section("bad case")["out_is_null"], "1");
    assert_error(
        section("null toml"),
        KONTAKT_NULL_OR_UTF8,
        &["toml is a null pointer"],
    );
    assert_error(
        section("null out"),
        KONTAKT_NULL_OR_UTF8,
        &["out is a null pointer"],
    );
    assert_error(
        section("missing file"),
        KONTAKT_INVALID_INPUT,
        &["no/such/bearing.toml"],
    );
    assert_error(
        section("null element reset"),
        KONTAKT_NULL_OR_UTF8,
        &["element is a null pointer"],
    );
}

/// The C program's friction sections against the Rust element at the same displacement and
/// speeds: every friction field and the reaction to 1e-12 relative.
fn friction_matches_rust<'a>(section: &dyn Fn(&str) -> &'a Section, path: &PathBuf) {
    use kontakt_case::bearing_model::BearingElement;
    let mut rust = BearingElement::from_toml(&std::fs::read_to_string(path).unwrap()).unwrap();
    let rel = |a: f64, b: f64| {
        if a == b {
            0.0
        } else {
            (a - b).abs() / a.abs().max(b.abs())
        }
    };
    for (label, speeds, status) in [
        ("friction case speed", None, KONTAKT_FRICTION_RUNNING),
        (
            "friction at rest",
            Some([0.0, 0.0]),
            KONTAKT_FRICTION_STARTING,
        ),
        (
            "friction turning",
            Some([-50.0, 20.0]),
            KONTAKT_FRICTION_RUNNING,
        ),
        (
            "friction after nan",
            Some([-50.0, 20.0]),
            KONTAKT_FRICTION_RUNNING,
        ),
    ] {
        let s = section(label);
        assert_eq!(code(s), 0, "{label}: {s:?}");
        if let Some([wi, wo]) = speeds {
            rust.set_speeds(wi, wo).unwrap();
        }
        let u = numbers(s, "displacement");
        let o = rust
            .evaluate([u[0], u[1], u[2], u[3], u[4]], [0.0; 5])
            .unwrap();
        let f = &o.friction;
        assert_eq!(
            numbers(s, "friction_status"),
            vec![f64::from(status)],
            "{label}"
        );
        assert_eq!(
            numbers(s, "ring_speeds"),
            vec![f.inner_speed_rad_s, f.outer_speed_rad_s],
            "{label}"
        );
        let c_values = [
            numbers(s, "friction_torque"),
            numbers(s, "friction_inner_ring"),
            numbers(s, "friction_power"),
            numbers(s, "friction_breakdown"),
            numbers(s, "moment"),
            numbers(s, "force"),
        ]
        .concat();
        let rust_values = [
            vec![f.torque_nmm, f.inner_ring_nmm, f.power_w],
            vec![f.cone_nmm, f.cup_nmm, f.rib_nmm, f.drag_nmm],
            o.moment_nmm.to_vec(),
            o.force_n.to_vec(),
        ]
        .concat();
        for (i, (a, b)) in c_values.iter().zip(&rust_values).enumerate() {
            assert!(rel(*a, *b) <= 1e-12, "{label} value {i}: C {a}, Rust {b}");
        }
        assert!(f.torque_nmm > 0.0, "{label}");
        println!("C bearing element, {label}: {f:?}");
    }
    // Mz opposes the relative rotation: ω_i − ω_o = −70 rad/s turns the inner ring forward
    assert!(numbers(section("friction turning"), "moment")[2] > 0.0);
    assert_eq!(numbers(section("friction at rest"), "moment")[2], 0.0);
    for label in ["friction set rest", "friction set turning"] {
        assert_eq!(code(section(label)), 0, "{label}");
    }
    assert_error(
        section("friction nan speed"),
        KONTAKT_INVALID_INPUT,
        &["outer_rad_s = NaN"],
    );
    assert_error(
        section("friction null element"),
        KONTAKT_NULL_OR_UTF8,
        &["element is a null pointer"],
    );
}
