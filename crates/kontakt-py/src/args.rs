//! The one door for Python arguments: every public function takes its arguments as Python
//! objects and converts them here, so that every conversion error is one line naming the
//! argument as the user typed it, the value received and what is valid
//! (`invalid force = True (bool): expected a finite force > 0 N`):
//!
//! - a value of the wrong Python type (a string, a bool or a complex number for a number, a
//!   float for a count, a complex or bool array for a map) is a `TypeError`;
//! - a value of the right type that the parameter cannot hold (a negative count, an int
//!   beyond 64 bits, an array of the wrong shape) is an `InputError` with `field`, `value`
//!   and `valid`.
//!
//! pyo3's own conversions raise Python's messages without the argument's name
//! (`can't convert negative int to unsigned`), take `True` for 1.0 and drop the imaginary
//! part of a complex array; nothing here does.

use crate::errors::invalid;
use numpy::{AllowTypeChange, PyArrayLikeDyn};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyBytes, PyComplex, PyDict, PyList, PyString, PyTuple};
use std::path::PathBuf;

/// `repr(v)` shortened to 60 characters, with its type: `True (bool)`.
pub fn shown(v: &Bound<'_, PyAny>) -> String {
    let repr = v
        .repr()
        .map_or_else(|_| "?".to_string(), |r| r.to_string())
        .replace('\n', " ");
    let repr = if repr.chars().count() > 60 {
        format!("{}...", repr.chars().take(57).collect::<String>())
    } else {
        repr
    };
    let ty = v
        .get_type()
        .name()
        .map_or_else(|_| "?".to_string(), |n| n.to_string());
    format!("{repr} ({ty})")
}

/// The `TypeError` of an argument of the wrong Python type, in the words of `InputError`.
pub fn wrong_type(name: &str, v: &Bound<'_, PyAny>, valid: &str) -> PyErr {
    PyTypeError::new_err(format!("invalid {name} = {}: expected {valid}", shown(v)))
}

/// A bool, NumPy's included (`numpy.bool_` is not a Python bool).
fn is_bool(v: &Bound<'_, PyAny>) -> bool {
    v.is_instance_of::<PyBool>() || v.get_type().name().is_ok_and(|n| n == "bool")
}

/// A complex number, NumPy's included.
fn is_complex(v: &Bound<'_, PyAny>) -> bool {
    v.is_instance_of::<PyComplex>()
        || v.get_type()
            .name()
            .is_ok_and(|n| n.to_string().starts_with("complex"))
}

/// `v` unless it is omitted or Python's `None`.
pub fn given<'a, 'py>(v: Option<&'a Bound<'py, PyAny>>) -> Option<&'a Bound<'py, PyAny>> {
    v.filter(|v| !v.is_none())
}

/// A real number (int, float, NumPy's real scalars); not a bool, not a complex, not a str.
pub fn real(v: &Bound<'_, PyAny>, name: &str, valid: &str) -> PyResult<f64> {
    let what = format!("a real number (int or float): {valid}");
    if is_bool(v)
        || is_complex(v)
        || v.is_instance_of::<PyString>()
        || v.is_instance_of::<PyBytes>()
    {
        return Err(wrong_type(name, v, &what));
    }
    v.extract::<f64>().map_err(|e| {
        if e.is_instance_of::<PyTypeError>(v.py()) {
            wrong_type(name, v, &what)
        } else {
            // an int beyond the range of a float
            invalid(name, shown(v), valid)
        }
    })
}

/// An optional real number: `None` (Python's or omitted) is `None`.
pub fn opt_real(v: Option<&Bound<'_, PyAny>>, name: &str, valid: &str) -> PyResult<Option<f64>> {
    given(v).map(|v| real(v, name, valid)).transpose()
}

/// The items of a sequence (list, tuple, 1-d array; not a str, bytes or dict), exactly `N`.
fn items<'py, const N: usize>(
    v: &Bound<'py, PyAny>,
    name: &str,
    valid: &str,
) -> PyResult<Vec<Bound<'py, PyAny>>> {
    let what = format!("a sequence of {N} ({valid})");
    if v.is_instance_of::<PyString>()
        || v.is_instance_of::<PyBytes>()
        || v.is_instance_of::<PyDict>()
    {
        return Err(wrong_type(name, v, &what));
    }
    let before = shown(v); // an iterator's repr changes as it is read
    // at most N + 1 items: an endless iterator is refused, not read forever
    let items: Vec<_> = v
        .try_iter()
        .map_err(|_| wrong_type(name, v, &what))?
        .take(N + 1)
        .collect::<PyResult<_>>()
        .map_err(|_| wrong_type(name, v, &what))?;
    if items.len() != N {
        let count = if items.len() > N {
            format!("more than {N}")
        } else {
            items.len().to_string()
        };
        return Err(invalid(name, format!("{before} of {count} items"), &what));
    }
    Ok(items)
}

/// `N` real numbers (a tuple, list or array); items are named `name[i]`.
pub fn reals<const N: usize>(v: &Bound<'_, PyAny>, name: &str, valid: &str) -> PyResult<[f64; N]> {
    let mut out = [0.0; N];
    for (i, (o, x)) in out.iter_mut().zip(items::<N>(v, name, valid)?).enumerate() {
        *o = real(&x, &format!("{name}[{i}]"), valid)?;
    }
    Ok(out)
}

/// A whole number >= 0 (int or NumPy integer; not a bool, not a float).
pub fn count(v: &Bound<'_, PyAny>, name: &str, valid: &str) -> PyResult<u64> {
    let what = format!("an int: {valid}");
    if is_bool(v) {
        return Err(wrong_type(name, v, &what));
    }
    // `operator.index`: ints and NumPy's integers, not floats
    let int = v
        .py()
        .import("operator")?
        .call_method1("index", (v,))
        .map_err(|_| wrong_type(name, v, &what))?;
    int.extract::<u64>()
        .map_err(|_| invalid(name, shown(v), valid))
}

/// An optional count: `None` is `None`.
pub fn opt_count(v: Option<&Bound<'_, PyAny>>, name: &str, valid: &str) -> PyResult<Option<u64>> {
    given(v).map(|v| count(v, name, valid)).transpose()
}

/// A count that must fit a `usize` (a grid size, a thread count).
pub fn size(v: &Bound<'_, PyAny>, name: &str, valid: &str) -> PyResult<usize> {
    let n = count(v, name, valid)?;
    usize::try_from(n).map_err(|_| invalid(name, n, valid))
}

/// An optional `size`.
pub fn opt_size(v: Option<&Bound<'_, PyAny>>, name: &str, valid: &str) -> PyResult<Option<usize>> {
    given(v).map(|v| size(v, name, valid)).transpose()
}

/// `N` sizes (a tuple, list or array); items are named `name[i]`.
pub fn sizes<const N: usize>(
    v: &Bound<'_, PyAny>,
    name: &str,
    valid: &str,
) -> PyResult<[usize; N]> {
    let mut out = [0; N];
    for (i, (o, x)) in out.iter_mut().zip(items::<N>(v, name, valid)?).enumerate() {
        *o = size(&x, &format!("{name}[{i}]"), valid)?;
    }
    Ok(out)
}

/// A str; `default` when omitted or None.
pub fn text_or(
    v: Option<&Bound<'_, PyAny>>,
    name: &str,
    valid: &str,
    default: &str,
) -> PyResult<String> {
    match given(v) {
        None => Ok(default.to_string()),
        Some(v) => text(v, name, valid),
    }
}

/// A str.
pub fn text(v: &Bound<'_, PyAny>, name: &str, valid: &str) -> PyResult<String> {
    if !v.is_instance_of::<PyString>() {
        return Err(wrong_type(name, v, &format!("a str: {valid}")));
    }
    v.extract()
}

/// An optional str.
pub fn opt_text(v: Option<&Bound<'_, PyAny>>, name: &str, valid: &str) -> PyResult<Option<String>> {
    given(v).map(|v| text(v, name, valid)).transpose()
}

/// A file system path: a str or an `os.PathLike`.
pub fn path(v: &Bound<'_, PyAny>, name: &str) -> PyResult<PathBuf> {
    if v.is_instance_of::<PyBytes>() {
        return Err(wrong_type(name, v, "a path (str or os.PathLike)"));
    }
    v.extract()
        .map_err(|_| wrong_type(name, v, "a path (str or os.PathLike)"))
}

/// An optional path.
pub fn opt_path(v: Option<&Bound<'_, PyAny>>, name: &str) -> PyResult<Option<PathBuf>> {
    given(v).map(|v| path(v, name)).transpose()
}

/// A bool among the items of nested lists and tuples (NumPy would make it 0.0 or 1.0 in an
/// array of floats) is a `TypeError` naming the item; deeper than NumPy's 64 dimensions
/// (a list that contains itself) is left to NumPy, which refuses it.
fn no_bool_items(v: &Bound<'_, PyAny>, name: &str, what: &str, depth: usize) -> PyResult<()> {
    if depth > 64 || !(v.is_instance_of::<PyList>() || v.is_instance_of::<PyTuple>()) {
        return Ok(());
    }
    for (i, item) in v.try_iter()?.enumerate() {
        let item = item?;
        if is_bool(&item) {
            return Err(wrong_type(&format!("{name}[{i}]"), &item, what));
        }
        no_bool_items(&item, &format!("{name}[{i}]"), what, depth + 1)?;
    }
    Ok(())
}

/// An array of real numbers of any shape (an ndarray, a nested list, a scalar), as float64.
/// A bool, complex, string, date or record dtype is a `TypeError` (NumPy would turn True into
/// 1.0, drop an imaginary part, or parse the strings); what NumPy cannot make an array of
/// (ragged lists, objects) is an `InputError`.
pub fn array<'py>(
    v: &Bound<'py, PyAny>,
    name: &str,
    valid: &str,
) -> PyResult<PyArrayLikeDyn<'py, f64, AllowTypeChange>> {
    let py = v.py();
    let what = format!("an array of real numbers (float or int dtype): {valid}");
    no_bool_items(v, name, &what, 0)?;
    let a = py
        .import("numpy")?
        .call_method1("asarray", (v,))
        .map_err(|_| invalid(name, shown(v), &what))?;
    let kind: String = a.getattr("dtype")?.getattr("kind")?.extract()?;
    match kind.as_str() {
        "f" | "i" | "u" | "O" => {}
        _ => {
            let dtype = a.getattr("dtype")?.str()?.to_string();
            return Err(PyTypeError::new_err(format!(
                "invalid {name} = an array of dtype {dtype}: expected {what}"
            )));
        }
    }
    a.extract().map_err(|e: PyErr| {
        if e.is_instance_of::<PyTypeError>(py) {
            wrong_type(name, v, &what)
        } else {
            invalid(name, shown(v), &what)
        }
    })
}

/// An array's shape as Python writes it: `(5,)`, `(16, 16)`.
pub fn shape(dims: &[usize]) -> String {
    match dims {
        [n] => format!("({n},)"),
        _ => {
            let d: Vec<String> = dims.iter().map(ToString::to_string).collect();
            format!("({})", d.join(", "))
        }
    }
}
