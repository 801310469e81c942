//! What the tests and the bench of the exported fmi2 functions share: an FMU instance of a
//! case, its case written to a resources folder of its own, as a host instantiates it
//! (no logger: the instance keeps its last message, `Instance::last_message`).

#![allow(dead_code, unsafe_code)] // each user takes what it needs; calling the C API

use kontakt_fmi::fmi2::{CASE_FILE, CallbackFunctions, fmi2Instantiate};
use kontakt_fmi::model::Model;
use std::ffi::{CString, c_void};
use std::path::Path;

/// `fmi2Instantiate` (0: model exchange, 1: co-simulation) with `dir/resources/case.toml`
/// holding `case` and the given GUID; null on failure.
pub fn instantiate(case: &str, fmu_type: i32, dir: &Path, guid: &str) -> *mut c_void {
    let resources = dir.join("resources");
    std::fs::create_dir_all(&resources).expect("a resources folder");
    std::fs::write(resources.join(CASE_FILE), case).expect("the case written");
    instantiate_at(&resources, fmu_type, guid)
}

/// `fmi2Instantiate` with the resource location `folder` (a `file:` URI of it).
pub fn instantiate_at(folder: &Path, fmu_type: i32, guid: &str) -> *mut c_void {
    let uri = format!("{}//{}/", "file:", folder.display()).replace(' ', "%20");
    let uri = CString::new(uri).expect("no NUL");
    let guid = CString::new(guid).expect("no NUL");
    // the callbacks outlive every instance
    let functions = Box::leak(Box::new(CallbackFunctions {
        logger: None,
        allocate_memory: None,
        free_memory: None,
        step_finished: None,
        component_environment: std::ptr::null_mut(),
    }));
    // SAFETY: NUL-terminated strings, callbacks that outlive the instance.
    unsafe {
        fmi2Instantiate(
            c"test".as_ptr(),
            fmu_type,
            guid.as_ptr(),
            uri.as_ptr(),
            functions,
            0,
            0,
        )
    }
}

/// The value references of a bearing FMU's displacement and velocity inputs (the first
/// ten inputs) and of all its outputs, and the position of `status` among the outputs.
pub fn bearing_references(case: &str) -> (Vec<u32>, Vec<u32>, usize) {
    let variables = Model::from_case(case).expect("a bearing case").variables();
    let of = |causality: &str| -> Vec<u32> {
        (0..variables.len() as u32)
            .filter(|&i| variables[i as usize].causality == causality)
            .collect()
    };
    let outputs = of("output");
    let status = outputs
        .iter()
        .position(|&i| variables[i as usize].name == "status")
        .expect("a status output");
    (of("input")[..10].to_vec(), outputs, status)
}
