//! Criterion benchmarks of the bearing element (issue 28 §4): the same evaluation through
//! the C function `kontakt_bearing_element_evaluate` and through the Rust
//! `BearingElement::evaluate`, side by side, for the 7205 angular-contact ball bearing
//! (12 balls) and the 32008 X tapered roller bearing (23 rollers × 31 slices) of
//! examples/, at a loaded displacement with a velocity and damping on. Each element is
//! created once outside the timed closure; the timed call is one evaluation, warm-started
//! from the previous one (a multi-body code's steady use). The difference of the two is the
//! cost of the C boundary (null checks, `catch_unwind`, the result copy with its 512-byte
//! message). `trb_32008x_friction` is the same bearing with a `[lubricant]`
//! (examples/bearing_32008x_friction.toml, 1000 r/min): the evaluation plus the friction
//! torque of every slice (issue 29 §5); its difference to `trb_32008x` is the friction's
//! cost. Run: `cargo bench -p kontakt-capi --bench bearing_element`.

#![allow(unsafe_code)] // calling the C API

use criterion::{Criterion, criterion_group, criterion_main};
use kontakt_capi::{
    KONTAKT_OK, KontaktBearingResult, kontakt_bearing_element_evaluate,
    kontakt_bearing_element_free, kontakt_bearing_element_from_toml,
    kontakt_bearing_element_set_damping,
};
use kontakt_case::bearing_model::BearingElement;
use std::ffi::CString;
use std::hint::black_box;
use std::path::PathBuf;
use std::ptr::null_mut;

fn case_text(name: &str) -> String {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples")
        .join(name);
    std::fs::read_to_string(path).expect("the example bearing case")
}

fn bench_bearing_element(c: &mut Criterion) {
    let mut group = c.benchmark_group("bearing_element");
    let v = [3.0, -1.0, 2.0, 0.05, -0.02];
    let damping_s = 1e-4;
    for (label, file, u) in [
        (
            "acbb_7205",
            "bearing_7205.toml",
            [0.01, 0.003, 0.02, 2e-4, -1e-4],
        ),
        (
            "trb_32008x",
            "bearing_32008x.toml",
            [0.01, -0.002, 0.015, 1e-4, 5e-5],
        ),
        (
            "trb_32008x_friction",
            "bearing_32008x_friction.toml",
            [0.01, -0.002, 0.015, 1e-4, 5e-5],
        ),
    ] {
        let text = case_text(file);

        let mut rust = BearingElement::from_toml(&text).expect("valid case");
        rust.set_damping(damping_s).expect("valid damping");
        let reference = rust.evaluate(u, v).expect("evaluate");
        group.bench_function(format!("{label}_rust"), |b| {
            b.iter(|| rust.evaluate(black_box(u), black_box(v)).expect("evaluate"))
        });

        let c_text = CString::new(text).expect("no NUL in the case");
        let mut e = null_mut();
        // SAFETY: a valid C string and a writable out pointer.
        let code = unsafe { kontakt_bearing_element_from_toml(c_text.as_ptr(), &mut e) };
        assert_eq!(code, KONTAKT_OK);
        // SAFETY: a live element.
        assert_eq!(
            unsafe { kontakt_bearing_element_set_damping(e, damping_s) },
            KONTAKT_OK
        );
        // SAFETY: plain data: all zeros is a valid value.
        let mut r: KontaktBearingResult = unsafe { std::mem::zeroed() };
        // SAFETY: a live element, arrays of 5 doubles, a writable result.
        let code = unsafe { kontakt_bearing_element_evaluate(e, u.as_ptr(), v.as_ptr(), &mut r) };
        assert_eq!(code, KONTAKT_OK);
        assert_eq!(r.force, reference.force_n, "C and Rust agree");
        group.bench_function(format!("{label}_c_api"), |b| {
            b.iter(|| {
                let (u, v) = (black_box(u), black_box(v));
                // SAFETY: as above.
                unsafe { kontakt_bearing_element_evaluate(e, u.as_ptr(), v.as_ptr(), &mut r) }
            })
        });
        // SAFETY: created above, freed once.
        unsafe { kontakt_bearing_element_free(e) };
    }
    group.finish();
}

criterion_group!(benches, bench_bearing_element);
criterion_main!(benches);
