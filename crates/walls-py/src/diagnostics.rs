//! Diagnostics for Python: the dictionaries of `walls-lint --format json`, and
//! `walls.WallsError`, which carries them when a file cannot be formatted or resolved.
//!
//! The dictionaries are the JSON renderer's own output for one file, read back by
//! Python's `json` module, so that they are exactly what the command line prints: one
//! renderer, no second description of a diagnostic.

use pyo3::create_exception;
use pyo3::exceptions::{PyException, PyRuntimeError};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyList};
use walls_diagnostics::render::{self, FileReport};
use walls_diagnostics::{Diagnostic, LineIndex};

create_exception!(
    walls,
    WallsError,
    PyException,
    "A walls file that could not be formatted, resolved or written, or a mesh that makes \
     no walls. `diagnostics` holds the file's errors, as `walls.lint` gives them (empty \
     for a mesh's, whose message names its place)."
);

/// Adds `WallsError` to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("WallsError", m.py().get_type::<WallsError>())
}

/// `diagnostics` of `text` as `walls-lint --format json` lists them for one file: a
/// list of dictionaries with `code`, `severity`, `message`, `line`, `column`,
/// `end_line`, `end_column` and, where the diagnostic has them, `help` and `fix`.
pub fn to_python<'py>(
    py: Python<'py>,
    text: &str,
    diagnostics: &[Diagnostic],
) -> PyResult<Bound<'py, PyList>> {
    let report = FileReport {
        path: "<string>",
        source: text,
        diagnostics,
    };
    let mut json = Vec::new();
    render::json(&mut json, &[report], &[])
        .map_err(|e| PyRuntimeError::new_err(format!("rendering the diagnostics: {e}")))?;
    Ok(from_json(py, &json)?
        .get_item("files")?
        .get_item(0)?
        .get_item("diagnostics")?
        .cast_into::<PyList>()?)
}

/// The Python value of a JSON document (`json.loads`).
pub fn from_json<'py>(py: Python<'py>, json: &[u8]) -> PyResult<Bound<'py, PyAny>> {
    py.import("json")?
        .call_method1("loads", (PyBytes::new(py, json),))
}

/// A `WallsError` for `text` and the `diagnostics` that stopped the work: its message
/// says `what` could not be done, with the first diagnostic and its line and column; its
/// `diagnostics` attribute lists them all as [`to_python`] does.
pub fn error(py: Python<'_>, what: &str, text: &str, diagnostics: &[Diagnostic]) -> PyErr {
    let message = match diagnostics.first() {
        Some(first) => {
            let at = LineIndex::new(text).line_col(text, first.span.start);
            let more = match diagnostics.len() - 1 {
                0 => String::new(),
                n => format!(" (and {n} more)"),
            };
            format!(
                "{what}: {}:{}: [{}] {}{more}",
                at.line, at.column, first.code.id, first.message
            )
        }
        None => what.to_string(),
    };
    match to_python(py, text, diagnostics) {
        Ok(list) => carrying(py, message, list),
        Err(e) => e,
    }
}

/// A `WallsError` that is not a walls file's (a mesh's, whose message names its line,
/// facet, face or edge): its `diagnostics` is empty.
pub fn plain(py: Python<'_>, message: String) -> PyErr {
    carrying(py, message, PyList::empty(py))
}

/// A `WallsError` with `message` and `diagnostics`: every one has the attribute.
fn carrying(py: Python<'_>, message: String, diagnostics: Bound<'_, PyList>) -> PyErr {
    let err = WallsError::new_err(message);
    match err.value(py).setattr("diagnostics", diagnostics) {
        Ok(()) => err,
        Err(e) => e,
    }
}
