//! `walls._walls`, the extension module of the `walls` Python package (docs/python.md).
//!
//! Every function here calls the library the command-line tools call, and none checks,
//! formats or resolves on its own: [`api`] is `walls.lint`, `walls.format` and
//! `walls.scene` over text; [`diagnostics`] is `walls.WallsError` and the diagnostics as
//! `walls-lint --format json` gives them; [`tools`] runs the command-line tools for the
//! wheel's console scripts; [`build`] is `walls.Wall` and the builder's calls; [`args`]
//! converts the arguments of them all, strictly and in one place; [`run`] is
//! `walls.run` (a run of `walls-sim run`), [`ss`] `walls.read_ss` and `walls.write_ss`,
//! [`preview`] `walls.preview` (the page of `walls-sim preview --out page.html`), whose
//! NumPy side is `python/walls/_analysis.py`; [`write`] writes their files through
//! `walls-output`, as the tools write theirs. The work runs with the GIL released, so
//! threads may lint files side by side.
//!
//! Each file of the module adds its own functions in its `register`; a new one is a
//! `mod` line and a `register` call in [`_walls`].

mod api;
mod args;
mod build;
mod diagnostics;
mod preview;
mod run;
mod ss;
mod tools;
mod write;

use pyo3::prelude::*;

/// The module's initialisation: the version, then each file's functions and types.
#[pymodule]
fn _walls(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    diagnostics::register(m)?;
    api::register(m)?;
    build::register(m)?;
    tools::register(m)?;
    run::register(m)?;
    ss::register(m)?;
    preview::register(m)?;
    write::register(m)?;
    Ok(())
}
