//! One model-exchange evaluation of the bearing FMU — `fmi2SetReal` of the inputs and
//! `fmi2GetReal` of the outputs — allocates nothing, cold and warm, damped, lifted off
//! (issue 31, "Speed"; hot loops allocate nothing), for a ball and a tapered roller
//! bearing.

#![allow(unsafe_code)] // calling the C API
#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

// The allocation counter of the kontakt crate's tests, shared rather than copied.
#[path = "../../kontakt/tests/support/counting_alloc.rs"]
mod counting_alloc;

use counting_alloc::allocations;
use kontakt_fmi::description::guid;
use kontakt_fmi::fmi2::*;
use std::path::PathBuf;

mod support;

#[test]
fn a_model_exchange_call_allocates_nothing() {
    for name in ["bearing_7205.toml", "bearing_32008x.toml"] {
        let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
        let text = std::fs::read_to_string(root.join("examples").join(name)).unwrap();
        let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
            .join("fmi-alloc")
            .join(name);
        let fmu = support::instantiate(&text, 0, &dir, &guid(&text));
        assert!(!fmu.is_null());
        let (inputs, outputs, status) = support::bearing_references(&text);
        let mut y = vec![0.0; outputs.len()];
        // SAFETY: a live instance, arrays of the stated lengths.
        let call = |x: [f64; 10], y: &mut [f64]| unsafe {
            let a = fmi2SetReal(fmu, inputs.as_ptr(), 10, x.as_ptr());
            let b = fmi2GetReal(fmu, outputs.as_ptr(), outputs.len(), y.as_mut_ptr());
            (a, b)
        };
        // SAFETY: as above.
        unsafe {
            assert_eq!(fmi2EnterInitializationMode(fmu), 0);
            assert_eq!(fmi2SetReal(fmu, &0, 1, &1e-4), 0);
        }
        let u = [0.01, 0.003, 0.02, 1e-4, -5e-5];
        let mut x = [0.0; 10];
        x[..5].copy_from_slice(&u);
        assert_eq!(allocations(|| call(x, &mut y)), ((0, 0), 0), "{name} cold");
        assert_eq!(y[status], 1.0, "loaded");
        x[5..].copy_from_slice(&[3.0, -1.0, 2.0, 0.05, -0.02]);
        x[0] *= 1.01;
        assert_eq!(
            allocations(|| call(x, &mut y)),
            ((0, 0), 0),
            "{name} warm, damped"
        );
        let lifted = [0.0, 0.0, -0.05, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        let ((a, b), n) = allocations(|| call(lifted, &mut y));
        assert_eq!((a, b, y[status]), (0, 0, 0.0), "{name} lifted off");
        assert_eq!(n, 0, "{name} lifted off");
        // SAFETY: instantiated above, freed once.
        unsafe { fmi2FreeInstance(fmu) };
    }
}
