//! The command-line tools run in this process, for the wheel's console scripts
//! (`python/walls/_cli.py`): maturin puts either an extension or binaries in a wheel, so
//! `walls-lint`, `walls-fmt`, `walls-sim`, `walls-mesh` and `walls-lsp` are Python scripts
//! that call the tools' own entry points here, with the GIL released.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use std::ffi::OsString;
use std::io::Write;

/// Adds the functions of this file to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(run_tool, m)?)
}

/// Runs the tool `tool` ("walls-lint", "walls-fmt", "walls-sim", "walls-mesh" or
/// "walls-lsp") with the command line `argv` (argv[0] is the program's name) and returns
/// the status its binary would exit with.
#[pyfunction]
fn run_tool(py: Python<'_>, tool: &str, argv: Vec<OsString>) -> PyResult<i32> {
    let entry: fn(Vec<OsString>) -> i32 = match tool {
        "walls-lint" => walls_cli::entry::lint,
        "walls-fmt" => walls_cli::entry::fmt,
        "walls-sim" => walls_cli::entry::sim,
        "walls-mesh" => walls_cli::entry::mesh,
        "walls-lsp" => walls_lsp::entry,
        _ => {
            return Err(PyValueError::new_err(format!(
                "no tool {tool:?}: walls-lint, walls-fmt, walls-sim, walls-mesh or walls-lsp"
            )));
        }
    };
    Ok(py.detach(|| {
        let status = entry(argv);
        // A binary's runtime flushes standard output when main returns; a library's
        // caller ends the process without that. A closed stream has nobody to tell.
        let _ = std::io::stdout().flush();
        status
    }))
}
