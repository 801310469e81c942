//! The C example `examples/c/element.c`, compiled with the system C compiler (`cc`, or
//! `$CC`) against `include/kontakt.h` and linked with the static library that `cargo test`
//! builds next to this test (`target/<profile>/libkontakt_capi.a`), run; its printed
//! numbers must equal the Rust API's [`ContactElement::evaluate`] on the same input and
//! the same sequence of calls to 1e-12 relative (per quantity, relative to its largest
//! component), for the Hertz and the PimP back-ends. It also checks the error path (a NaN
//! pose: code 1, the message names `pose1`) and the separated pose (status 0, zero force).

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

use kontakt::bearing::{RollerRib, RollerRibSpec};
use kontakt::element::{Backend, ContactElement, ContactStatus, ElementResult, ElementSpec};
use kontakt::geometry::Twist;
use kontakt::pimp::PimpOptions;
use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};

#[path = "support/c_program.rs"]
mod c_program;

use c_program::{Section, numbers, run_c_program, sections};

fn v3(v: &Vector3<f64>) -> Vec<f64> {
    vec![v.x, v.y, v.z]
}

/// The C section equals the Rust result to 1e-12 relative (per quantity).
fn assert_same(label: &str, s: &Section, r: &ElementResult) {
    let status = match r.status {
        ContactStatus::Separated => 0.0,
        ContactStatus::Contact => 1.0,
        ContactStatus::OutOfValidity => 2.0,
    };
    let expected: Vec<(&str, Vec<f64>)> = vec![
        ("code", vec![0.0]),
        ("status", vec![status]),
        ("separation", vec![r.separation]),
        ("approach", vec![r.approach]),
        ("point", v3(&r.point.coords)),
        ("normal", v3(&r.normal)),
        ("normal_force", vec![r.normal_force]),
        ("damping_force", vec![r.damping_force]),
        ("friction_force", v3(&r.friction_force)),
        ("friction_moment", v3(&r.friction_moment)),
        ("friction_power", vec![r.friction_power]),
        ("force1", v3(&r.force1)),
        ("moment1", v3(&r.moment1)),
        ("moment2", v3(&r.moment2)),
        ("max_pressure", vec![r.max_pressure]),
        ("contact_area", vec![r.contact_area]),
        ("iterations", vec![r.iterations as f64]),
    ];
    for (key, want) in expected {
        let got = numbers(s, key);
        assert_eq!(got.len(), want.len(), "{label} {key}");
        let scale = got.iter().chain(&want).fold(0.0_f64, |m, x| m.max(x.abs()));
        for (g, w) in got.iter().zip(&want) {
            assert!(
                (g - w).abs() <= 1e-12 * scale,
                "{label} {key}: C {got:?}, Rust {want:?}"
            );
        }
    }
    assert_eq!(
        s.get("message").map(String::as_str).unwrap_or(""),
        r.message
    );
}

fn pose_along(n: &Vector3<f64>, d: f64) -> Isometry3<f64> {
    Isometry3::from_parts(Translation3::from(n * d), UnitQuaternion::identity())
}

#[test]
fn c_example_matches_the_rust_api() {
    let stdout = run_c_program("element.c", &[]);
    println!("{stdout}");
    assert!(stdout.starts_with(&format!("kontakt {}", env!("CARGO_PKG_VERSION"))));
    let all = sections(&stdout);
    let rr = RollerRib::new(RollerRibSpec::builtin("torus-torus-14").unwrap()).unwrap();
    for (name, backend) in [
        ("hertz", Backend::Hertz),
        ("pimp", Backend::Pimp(PimpOptions::default())),
    ] {
        // The same element through the library (steel, Coulomb 0.1, dry: the case defaults).
        let mut spec = ElementSpec::new(rr.face.clone(), rr.rib.clone()).unwrap();
        spec.backend = backend;
        let mut e = ContactElement::new(spec).unwrap();
        let id = Isometry3::identity();
        let rest = Twist::zero();
        let turning = Twist::new(Vector3::new(5.0, 0.0, 0.0), Vector3::new(0.0, 0.0, 10.0));
        let section = |what: &str| {
            all.get(&format!("{name} {what}"))
                .unwrap_or_else(|| panic!("no section `{name} {what}` in\n{stdout}"))
        };

        let reference = e.evaluate(&id, &id, &rest, &rest).unwrap();
        assert_same(name, section("reference"), &reference);
        let n = reference.normal.into_inner();

        let pressed = e
            .evaluate(&pose_along(&n, -0.004), &id, &turning, &rest)
            .unwrap();
        let s = section("pressed");
        assert_same(name, s, &pressed);
        assert_eq!(pressed.status, ContactStatus::Contact);
        assert!((pressed.approach - 0.004).abs() < 1e-9);
        assert!(pressed.normal_force > 100.0 && pressed.friction_power > 0.0);
        let f2 = numbers(s, "force2");
        assert_eq!(f2, v3(&-pressed.force1));

        let apart = e.evaluate(&pose_along(&n, 0.1), &id, &rest, &rest).unwrap();
        let s = section("apart");
        assert_same(name, s, &apart);
        assert_eq!(numbers(s, "status"), vec![0.0]);
        assert!((numbers(s, "separation")[0] - 0.1).abs() < 1e-6);
        assert_eq!(numbers(s, "force1"), vec![0.0; 3]);

        let s = section("nan");
        assert_eq!(numbers(s, "code"), vec![1.0]);
        let message = &s["error"];
        assert!(message.contains("pose1"), "{message}");
        let mut bad = Isometry3::identity();
        bad.translation.x = f64::NAN;
        let err = e.evaluate(&bad, &id, &rest, &rest).unwrap_err();
        assert_eq!(message, &err.to_string());
    }
}
