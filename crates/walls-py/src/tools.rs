//! The command-line tools run in this process, for the wheel's console scripts
//! (`python/walls/_cli.py`): maturin puts either an extension or binaries in a wheel, so
//! `walls-lint`, `walls-fmt`, `walls-sim`, `walls-mesh` and `walls-lsp` are Python scripts
//! that call the tools' own entry points here, with the GIL released.

use crate::args;
use pyo3::prelude::*;
use std::ffi::OsString;
use std::io::Write;

/// Adds the functions of this file to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(run_tool, m)?)
}

/// A tool's entry point: its command line to the status its binary exits with.
type Entry = fn(Vec<OsString>) -> i32;

/// The tools, by the name of their binary, and their entry points.
const TOOLS: &[(&str, Entry)] = &[
    ("walls-lint", walls_cli::entry::lint),
    ("walls-fmt", walls_cli::entry::fmt),
    ("walls-sim", walls_cli::entry::sim),
    ("walls-mesh", walls_cli::entry::mesh),
    ("walls-lsp", walls_lsp::entry),
];

/// Runs the tool `tool` ("walls-lint", "walls-fmt", "walls-sim", "walls-mesh" or
/// "walls-lsp") with the command line `argv` (argv[0] is the program's name) and returns
/// the status its binary would exit with.
#[pyfunction]
fn run_tool(
    py: Python<'_>,
    #[pyo3(from_py_with = tool)] entry: Entry,
    argv: Vec<OsString>,
) -> PyResult<i32> {
    Ok(py.detach(|| {
        let status = entry(argv);
        // A binary's runtime flushes standard output when main returns; a library's
        // caller ends the process without that. A closed stream has nobody to tell.
        let _ = std::io::stdout().flush();
        status
    }))
}

/// `tool` of `run_tool`: a tool's entry point, by its binary's name.
fn tool(value: &Bound<'_, PyAny>) -> PyResult<Entry> {
    args::choice(value, &"tool", TOOLS)
}
