//! `_walls._write`: the one way the Python package writes a file (`walls.write_ss`,
//! `walls.Preview.save`), through `walls-output` under the policy every tool's output
//! follows (docs/reliability.md): a device, a FIFO, a socket, a folder, a file with
//! several names (hard links) or a read-only one is refused, and the file is written whole
//! to a new file in its folder and renamed into place, so a failure leaves the old one.
//! A regular file that is there is replaced, as `numpy.save` does (the `--force` of the
//! command line, which a Python function has no way to ask for).

use crate::{args, diagnostics};
use pyo3::prelude::*;
use walls_output::{Outputs, Tool};

/// Adds the functions of this file to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(_write, m)?)?;
    Ok(())
}

/// Writes `data` as the whole file at `path`, replacing a regular file that is there; a
/// refusal or a failure raises `WallsError` naming the path and why.
#[pyfunction]
fn _write(
    py: Python<'_>,
    #[pyo3(from_py_with = args::path)] path: std::path::PathBuf,
    data: &[u8],
) -> PyResult<()> {
    let outputs = Outputs::new(Tool::PYTHON, true);
    let written = py.detach(|| {
        let shown = path.display().to_string();
        let target = outputs
            .plan(&path)
            .map_err(|e| e.message(&shown, Tool::PYTHON))?;
        target.write(data).map_err(|e| target.message(&e))
    });
    written.map_err(|message| diagnostics::plain(py, message))
}
