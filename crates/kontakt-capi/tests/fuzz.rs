//! Fuzz harness of the C API (docs/RELIABILITY.md): the extern functions called with
//! edited element cases (TOML text with NUL bytes and invalid UTF-8 too), hostile poses
//! and twists (NaN, ±inf, non-unit quaternions, 1e300) and null pointers; the bearing
//! element with edited bearing cases, hostile displacements, velocities and dampings.
//!
//! Properties: never a panic across the boundary (code 4 is a failure here too); every
//! code is one of the documented ones; a failure sets a non-empty one-line message, a
//! success clears it; a result holds finite numbers. `KONTAKT_FUZZ_CASES=N` sets the number
//! of inputs.

#![allow(unsafe_code)] // calling the C API
#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

#[path = "../../kontakt-case/tests/support/fuzz_gen.rs"]
mod fuzz_gen;

use fuzz_gen::{apply, config, edit, to_text};
use kontakt_capi::*;
use proptest::prelude::*;
use std::ffi::{CStr, c_char};
use std::ptr::{null, null_mut};
use toml::Value;

fn last_error() -> String {
    // SAFETY: the library returns a NUL-terminated string valid until the next call.
    unsafe { CStr::from_ptr(kontakt_last_error_message()) }
        .to_string_lossy()
        .into_owned()
}

fn seeds() -> Vec<Value> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("examples");
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    files.sort();
    files
        .iter()
        .map(|f| {
            let mut t: toml::Table = std::fs::read_to_string(f).unwrap().parse().unwrap();
            if let Some(Value::Table(e)) = t.get_mut("element")
                && e.contains_key("cells")
            {
                e.insert("cells".into(), Value::Array(vec![Value::Integer(12); 2]));
            }
            Value::Table(t)
        })
        .collect()
}

/// Check a code and the thread's message after a call.
fn check_code(what: &str, code: i32) {
    let m = last_error();
    assert_ne!(code, KONTAKT_PANIC, "{what}: panic: {m}");
    assert!(
        [
            KONTAKT_OK,
            KONTAKT_INVALID_INPUT,
            KONTAKT_FAILED,
            KONTAKT_NULL_OR_UTF8
        ]
        .contains(&code),
        "{what}: undocumented code {code}"
    );
    if code == KONTAKT_OK {
        assert!(m.is_empty(), "{what}: message after success: {m}");
    } else {
        assert!(
            !m.trim().is_empty(),
            "{what}: code {code} without a message"
        );
        assert!(!m.contains('\n'), "{what}: message of several lines: {m:?}");
    }
}

fn check_result(r: &KontaktResult) {
    let mut all = vec![
        r.separation,
        r.approach,
        r.normal_force,
        r.damping_force,
        r.friction_power,
        r.max_pressure,
        r.contact_area,
    ];
    for v in [
        r.point,
        r.normal,
        r.friction_force,
        r.friction_moment,
        r.force1,
        r.moment1,
        r.moment2,
    ] {
        all.extend(v);
    }
    assert!(
        all.iter().all(|x| x.is_finite()),
        "non-finite result: {r:?}"
    );
    assert!((0..=2).contains(&r.status), "status {}", r.status);
}

fn number() -> impl Strategy<Value = f64> {
    prop_oneof![
        3 => fuzz_gen::float(),
        3 => -0.05..0.05f64,
        1 => Just(0.0),
        1 => Just(1.0),
    ]
}

/// A pose: near the identity (so that the bodies touch) or hostile.
fn pose() -> impl Strategy<Value = [f64; 7]> {
    prop_oneof![
        2 => (-0.05..0.05f64, -0.05..0.05f64, -0.05..0.05f64, -0.02..0.02f64, -0.02..0.02f64)
            .prop_map(|(x, y, z, a, b)| {
                let n = (1.0 + a * a + b * b).sqrt();
                [x, y, z, 1.0 / n, a / n, b / n, 0.0]
            }),
        1 => prop::array::uniform7(number()),
        1 => Just([0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]),
    ]
}

fn twist() -> impl Strategy<Value = [f64; 6]> {
    prop_oneof![Just([0.0; 6]), prop::array::uniform6(number())]
}

/// Evaluate with the pointers given or null (each of the six picked by a bit of `nulls`).
fn evaluate(e: *mut KontaktElement, p: &[[f64; 7]; 2], t: &[[f64; 6]; 2], nulls: u8) {
    // SAFETY: KontaktResult is plain data: all zeros is a valid value.
    let mut r: KontaktResult = unsafe { std::mem::zeroed() };
    let or_null = |bit: u8, ptr: *const f64| if nulls & bit != 0 { null() } else { ptr };
    let out: *mut KontaktResult = if nulls & 32 != 0 { null_mut() } else { &mut r };
    let elem = if nulls & 64 != 0 { null_mut() } else { e };
    // SAFETY: each pointer is null or points to the stated number of doubles; `e` is live.
    let code = unsafe {
        kontakt_element_evaluate(
            elem,
            or_null(1, p[0].as_ptr()),
            or_null(2, p[1].as_ptr()),
            or_null(4, t[0].as_ptr()),
            or_null(8, t[1].as_ptr()),
            out,
        )
    };
    check_code("kontakt_element_evaluate", code);
    if nulls & (1 | 2 | 4 | 8 | 32 | 64) != 0 {
        assert_eq!(code, KONTAKT_NULL_OR_UTF8);
    }
    if code == KONTAKT_OK {
        check_result(&r);
    }
}

/// The example bearing cases of the repository (`examples/bearing_*.toml`).
fn bearing_seeds() -> Vec<Value> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| {
            p.file_name()
                .is_some_and(|n| n.to_string_lossy().starts_with("bearing_"))
        })
        .collect();
    files.sort();
    files
        .iter()
        .map(|f| Value::Table(std::fs::read_to_string(f).unwrap().parse().unwrap()))
        .collect()
}

fn check_bearing_result(r: &KontaktBearingResult) {
    let mut all = vec![r.max_element_load];
    all.extend(r.force);
    all.extend(r.moment);
    all.extend(r.damping);
    all.extend(r.stiffness.iter().flatten());
    assert!(
        all.iter().all(|x| x.is_finite()),
        "non-finite result: {r:?}"
    );
    assert!((0..=1).contains(&r.status), "status {}", r.status);
}

/// A displacement: in the loaded range of the example bearings (tens of µm, 1e-3 rad) or
/// hostile.
fn displacement() -> impl Strategy<Value = [f64; 5]> {
    prop_oneof![
        3 => (-0.05..0.05f64, -0.05..0.05f64, -0.05..0.05f64, -1e-3..1e-3f64, -1e-3..1e-3f64)
            .prop_map(|(x, y, z, a, b)| [x, y, z, a, b]),
        1 => prop::array::uniform5(number()),
    ]
}

proptest! {
    #![proptest_config(config(2_000))]

    /// Edited element cases: created, evaluated at several poses, reset, freed.
    #[test]
    fn element_cases_and_poses(
        seed in any::<usize>(),
        edits in prop::collection::vec(edit(), 0..3),
        poses in prop::collection::vec((pose(), pose(), twist(), twist()), 1..4),
        nulls in prop_oneof![4 => Just(0u8), 1 => any::<u8>()],
    ) {
        let seeds = seeds();
        let mut doc = seeds[seed % seeds.len()].clone();
        apply(&mut doc, &edits);
        let Some(text) = to_text(&doc) else { return Ok(()) };
        let c = std::ffi::CString::new(text.replace('\0', "")).unwrap();
        let mut e = null_mut();
        // SAFETY: a C string and a writable out pointer.
        let code = unsafe { kontakt_element_from_toml(c.as_ptr(), &mut e) };
        check_code("kontakt_element_from_toml", code);
        if code != KONTAKT_OK {
            prop_assert!(e.is_null());
            return Ok(());
        }
        for (p1, p2, t1, t2) in &poses {
            evaluate(e, &[*p1, *p2], &[*t1, *t2], nulls);
        }
        // SAFETY: a live element.
        check_code("kontakt_element_reset", unsafe { kontakt_element_reset(e) });
        // SAFETY: freed once.
        unsafe { kontakt_element_free(e) };
    }

    /// Raw bytes as the TOML text or the file path (NUL-terminated, any UTF-8 or not).
    #[test]
    fn raw_bytes_as_text_and_path(bytes in prop::collection::vec(1..=255u8, 0..200), file in any::<bool>(), null_out in any::<bool>()) {
        let mut b = bytes.clone();
        b.push(0);
        let mut e = null_mut();
        let out = if null_out { null_mut() } else { &mut e as *mut *mut KontaktElement };
        // SAFETY: a NUL-terminated byte string; `out` null or writable.
        let code = unsafe {
            if file {
                kontakt_element_from_file(b.as_ptr().cast::<c_char>(), out)
            } else {
                kontakt_element_from_toml(b.as_ptr().cast::<c_char>(), out)
            }
        };
        check_code("kontakt_element_from_*", code);
        if null_out {
            prop_assert_eq!(code, KONTAKT_NULL_OR_UTF8);
        }
        if code == KONTAKT_OK {
            // SAFETY: a live element, freed once.
            unsafe { kontakt_element_free(e) };
        }
    }
}

proptest! {
    #![proptest_config(config(200))]

    /// Edited bearing cases: created, damped, evaluated at several displacements and
    /// velocities (with null pointers now and then), reset, freed.
    #[test]
    fn bearing_cases_and_displacements(
        seed in any::<usize>(),
        edits in prop::collection::vec(edit(), 0..2),
        calls in prop::collection::vec((displacement(), prop::array::uniform5(number())), 1..4),
        damping in prop_oneof![2 => Just(0.0), 1 => number()],
        nulls in prop_oneof![4 => Just(0u8), 1 => any::<u8>()],
    ) {
        let seeds = bearing_seeds();
        let mut doc = seeds[seed % seeds.len()].clone();
        apply(&mut doc, &edits);
        let Some(text) = to_text(&doc) else { return Ok(()) };
        let c = std::ffi::CString::new(text.replace('\0', "")).unwrap();
        let mut e = null_mut();
        // SAFETY: a C string and a writable out pointer.
        let code = unsafe { kontakt_bearing_element_from_toml(c.as_ptr(), &mut e) };
        check_code("kontakt_bearing_element_from_toml", code);
        if code != KONTAKT_OK {
            prop_assert!(e.is_null());
            return Ok(());
        }
        // SAFETY: a live element.
        let code = unsafe { kontakt_bearing_element_set_damping(e, damping) };
        check_code("kontakt_bearing_element_set_damping", code);
        for (u, v) in &calls {
            // SAFETY: plain data: all zeros is a valid value.
            let mut r: KontaktBearingResult = unsafe { std::mem::zeroed() };
            let or_null = |bit: u8, ptr: *const f64| if nulls & bit != 0 { null() } else { ptr };
            let out: *mut KontaktBearingResult = if nulls & 4 != 0 { null_mut() } else { &mut r };
            let elem = if nulls & 8 != 0 { null_mut() } else { e };
            // SAFETY: each pointer is null or points to 5 doubles; `e` is live.
            let code = unsafe {
                kontakt_bearing_element_evaluate(elem, or_null(1, u.as_ptr()), or_null(2, v.as_ptr()), out)
            };
            check_code("kontakt_bearing_element_evaluate", code);
            if nulls & 15 != 0 {
                prop_assert_eq!(code, KONTAKT_NULL_OR_UTF8);
            }
            if code == KONTAKT_OK {
                check_bearing_result(&r);
            }
        }
        // SAFETY: a live element.
        check_code("kontakt_bearing_element_reset", unsafe { kontakt_bearing_element_reset(e) });
        // SAFETY: freed once.
        unsafe { kontakt_bearing_element_free(e) };
    }
}

/// Found by fuzzing: a finite but huge spin (ω_z = 2.85e152 rad/s) with a damping
/// coefficient of 1e300 N·s/mm overflowed the forces to inf and NaN in a result with code
/// 0; it is now code 2 (the computation failed) naming the overflowing result.
#[test]
fn overflowing_result_is_an_error() {
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/element_roller_rib.toml"),
    )
    .unwrap()
    .replace(
        "coefficient_n_s_per_mm = 0.5",
        "coefficient_n_s_per_mm = 1e300",
    );
    let c = std::ffi::CString::new(text).unwrap();
    let mut e = null_mut();
    // SAFETY: a C string and a writable out pointer.
    assert_eq!(
        unsafe { kontakt_element_from_toml(c.as_ptr(), &mut e) },
        KONTAKT_OK
    );
    let p1 = [
        0.0,
        0.010992173302650109,
        0.0,
        0.9999910853855316,
        -0.004222457751912781,
        0.0,
        0.0,
    ];
    let p2 = [0.0, -0.030301956237438515, 0.0, 1.0, 0.0, 0.0, 0.0];
    let t1 = [1e-9, 1e-9, 1e-9, 1e-9, 0.0, 2.8496990505027887e152];
    // SAFETY: KontaktResult is plain data: all zeros is a valid value.
    let mut r: KontaktResult = unsafe { std::mem::zeroed() };
    // SAFETY: a live element, arrays of 7 and 6 doubles, a writable result.
    let code = unsafe {
        kontakt_element_evaluate(
            e,
            p1.as_ptr(),
            p2.as_ptr(),
            t1.as_ptr(),
            [0.0; 6].as_ptr(),
            &mut r,
        )
    };
    let m = last_error();
    assert_eq!(code, KONTAKT_FAILED, "{m}");
    assert!(m.contains("overflows"), "{m}");
    // SAFETY: freed once.
    unsafe { kontakt_element_free(e) };
}
