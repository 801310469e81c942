//! Bearing elements on several threads at once, one element per thread: every thread's
//! results equal those of the same sequence of calls on one thread, bit for bit, and the
//! error message is per thread (a failure on one thread leaves another's message empty).

#![allow(unsafe_code)] // calling the C API
#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

use kontakt_capi::*;
use std::ffi::{CStr, CString};
use std::path::PathBuf;
use std::ptr::null_mut;

fn case_text() -> CString {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/bearing_32008x.toml");
    CString::new(std::fs::read_to_string(path).unwrap()).unwrap()
}

/// Create an element, evaluate it along a path of displacements (with one NaN call in
/// the middle when `fail`), return the forces and moments and whether the thread's message
/// was empty after the last (successful) call.
fn run(text: &CString, fail: bool) -> (Vec<[f64; 6]>, bool) {
    let mut e = null_mut();
    // SAFETY: a valid C string and a writable out pointer.
    assert_eq!(
        unsafe { kontakt_bearing_element_from_toml(text.as_ptr(), &mut e) },
        KONTAKT_OK
    );
    let mut out = Vec::new();
    for step in 0..40 {
        let s = f64::from(step) / 40.0;
        let u = [0.01 * s, -0.002, 0.01 + 0.01 * s, 1e-4 * s, 0.0];
        let u = if fail && step == 20 { [f64::NAN; 5] } else { u };
        let v = [1.0, 0.0, 0.5, 0.0, 0.01];
        // SAFETY: plain data: all zeros is a valid value.
        let mut r: KontaktBearingResult = unsafe { std::mem::zeroed() };
        // SAFETY: a live element of this thread, arrays of 5 doubles, a writable result.
        let code = unsafe { kontakt_bearing_element_evaluate(e, u.as_ptr(), v.as_ptr(), &mut r) };
        if code == KONTAKT_OK {
            out.push([
                r.force[0],
                r.force[1],
                r.force[2],
                r.moment[0],
                r.moment[1],
                r.stiffness[2][2],
            ]);
        } else {
            assert!(fail && step == 20);
        }
    }
    // SAFETY: the thread's NUL-terminated message, read before the next call.
    let empty = unsafe { CStr::from_ptr(kontakt_last_error_message()) }
        .to_bytes()
        .is_empty();
    // SAFETY: created above, freed once.
    unsafe { kontakt_bearing_element_free(e) };
    (out, empty)
}

#[test]
fn one_element_per_thread_gives_the_single_thread_results() {
    let text = case_text();
    let (reference, _) = run(&text, false);
    let (with_failure, _) = run(&text, true);
    std::thread::scope(|scope| {
        let handles: Vec<_> = (0..4)
            .map(|t| {
                let text = &text;
                scope.spawn(move || run(text, t % 2 == 1))
            })
            .collect();
        for (t, h) in handles.into_iter().enumerate() {
            let (results, empty) = h.join().unwrap();
            let want = if t % 2 == 1 {
                &with_failure
            } else {
                &reference
            };
            assert_eq!(&results, want, "thread {t}");
            assert!(empty, "thread {t}: the message of the last successful call");
        }
    });
    assert_eq!(reference.len(), 40);
    assert!(reference.iter().all(|r| r[2] < 0.0));
}
