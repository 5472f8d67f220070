//! `walls.lint`, `walls.format` and `walls.scene`: a walls file's text (or bytes, read as
//! a file is) to what `walls-lint --format json`, `walls-fmt` and `walls-sim scene` give
//! for it, through the same library calls.

use crate::args::{self, Text};
use crate::diagnostics;
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyList;
use walls_format::FormatOptions;
use walls_ide::Checked;
use walls_keywords::ContactModel;
use walls_model::Options;

/// Adds the functions of this file to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(lint, m)?)?;
    m.add_function(wrap_pyfunction!(format, m)?)?;
    m.add_function(wrap_pyfunction!(scene, m)?)?;
    Ok(())
}

/// The one check of a file (`walls_ide::check_text` / `check_bytes`), with the GIL
/// released.
pub fn check(py: Python<'_>, text: Text, options: &Options) -> Checked {
    py.detach(|| match text {
        Text::Str(text) => walls_ide::check_text(text, options),
        Text::Bytes(bytes) => walls_ide::check_bytes(bytes, options),
    })
}

/// An optional argument that must be a positive, finite number (`min_radius`, `dt`).
fn positive(name: &str, value: Option<&Bound<'_, PyAny>>) -> PyResult<Option<f64>> {
    args::optional(value, |v| {
        let x = args::number(v, &name)?;
        if x > 0.0 {
            Ok(x)
        } else {
            Err(PyValueError::new_err(format!(
                "{name} must be a positive number, not {x}"
            )))
        }
    })
}

/// Checks a walls file as `walls-lint` does and returns its diagnostics, each a dict as
/// `walls-lint --format json` gives it (`code`, `severity`, `message`, `line`,
/// `column`, `end_line`, `end_column`, and `help` and `fix` where there are some).
///
/// `text` is a `str`, or `bytes` read as a file is (bytes that are not UTF-8 give S001).
/// `mode` is "ssdem" or "hsdem"; `max_walls` is pkdgrav's MAX_NUM_WALLS (20 when None);
/// `min_radius` (the smallest particle radius) turns on the SSDEM wall-speed check, with
/// `dt` the timestep for walls whose `step` is 0.
#[pyfunction]
#[pyo3(
    signature = (text, mode = ContactModel::Ssdem, *, max_walls = None, min_radius = None, dt = None),
    text_signature = "(text, mode=\"ssdem\", *, max_walls=None, min_radius=None, dt=None)"
)]
fn lint<'py>(
    py: Python<'py>,
    text: &Bound<'py, PyAny>,
    #[pyo3(from_py_with = args::mode)] mode: ContactModel,
    max_walls: Option<&Bound<'py, PyAny>>,
    min_radius: Option<&Bound<'py, PyAny>>,
    dt: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyList>> {
    let defaults = Options::default();
    let options = Options {
        mode,
        max_walls: args::optional(max_walls, args::max_walls)?.unwrap_or(defaults.max_walls),
        min_radius: positive("min_radius", min_radius)?,
        dt: positive("dt", dt)?,
    };
    let checked = check(py, args::text(text)?, &options);
    diagnostics::to_python(py, &checked.text, &checked.diagnostics)
}

/// What a `WallsError` of `format` says first.
const NOT_FORMATTED: &str = "syntax errors prevent formatting";

/// Formats a walls file as `walls-fmt` does and returns the canonical text.
///
/// The options are `.walls-fmt.toml`'s (None keeps the default): `indent_width` (2, at
/// most 16), `align_trailing_comments` (False) and `keep_blank_lines` (True). Raises
/// `WallsError`, with the diagnostics, when syntax errors leave the file's statements
/// unclear (or the bytes are not UTF-8).
#[pyfunction]
#[pyo3(signature = (text, *, indent_width = None, align_trailing_comments = None, keep_blank_lines = None))]
fn format<'py>(
    py: Python<'py>,
    text: &Bound<'py, PyAny>,
    indent_width: Option<&Bound<'py, PyAny>>,
    align_trailing_comments: Option<&Bound<'py, PyAny>>,
    keep_blank_lines: Option<&Bound<'py, PyAny>>,
) -> PyResult<String> {
    let defaults = FormatOptions::default();
    let width = |v: &Bound<'py, PyAny>| {
        let most = walls_format::MAX_INDENT_WIDTH as i128;
        args::integer(v, &"indent_width", 0..=most).map(|n| n as usize)
    };
    let options = FormatOptions {
        indent_width: args::optional(indent_width, width)?.unwrap_or(defaults.indent_width),
        align_trailing_comments: args::optional(align_trailing_comments, |v| {
            args::flag(v, &"align_trailing_comments")
        })?
        .unwrap_or(defaults.align_trailing_comments),
        keep_blank_lines: args::optional(keep_blank_lines, |v| args::flag(v, &"keep_blank_lines"))?
            .unwrap_or(defaults.keep_blank_lines),
    };
    let text = match args::text(text)? {
        Text::Str(text) => text,
        Text::Bytes(bytes) => match walls_syntax::decode(bytes) {
            Ok(text) => text,
            Err((prefix, d)) => {
                return Err(diagnostics::error(py, NOT_FORMATTED, &prefix, &[*d]));
            }
        },
    };
    let formatted = py.detach(|| walls_format::format_text(&text, &options));
    formatted.map_err(|e| diagnostics::error(py, NOT_FORMATTED, &text, &e.diagnostics))
}

/// Resolves a walls file as `walls-sim scene` does and returns the scene it prints: a
/// dict with every wall and the effective value of every token, in pkdgrav units, and
/// with `time`, each wall's position then.
///
/// With `strict` (the default) a file with errors raises `WallsError` with them;
/// `strict=False` gives the scene resolved from what parsed, as `walls-sim scene` does
/// beside its exit status 1. `mode` is "ssdem" or "hsdem".
#[pyfunction]
#[pyo3(
    signature = (text, time = None, strict = true, *, mode = ContactModel::Ssdem),
    text_signature = "(text, time=None, strict=True, *, mode=\"ssdem\")"
)]
fn scene<'py>(
    py: Python<'py>,
    text: &Bound<'py, PyAny>,
    time: Option<&Bound<'py, PyAny>>,
    #[pyo3(from_py_with = args::strict)] strict: bool,
    #[pyo3(from_py_with = args::mode)] mode: ContactModel,
) -> PyResult<Bound<'py, PyAny>> {
    let time = args::optional(time, |v| args::number(v, &"time"))?;
    let options = Options {
        mode,
        ..Options::default()
    };
    let checked = check(py, args::text(text)?, &options);
    if strict {
        let errors = checked.errors();
        if !errors.is_empty() {
            return Err(diagnostics::error(
                py,
                "the walls file has errors",
                &checked.text,
                &errors,
            ));
        }
    }
    let mut json = Vec::new();
    py.detach(|| walls_geometry::json::write_scene(&mut json, &checked.scene, &checked.text, time))
        .map_err(|e| PyRuntimeError::new_err(format!("writing the scene: {e}")))?;
    diagnostics::from_json(py, &json)
}
