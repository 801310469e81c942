//! The library's `Error` as Python exceptions.

use pyo3::create_exception;
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;

create_exception!(
    kontakt,
    InputError,
    PyValueError,
    "Invalid input: the attributes `field`, `value` and `valid` name the offending field \
     (or case key), the value received and the valid range (or what is wrong)."
);
create_exception!(
    kontakt,
    ConvergenceError,
    RuntimeError,
    "An iterative solver did not reach its tolerance: `what`, `iterations`, `residual`."
);

// `create_exception!` needs the base type's name in scope.
use PyRuntimeError as RuntimeError;

/// An `InputError` with its attributes set.
pub fn input_error(field: &str, value: &str, valid: &str, message: String) -> PyErr {
    let err = InputError::new_err(message);
    Python::attach(|py| {
        let v = err.value(py);
        // Setting an attribute on a fresh exception instance cannot fail in practice; if it
        // did, the message still says everything.
        let _ = v.setattr("field", field);
        let _ = v.setattr("value", value);
        let _ = v.setattr("valid", valid);
    });
    err
}

/// An input error raised by the binding itself (shape, dtype, key), in the library's words:
/// `invalid {field} = {value}: expected {valid}`.
pub fn invalid(field: &str, value: impl std::fmt::Display, valid: &str) -> PyErr {
    let value = value.to_string();
    input_error(
        field,
        &value,
        valid,
        format!("invalid {field} = {value}: expected {valid}"),
    )
}

/// The library's error as a Python exception; `rename` maps library field names to the
/// Python argument names.
pub fn to_py_with(e: kontakt::Error, rename: impl Fn(&str) -> Option<String>) -> PyErr {
    let e = e.map_field(|f| rename(f).unwrap_or_else(|| f.to_string()));
    let message = e.to_string();
    match e {
        kontakt::Error::InvalidInput {
            field,
            value,
            expected,
        } => input_error(&field, &value, &expected, message),
        kontakt::Error::Geometry { field, reason } => input_error(&field, "", &reason, message),
        kontakt::Error::CaseFile {
            key, message: m, ..
        } => input_error(&key, "", &m, message),
        kontakt::Error::NotConverged {
            what,
            iterations,
            residual,
        } => {
            let err = ConvergenceError::new_err(message);
            Python::attach(|py| {
                let v = err.value(py);
                let _ = v.setattr("what", what.as_ref());
                let _ = v.setattr("iterations", iterations);
                let _ = v.setattr("residual", residual);
            });
            err
        }
        // `Error` is non-exhaustive: a future kind is at least a RuntimeError with its text.
        _ => PyRuntimeError::new_err(message),
    }
}

/// The library's error as a Python exception, field names unchanged.
pub fn to_py(e: kontakt::Error) -> PyErr {
    to_py_with(e, |_| None)
}
