//! The bearing element's evaluation, through the C function and through the Rust
//! `BearingElement::evaluate` under it, allocates nothing per call —
//! cold (the first call, from the closed forms), warm (from the previous call), damped,
//! lifted off, and after a failed call (the thread's message buffer is reused) — for a
//! ball and a tapered roller bearing (issue 28, "Speed": hot loops allocate nothing), and
//! with the friction torque of a lubricated one (issue 29 §5).

#![allow(unsafe_code)] // calling the C API
#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

// The allocation counter of the kontakt crate's tests, shared rather than copied.
#[path = "../../kontakt/tests/support/counting_alloc.rs"]
mod counting_alloc;

use counting_alloc::allocations;
use kontakt_capi::*;
use std::ffi::CString;
use std::path::PathBuf;
use std::ptr::null_mut;

fn element(name: &str) -> *mut KontaktBearingElement {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples")
        .join(name);
    let path = CString::new(path.to_str().unwrap()).unwrap();
    let mut e = null_mut();
    // SAFETY: a valid C string and a writable out pointer.
    let code = unsafe { kontakt_bearing_element_from_file(path.as_ptr(), &mut e) };
    assert_eq!(code, KONTAKT_OK);
    e
}

/// One evaluation: the code, the status and the number of allocations it made.
fn counted(e: *mut KontaktBearingElement, u: [f64; 5], v: [f64; 5]) -> (i32, i32, usize) {
    // SAFETY: plain data: all zeros is a valid value.
    let mut r: KontaktBearingResult = unsafe { std::mem::zeroed() };
    let (code, n) = allocations(|| {
        // SAFETY: a live element, arrays of 5 doubles, a writable result.
        unsafe { kontakt_bearing_element_evaluate(e, u.as_ptr(), v.as_ptr(), &mut r) }
    });
    (code, r.status, n)
}

#[test]
fn bearing_element_evaluation_allocates_nothing() {
    for (name, u) in [
        ("bearing_7205.toml", [0.01, 0.003, 0.02, 2e-4, -1e-4]),
        ("bearing_32008x.toml", [0.01, -0.002, 0.015, 1e-4, 5e-5]),
    ] {
        let e = element(name);
        let v = [3.0, -1.0, 2.0, 0.05, -0.02];
        let loaded = KONTAKT_BEARING_LOADED;
        assert_eq!(
            counted(e, u, [0.0; 5]),
            (KONTAKT_OK, loaded, 0),
            "{name} cold"
        );
        let nearby = u.map(|x| 1.01 * x);
        assert_eq!(
            counted(e, nearby, v),
            (KONTAKT_OK, loaded, 0),
            "{name} warm"
        );
        // SAFETY: a live element.
        assert_eq!(
            unsafe { kontakt_bearing_element_set_damping(e, 1e-4) },
            KONTAKT_OK
        );
        assert_eq!(counted(e, u, v), (KONTAKT_OK, loaded, 0), "{name} damped");
        let out = [0.0, 0.0, -0.2, 0.0, 0.0];
        let lifted = KONTAKT_BEARING_LIFTED_OFF;
        assert_eq!(counted(e, out, v), (KONTAKT_OK, lifted, 0), "{name} lifted");
        // a failed call writes its message (allocating); the next success reuses the buffer
        let (code, _, _) = counted(e, [f64::NAN; 5], v);
        assert_eq!(code, KONTAKT_INVALID_INPUT);
        assert_eq!(
            counted(e, u, v),
            (KONTAKT_OK, loaded, 0),
            "{name} after an error"
        );
        // SAFETY: created above, freed once.
        unsafe { kontakt_bearing_element_free(e) };
    }
}

#[test]
fn rust_bearing_element_evaluation_allocates_nothing() {
    use kontakt_case::bearing_model::BearingElement;
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/bearing_32216.toml");
    let mut e = BearingElement::from_toml(&std::fs::read_to_string(path).unwrap()).unwrap();
    e.set_damping(1e-4).unwrap();
    let u = [0.01, 0.0, 0.02, 0.0, 1e-4];
    for (i, du) in [1.0, 1.01, 0.99].into_iter().enumerate() {
        let (o, n) = allocations(|| e.evaluate(u.map(|x| du * x), [1.0; 5]).unwrap());
        assert!(o.max_element_load_n > 0.0);
        assert_eq!(n, 0, "call {i}");
    }
}

/// With a `[lubricant]` (the ISO slice model of the 32008 X) every evaluation also computes
/// the friction torque, running, after a speed change and at rest (starting torque), and
/// still allocates nothing, through C and through Rust.
#[test]
fn bearing_element_friction_allocates_nothing() {
    let e = element("bearing_32008x_friction.toml");
    let u = [0.01, -0.002, 0.015, 1e-4, 5e-5];
    let loaded = KONTAKT_BEARING_LOADED;
    for (i, speeds) in [None, Some([200.0, -10.0]), Some([0.0, 0.0])]
        .into_iter()
        .enumerate()
    {
        if let Some([wi, wo]) = speeds {
            // SAFETY: a live element.
            let code = unsafe { kontakt_bearing_element_set_speeds(e, wi, wo) };
            assert_eq!(code, KONTAKT_OK);
        }
        // SAFETY: plain data: all zeros is a valid value.
        let mut r: KontaktBearingResult = unsafe { std::mem::zeroed() };
        let (code, n) = allocations(|| {
            // SAFETY: a live element, arrays of 5 doubles, a writable result.
            unsafe { kontakt_bearing_element_evaluate(e, u.as_ptr(), [0.0; 5].as_ptr(), &mut r) }
        });
        assert_eq!((code, r.status, n), (KONTAKT_OK, loaded, 0), "call {i}");
        assert!(r.friction_torque > 0.0, "call {i}");
        assert_ne!(r.friction_status, KONTAKT_FRICTION_OFF, "call {i}");
    }
    // SAFETY: created above, freed once.
    unsafe { kontakt_bearing_element_free(e) };

    use kontakt_case::bearing_model::BearingElement;
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/bearing_32008x_friction.toml");
    let mut e = BearingElement::from_toml(&std::fs::read_to_string(path).unwrap()).unwrap();
    for (i, du) in [1.0, 1.01, 0.99].into_iter().enumerate() {
        let (o, n) = allocations(|| e.evaluate(u.map(|x| du * x), [0.0; 5]).unwrap());
        assert!(o.friction.power_w > 0.0);
        assert_eq!(n, 0, "Rust call {i}");
    }
}

/// The NJ cylindrical roller bearing of the rib-contact model with a lubricant: its
/// roller-end/rib friction (the mixed law over each loaded rib's Hertz ellipse) allocates
/// nothing either.
#[test]
fn cylindrical_rib_friction_allocates_nothing() {
    use kontakt_case::bearing_model::BearingElement;
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let read = |name: &str| std::fs::read_to_string(dir.join(name)).unwrap();
    let oil = read("bearing_32008x_friction.toml");
    let lubricant = &oil[oil.find("[lubricant]").unwrap()..oil.find("[catalogue]").unwrap()];
    let text = format!(
        "{}\n{lubricant}\n[speed]\ninner_rpm = 1500.0\n",
        read("bearing_nj_crb_rib_contact.toml")
    );
    let mut e = BearingElement::from_toml(&text).unwrap();
    // the case's equilibrium under 10 kN radial + 1.5 kN axial
    let case = kontakt_case::BearingCase::from_toml_str(&text).unwrap();
    let r = kontakt_case::run_bearing_case(&case).unwrap();
    let (d, t) = (r.displacement_mm, r.tilt_rad);
    let u = [d[0], d[1], d[2], t[0], t[1]];
    e.evaluate(u, [0.0; 5]).unwrap();
    for (i, du) in [1.0, 1.01, 0.99].into_iter().enumerate() {
        let (o, n) = allocations(|| e.evaluate(u.map(|x| du * x), [0.0; 5]).unwrap());
        assert!(o.friction.rib_nmm > 0.0, "{:?}", o.friction);
        assert_eq!(n, 0, "call {i}");
    }
}

/// A ball bearing element with a lubricant (the 6205 at 3000 r/min, its balls at speed):
/// the ball friction over every contact ellipse allocates nothing per call either, also
/// after a speed change.
#[test]
fn ball_bearing_friction_allocates_nothing() {
    use kontakt_case::bearing_model::BearingElement;
    let path =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/bearing_6205_friction.toml");
    let text = std::fs::read_to_string(path).unwrap();
    let mut e = BearingElement::from_toml(&text).unwrap();
    let case = kontakt_case::BearingCase::from_toml_str(&text).unwrap();
    let r = kontakt_case::run_bearing_case(&case).unwrap();
    let (d, t) = (r.displacement_mm, r.tilt_rad);
    let u = [d[0], d[1], d[2], t[0], t[1]];
    e.evaluate(u, [0.0; 5]).unwrap();
    for (i, du) in [1.0, 1.01, 0.99].into_iter().enumerate() {
        if i == 2 {
            e.set_speeds(200.0, 0.0).unwrap();
        }
        let (o, n) = allocations(|| e.evaluate(u.map(|x| du * x), [0.0; 5]).unwrap());
        assert!(o.friction.torque_nmm > 0.0, "{:?}", o.friction);
        assert_eq!(n, 0, "call {i}");
    }
}
