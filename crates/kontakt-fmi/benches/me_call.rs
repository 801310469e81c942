//! Criterion benchmark of one model-exchange evaluation of the bearing FMU (issue 31,
//! "Speed": at most 10 % above the Rust call): `fmi2SetReal` of the ten inputs and
//! `fmi2GetReal` of all outputs on an FMU instance, beside `BearingElement::evaluate`
//! on the same case, side by side, for the 7205 angular-contact ball bearing and the
//! 32008 X tapered roller bearing of examples/, loaded, with a velocity and damping on.
//! Both are warm-started from the previous call (a host's steady use); the difference is
//! the cost of the FMI layer (pointer checks, `catch_unwind`, the value-reference lookups,
//! the copy into the output table). Run: `cargo bench -p kontakt-fmi --bench me_call`.

#![allow(unsafe_code)] // calling the C API

use criterion::{Criterion, criterion_group, criterion_main};
use kontakt_case::bearing_model::BearingElement;
use kontakt_fmi::description::guid;
use kontakt_fmi::fmi2::{
    EventInfo, fmi2EnterContinuousTimeMode, fmi2EnterInitializationMode,
    fmi2ExitInitializationMode, fmi2FreeInstance, fmi2GetReal, fmi2NewDiscreteStates, fmi2SetReal,
};
use std::hint::black_box;

#[path = "../tests/support/mod.rs"]
mod support;

/// The bearings, displacements, velocity and damping of kontakt-capi's `bearing_element`
/// bench, so that the Rust, C and FMU rows compare.
const CASES: [(&str, &str, [f64; 5]); 2] = [
    (
        "acbb_7205",
        include_str!("../../../examples/bearing_7205.toml"),
        [0.01, 0.003, 0.02, 2e-4, -1e-4],
    ),
    (
        "trb_32008x",
        include_str!("../../../examples/bearing_32008x.toml"),
        [0.01, -0.002, 0.015, 1e-4, 5e-5],
    ),
];

fn bench_me_call(c: &mut Criterion) {
    let mut group = c.benchmark_group("fmu_me_call");
    let v = [3.0, -1.0, 2.0, 0.05, -0.02];
    let damping_s = 1e-4;
    for (label, text, u) in CASES {
        let mut rust = BearingElement::from_toml(text).expect("valid case");
        rust.set_damping(damping_s).expect("valid damping");
        let reference = rust.evaluate(u, v).expect("evaluate");
        group.bench_function(format!("{label}_rust"), |b| {
            b.iter(|| rust.evaluate(black_box(u), black_box(v)).expect("evaluate"))
        });

        let dir =
            std::env::temp_dir().join(format!("kontakt-fmi-bench-{}-{label}", std::process::id()));
        let fmu = support::instantiate(text, 0, &dir, &guid(text));
        assert!(!fmu.is_null(), "instantiated");
        let (inputs, outputs, _) = support::bearing_references(text);
        let mut x = [0.0; 10];
        x[..5].copy_from_slice(&u);
        x[5..].copy_from_slice(&v);
        let mut y = vec![0.0; outputs.len()];
        // SAFETY: a live instance, arrays of the stated lengths.
        unsafe {
            let mut info = std::mem::zeroed::<EventInfo>();
            assert_eq!(fmi2EnterInitializationMode(fmu), 0);
            assert_eq!(fmi2SetReal(fmu, &0, 1, &damping_s), 0);
            assert_eq!(fmi2ExitInitializationMode(fmu), 0);
            assert_eq!(fmi2NewDiscreteStates(fmu, &mut info), 0);
            assert_eq!(fmi2EnterContinuousTimeMode(fmu), 0);
            assert_eq!(fmi2SetReal(fmu, inputs.as_ptr(), 10, x.as_ptr()), 0);
            assert_eq!(
                fmi2GetReal(fmu, outputs.as_ptr(), outputs.len(), y.as_mut_ptr()),
                0
            );
        }
        assert_eq!(y[..3], reference.force_n, "FMU and Rust agree");
        group.bench_function(format!("{label}_fmu_me"), |b| {
            b.iter(|| {
                let x = black_box(x);
                // SAFETY: as above.
                unsafe {
                    fmi2SetReal(fmu, inputs.as_ptr(), 10, x.as_ptr());
                    fmi2GetReal(fmu, outputs.as_ptr(), outputs.len(), y.as_mut_ptr())
                }
            })
        });
        // SAFETY: instantiated above, freed once.
        unsafe { fmi2FreeInstance(fmu) };
        let _ = std::fs::remove_dir_all(&dir);
    }
    group.finish();
}

criterion_group!(benches, bench_me_call);
criterion_main!(benches);
