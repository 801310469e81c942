//! The C functions called from Rust: creation from TOML and from the case files in
//! `examples/`, evaluation against the Rust API (bit for bit), every null pointer (code 3),
//! invalid UTF-8 (code 3), invalid cases and poses (code 1, the message names the key or
//! field), an unreadable file (code 1, field `path`), the out-of-validity message in the
//! result, reset, and the message cleared by a successful call.

#![allow(unsafe_code)] // calling the C API
#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

use kontakt::geometry::Twist;
use kontakt_capi::*;
use nalgebra::Isometry3;
use std::ffi::{CStr, CString, c_char};
use std::path::PathBuf;
use std::ptr::{null, null_mut};

const BALL: &str = r#"
method = "element"
[geometry]
kind = "surfaces"
[geometry.body1]
shape = "sphere"
radius_mm = 10.0
[geometry.body2]
shape = "plane"
[element]
backend = "hertz"
"#;

const ID: [f64; 7] = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0];
const REST: [f64; 6] = [0.0; 6];

fn last_error() -> String {
    // SAFETY: the library returns a NUL-terminated string valid until the next call.
    unsafe { CStr::from_ptr(kontakt_last_error_message()) }
        .to_str()
        .unwrap()
        .to_string()
}

fn from_toml(text: &str) -> (i32, *mut KontaktElement) {
    let c = CString::new(text).unwrap();
    let mut e = null_mut();
    // SAFETY: a valid C string and a writable out pointer.
    let code = unsafe { kontakt_element_from_toml(c.as_ptr(), &mut e) };
    (code, e)
}

fn evaluate(e: *mut KontaktElement, pose1: &[f64; 7]) -> (i32, KontaktResult) {
    // SAFETY: KontaktResult is plain data: all zeros is a valid value.
    let mut r: KontaktResult = unsafe { std::mem::zeroed() };
    // SAFETY: a live element, arrays of 7 and 6 doubles, a writable result.
    let code = unsafe {
        kontakt_element_evaluate(
            e,
            pose1.as_ptr(),
            ID.as_ptr(),
            REST.as_ptr(),
            REST.as_ptr(),
            &mut r,
        )
    };
    (code, r)
}

fn message(r: &KontaktResult) -> String {
    // SAFETY: the message array is NUL-terminated.
    unsafe { CStr::from_ptr(r.message.as_ptr()) }
        .to_str()
        .unwrap()
        .to_string()
}

/// A ball pressed 5 µm into the flat: the C record equals the Rust API's result exactly.
#[test]
fn evaluation_matches_the_rust_api() {
    let (code, e) = from_toml(BALL);
    assert_eq!(code, KONTAKT_OK, "{}", last_error());
    assert!(!e.is_null());
    assert_eq!(last_error(), "");
    let pose = [0.0, 0.0, 10.0 - 0.005, 1.0, 0.0, 0.0, 0.0];
    let (code, r) = evaluate(e, &pose);
    assert_eq!(code, KONTAKT_OK);
    let mut rust = kontakt_case::element_from_toml(BALL).unwrap();
    let want = rust
        .evaluate(
            &Isometry3::translation(0.0, 0.0, 10.0 - 0.005),
            &Isometry3::identity(),
            &Twist::zero(),
            &Twist::zero(),
        )
        .unwrap();
    let want = KontaktResult::from_result(&want);
    assert_eq!(r.status, KONTAKT_STATUS_CONTACT);
    assert_eq!(format!("{r:?}"), format!("{want:?}"));
    assert!(r.normal_force > 0.0 && r.force1[2] == r.normal_force);
    // SAFETY: reset and free a live element once.
    unsafe {
        assert_eq!(kontakt_element_reset(e), KONTAKT_OK);
        kontakt_element_free(e);
    }
}

/// Beyond 1 % of the radius the status is out of validity, the reason in `message`.
#[test]
fn out_of_validity_carries_its_message() {
    let (_, e) = from_toml(BALL);
    let (code, r) = evaluate(e, &[0.0, 0.0, 10.0 - 0.2, 1.0, 0.0, 0.0, 0.0]);
    assert_eq!(code, KONTAKT_OK);
    assert_eq!(r.status, KONTAKT_STATUS_OUT_OF_VALIDITY);
    assert!(message(&r).contains("exceeds"), "{}", message(&r));
    let (_, r) = evaluate(e, &[0.0, 0.0, 10.5, 1.0, 0.0, 0.0, 0.0]);
    assert_eq!(r.status, KONTAKT_STATUS_SEPARATED);
    assert_eq!(message(&r), "");
    assert_eq!(r.force1, [0.0; 3]);
    // SAFETY: a live element, freed once.
    unsafe { kontakt_element_free(e) };
}

/// Bad poses and twists: code 1, the message names the field, the value and the range;
/// the result is left unchanged; a good call afterwards clears the message.
#[test]
fn bad_poses_name_the_field() {
    let (_, e) = from_toml(BALL);
    let (code, r) = evaluate(e, &[f64::NAN, 0.0, 10.0, 1.0, 0.0, 0.0, 0.0]);
    assert_eq!(code, KONTAKT_INVALID_INPUT);
    assert!(
        last_error().starts_with("invalid pose1"),
        "{}",
        last_error()
    );
    assert_eq!(r.status, 0);
    assert_eq!(r.normal_force, 0.0);
    let (code, _) = evaluate(e, &[0.0, 0.0, 10.0, 2.0, 0.0, 0.0, 0.0]);
    assert_eq!(code, KONTAKT_INVALID_INPUT);
    assert!(last_error().contains("pose1"), "{}", last_error());
    let nan_twist = [f64::NAN, 0.0, 0.0, 0.0, 0.0, 0.0];
    // SAFETY: KontaktResult is plain data.
    let mut r: KontaktResult = unsafe { std::mem::zeroed() };
    // SAFETY: a live element, arrays of 7 and 6 doubles, a writable result.
    let code = unsafe {
        kontakt_element_evaluate(
            e,
            ID.as_ptr(),
            ID.as_ptr(),
            REST.as_ptr(),
            nan_twist.as_ptr(),
            &mut r,
        )
    };
    assert_eq!(code, KONTAKT_INVALID_INPUT);
    assert!(last_error().contains("twist2"), "{}", last_error());
    let (code, _) = evaluate(e, &[0.0, 0.0, 10.5, 1.0, 0.0, 0.0, 0.0]);
    assert_eq!(code, KONTAKT_OK);
    assert_eq!(last_error(), "");
    // SAFETY: a live element, freed once.
    unsafe { kontakt_element_free(e) };
}

/// Every pointer is checked: code 3 naming the argument; `*out` is null after a failed
/// creation; freeing null does nothing.
#[test]
fn null_pointers_are_refused() {
    let c = CString::new(BALL).unwrap();
    let mut e: *mut KontaktElement = std::ptr::dangling_mut(); // overwritten with null
    // SAFETY: null inputs are what is tested; every non-null pointer is valid.
    unsafe {
        assert_eq!(
            kontakt_element_from_toml(null(), &mut e),
            KONTAKT_NULL_OR_UTF8
        );
        assert!(e.is_null());
        assert!(last_error().contains("toml"));
        assert_eq!(
            kontakt_element_from_toml(c.as_ptr(), null_mut()),
            KONTAKT_NULL_OR_UTF8
        );
        assert!(last_error().contains("out"));
        assert_eq!(
            kontakt_element_from_file(null(), &mut e),
            KONTAKT_NULL_OR_UTF8
        );
        assert!(last_error().contains("path"));
        assert_eq!(kontakt_element_reset(null_mut()), KONTAKT_NULL_OR_UTF8);
        kontakt_element_free(null_mut());
    }
    let (_, e) = from_toml(BALL);
    // SAFETY: KontaktResult is plain data.
    let mut r: KontaktResult = unsafe { std::mem::zeroed() };
    let p = ID.as_ptr();
    let t = REST.as_ptr();
    let calls: [(
        &str,
        *mut KontaktElement,
        [*const f64; 4],
        *mut KontaktResult,
    ); 6] = [
        ("element", null_mut(), [p, p, t, t], &mut r),
        ("pose1", e, [null(), p, t, t], &mut r),
        ("pose2", e, [p, null(), t, t], &mut r),
        ("twist1", e, [p, p, null(), t], &mut r),
        ("twist2", e, [p, p, t, null()], &mut r),
        ("out", e, [p, p, t, t], null_mut()),
    ];
    for (name, el, [p1, p2, t1, t2], out) in calls {
        // SAFETY: every pointer is null or valid.
        let code = unsafe { kontakt_element_evaluate(el, p1, p2, t1, t2, out) };
        assert_eq!(code, KONTAKT_NULL_OR_UTF8, "{name}");
        assert_eq!(last_error(), format!("{name} is a null pointer"));
    }
    // SAFETY: a live element, freed once.
    unsafe { kontakt_element_free(e) };
}

/// Invalid UTF-8 is code 3.
#[test]
fn invalid_utf8_is_refused() {
    let bytes: &[u8] = b"method = \"\xff\"\0";
    let mut e = null_mut();
    // SAFETY: a NUL-terminated byte string and a writable out pointer.
    let code = unsafe { kontakt_element_from_toml(bytes.as_ptr().cast::<c_char>(), &mut e) };
    assert_eq!(code, KONTAKT_NULL_OR_UTF8);
    assert!(last_error().contains("UTF-8"), "{}", last_error());
    assert!(e.is_null());
}

/// Invalid cases: code 1, the message names the case-file key.
#[test]
fn invalid_cases_name_the_key() {
    for (text, key) in [
        (
            BALL.replace("\"hertz\"", "\"fem\""),
            "line 11: `element.backend` = `fem`",
        ),
        (
            BALL.replace("radius_mm = 10.0", "radius_mm = -2.0"),
            "invalid geometry.body1.radius_mm = -2",
        ),
        (
            format!("{BALL}[damping]\ncoefficient_n_s_per_mm = 1.0\nramp_mm = 0.0\n"),
            "invalid damping.ramp_mm = 0",
        ),
        (BALL.replace("\"element\"", "\"pimp\""), "invalid method"),
    ] {
        let (code, e) = from_toml(&text);
        assert_eq!(code, KONTAKT_INVALID_INPUT, "{text}");
        assert!(e.is_null());
        assert!(last_error().starts_with(key), "{}", last_error());
    }
}

/// The case files next to the C example load from disk; a missing file is code 1 with
/// field `path`.
#[test]
fn case_files_load() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples");
    for name in ["element_roller_rib.toml", "element_ball_on_flat.toml"] {
        let path = CString::new(dir.join(name).to_str().unwrap()).unwrap();
        let mut e = null_mut();
        // SAFETY: a valid C string and a writable out pointer.
        let code = unsafe { kontakt_element_from_file(path.as_ptr(), &mut e) };
        assert_eq!(code, KONTAKT_OK, "{name}: {}", last_error());
        // SAFETY: a live element, freed once.
        unsafe { kontakt_element_free(e) };
    }
    let missing = CString::new(dir.join("missing.toml").to_str().unwrap()).unwrap();
    let mut e = null_mut();
    // SAFETY: a valid C string and a writable out pointer.
    let code = unsafe { kontakt_element_from_file(missing.as_ptr(), &mut e) };
    assert_eq!(code, KONTAKT_INVALID_INPUT);
    assert!(
        last_error().starts_with("cannot read case file"),
        "{}",
        last_error()
    );
    assert!(e.is_null());
}

/// The version string is the crate's.
#[test]
fn version_is_reported() {
    // SAFETY: a static NUL-terminated string.
    let v = unsafe { CStr::from_ptr(kontakt_version()) };
    assert_eq!(v.to_str().unwrap(), env!("CARGO_PKG_VERSION"));
}
