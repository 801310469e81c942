//! # kontakt-py — the Python package `kontakt` (module `kontakt._kontakt`)
//!
//! A thin layer over the library (`kontakt`) and its case layer (`kontakt-case`): Python
//! values in, the library's types in the middle, Python values and NumPy arrays out. No
//! physics and no dispatch lives here: Hertz contacts are the library's planned contacts;
//! half-space solves on NumPy maps, PimP, traction and friction cases run through
//! `kontakt_case` (`Case::run`, the one dispatch the CLI uses), so `to_dict()` gives the
//! CLI's JSON keys and values.
//! A whole bearing (`Bearing`) is the case layer's `BearingModel`: planned from a bearing
//! case, solved for many loads; `BearingElement` is the case layer's `BearingElement`, the
//! bearing as one force element of a multi-body code.
//!
//! Units are the library's: mm, N, MPa, mm/s, rad/s, radians (case dicts and files keep
//! their degrees). Errors: `kontakt.InputError(ValueError)` with `field`, `value` and
//! `valid`; `kontakt.ConvergenceError(RuntimeError)`. Long solves release the GIL.

// pyo3's `#[pymodule]`, `#[pyclass]` and `#[pymethods]` macros expand to `unsafe` FFI glue
// (the CPython C API); the workspace denies unsafe code, so this binding crate opts in. The
// code written here contains no `unsafe` block of its own.
#![allow(unsafe_code)]

mod args;
mod bearing;
mod bearing_element;
mod case;
mod element;
mod errors;
mod halfspace;
mod hertz;
mod sweep;

use pyo3::prelude::*;

/// The compiled core of the `kontakt` package; import `kontakt` instead.
#[pymodule]
fn _kontakt(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("__version__", kontakt::VERSION)?;
    m.add("InputError", py.get_type::<errors::InputError>())?;
    m.add(
        "ConvergenceError",
        py.get_type::<errors::ConvergenceError>(),
    )?;
    m.add_class::<hertz::Material>()?;
    m.add_class::<hertz::HertzPoint>()?;
    m.add_class::<hertz::HertzPointResult>()?;
    m.add_class::<hertz::HertzLine>()?;
    m.add_class::<hertz::HertzLineResult>()?;
    m.add_class::<halfspace::HalfSpace>()?;
    m.add_class::<halfspace::HalfSpaceResult>()?;
    m.add_class::<case::CaseResult>()?;
    m.add_function(wrap_pyfunction!(case::run_toml, m)?)?;
    m.add_function(wrap_pyfunction!(case::run_file, m)?)?;
    m.add_function(wrap_pyfunction!(case::run_case, m)?)?;
    m.add_function(wrap_pyfunction!(case::to_toml, m)?)?;
    m.add_class::<element::ContactElement>()?;
    m.add_class::<element::ElementResult>()?;
    m.add_class::<bearing::Bearing>()?;
    m.add_class::<bearing::BearingResult>()?;
    m.add_class::<bearing_element::BearingElement>()?;
    m.add_class::<bearing_element::BearingElementResult>()?;
    m.add_class::<sweep::Sweep>()?;
    Ok(())
}
